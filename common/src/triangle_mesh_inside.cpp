// MeshInsideTest: ray counting on a grid of triangle shadows.
#include <algorithm>
#include <cmath>

#include "dda/common/triangle_mesh.hpp"

namespace dda {

namespace {

double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

}  // namespace

MeshInsideTest::MeshInsideTest(const TriangleMesh& mesh) : mesh_(mesh), box_(mesh_bounds(mesh)) {
  scale_ = (box_.hi - box_.lo).norm();
  const double wx = box_.hi.x() - box_.lo.x(), wy = box_.hi.y() - box_.lo.y();
  // About one grid cell per triangle, square cells.
  const double n = std::max<double>(1.0, static_cast<double>(mesh.triangles.size()));
  cell_ = std::max(std::sqrt(std::max(wx * wy, 1e-300) / n), 1e-9 * std::max(scale_, 1e-300));
  nx_ = std::clamp(static_cast<int>(wx / cell_) + 1, 1, 4096);
  ny_ = std::clamp(static_cast<int>(wy / cell_) + 1, 1, 4096);
  cell_ = std::max(wx / nx_, wy / ny_) * (1 + 1e-12) + 1e-300;
  auto range = [&](double lo, double hi, double origin, int count, int& a, int& b) {
    a = std::clamp(static_cast<int>(std::floor((lo - origin) / cell_)), 0, count - 1);
    b = std::clamp(static_cast<int>(std::floor((hi - origin) / cell_)), 0, count - 1);
  };
  // Two passes (count, fill) into one flat table.
  std::vector<int> count(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      offsets_.assign(count.size(), 0);
      for (std::size_t k = 1; k < count.size(); ++k) offsets_[k] = offsets_[k - 1] + count[k - 1];
      ids_.assign(static_cast<std::size_t>(offsets_.back()), 0);
      std::fill(count.begin(), count.end(), 0);
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
      for (int v : mesh.triangles[t]) {
        lo = lo.cwiseMin(mesh.vertices[static_cast<std::size_t>(v)]);
        hi = hi.cwiseMax(mesh.vertices[static_cast<std::size_t>(v)]);
      }
      int x0, x1, y0, y1;
      range(lo.x(), hi.x(), box_.lo.x(), nx_, x0, x1);
      range(lo.y(), hi.y(), box_.lo.y(), ny_, y0, y1);
      for (int j = y0; j <= y1; ++j)
        for (int i = x0; i <= x1; ++i) {
          const auto k = static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
          if (pass == 1) ids_[static_cast<std::size_t>(offsets_[k] + count[k])] = static_cast<int>(t);
          ++count[k];
        }
    }
  }
}

bool MeshInsideTest::contains(const Vec3& p) const {
  if (mesh_.triangles.empty() || !box_.contains(p)) return false;
  const int i = std::clamp(static_cast<int>(std::floor((p.x() - box_.lo.x()) / cell_)), 0, nx_ - 1);
  const int j = std::clamp(static_cast<int>(std::floor((p.y() - box_.lo.y()) / cell_)), 0, ny_ - 1);
  const auto k = static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
  // Relative to the model's size, and to the coordinates' own rounding
  // for models far from the origin.
  const double tol = 1e-12 * scale_ + 1e-15 * std::max(box_.lo.cwiseAbs().maxCoeff(), box_.hi.cwiseAbs().maxCoeff());
  int crossings = 0;
  for (int n = offsets_[k]; n < offsets_[k + 1]; ++n) {
    const auto& t = mesh_.triangles[static_cast<std::size_t>(ids_[static_cast<std::size_t>(n)])];
    const Vec3& a = mesh_.vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh_.vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh_.vertices[static_cast<std::size_t>(t[2])];
    // Edge functions of the shadow at p: each is the weight of the corner
    // opposite the edge, times twice the shadow's signed area.
    const double wa = cross2(c.x() - b.x(), c.y() - b.y(), p.x() - b.x(), p.y() - b.y());
    const double wb = cross2(a.x() - c.x(), a.y() - c.y(), p.x() - c.x(), p.y() - c.y());
    const double wc = cross2(b.x() - a.x(), b.y() - a.y(), p.x() - a.x(), p.y() - a.y());
    const double area = wa + wb + wc, sign = area >= 0 ? 1 : -1;
    const double ta = tol * (c - b).head<2>().norm(), tb = tol * (a - c).head<2>().norm(),
                 tc = tol * (b - a).head<2>().norm();
    if (sign * wa < -ta || sign * wb < -tb || sign * wc < -tc) continue;  // clearly off the shadow
    // On or within rounding of the shadow's border (or a vertical triangle's
    // shadow line): the count would be unsure.
    if (!(sign * wa > ta && sign * wb > tb && sign * wc > tc)) return mesh_contains(mesh_, p);
    const double z = (wa * a.z() + wb * b.z() + wc * c.z()) / area;
    if (std::abs(z - p.z()) <= tol) return mesh_contains(mesh_, p);  // on the surface
    if (z > p.z()) crossings += area > 0 ? 1 : -1;
  }
  if (crossings != 0 && crossings != 1) return mesh_contains(mesh_, p);  // not a closed outward surface here
  return crossings == 1;
}

}  // namespace dda
