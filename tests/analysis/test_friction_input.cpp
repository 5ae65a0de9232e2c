// Friction laws and dynamic input conventions (hand calculations).
#include <gtest/gtest.h>

#include <cmath>

#include "dda/analysis/excitation.hpp"
#include "dda/analysis/friction.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

using namespace dda::analysis;

TEST(Friction, TableStepsAndInterpolation) {
  const FrictionLaw f = FrictionLaw::table({0, 10, 10, 20, 30}, {32, 32, 30, 30, 28}, "test");
  EXPECT_NEAR(f.mu(-1, 0), std::tan(dda::deg2rad(32)), 1e-15);
  EXPECT_NEAR(f.mu(9.999, 0), std::tan(dda::deg2rad(32)), 1e-15);
  EXPECT_NEAR(f.mu(10.0, 0), std::tan(dda::deg2rad(30)), 1e-15);  // the later value holds at the step
  EXPECT_NEAR(f.mu(25.0, 0), std::tan(dda::deg2rad(29)), 1e-15);  // linear between 20 and 30
  EXPECT_NEAR(f.mu(99.0, 0), std::tan(dda::deg2rad(28)), 1e-15);
  EXPECT_THROW(FrictionLaw::table({0, 5, 4}, {30, 30, 30}, "t"), dda::InputError);
  EXPECT_THROW(FrictionLaw::table({0}, {95}, "t"), dda::InputError);
}

TEST(Friction, LogVelocity) {
  const FrictionLaw f = FrictionLaw::log_velocity(0.6, -0.02, 1.0, 1e-4);
  EXPECT_NEAR(f.mu(0, 1.0), 0.6, 1e-15);
  EXPECT_NEAR(f.mu(0, 0.01), 0.6 - 0.02 * std::log(0.01), 1e-15);
  EXPECT_NEAR(f.mu(0, 0.0), 0.6 - 0.02 * std::log(1e-4), 1e-15);  // floored at v_min
  EXPECT_DOUBLE_EQ(FrictionLaw::log_velocity(0.01, 0.1).mu(0, 1e-6), 0.0);  // never negative
}

// Ground acceleration a_g acts as body acceleration -a_g (loading mode).
TEST(Excitation, GroundIsMinusBody) {
  auto rec = std::make_shared<dda::AccelRecord>();
  rec->t = {0.0, 1.0};
  rec->a = {std::vector<double>{1.0, 3.0}, std::vector<double>{0.0, 0.0}, std::vector<double>{-2.0, -2.0}};
  const Excitation g = excitation_from_record(rec, InputMeaning::ground);
  const Excitation b = excitation_from_record(rec, InputMeaning::body);
  EXPECT_TRUE(g.body(0.5).isApprox(Vec3(-2.0, 0.0, 2.0)));
  EXPECT_TRUE(b.body(0.5).isApprox(Vec3(2.0, 0.0, -2.0)));
  EXPECT_TRUE(b.body(1.5).isZero());  // zero after the record
  const Excitation s = sinusoid(Vec3::UnitY(), 2.0, dda::kPi, 1.0, InputMeaning::body);
  EXPECT_NEAR(s.body(0.5).y(), 0.5 * 2.0 * 1.0, 1e-12);  // half-way up the ramp at the crest
  EXPECT_THROW(parse_input_meaning("sideways", "--input"), dda::InputError);
}

TEST(Orientation, PlaneParsingAndVectors) {
  const Plane p = parse_plane("20/090", "--plane");
  EXPECT_NEAR(p.normal().x(), std::sin(dda::deg2rad(20)), 1e-15);
  EXPECT_NEAR(p.normal().z(), std::cos(dda::deg2rad(20)), 1e-15);
  EXPECT_NEAR(p.dip_vector().dot(p.normal()), 0.0, 1e-15);
  const TrendPlunge tp = trend_plunge(p.dip_vector());
  EXPECT_NEAR(tp.trend_deg, 90.0, 1e-12);
  EXPECT_NEAR(tp.plunge_deg, 20.0, 1e-12);
  EXPECT_THROW(parse_plane("95/010", "--plane"), dda::InputError);
  EXPECT_THROW(parse_plane("twenty", "--plane"), dda::InputError);
}
