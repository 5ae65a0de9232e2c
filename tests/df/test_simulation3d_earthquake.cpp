// 3D earthquake input (df/3d/ground_motion3d.hpp; the motion itself is tested in
// test_ground_motion.cpp) on validation case V3
// (docs/validation.md): a 1 m cube on a plane 20/090 with phi = 30,
// under the resultant acceleration r(t) = g [0.5 sin 10t, 0, -1] for
// t in [0, 2 pi] (ten cycles), and the same with a second horizontal
// component. Expected numbers: the analytical 3D solution of the seed report
// (`dda sliding3d`, tools/analysis/sliding3d.hpp) run here with dt = 1e-4;
// docs/validation.md gives its final displacement for the first case, D = (1.165, 0,
// -0.424) m, |D| = 1.239 m, checked too. The seed reports its 3D-DDA within
// 3 % (one component) and 8 % (two) of the analytical result; the issue
// asks for 2 %.
//
// Loading mode: the free cube feels b(t) = -a_g(t) = r(t) - gravity.
// Displacement mode: the base (the fixed block) moves with the ground
// displacement d_g(t), a_g integrated twice; compared is the cube's motion
// relative to the base. dt = 1 ms; the penalty is discussed at kPenalty.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "dda/analysis/sliding3d.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "df_test_models3d.hpp"

namespace dda::df3 {
namespace {

constexpr double kG = 9.81;
constexpr double kPi = std::numbers::pi;
// N/m per contact point, normal and shear; 4e3 x the cube's weight per
// metre. The error against the rigid block (final |D|, loading mode) is
// not the penalty's: 0.69 % at 1e10, 0.51 % at 1e11 and 0.62 % at 1e12
// with dt = 1 ms, and 0.50, 0.83 and 0.74 % with dt = 0.25 ms. Sliding
// contacts turn their friction as their shear springs do (docs/solver3d.md,
// "Friction at its limit"); when it followed every slip, the corners'
// sideways slips (the cube spreads and shrinks as the shaking changes its
// normal load) turned it across the slope and the softer penalty, whose
// corners slip further, was 1.25 % long.
constexpr double kPenalty = 1e11;

// b(t) / g of the two cases.
Vec3 body_one(double t) { return Vec3(0.5 * std::sin(10 * t), 0, 0); }
Vec3 body_two(double t) { return Vec3(0.5 * std::sin(10 * t), 0.3 * std::cos(7 * t), 0); }

// The ground acceleration a_g = -b sampled every 1 ms over [0, t_end].
std::shared_ptr<const GroundMotion3> ground(Vec3 (*body)(double), double t_end) {
  std::vector<double> t;
  std::vector<Vec3> a;
  const int n = static_cast<int>(std::ceil(t_end / 1e-3)) + 1;
  for (int k = 0; k <= n; ++k) {
    t.push_back(k * 1e-3);
    a.push_back(-kG * body(k * 1e-3));
  }
  return std::make_shared<GroundMotion3>(t, a);
}

// Displacements at t = 0.1 s, 0.2 s, ... and at t_end.
using Trajectory = std::vector<Vec3>;
constexpr double kSample = 0.1;

Trajectory analytical(Vec3 (*body)(double), double t_end) {
  analysis::SlidingModel m;
  m.planes = {analysis::Plane{20, 90}};
  m.friction = {analysis::FrictionLaw::constant_angle(30)};
  m.input.body = [body](double t) { return Vec3(kG * body(t)); };
  m.input.duration = t_end;
  m.gravity = kG;
  const auto run = analysis::run_sliding(m, 1e-4, t_end, static_cast<int>(std::lround(kSample / 1e-4)));
  Trajectory out;
  for (std::size_t k = 1; k < run.samples.size(); ++k) out.push_back(run.samples[k].u);
  return out;
}

Trajectory dda(Vec3 (*body)(double), double t_end, const std::string& mode, double penalty = kPenalty) {
  const Eigen::Matrix3d r = testing::plane_rotation(20, 90);
  Model3 m;
  m.blocks = {testing::box({-5, -5, -1}, {5, 5, 0}, r), testing::box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, r)};
  m.fixed = {true, false};
  m.materials = {{2600, 1e10, 0.25}};
  m.default_joint.friction_deg = 30;
  m.normal_penalty = m.shear_penalty = penalty;
  m.gravity = {0, 0, -kG};
  m.control.initial_equilibrium = false;  // gravity switched on at t = 0: what the expected numbers assume
  m.earthquake = {ground(body, t_end), &df::ground_motion_mode(mode)};
  Simulation3 sim(m);
  const Vec3 c0 = sim.blocks()[1].centroid, b0 = sim.blocks()[0].centroid;
  const double dt = 1e-3;
  int unconverged = 0;
  Trajectory out;
  const int steps = static_cast<int>(std::lround(t_end / dt)), every = static_cast<int>(std::lround(kSample / dt));
  for (int s = 1; s <= steps; ++s) {
    if (!sim.step(dt).converged) ++unconverged;
    if (s % every == 0 || s == steps) out.push_back((sim.blocks()[1].centroid - c0) - (sim.blocks()[0].centroid - b0));
  }
  EXPECT_EQ(unconverged, 0);
  return out;
}

// The final displacements differ by at most 2 % of the final |D|, and so do
// the displacements at every 0.1 s on the way.
void compare(const char* what, const Trajectory& got, const Trajectory& expected) {
  ASSERT_EQ(got.size(), expected.size());
  const Vec3 &g = got.back(), &e = expected.back();
  double worst = 0, worst_t = 0;
  for (std::size_t k = 0; k < got.size(); ++k)
    if ((got[k] - expected[k]).norm() > worst) worst = (got[k] - expected[k]).norm(), worst_t = kSample * (k + 1);
  std::printf("%s: DDA (%.4f, %.4f, %.4f) m, analytical (%.4f, %.4f, %.4f) m, difference %.2f %% of |D|; "
              "largest on the way %.2f %% at t = %.1f s\n",
              what, g.x(), g.y(), g.z(), e.x(), e.y(), e.z(), 100 * (g - e).norm() / e.norm(), 100 * worst / e.norm(),
              worst_t);
  EXPECT_LT((g - e).norm(), 0.02 * e.norm());
  EXPECT_LT(worst, 0.02 * e.norm());
}

TEST(Simulation3Earthquake, OneHorizontalComponentLoadingModeV3) {
  const double t_end = 2 * kPi;
  const Trajectory expected = analytical(body_one, t_end);
  // The analytical solver against docs/validation.md: D = (1.165, 0, -0.424) m.
  EXPECT_NEAR(expected.back().x(), 1.165, 0.005);
  EXPECT_NEAR(expected.back().z(), -0.424, 0.005);
  const Trajectory got = dda(body_one, t_end, "loading");
  compare("V3-3D loading", got, expected);
  // A ten times softer penalty stays as close (measured 0.69 %, and 0.51 %
  // at 1e11; see kPenalty): within 1 %, half the bound above.
  const Vec3 soft = dda(body_one, t_end, "loading", kPenalty / 10).back();
  std::printf("V3-3D loading, error at penalty 1e10: %.2f %%, 1e11: %.2f %%\n",
              100 * (soft - expected.back()).norm() / expected.back().norm(),
              100 * (got.back() - expected.back()).norm() / expected.back().norm());
  EXPECT_LT((soft - expected.back()).norm(), 0.01 * expected.back().norm());
}

TEST(Simulation3Earthquake, OneHorizontalComponentDisplacementModeV3) {
  const double t_end = 2 * kPi;
  compare("V3-3D displacement", dda(body_one, t_end, "displacement"), analytical(body_one, t_end));
}

TEST(Simulation3Earthquake, TwoHorizontalComponentsV3) {
  const double t_end = 2 * kPi;
  const Trajectory expected = analytical(body_two, t_end);
  // The second component moves the block across the dip (back and forth:
  // at t_end it happens to be back near y = 0).
  double most = 0;
  for (const Vec3& u : expected) most = std::max(most, std::abs(u.y()));
  EXPECT_GT(most, 0.05);
  compare("V3-3D two components, loading", dda(body_two, t_end, "loading"), expected);
  compare("V3-3D two components, displacement", dda(body_two, t_end, "displacement"), expected);
}

}  // namespace
}  // namespace dda::df3
