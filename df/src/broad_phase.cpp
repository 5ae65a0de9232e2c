// Uniform-grid broad phase.
#include "dda/df/broad_phase.hpp"

#include <algorithm>
#include <cmath>

namespace dda::df {

std::vector<std::pair<int, int>> broad_phase(const std::vector<Box2>& boxes, double margin) {
  std::vector<std::pair<int, int>> pairs;
  const int n = static_cast<int>(boxes.size());
  if (n < 2) return pairs;

  std::vector<Box2> grown(boxes);
  Box2 world = grown[0];
  double mean_size = 0;
  for (Box2& b : grown) {
    b.lo.array() -= margin;
    b.hi.array() += margin;
    world.lo = world.lo.cwiseMin(b.lo);
    world.hi = world.hi.cwiseMax(b.hi);
    mean_size += std::max(b.width(), b.height());
  }
  mean_size /= n;

  // Cell about the mean box size, but never more than ~4 cells per block in
  // total, so one huge block cannot make the grid quadratic.
  double cell = std::max(mean_size, 1e-12);
  const double cells_wanted = 4.0 * n;
  while ((world.width() / cell + 1) * (world.height() / cell + 1) > cells_wanted) cell *= 1.5;
  const int nx = static_cast<int>(world.width() / cell) + 1;
  const int ny = static_cast<int>(world.height() / cell) + 1;
  auto cell_of = [&](double v, double lo, int count) {
    return std::clamp(static_cast<int>((v - lo) / cell), 0, count - 1);
  };

  std::vector<std::vector<int>> cells(static_cast<std::size_t>(nx) * ny);
  for (int i = 0; i < n; ++i) {
    const int x0 = cell_of(grown[i].lo.x(), world.lo.x(), nx), x1 = cell_of(grown[i].hi.x(), world.lo.x(), nx);
    const int y0 = cell_of(grown[i].lo.y(), world.lo.y(), ny), y1 = cell_of(grown[i].hi.y(), world.lo.y(), ny);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) cells[static_cast<std::size_t>(y) * nx + x].push_back(i);
  }

  auto overlap = [&](int a, int b) {
    return grown[a].lo.x() <= grown[b].hi.x() && grown[b].lo.x() <= grown[a].hi.x() &&
           grown[a].lo.y() <= grown[b].hi.y() && grown[b].lo.y() <= grown[a].hi.y();
  };
  for (const std::vector<int>& c : cells)
    for (std::size_t a = 0; a < c.size(); ++a)
      for (std::size_t b = a + 1; b < c.size(); ++b)
        if (overlap(c[a], c[b])) pairs.emplace_back(std::min(c[a], c[b]), std::max(c[a], c[b]));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace dda::df
