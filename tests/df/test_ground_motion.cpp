// The earthquake input both dimensions share (core/ground_motion.hpp): the
// exact integrals of a piecewise-linear record in 2D and 3D, the modes'
// routes, and the tables each kernel builds from them, checked against the
// closed forms of a record whose integrals are known.
#include <gtest/gtest.h>

#include <cmath>

#include "dda/common/error.hpp"
#include "dda/df/2d/ground_motion.hpp"
#include "dda/df/core/ground_motion.hpp"

namespace dda::df {
namespace {

template <int dim>
using Vec = Eigen::Matrix<double, dim, 1>;

// A record that is piecewise linear by construction, so its integrals are
// known in closed form: a = s t on [0, 2] (v = s t^2/2, d = s t^3/6), then
// a = s (2 - 2 (t - 2)) on [2, 3] ending at 0 at t = 3, sampled unevenly.
template <int dim>
struct Ramp {
  Vec<dim> s;
  std::vector<double> t{0.0, 0.5, 1.25, 2.0, 3.0};
  Ramp() {
    s.setZero();
    s[0] = 1.0;
    s[dim - 1] = -2.0;
  }
  GroundMotion<dim> motion() const {
    std::vector<Vec<dim>> a;
    for (const double x : t) a.push_back(acceleration(x));
    return GroundMotion<dim>(t, a, "ramp");
  }
  Vec<dim> acceleration(double x) const { return x <= 2 ? Vec<dim>(s * x) : Vec<dim>(s * (2 - 2 * (x - 2))); }
  // On [2, 3]: a = s (2 - 2 tau), tau = t - 2; v = v2 + s (2 tau - tau^2),
  // d = d2 + v2 tau + s (tau^2 - tau^3 / 3), with v2 = 2 s, d2 = 4/3 s.
  Vec<dim> velocity(double x) const {
    if (x <= 2) return s * x * x / 2;
    const double tau = std::min(x, 3.0) - 2;
    return s * (2 + 2 * tau - tau * tau);
  }
  Vec<dim> displacement(double x) const {
    if (x <= 2) return s * x * x * x / 6;
    const double tau = std::min(x, 3.0) - 2;
    const Vec<dim> at_end = s * (4.0 / 3 + 2 * tau + tau * tau - tau * tau * tau / 3);
    return at_end + (x - std::min(x, 3.0)) * velocity(3.0);  // drifts on at the final velocity
  }
};

template <typename T>
class GroundMotionInBothDimensions : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(GroundMotionInBothDimensions, Dimensions);

TYPED_TEST(GroundMotionInBothDimensions, IntegratesAPiecewiseLinearRecordExactly) {
  constexpr int dim = TypeParam::value;
  const Ramp<dim> r;
  const GroundMotion<dim> g = r.motion();
  for (const double x : {0.0, 0.3, 1.0, 1.9, 2.0, 2.4, 3.0, 4.5}) {
    EXPECT_LT((g.velocity(x) - r.velocity(x)).norm(), 1e-12) << x;
    EXPECT_LT((g.displacement(x) - r.displacement(x)).norm(), 1e-12) << x;
  }
  EXPECT_LT((g.acceleration(2.5) - r.acceleration(2.5)).norm(), 1e-12);
  EXPECT_EQ(g.acceleration(3.5), Vec<dim>::Zero()) << "no shaking after the record";
  // The mean over a step is the exact impulse per unit time, across a sample.
  EXPECT_LT((g.mean_acceleration(1.8, 2.3) - (r.velocity(2.3) - r.velocity(1.8)) / 0.5).norm(), 1e-12);
  EXPECT_LT((g.mean_acceleration(0.7, 0.7) - r.acceleration(0.7)).norm(), 1e-12);
}

TYPED_TEST(GroundMotionInBothDimensions, RefinesTheRecordToTheStepKeepingEverySample) {
  constexpr int dim = TypeParam::value;
  const GroundMotion<dim> g = Ramp<dim>().motion();
  // Intervals 0.5, 0.75, 0.75, 1 at a step of 0.25: 2 + 3 + 3 + 4 parts.
  const std::vector<double> rows = g.refined_times(0.25);
  ASSERT_EQ(rows.size(), 13u);
  for (const double sample : g.times()) EXPECT_NE(std::find(rows.begin(), rows.end(), sample), rows.end());
  for (std::size_t k = 1; k < rows.size(); ++k) EXPECT_LE(rows[k] - rows[k - 1], 0.25 * (1 + 1e-12));
}

TYPED_TEST(GroundMotionInBothDimensions, TheIncidentWaveIsHalfTheOutcropVelocityAndStopsAfterTheRecord) {
  constexpr int dim = TypeParam::value;
  const Ramp<dim> r;
  const auto rows = incident_velocity_rows(r.motion(), 0.1);
  for (std::size_t k = 0; k + 1 < rows.size(); ++k)
    EXPECT_LT((rows[k].second - 0.5 * r.velocity(rows[k].first)).norm(), 1e-12) << rows[k].first;
  EXPECT_DOUBLE_EQ(rows.back().first, 3.1);
  EXPECT_EQ(rows.back().second, Vec<dim>::Zero());
}

TYPED_TEST(GroundMotionInBothDimensions, EachModeDrivesItsOwnRoute) {
  constexpr int dim = TypeParam::value;
  const Ramp<dim> r;
  const GroundMotion<dim> g = r.motion();
  const GroundMotionMode& loading = ground_motion_mode("loading");
  const GroundMotionMode& displacement = ground_motion_mode("displacement");
  const GroundMotionMode& incident = ground_motion_mode("incident");
  // Loading: minus the step's mean acceleration, the instantaneous one at dt = 0.
  EXPECT_LT((loading.body_acceleration(g, 1.0, 0.5) + (r.velocity(1.5) - r.velocity(1.0)) / 0.5).norm(), 1e-12);
  EXPECT_LT((loading.body_acceleration(g, 1.0, 0.0) + r.acceleration(1.0)).norm(), 1e-12);
  EXPECT_EQ(loading.foundation_displacement(g, 1.0), Vec<dim>::Zero());
  // Displacement: the foundation follows d_g, and no body force.
  EXPECT_LT((displacement.foundation_displacement(g, 2.5) - r.displacement(2.5)).norm(), 1e-12);
  EXPECT_EQ(displacement.body_acceleration(g, 1.0, 0.5), Vec<dim>::Zero());
  // Incident: neither (the wave enters through the viscous boundary).
  EXPECT_EQ(incident.body_acceleration(g, 1.0, 0.5), Vec<dim>::Zero());
  EXPECT_EQ(incident.foundation_displacement(g, 2.5), Vec<dim>::Zero());
  // The baseline defaults: none for a body force, degree 3 where the path matters.
  EXPECT_EQ(loading.default_baseline, 0);
  EXPECT_EQ(displacement.default_baseline, 3);
  EXPECT_EQ(incident.default_baseline, 3);
}

TEST(GroundMotion, RefusesRecordsItCannotUse) {
  EXPECT_THROW(GroundMotion<2>({0, 0}, {Vec<2>::Zero(), Vec<2>::Zero()}, "r.csv"), InputError);
  EXPECT_THROW(GroundMotion<3>({0, 1}, {Vec<3>::Zero()}, "r.csv"), InputError);
  EXPECT_THROW(GroundMotion<2>({0, NAN}, {Vec<2>::Zero(), Vec<2>::Zero()}, "r.csv"), InputError);
  try {
    (void)ground_motion_mode("velocity");
    ADD_FAILURE() << "an unknown mode was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "Unknown earthquake mode 'velocity' (known: loading, displacement, incident).");
  }
  // A 2D model has no place for a vertical-out-of-plane component.
  AccelRecord rec;
  rec.source = "quake.csv";
  rec.t = {0, 1};
  rec.a = {std::vector<double>{0, 1}, std::vector<double>{0, 0}, std::vector<double>{0, 0.5}};
  EXPECT_NO_THROW(ground_motion_of<3>(rec));
  try {
    ground_motion_of<2>(rec);
    ADD_FAILURE() << "a z column was dropped silently";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("quake.csv: has a fourth column (az)", 0), 0u) << e.what();
  }
}

// The 2D kernel's foundation table: rows at the samples with the exact d_g
// and v_g as rates. Its Hermite curve is then d_g itself between the rows
// too (a cubic between samples), not just at them.
TEST(GroundMotion2, TheFoundationTableIsTheExactGroundPath) {
  const Ramp<2> r;
  ModelInput in;
  in.control.dt = 0.2;
  in.fixed_points.push_back(FixedPoint{});
  in.fixed_points.back().name = "base";
  apply_ground_motion(r.motion(), ground_motion_mode("displacement"), {0}, in);
  ASSERT_TRUE(in.fixed_points[0].history);
  const TimeHistory& h = *in.fixed_points[0].history;
  for (const double x : {0.05, 0.33, 1.01, 1.99, 2.47, 2.93, 3.0, 3.8})
    EXPECT_LT((h.at(x) - r.displacement(x)).norm(), 1e-12) << x;
}

}  // namespace
}  // namespace dda::df
