// The 3D block's kinematics and 12x12 matrices (df/3d/block3d.hpp). Expected
// numbers are closed forms or quadratures that do not use the second
// moments, so they check the exact integrals independently.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "dda/df/3d/block3d.hpp"

namespace dda::df3 {
namespace {

struct Shape {
  std::vector<Vec3> vertices;
  std::vector<PolyFace> faces;
};

// Box [lo, hi], vertex i = ix + 2 iy + 4 iz, loops counter-clockwise from outside.
Shape box(const Vec3& lo, const Vec3& hi) {
  Shape s;
  for (int i = 0; i < 8; ++i)
    s.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  for (const auto& loop : std::vector<std::vector<int>>{
           {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}) {
    PolyFace f;
    f.vertices = loop;
    s.faces.push_back(f);
  }
  return s;
}

// Tetrahedron a b c d with (b-a).((c-a)x(d-a)) > 0.
Shape tetrahedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  Shape s;
  s.vertices = {a, b, c, d};
  for (const auto& loop : std::vector<std::vector<int>>{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) {
    PolyFace f;
    f.vertices = loop;
    s.faces.push_back(f);
  }
  return s;
}

// A skewed tetrahedron far from the origin (so nothing cancels by symmetry).
Shape skew_tetrahedron() {
  return tetrahedron({10, -5, 3}, {12.5, -4.6, 3.2}, {10.7, -2.9, 3.4}, {10.4, -4.3, 5.1});
}

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

TEST(Block3Kinematics, DisplacementMatrixIsRigidMotionPlusStrain) {
  // u = u0 + r x X + E X written out by hand for one point and one d.
  const Vec3 c(1, 2, 3), x(1.5, 1.0, 4.0), X = x - c;
  Vector12d d;
  d << 0.1, -0.2, 0.3, 0.01, -0.02, 0.03, 1e-3, 2e-3, -3e-3, 4e-3, -5e-3, 6e-3;
  Matrix3d e;
  e << d[6], d[11] / 2, d[10] / 2, d[11] / 2, d[7], d[9] / 2, d[10] / 2, d[9] / 2, d[8];
  const Vec3 expected = d.head<3>() + d.segment<3>(3).cross(X) + e * X;
  EXPECT_LE((displacement_matrix(x, c) * d - expected).norm(), 1e-15);
}

// rho * sum of w T^T T over a quadrature exact for quadratics.
Matrix12d quadrature_mass(const std::vector<Vec3>& points, const std::vector<double>& weights, const Vec3& c,
                          double rho) {
  Matrix12d m = Matrix12d::Zero();
  for (std::size_t q = 0; q < points.size(); ++q) {
    const Matrix3x12d t = displacement_matrix(points[q], c);
    m += rho * weights[q] * t.transpose() * t;
  }
  return m;
}

TEST(Block3Kinematics, MassMatrixMatchesQuadratureOnTetrahedron) {
  // T^T T is quadratic in x: the 4-point tetrahedron rule (barycentric
  // (a, b, b, b), a = (5 + 3 sqrt 5)/20, weights V/4) integrates it exactly.
  const Shape s = skew_tetrahedron();
  const BlockGeometry3 g = block_geometry(s.vertices, s.faces);
  const double a = (5 + 3 * std::sqrt(5.0)) / 20, b = (5 - std::sqrt(5.0)) / 20;
  std::vector<Vec3> pts;
  for (int k = 0; k < 4; ++k) {
    Vec3 p = Vec3::Zero();
    for (int j = 0; j < 4; ++j) p += (j == k ? a : b) * s.vertices[j];
    pts.push_back(p);
  }
  const Vec3 e1 = s.vertices[1] - s.vertices[0], e2 = s.vertices[2] - s.vertices[0], e3 = s.vertices[3] - s.vertices[0];
  const double v = e1.dot(e2.cross(e3)) / 6;
  EXPECT_NEAR(g.volume, v, 1e-13 * v);
  const double rho = 2700;
  EXPECT_LE(relative(mass_matrix(g, rho), quadrature_mass(pts, std::vector<double>(4, v / 4), g.centroid, rho)),
            1e-10);
}

TEST(Block3Kinematics, MassMatrixMatchesQuadratureOnBox) {
  // 2-point Gauss per axis (x = mid +- h/(2 sqrt 3)) is exact to cubics per axis.
  const Vec3 lo(-3, 4, 1), hi(-1, 5, 4);
  const Shape s = box(lo, hi);
  const BlockGeometry3 g = block_geometry(s.vertices, s.faces);
  const Vec3 mid = (lo + hi) / 2, h = (hi - lo) / (2 * std::sqrt(3.0));
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i)
    pts.push_back(mid + Vec3(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z()));
  const double v = (hi - lo).prod();
  const double rho = 2500;
  EXPECT_LE(relative(mass_matrix(g, rho), quadrature_mass(pts, std::vector<double>(8, v / 8), g.centroid, rho)),
            1e-10);
}

TEST(Block3Kinematics, MassMatrixIsSymmetricPositiveDefinite) {
  for (const Shape& s : {skew_tetrahedron(), box({0, 0, 0}, {1, 2, 3})}) {
    const Matrix12d m = mass_matrix(block_geometry(s.vertices, s.faces), 2600);
    EXPECT_EQ(m, m.transpose());
    EXPECT_EQ(m.llt().info(), Eigen::Success);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix12d>(m).eigenvalues().minCoeff(), 0);
  }
}

TEST(Block3Kinematics, KineticEnergyOfRigidMotions) {
  // Translation: 1/2 m |v|^2. Rotation about the centroid: 1/2 w^T I w with
  // I = rho (trace(S) Id - S), the inertia tensor from the second moment S.
  const Shape s = skew_tetrahedron();
  const BlockGeometry3 g = block_geometry(s.vertices, s.faces);
  const double rho = 2650, mass = rho * g.volume;
  const Matrix12d m = mass_matrix(g, rho);
  Vector12d v = Vector12d::Zero();
  v.head<3>() = Vec3(0.3, -1.2, 0.7);
  EXPECT_NEAR(0.5 * v.dot(m * v), 0.5 * mass * v.head<3>().squaredNorm(), 1e-12 * mass);
  const Vec3 w(0.4, -0.9, 1.3);
  v.setZero();
  v.segment<3>(kRotation) = w;
  const Matrix3d inertia = rho * (g.second_moment.trace() * Matrix3d::Identity() - g.second_moment);
  const double expected = 0.5 * w.dot(inertia * w);
  EXPECT_NEAR(0.5 * v.dot(m * v), expected, 1e-12 * expected);
}

TEST(Block3Kinematics, StrainEnergyUniaxialAndShear) {
  // Uniaxial strain: W = V (lambda + 2 mu) ex^2 / 2 with
  // lambda + 2 mu = E (1 - nu) / ((1 + nu)(1 - 2 nu)). Pure engineering shear
  // g: W = V G g^2 / 2, G = E / (2 (1 + nu)).
  const Shape s = box({0, 0, 0}, {1, 2, 3});
  const BlockGeometry3 g = block_geometry(s.vertices, s.faces);
  const Material3 mat{2600, 5e9, 0.3};
  const Matrix12d k = elastic_stiffness(g, mat);
  const double e = mat.young, nu = mat.poisson, strain = 1e-3;
  for (int axis = 0; axis < 3; ++axis) {
    Vector12d d = Vector12d::Zero();
    d[kStrain + axis] = strain;
    const double w = g.volume * e * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) * strain * strain / 2;
    EXPECT_NEAR(0.5 * d.dot(k * d), w, 1e-12 * w) << "axis " << axis;
  }
  for (int shear = 3; shear < 6; ++shear) {
    Vector12d d = Vector12d::Zero();
    d[kStrain + shear] = strain;
    const double w = g.volume * e / (2 * (1 + nu)) * strain * strain / 2;
    EXPECT_NEAR(0.5 * d.dot(k * d), w, 1e-12 * w) << "shear " << shear;
  }
  // Rigid motions cost no strain energy.
  EXPECT_EQ((k.topLeftCorner<6, 12>().norm()), 0.0);
}

TEST(Block3Kinematics, InitialStressIsReleasedByAFreeBlock) {
  // F = -V sigma on the strains (2D convention). A free, stressed block with
  // only its elasticity relaxes: V D e = -V sigma, so sigma + D e = 0.
  const Shape s = box({0, 0, 0}, {2, 1, 1});
  const BlockGeometry3 g = block_geometry(s.vertices, s.faces);
  const Material3 mat{2600, 1e9, 0.25};
  Vector6d sigma;
  sigma << -1e6, 2e5, 3e5, 4e4, -5e4, 6e4;
  Matrix12d k = Matrix12d::Zero();
  Vector12d f = Vector12d::Zero();
  add_elasticity(g, mat, sigma, 0.0, k, f);
  EXPECT_LE((f.segment<6>(kStrain) + g.volume * sigma).norm(), 1e-12 * g.volume * sigma.norm());
  EXPECT_EQ(f.head<6>().norm(), 0.0);
  const Vector6d strain = k.block<6, 6>(kStrain, kStrain).llt().solve(f.segment<6>(kStrain));
  EXPECT_LE((sigma + elastic_matrix(mat) * strain).norm(), 1e-9 * sigma.norm());
  // Compression (negative sx) released: the block lengthens along x.
  EXPECT_GT(strain[0], 0);
}

TEST(Block3Kinematics, BodyForceAndPointLoad) {
  const Shape s = skew_tetrahedron();
  const BlockGeometry3 g = block_geometry(s.vertices, s.faces);
  // Body force: rho V b on the translations, nothing else (first moments vanish).
  Vector12d f = Vector12d::Zero();
  add_body_force(g, 2000, Vec3(0, 0, -9.81), f);
  EXPECT_NEAR(f[2], -2000 * g.volume * 9.81, 1e-12 * 2000 * g.volume * 9.81);
  EXPECT_EQ(std::abs(f[0]) + std::abs(f[1]) + f.tail<9>().norm(), 0.0);
  // Point load P at x: force P on the translations, its moment X x P about
  // the centroid on the rotations, and virtual work d.F = (T d).P for any d.
  const Vec3 x = s.vertices[3], p(100, -250, 40);
  f.setZero();
  add_point_load(g, x, p, f);
  EXPECT_LE((f.head<3>() - p).norm(), 1e-12 * p.norm());
  EXPECT_LE((f.segment<3>(kRotation) - (x - g.centroid).cross(p)).norm(), 1e-12 * p.norm());
  Vector12d d;
  d << 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12;
  EXPECT_NEAR(d.dot(f), (displacement_matrix(x, g.centroid) * d).dot(p), 1e-10 * p.norm() * d.norm());
}

TEST(Block3Kinematics, InertiaAndPointSpringAreTheirEnergies) {
  // The quadratic 1/2 d^T K d - d^T F must equal the term's energy up to a
  // constant: p/2 |T d - gap|^2 - p/2 |gap|^2 for the spring, and
  // 1/dt^2 (d - dt v0)^T M (d - dt v0) - v0^T M v0 for inertia.
  const Shape s = box({1, 1, 1}, {2, 3, 2});
  const BlockGeometry3 g = block_geometry(s.vertices, s.faces);
  Vector12d d, v0;
  d << 0.1, -0.2, 0.3, 0.01, -0.02, 0.03, 1e-3, 2e-3, -3e-3, 4e-3, -5e-3, 6e-3;
  v0 << 1, 0.5, -2, 0.1, 0.2, -0.3, 0.01, 0, 0.02, -0.01, 0.03, 0.005;
  const Vec3 x(2, 1, 1.5), gap(0.01, -0.02, 0.005);
  const double p = 1e9;
  Matrix12d k = Matrix12d::Zero();
  Vector12d f = Vector12d::Zero();
  add_point_spring(g, x, gap, p, k, f);
  const double spring = 0.5 * p * ((displacement_matrix(x, g.centroid) * d - gap).squaredNorm() - gap.squaredNorm());
  EXPECT_NEAR(0.5 * d.dot(k * d) - d.dot(f), spring, 1e-9 * std::abs(spring));
  const double dt = 0.01, rho = 2600;
  k.setZero();
  f.setZero();
  add_inertia(g, rho, v0, dt, k, f);
  const Matrix12d m = mass_matrix(g, rho);
  const Vector12d a = d - dt * v0;
  const double inertia = (a.dot(m * a) - dt * dt * v0.dot(m * v0)) / (dt * dt);
  EXPECT_NEAR(0.5 * d.dot(k * d) - d.dot(f), inertia, 1e-9 * std::abs(inertia));
}

TEST(Block3Kinematics, QuarterTurnAboutZ) {
  // Rodrigues with angle pi/2 about z: (1, 0, 0) -> (0, 1, 0).
  Vector12d d = Vector12d::Zero();
  d[kRotation + 2] = std::numbers::pi / 2;
  EXPECT_LE((move_point(Vec3::Zero(), d, Vec3(1, 0, 0)) - Vec3(0, 1, 0)).norm(), 1e-15);
  // About a centroid elsewhere, with a translation on top.
  d.head<3>() = Vec3(1, 2, 3);
  EXPECT_LE((move_point(Vec3(5, 5, 5), d, Vec3(6, 5, 5)) - Vec3(6, 8, 8)).norm(), 1e-14);
}

double max_distance_change(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j) {
      const double d0 = (a[i] - a[j]).norm();
      worst = std::max(worst, std::abs((b[i] - b[j]).norm() - d0) / d0);
    }
  return worst;
}

TEST(Block3Kinematics, ManySmallRotationsKeepTheShape) {
  // 1000 steps of a small rotation about an oblique axis: an exact rotation
  // keeps every vertex distance; the linearised r x X would stretch the
  // block by up to |r|^2 / 2 per step (4e-6 here, ~4e-3 after 1000 steps).
  Shape s = box({0, 0, 0}, {1, 2, 3});
  const std::vector<Vec3> start = s.vertices;
  Vector12d d = Vector12d::Zero();
  d.segment<3>(kRotation) = Vec3(0.001, 0.002, -0.0015);
  for (int step = 0; step < 1000; ++step) {
    const Vec3 c = block_geometry(s.vertices, s.faces).centroid;
    for (Vec3& v : s.vertices) v = move_point(c, d, v);
  }
  EXPECT_LE(max_distance_change(start, s.vertices), 1e-12);
  EXPECT_NEAR(block_geometry(s.vertices, s.faces).volume, 6.0, 1e-12 * 6);
}

// One DDA step of a free block (no contacts): inertia and body force only.
// Returns the increment d; moves the vertices and updates the velocity
// (v1 = 2 d / dt - v0, docs/formulation.md "Global system").
Vector12d free_step(Shape& s, Vector12d& v, double rho, const Vec3& b, double dt) {
  const BlockGeometry3 g = block_geometry(s.vertices, s.faces);
  Matrix12d k = Matrix12d::Zero();
  Vector12d f = Vector12d::Zero();
  add_inertia(g, rho, v, dt, k, f);
  add_body_force(g, rho, b, f);
  const Vector12d d = k.llt().solve(f);
  for (Vec3& x : s.vertices) x = move_point(g.centroid, d, x);
  v = 2 * d / dt - v;
  return d;
}

TEST(Block3Kinematics, FreeFallIsExact) {
  // z(t) = -g t^2 / 2, v = -g t: the integrator assumes constant
  // acceleration in the step, which is exactly free fall.
  Shape s = box({0, 0, 0}, {1, 2, 1.5});
  const Vec3 c0 = block_geometry(s.vertices, s.faces).centroid;
  Vector12d v = Vector12d::Zero();
  const double g = 9.81, dt = 0.01;
  for (int step = 0; step < 100; ++step) free_step(s, v, 2600, Vec3(0, 0, -g), dt);
  const double t = 100 * dt, expected = -g * t * t / 2;
  const Vec3 moved = block_geometry(s.vertices, s.faces).centroid - c0;
  EXPECT_LE(std::abs(moved.z() - expected) / std::abs(expected), 1e-10);
  EXPECT_LE(std::abs(moved.x()) + std::abs(moved.y()), 1e-12);
  EXPECT_LE(std::abs(v[2] + g * t) / (g * t), 1e-10);
  EXPECT_LE(v.tail<9>().norm() + std::abs(v[0]) + std::abs(v[1]), 1e-10);
}

TEST(Block3Kinematics, FreeSpinKeepsSpeedAndVolume) {
  // No force: K d = F gives d = v0 dt whatever M, so v1 = v0 and the spin
  // (about an oblique axis, not a principal one) keeps its angular velocity;
  // steps about one fixed axis compose, so after n steps the block has
  // turned exactly by R(n dt w) about its centroid.
  Shape s = box({2, -1, 0}, {3, 1, 3});
  const std::vector<Vec3> start = s.vertices;
  const BlockGeometry3 g0 = block_geometry(s.vertices, s.faces);
  const Vec3 w(0.3, -0.2, 0.5);
  Vector12d v = Vector12d::Zero();
  v.segment<3>(kRotation) = w;
  const double dt = 0.01;
  const int steps = 100;
  for (int step = 0; step < steps; ++step) free_step(s, v, 2600, Vec3::Zero(), dt);
  EXPECT_LE((v.segment<3>(kRotation) - w).norm() / w.norm(), 1e-12);
  EXPECT_LE(v.head<3>().norm() + v.tail<6>().norm(), 1e-12);
  const BlockGeometry3 g1 = block_geometry(s.vertices, s.faces);
  EXPECT_NEAR(g1.volume, g0.volume, 1e-12 * g0.volume);
  EXPECT_LE((g1.centroid - g0.centroid).norm(), 1e-12);
  EXPECT_LE(max_distance_change(start, s.vertices), 1e-12);
  const Matrix3d r = rotation_matrix(steps * dt * w);
  for (std::size_t i = 0; i < start.size(); ++i)
    EXPECT_LE((s.vertices[i] - (g0.centroid + r * (start[i] - g0.centroid))).norm(), 1e-12) << "vertex " << i;
}

}  // namespace
}  // namespace dda::df3
