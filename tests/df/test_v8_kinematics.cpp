// V8 (docs/validation.md, "Elastic and kinematic checks"): free fall, free spin, pushed
// block, column under gravity. The expected numbers are closed forms; the
// DDA integrator (constant acceleration in the step) is exact for constant
// acceleration, so the first three hold to rounding.
#include <gtest/gtest.h>

#include <array>

#include "df_test_models.hpp"
#include "dda/df/2d/block_kinematics.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {
namespace {

using test::make_block;
using test::rectangle;

TEST(V8, FreeFallIsExact) {
  // s = g t^2 / 2 and v = g t for a block without contacts. The step control
  // cuts dt as the block speeds up (g2 * w0 = 5 mm per step), which must not
  // spoil exactness.
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, 1)));
  in.materials = {test::rock()};
  in.control.dt = 0.01;
  in.measurements.push_back({"c", {0.5, 0.5}, -1});
  Simulation sim(build_model(in));
  sim.run_until(1.0);
  const MeasurementSample& s = sim.histories()[0].back();
  EXPECT_NEAR(s.time, 1.0, 1e-12);
  const double g = 9.81, expected = -0.5 * g;
  EXPECT_LE(std::abs(s.displacement.y() - expected) / std::abs(expected), 1e-9);
  EXPECT_NEAR(s.displacement.x(), 0.0, 1e-12);
  EXPECT_LE(std::abs(s.velocity.y() + g) / g, 1e-9);
  EXPECT_GT(sim.log().size(), 100u);  // dt was cut by the displacement limit
  // The receiver's acceleration is g in every step, whatever its length.
  for (std::size_t k = 1; k < sim.histories()[0].size(); ++k)
    EXPECT_LE((sim.histories()[0][k].acceleration - Vec2(0, -g)).norm() / g, 1e-9) << "sample " << k;
}

TEST(V8, FreeSpinKeepsAreaAndAngle) {
  // A non-convex block spinning at omega about its centroid: the exact
  // rotation update keeps the area, and after time t every vertex has turned
  // by omega t exactly (no gravity, no contacts).
  const Polygon2 l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  ModelInput in;
  in.geometry.blocks.push_back(make_block(l));
  in.materials = {test::rock()};
  in.gravity = {0, 0};
  in.control.dt = 0.01;
  in.control.max_displacement_ratio = 0.05;
  const double omega = 3.0;
  Vector6d v0 = Vector6d::Zero();
  v0[2] = omega;
  in.initial_velocity = {v0};
  Simulation sim(build_model(in));
  const double area0 = sim.blocks()[0].geometry.area;
  const Vec2 c = sim.blocks()[0].geometry.centroid;
  sim.run_until(4.0);
  EXPECT_GT(sim.log().size(), 300u);
  const BlockState& b = sim.blocks()[0];
  EXPECT_LE(std::abs(b.geometry.area - area0) / area0, 1e-9);
  EXPECT_LE((b.geometry.centroid - c).norm(), 1e-9);
  for (std::size_t k = 0; k < l.size(); ++k) {
    const Vec2 expected = c + test::rotated(Vec2(l[k] - c), omega * 4.0);
    EXPECT_LE((b.vertices[k] - expected).norm(), 1e-9) << "vertex " << k;
  }
}

TEST(V8, PushedBlockMovesFt2Over2m) {
  // DDA for Windows "pushblock": unit mass 5, unit block (m = 5 per unit
  // thickness), constant force F = 10 N through the centroid, no gravity:
  // s = F t^2 / (2 m) = 1 m at t = 1 s.
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, 1)));
  in.materials = {test::rock(5.0)};
  in.gravity = {0, 0};
  in.control.dt = 0.01;
  in.control.w0 = 10.0;  // allow 0.1 m per step
  in.loads.push_back({"push", {0.5, 0.5}, {10.0, 0.0}, -1});
  in.measurements.push_back({"c", {0.5, 0.5}, -1});
  Simulation sim(build_model(in));
  sim.run_until(1.0);
  const MeasurementSample& s = sim.histories()[0].back();
  EXPECT_LE(std::abs(s.displacement.x() - 1.0), 1e-9);
  EXPECT_NEAR(s.displacement.y(), 0.0, 1e-12);
  EXPECT_LE(std::abs(s.velocity.x() - 2.0), 1e-9);  // v = F t / m
  EXPECT_LE(std::abs(s.acceleration.x() - 2.0), 1e-9);  // a = F / m
}

TEST(V8, ColumnOnFixedBaseCarriesMeanStress) {
  // A w x h block resting on a fixed base under gravity, static relaxation
  // (k = 0). DDA has one constant stress per block; the base reaction W =
  // rho g S acts at Y = -h/2 below the centroid, so the ey equation reads
  // S sigma_yy = -(h/2) W, i.e. sigma_yy = -rho g h / 2: the mean of the
  // linear profile 0 (top) .. -rho g h (base) of docs/validation.md V8. Shear springs
  // at the base only act on ex and gxy, so this holds for any friction and
  // either plane mode.
  const double rho = 2500, g = 9.81, h = 2.0;
  ModelInput in;
  in.geometry.blocks.push_back(make_block(rectangle(-1, -1, 3, 1)));  // base
  in.geometry.blocks.push_back(make_block(rectangle(0, 0, 1, h)));    // column
  in.materials = {test::rock(rho, 1e9)};
  in.control.dt = 0.01;
  in.control.dynamic = 0.0;
  for (const double x : {-0.5, 0.5, 1.5}) in.fixed_points.push_back({"f", {x, -0.5}, 0, std::nullopt});
  in.measurements.push_back({"col", {0.5, 1.0}, 1});
  Simulation sim(build_model(in));
  for (int s = 0; s < 60; ++s) sim.step();
  const double expected = -rho * g * h / 2;
  const Vector3d& sigma = sim.blocks()[1].stress;
  EXPECT_LE(std::abs(sigma.y() - expected) / std::abs(expected), 1e-3) << sigma.transpose();
  EXPECT_LE(std::abs(sigma.z()), 1e-3 * std::abs(expected));
  EXPECT_EQ(sim.log().back().open, 0);
  EXPECT_EQ(sim.log().back().locked, 2);
  // At rest: the centre drops by the elastic shortening below it,
  // |eps_yy| h / 2 = 2.5e-5 m, plus the penalty compliance: well under 0.1 mm.
  EXPECT_LE(sim.histories()[0].back().displacement.norm(), 1e-4);
  EXPECT_LE(sim.log().back().kinetic_energy, 1e-9);
}

}  // namespace
}  // namespace dda::df

namespace dda::df {
namespace {

// The 2D mass matrix, rho times the integral of T^T T over the block,
// against quadrature: the polygon cut into triangles fanned from vertex 0
// (signed areas, so a non-convex block works), each integrated with the
// edge-midpoint rule, which is exact for the quadratic entries of T^T T.
TEST(MassMatrix2D, EqualsQuadratureOfTTransposeT) {
  const Polygon2 l_shape{{0, 0}, {3, 0}, {3, 1}, {1.2, 1}, {1.2, 2.5}, {0, 2.5}};  // non-convex
  const double rho = 2300;
  const BlockGeometry g = block_geometry(l_shape);
  Matrix6d expected = Matrix6d::Zero();
  for (std::size_t k = 1; k + 1 < l_shape.size(); ++k) {
    const Vec2 &a = l_shape[0], &b = l_shape[k], &c = l_shape[k + 1];
    const double area = 0.5 * cross(b - a, c - a);
    const std::array<Vec2, 3> midpoints{0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)};
    for (const Vec2& m : midpoints) {
      const Matrix26d t = t_matrix(g.centroid, m);
      expected += rho * area / 3 * t.transpose() * t;
    }
  }
  const Matrix6d m = mass_matrix(g, rho);
  EXPECT_LE((m - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff()) << m << "\n\n" << expected;
  EXPECT_EQ(m, m.transpose());
  EXPECT_NEAR(m(0, 0), rho * (3 * 1 + 1.2 * 1.5), 1e-9);  // rho times the area
}

}  // namespace
}  // namespace dda::df
