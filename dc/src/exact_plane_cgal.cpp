// The filtered determinants behind exact::side. A fast double evaluation
// with a forward error bound decides almost every case; only near-zero
// results (a vertex on or within rounding of a plane) are recomputed with
// CGAL::Mpzf, whose sums and products of doubles are exact. This is the only
// file of the 3D cutter that includes CGAL.
#include <CGAL/Mpzf.h>

#include <cmath>

#include "exact_plane.hpp"

namespace dda::dc::exact {

namespace {

// det of [[a0 a1 a2] [b0 b1 b2] [c0 c1 c2]] by the first row.
template <class T>
T det3(const T a[3], const T b[3], const T c[3]) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// det of a 4x4 matrix by 2x2 minors of rows 0-1 and rows 2-3 (Laplace).
template <class T>
T det4(const T m[4][4]) {
  auto minor = [&](int r, int i, int j) { return m[r][i] * m[r + 1][j] - m[r][j] * m[r + 1][i]; };
  const T s0 = minor(0, 0, 1), s1 = minor(0, 0, 2), s2 = minor(0, 0, 3);
  const T s3 = minor(0, 1, 2), s4 = minor(0, 1, 3), s5 = minor(0, 2, 3);
  const T c0 = minor(2, 0, 1), c1 = minor(2, 0, 2), c2 = minor(2, 0, 3);
  const T c3 = minor(2, 1, 2), c4 = minor(2, 1, 3), c5 = minor(2, 2, 3);
  return s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
}

// The same expansions on absolute values bound the sum of the magnitudes of
// every product, so rounding error stays below a small multiple of
// eps * bound (at most ~10 roundings per term; 1e-14 leaves a factor 10).
constexpr double kRelativeBound = 1e-14;

int sign_of(double v) { return (v > 0) - (v < 0); }

void rows(const Plane& p, double out[4]) {
  out[0] = p.n.x();
  out[1] = p.n.y();
  out[2] = p.n.z();
  out[3] = p.d;
}

}  // namespace

int orientation(const Plane& p, const Plane& q, const Plane& r) {
  double a[4], b[4], c[4];
  rows(p, a), rows(q, b), rows(r, c);
  const double v = det3(a, b, c);
  double aa[3], ab[3], ac[3];
  for (int i = 0; i < 3; ++i) aa[i] = std::abs(a[i]), ab[i] = std::abs(b[i]), ac[i] = std::abs(c[i]);
  // det3 of absolute values with "-" replaced by "+": the magnitude bound.
  const double bound = aa[0] * (ab[1] * ac[2] + ab[2] * ac[1]) + aa[1] * (ab[0] * ac[2] + ab[2] * ac[0]) +
                       aa[2] * (ab[0] * ac[1] + ab[1] * ac[0]);
  if (std::abs(v) > kRelativeBound * bound) return sign_of(v);
  CGAL::Mpzf ea[3], eb[3], ec[3];
  for (int i = 0; i < 3; ++i) ea[i] = a[i], eb[i] = b[i], ec[i] = c[i];
  return static_cast<int>(det3(ea, eb, ec).sign());
}

int side(const Plane& p, const Plane& q, const Plane& r, int orient, const Plane& h) {
  double m[4][4];
  rows(p, m[0]), rows(q, m[1]), rows(r, m[2]), rows(h, m[3]);
  const double v = det4(m);
  double am[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) am[i][j] = std::abs(m[i][j]);
  // det4 on magnitudes with every "-" turned "+".
  auto pminor = [&](int r0, int i, int j) { return am[r0][i] * am[r0 + 1][j] + am[r0][j] * am[r0 + 1][i]; };
  const double bound = pminor(0, 0, 1) * pminor(2, 2, 3) + pminor(0, 0, 2) * pminor(2, 1, 3) +
                       pminor(0, 0, 3) * pminor(2, 1, 2) + pminor(0, 1, 2) * pminor(2, 0, 3) +
                       pminor(0, 1, 3) * pminor(2, 0, 2) + pminor(0, 2, 3) * pminor(2, 0, 1);
  int s;
  if (std::abs(v) > kRelativeBound * bound) {
    s = sign_of(v);
  } else {
    CGAL::Mpzf e[4][4];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) e[i][j] = m[i][j];
    s = static_cast<int>(det4(e).sign());
  }
  // h(x) = det4 / det3 (Cramer's rule on the homogeneous system).
  return s * orient;
}

Vec3 meeting_point(const Plane& p, const Plane& q, const Plane& r) {
  // x = -(d_p (n_q x n_r) + d_q (n_r x n_p) + d_r (n_p x n_q)) / det; long
  // double keeps the error of nearly parallel triples small.
  using L = long double;
  auto cross = [](const Vec3& a, const Vec3& b) {
    return std::array<L, 3>{L(a.y()) * b.z() - L(a.z()) * b.y(), L(a.z()) * b.x() - L(a.x()) * b.z(),
                            L(a.x()) * b.y() - L(a.y()) * b.x()};
  };
  const auto qr = cross(q.n, r.n), rp = cross(r.n, p.n), pq = cross(p.n, q.n);
  const L det = L(p.n.x()) * qr[0] + L(p.n.y()) * qr[1] + L(p.n.z()) * qr[2];
  Vec3 x;
  for (int i = 0; i < 3; ++i) x[i] = static_cast<double>(-(L(p.d) * qr[i] + L(q.d) * rp[i] + L(r.d) * pq[i]) / det);
  return x;
}

}  // namespace dda::dc::exact
