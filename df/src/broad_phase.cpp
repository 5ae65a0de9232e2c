// Uniform-grid broad phase.
//
// The grid is a compressed cell -> blocks table (blocks in increasing order
// in every cell). Each block i then looks at the cells it covers, in
// parallel, and reports the blocks j > i whose boxes overlap its own; a pair
// is reported only from the cell that holds the lower-left corner of the
// two boxes' intersection, so no pair is found twice. Threads take
// contiguous ranges of i in order and the lists are joined in that order:
// the result is sorted and the same for any number of threads.
#include "dda/df/broad_phase.hpp"
#include "dda/df/block_system.hpp"

#include <omp.h>

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
  struct Range {
    int x0, x1, y0, y1;
  };
  std::vector<Range> range(n);
  for (int i = 0; i < n; ++i)
    range[i] = {cell_of(grown[i].lo.x(), world.lo.x(), nx), cell_of(grown[i].hi.x(), world.lo.x(), nx),
                cell_of(grown[i].lo.y(), world.lo.y(), ny), cell_of(grown[i].hi.y(), world.lo.y(), ny)};

  // Compressed cell table.
  const std::size_t ncells = static_cast<std::size_t>(nx) * ny;
  std::vector<int> start(ncells + 1, 0);
  for (int i = 0; i < n; ++i)
    for (int y = range[i].y0; y <= range[i].y1; ++y)
      for (int x = range[i].x0; x <= range[i].x1; ++x) ++start[static_cast<std::size_t>(y) * nx + x + 1];
  for (std::size_t c = 0; c < ncells; ++c) start[c + 1] += start[c];
  std::vector<int> members(static_cast<std::size_t>(start[ncells]));
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int i = 0; i < n; ++i)
      for (int y = range[i].y0; y <= range[i].y1; ++y)
        for (int x = range[i].x0; x <= range[i].x1; ++x) members[fill[static_cast<std::size_t>(y) * nx + x]++] = i;
  }

  std::vector<std::vector<std::pair<int, int>>> found;
#pragma omp parallel if (n > parallel_grain())
  {
#pragma omp single
    found.resize(static_cast<std::size_t>(omp_get_num_threads()));
    std::vector<std::pair<int, int>>& mine = found[static_cast<std::size_t>(omp_get_thread_num())];
    std::vector<int> js;
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      const Box2& bi = grown[i];
      js.clear();
      for (int y = range[i].y0; y <= range[i].y1; ++y)
        for (int x = range[i].x0; x <= range[i].x1; ++x) {
          const std::size_t c = static_cast<std::size_t>(y) * nx + x;
          // Members are increasing: start after i.
          const auto first = std::upper_bound(members.begin() + start[c], members.begin() + start[c + 1], i);
          for (auto it = first; it != members.begin() + start[c + 1]; ++it) {
            const int j = *it;
            const Box2& bj = grown[j];
            if (bi.lo.x() > bj.hi.x() || bj.lo.x() > bi.hi.x() || bi.lo.y() > bj.hi.y() || bj.lo.y() > bi.hi.y())
              continue;
            // Report from the cell of the intersection's lower-left corner only.
            const int cx = std::max(range[i].x0, range[j].x0), cy = std::max(range[i].y0, range[j].y0);
            if (cx == x && cy == y) js.push_back(j);
          }
        }
      std::sort(js.begin(), js.end());
      for (const int j : js) mine.emplace_back(i, j);
    }
  }
  std::size_t total = 0;
  for (const auto& f : found) total += f.size();
  pairs.reserve(total);
  for (const auto& f : found) pairs.insert(pairs.end(), f.begin(), f.end());
  return pairs;
}

}  // namespace dda::df
