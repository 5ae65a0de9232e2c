// Pore pressure of a phreatic surface and its exact integral over joint
// faces (water.hpp).
#include "dda/df/core/water.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace dda::df {

template <>
double WaterTable<2>::head(const Point& p) const {
  if (knots.empty()) return level;
  const double x = p.x();
  if (x <= knots.front().x()) return knots.front().y();
  if (x >= knots.back().x()) return knots.back().y();
  std::size_t k = 1;
  while (knots[k].x() < x) ++k;
  const Point& a = knots[k - 1];
  const Point& b = knots[k];
  return a.y() + (b.y() - a.y()) * (x - a.x()) / (b.x() - a.x());
}

template <>
double WaterTable<3>::head(const Point& p) const {
  if (knots.empty()) return level;
  // The plane h = c0 + c1 x + c2 y through the three knots (a vertical
  // plane was refused when the scenario was read).
  Eigen::Matrix3d m;
  Eigen::Vector3d h;
  for (int k = 0; k < 3; ++k) {
    m.row(k) << 1.0, knots[k].x(), knots[k].y();
    h[k] = knots[k].z();
  }
  const Eigen::Vector3d c = m.partialPivLu().solve(h);
  return c[0] + c[1] * p.x() + c[2] * p.y();
}

namespace {

// Running sums of the force and its first moment.
template <int dim>
struct Sums {
  using Point = Eigen::Matrix<double, dim, 1>;
  double force = 0;
  Point moment = Point::Zero();
  PressureResultant<dim> resultant(const Point& fallback) const {
    PressureResultant<dim> r;
    r.force = force;
    r.centre = force > 0 ? Point(moment / force) : fallback;
    return r;
  }
};

// A linear g >= 0 over the segment p0 p1 (values g0, g1): the integral is
// L (g0 + g1) / 2 and its first moment L / 6 [g0 p0 + g1 p1 + (g0 + g1)(p0 + p1)]
// (the mean of a linear function over a simplex with n vertices is that of
// its vertex values, and of g x it is (sum g_i x_i + sum g sum x) / (n (n + 1))).
void add_segment(Sums<2>& s, const Eigen::Vector2d& p0, double g0, const Eigen::Vector2d& p1, double g1) {
  const double l = (p1 - p0).norm();
  s.force += l * (g0 + g1) / 2;
  s.moment += l / 6 * (g0 * p0 + g1 * p1 + (g0 + g1) * (p0 + p1));
}

// The part of the segment where the linear f (values f0, f1) is positive.
void add_clipped_segment(Sums<2>& s, const Eigen::Vector2d& p0, double f0, const Eigen::Vector2d& p1, double f1) {
  if (f0 <= 0 && f1 <= 0) return;
  if (f0 >= 0 && f1 >= 0) return add_segment(s, p0, f0, p1, f1);
  const Eigen::Vector2d cut = p0 + f0 / (f0 - f1) * (p1 - p0);
  if (f0 > 0)
    add_segment(s, p0, f0, cut, 0);
  else
    add_segment(s, cut, 0, p1, f1);
}

void add_triangle(Sums<3>& s, const Eigen::Vector3d* p, const double* g) {
  const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
  const double gsum = g[0] + g[1] + g[2];
  s.force += area * gsum / 3;
  s.moment += area / 12 * (g[0] * p[0] + g[1] * p[1] + g[2] * p[2] + gsum * (p[0] + p[1] + p[2]));
}

// The part of the triangle where the linear f is positive: a triangle or a
// quadrilateral (cut along f = 0), fanned into triangles.
void add_clipped_triangle(Sums<3>& s, const Eigen::Vector3d* p, const double* f) {
  Eigen::Vector3d q[4];
  double g[4];
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    const int m = (k + 1) % 3;
    if (f[k] >= 0) q[n] = p[k], g[n++] = f[k];
    if ((f[k] > 0 && f[m] < 0) || (f[k] < 0 && f[m] > 0))
      q[n] = p[k] + f[k] / (f[k] - f[m]) * (p[m] - p[k]), g[n++] = 0;
  }
  for (int k = 1; k + 1 < n; ++k) {
    const Eigen::Vector3d t[3] = {q[0], q[k], q[k + 1]};
    const double v[3] = {g[0], g[k], g[k + 1]};
    add_triangle(s, t, v);
  }
}

}  // namespace

PressureResultant<2> pressure_on_segment(const WaterTable<2>& w, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  // Split at the knots' abscissas: h - z is linear on each piece.
  std::vector<double> cuts{0.0, 1.0};
  const double dx = b.x() - a.x();
  if (dx != 0)
    for (const Eigen::Vector2d& k : w.knots) {
      const double t = (k.x() - a.x()) / dx;
      if (t > 0 && t < 1) cuts.push_back(t);
    }
  std::sort(cuts.begin(), cuts.end());
  Sums<2> s;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const Eigen::Vector2d p0 = a + cuts[k] * (b - a), p1 = a + cuts[k + 1] * (b - a);
    add_clipped_segment(s, p0, w.unit_weight * (w.head(p0) - p0.y()), p1, w.unit_weight * (w.head(p1) - p1.y()));
  }
  return s.resultant(a);
}

PressureResultant<3> pressure_on_polygon(const WaterTable<3>& w, const std::vector<Eigen::Vector3d>& face) {
  Sums<3> s;
  auto f = [&w](const Eigen::Vector3d& p) { return w.unit_weight * (w.head(p) - p.z()); };
  for (std::size_t k = 1; k + 1 < face.size(); ++k) {
    const Eigen::Vector3d t[3] = {face[0], face[k], face[k + 1]};
    const double v[3] = {f(t[0]), f(t[1]), f(t[2])};
    add_clipped_triangle(s, t, v);
  }
  return s.resultant(face.empty() ? Eigen::Vector3d::Zero() : face.front());
}

}  // namespace dda::df
