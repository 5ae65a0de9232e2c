// Uniform-grid broad phase, in 2D and 3D.
//
// The grid is a compressed cell -> blocks table (blocks in increasing order
// in every cell). Each block i then looks at the cells it covers, in
// parallel, and reports the blocks j > i whose boxes overlap its own; a pair
// is reported only from the cell that holds the lowest corner of the two
// boxes' intersection, so no pair is found twice. Threads take contiguous
// ranges of i in order and the lists are joined in that order: the result
// is sorted and the same for any number of threads.
#include "dda/df/core/broad_phase.hpp"
#include "dda/df/core/block_system.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "dda/common/geometry3d.hpp"

namespace dda::df {

namespace {

template <int D>
using Cell = std::array<int, D>;

// The cells a box covers: lo[d]..hi[d] along each axis.
template <int D>
struct CellRange {
  Cell<D> lo, hi;
};

// Calls visit(index, cell) for every cell of r, x fastest
// (index = x + nx (y + ny z)).
template <int D, class Visit>
void for_each_cell(const CellRange<D>& r, const Cell<D>& count, Visit&& visit) {
  Cell<D> at = r.lo;
  while (true) {
    std::size_t index = 0;
    for (int d = D - 1; d >= 0; --d) index = index * static_cast<std::size_t>(count[d]) + at[d];
    visit(index, at);
    int d = 0;
    while (d < D && at[d] == r.hi[d]) {
      at[d] = r.lo[d];
      ++d;
    }
    if (d == D) return;
    ++at[d];
  }
}

}  // namespace

template <class Box>
std::vector<std::pair<int, int>> grid_broad_phase(const std::vector<Box>& boxes, double margin) {
  constexpr int D = decltype(Box::lo)::RowsAtCompileTime;
  std::vector<std::pair<int, int>> pairs;
  const int n = static_cast<int>(boxes.size());
  if (n < 2) return pairs;

  std::vector<Box> grown(boxes);
  Box world = grown[0];
  double mean_size = 0;
  for (Box& b : grown) {
    b.lo.array() -= margin;
    b.hi.array() += margin;
    world.lo = world.lo.cwiseMin(b.lo);
    world.hi = world.hi.cwiseMax(b.hi);
    mean_size += (b.hi - b.lo).maxCoeff();
  }
  mean_size /= n;

  // Cell about the mean box size, but never more than ~4 cells per block in
  // total, so one huge block cannot make the grid quadratic.
  const decltype(Box::lo) extent = world.hi - world.lo;
  auto cells_for = [&](double size) {
    double cells = 1;
    for (int d = 0; d < D; ++d) cells *= extent[d] / size + 1;
    return cells;
  };
  double cell = std::max(mean_size, 1e-12);
  while (cells_for(cell) > 4.0 * n) cell *= 1.5;
  Cell<D> count;
  for (int d = 0; d < D; ++d) count[d] = static_cast<int>(extent[d] / cell) + 1;
  auto cell_of = [&](double v, int d) {
    return std::clamp(static_cast<int>((v - world.lo[d]) / cell), 0, count[d] - 1);
  };
  std::vector<CellRange<D>> range(n);
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < D; ++d) {
      range[i].lo[d] = cell_of(grown[i].lo[d], d);
      range[i].hi[d] = cell_of(grown[i].hi[d], d);
    }

  // Compressed cell table.
  std::size_t ncells = 1;
  for (int d = 0; d < D; ++d) ncells *= static_cast<std::size_t>(count[d]);
  std::vector<int> start(ncells + 1, 0);
  for (int i = 0; i < n; ++i) for_each_cell<D>(range[i], count, [&](std::size_t c, const Cell<D>&) { ++start[c + 1]; });
  for (std::size_t c = 0; c < ncells; ++c) start[c + 1] += start[c];
  std::vector<int> members(static_cast<std::size_t>(start[ncells]));
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int i = 0; i < n; ++i)
      for_each_cell<D>(range[i], count, [&](std::size_t c, const Cell<D>&) { members[fill[c]++] = i; });
  }

  auto overlap = [](const Box& a, const Box& b) {
    for (int d = 0; d < D; ++d)
      if (a.lo[d] > b.hi[d] || b.lo[d] > a.hi[d]) return false;
    return true;
  };

  std::vector<std::vector<std::pair<int, int>>> found;
#pragma omp parallel if (n > parallel_grain())
  {
#pragma omp single
    found.resize(static_cast<std::size_t>(omp_get_num_threads()));
    std::vector<std::pair<int, int>>& mine = found[static_cast<std::size_t>(omp_get_thread_num())];
    std::vector<int> js;
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      js.clear();
      for_each_cell<D>(range[i], count, [&](std::size_t c, const Cell<D>& at) {
        // Members are increasing: start after i.
        const auto end = members.begin() + start[c + 1];
        for (auto it = std::upper_bound(members.begin() + start[c], end, i); it != end; ++it) {
          const int j = *it;
          if (!overlap(grown[i], grown[j])) continue;
          // Report from the cell of the intersection's lowest corner only.
          bool lowest = true;
          for (int d = 0; d < D; ++d) lowest = lowest && std::max(range[i].lo[d], range[j].lo[d]) == at[d];
          if (lowest) js.push_back(j);
        }
      });
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

template std::vector<std::pair<int, int>> grid_broad_phase(const std::vector<Box2>&, double);
template std::vector<std::pair<int, int>> grid_broad_phase(const std::vector<Box3>&, double);

std::vector<std::pair<int, int>> broad_phase(const std::vector<Box2>& boxes, double margin) {
  return grid_broad_phase(boxes, margin);
}

}  // namespace dda::df
