#pragma once
// The global system K d = F stored as 6x6 blocks.
//
// Only the lower block triangle is kept (K is symmetric), and of each
// diagonal block only its lower triangle is read (writers may skip the
// upper one). Every stored block is written out whole, zeros included, so
// the sparsity pattern depends only on which block pairs are coupled: the
// solver can reuse its symbolic analysis while the contact pairs stay the
// same.
//
// Pattern. reset(blocks, items) declares the couplings of a step up front:
// item k (a contact) couples blocks items[k].first and items[k].second. The
// pattern is the set of those pairs, whatever the items' states, so it stays
// the same through the open-close iteration and from step to step while the
// contact pairs hold. The off-diagonal blocks live in a flat block-CSC array
// (block column j: rows i > j, increasing); add_coupling finds its slot by a
// binary search and allocates nothing. A coupling outside the declared
// pattern (reset(blocks) declares none) still works: it goes to a side map,
// is merged into the pattern when the matrix is next formed, and stays in
// the pattern of later resets ("sticky"), so the pattern settles.
//
// Parallel assembly. scatter(f) calls f(k) for every item, in a fixed
// order per block, so the assembled system is bit-identical with 1 or N
// threads, without locks:
//  1. The blocks are cut into kParts ranges of consecutive indices; an item
//     whose two blocks lie in one range belongs to that range. The ranges
//     run in parallel, each one's items in item order (they write disjoint
//     6x6 blocks and rhs segments). With blocks numbered by position (rows
//     of a wall, cells of a grid) nearly all items are in a range.
//  2. The items that straddle two ranges run in rounds: a round never holds
//     two items that touch the same block, so a round runs in parallel; the
//     rounds come from a greedy colouring that depends only on the items.
//  3. Items of blocks with more than 64 straddling items (a base block under
//     a whole wall) that find no free colour run last, serially, in order.
// Each step ends with a barrier: few barriers, which matters on a loaded
// machine where one can cost a scheduler time slice.
#include <Eigen/SparseCore>
#include <cstdint>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "dda/df/core/types.hpp"

namespace dda::df {

// Loops of DF over fewer blocks than this (contact loops: proportionally
// more contacts) run on one thread: waking the other threads would cost
// more than it saves. Results never depend on it, nor on the thread count.
// Default 1000; tests lower it to run the parallel paths on small models.
int parallel_grain();
void set_parallel_grain(int blocks);
// Inside a parallel region: the calling thread's share [first, last) of n
// items cut into one contiguous run per thread of the team, in thread order
// (disjoint, together all n; what BlockSystem::multiply_sweep asks of its
// callers).
std::pair<int, int> thread_share(int n);

class BlockSystem {
 public:
  explicit BlockSystem(int blocks = 0);
  // Zero everything, keep the size; no declared couplings.
  void reset(int blocks);
  // Zero everything and declare the couplings of `items` (pairs of blocks;
  // pairs with a negative index or i == j couple nothing). The pattern and
  // the rounds are kept when the items are those of the last reset.
  void reset(int blocks, const std::vector<std::pair<int, int>>& items);

  int blocks() const { return static_cast<int>(diag_.size()); }
  // The writers (the non-const diagonal(i) and rhs(i), add_coupling) mark
  // the rows they give access to as changed (see changed_rows()).
  Matrix6d& diagonal(int i) {
    changed_[i] = 1;
    return diag_[i];
  }
  const Matrix6d& diagonal(int i) const { return diag_[i]; }
  // Adds K_ij (and implicitly K_ji = K_ij^T), i != j. Thread-safe for
  // declared pairs written by one thread at a time (see scatter).
  void add_coupling(int i, int j, const Matrix6d& kij);
  auto rhs(int i) {
    changed_[i] = 1;
    return rhs_.segment<kDofs>(kDofs * i);
  }
  const Eigen::VectorXd& rhs() const { return rhs_; }

  // The block rows of K and F that may have changed since clear_changes():
  // those written through diagonal(i), rhs(i) and add_coupling(i, j) (a
  // flag per block), or nullptr when every row may have (after a reset).
  // Between two open-close iterates only the rows of the contacts revisited
  // are written (a few per cent of them once the states settle), and a
  // solver can keep what it computed from the others in the last solve
  // (block_pcg.hpp). Marking is a byte store per access, race-free under
  // scatter's rule that no two threads write one block at a time.
  const std::vector<std::uint8_t>* changed_rows() const { return all_changed_ ? nullptr : &changed_; }
  // Starts a new record of changes (the solver, after a solve) and gives it
  // a number unique over all BlockSystems, change_record(): a system with
  // that number is the one of the clear plus the rows flagged since (a copy
  // carries both), which is how a solver knows that the rows not flagged
  // are those it solved. Bookkeeping only: K and F are not touched, hence
  // const.
  void clear_changes() const;
  std::uint64_t change_record() const { return all_changed_ ? 0 : change_record_; }

  // Calls f(k) for every item of the last reset(blocks, items), in parallel
  // rounds (see above). f may write the diagonal blocks and rhs of the two
  // blocks of item k and their coupling, nothing else shared. With `only`
  // (one flag per item), only the items flagged non-zero: an update that
  // concerns a few items (the open-close iterates) does not call f for the
  // others, and the order per block is still fixed.
  void scatter(const std::function<void(int)>& f, const std::vector<std::uint8_t>* only = nullptr);
  int rounds() const { return static_cast<int>(round_start_.size()) - 1; }

  // Lower triangle in compressed column form (for the solver): a new matrix.
  Eigen::SparseMatrix<double> lower() const;
  // The same, kept between calls: the index arrays are rebuilt only when the
  // pattern changes, the values are refreshed on every call. Not thread-safe.
  const Eigen::SparseMatrix<double>& csc() const;
  // Changes whenever the pattern changes (unique over all BlockSystems).
  std::uint64_t pattern_id() const;
  // Full symmetric matrix (tests, energy checks).
  Eigen::SparseMatrix<double> full() const;

  // y = K x, with K read from the lower triangle (the diagonal blocks too;
  // `symmetric_diagonal`, if given, holds them already made symmetric, one
  // per block, which is faster). Parallel (multiply_sweep on each thread's
  // share of the rows); the result does not depend on the thread count.
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y, const Matrix6d* symmetric_diagonal = nullptr) const;
  // Block rows [first, last) of the same product, on the calling thread
  // alone (y sized already), by a sweep over the block columns that reads
  // each stored coupling block once for both of its blocks' rows (reading
  // it once per row made the product of a 50k-block model read 86 MB of
  // couplings instead of 43 MB). The threads' ranges must not overlap and
  // together cover the rows; each row's sum is formed in the same order
  // whatever the ranges (see the definition), so the result does not
  // depend on how the rows are shared out. `done(lo, hi)` is called on
  // every `chunk` rows [lo, hi) of the range (counted from `first`) as soon
  // as they are final, for a caller that works on them while they are in
  // cache (block_pcg.hpp). Reads the pattern as multiply() leaves it: call
  // that first if couplings may have been added outside the declared
  // pattern.
  void multiply_sweep(const Eigen::VectorXd& x, Eigen::VectorXd& y, const Matrix6d* symmetric_diagonal, int first,
                      int last, int chunk, const std::function<void(int, int)>& done) const;
  // Row i of K x alone: D_i x_i, then K_ic x_c for the coupled columns
  // c < i, then K_ri^T x_r for the coupled rows r > i (for a residual
  // refreshed on a few rows; the sums are in another order than the
  // sweep's, so the row agrees with multiply() to rounding). Reads the
  // pattern as multiply() leaves it.
  Vector6d multiply_row(int i, const Eigen::VectorXd& x, const Matrix6d* symmetric_diagonal = nullptr) const;
  // Builds a block system from the lower triangle of a matrix of 6x6 blocks.
  static BlockSystem from_lower(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& rhs);

 private:
  static std::uint64_t key(int i, int j) {
    return (static_cast<std::uint64_t>(i) << 32) | static_cast<std::uint32_t>(j);
  }
  void build_pattern(const std::vector<std::pair<int, int>>& pairs);  // (i, j), i > j; any order, repeats allowed
  void build_rounds();
  void merge_extra() const;
  int slot(int i, int j) const;  // i > j; -1 if not in the pattern

  std::vector<Matrix6d> diag_;
  Eigen::VectorXd rhs_;
  // Block-CSC pattern of the strictly lower block triangle.
  mutable std::vector<int> col_start_{0}, col_row_;
  mutable std::vector<Matrix6d> off_;
  // Transposed index: block row i holds slots (i, c), c < i.
  mutable std::vector<int> row_start_{0}, row_col_, row_slot_;
  mutable std::map<std::uint64_t, Matrix6d> extra_;  // couplings outside the pattern
  mutable std::vector<std::pair<int, int>> sticky_;  // pairs merged from extra_, kept in later patterns
  mutable std::uint64_t pattern_id_ = 0;
  // Rows written since clear_changes(); all of them after a reset.
  mutable std::vector<std::uint8_t> changed_;
  mutable bool all_changed_ = true;
  mutable std::uint64_t change_record_ = 0;
  // Items and rounds of the last reset(blocks, items).
  std::vector<std::pair<int, int>> items_;
  static constexpr int kParts = 8;  // fixed: it sets the summation order
  std::vector<int> part_start_, part_item_;
  std::vector<int> round_start_{0}, round_item_, tail_;
  // csc() cache.
  mutable Eigen::SparseMatrix<double> csc_;
  mutable std::uint64_t csc_pattern_ = ~std::uint64_t{0};
  mutable std::vector<int> csc_col_pos_;  // first value of each block column's off-diagonal part
};

}  // namespace dda::df
