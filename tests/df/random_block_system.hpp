#pragma once
// A random block system with the pattern of a bedded rock mass (each block
// coupled to its neighbour in the bed and to one in the bed below), made
// diagonally dominant like a DDA step matrix: for the tests of the block
// product and of PCG.
#include <random>
#include <utility>
#include <vector>

#include "dda/df/core/block_system.hpp"

namespace dda::df::test {

struct LayeredSystemShape {
  int bed = 17;                  // blocks per bed: block i is coupled to i - 1 and to i - bed + i % 3
  int far_pairs = 0;             // pairs of random blocks coupled too (a few may be i == i: no coupling)
  double diagonal_shift = 12;    // added to each diagonal block's a a^T
  bool rhs = false;              // random right-hand side as well
};

// Entries uniform in [-1, 1), drawn from `rng` in a fixed order: the far
// pairs, then per block its diagonal block (and rhs), then the couplings in
// item order.
inline BlockSystem random_layered_system(int nb, std::mt19937& rng, const LayeredSystemShape& shape = {}) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> block(0, nb - 1);
  std::vector<std::pair<int, int>> items;
  for (int i = 1; i < nb; ++i) {
    items.emplace_back(i, i - 1);                                                // a bed's neighbours
    if (i >= shape.bed) items.emplace_back(i, i - shape.bed + (i % 3));          // the bed below
  }
  for (int k = 0; k < shape.far_pairs; ++k) items.emplace_back(block(rng), block(rng));
  BlockSystem sys;
  sys.reset(nb, items);
  auto random6 = [&] { return Matrix6d(Matrix6d::NullaryExpr([&] { return u(rng); })); };
  for (int i = 0; i < nb; ++i) {
    const Matrix6d a = random6();
    sys.diagonal(i) += a * a.transpose() + shape.diagonal_shift * Matrix6d::Identity();
    if (shape.rhs) sys.rhs(i) = Vector6d::NullaryExpr([&] { return u(rng); });
  }
  for (const auto& [a, b] : items)
    if (a != b) sys.add_coupling(a, b, random6());
  return sys;
}

}  // namespace dda::df::test
