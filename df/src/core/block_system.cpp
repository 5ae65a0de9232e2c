// 6x6 block storage of K: declared pattern, parallel rounds, compressed-column form.
#include "dda/df/core/block_system.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstddef>
#include <exception>

#include <omp.h>

namespace dda::df {
namespace {

std::uint64_t next_pattern_id() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

int grain = 1000;

// Every block to zero, in parallel: the off-diagonal blocks of a 10k-block
// model are megabytes, cleared on every full assembly.
void set_zero(std::vector<Matrix6d>& blocks) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(blocks.size());
#pragma omp parallel for schedule(static) if (n > grain)
  for (std::ptrdiff_t k = 0; k < n; ++k) blocks[k].setZero();
}

}  // namespace

int parallel_grain() { return grain; }
void set_parallel_grain(int blocks) { grain = std::max(1, blocks); }

std::pair<int, int> thread_share(int n) {
  const long threads = omp_get_num_threads(), t = omp_get_thread_num();
  return {static_cast<int>(n * t / threads), static_cast<int>(n * (t + 1) / threads)};
}

BlockSystem::BlockSystem(int blocks) { reset(blocks); }

void BlockSystem::reset(int blocks) {
  if (blocks != this->blocks()) sticky_.clear();
  diag_.assign(blocks, Matrix6d::Zero());
  rhs_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(kDofs) * blocks);
  changed_.assign(blocks, 1);
  all_changed_ = true;
  extra_.clear();
  items_.clear();
  round_start_.assign(1, 0);
  round_item_.clear();
  tail_.clear();
  part_start_.assign(kParts + 1, 0);
  part_item_.clear();
  build_pattern(sticky_);
}

void BlockSystem::reset(int blocks, const std::vector<std::pair<int, int>>& items) {
  const bool same_size = blocks == this->blocks();
  if (!same_size) sticky_.clear();
  changed_.assign(blocks, 1);
  all_changed_ = true;
  if (same_size) {
    set_zero(diag_);
    rhs_.setZero();
  } else {
    diag_.assign(blocks, Matrix6d::Zero());
    rhs_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(kDofs) * blocks);
  }
  // Couplings that went outside the pattern last time become part of it.
  merge_extra();
  if (same_size && items == items_) {
    set_zero(off_);
    return;
  }
  items_ = items;
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(items.size() + sticky_.size());
  for (const auto& [a, b] : items)
    if (a >= 0 && b >= 0 && a != b) pairs.emplace_back(std::max(a, b), std::min(a, b));
  pairs.insert(pairs.end(), sticky_.begin(), sticky_.end());
  build_pattern(pairs);
  build_rounds();
}

void BlockSystem::build_pattern(const std::vector<std::pair<int, int>>& pairs) {
  // The rows of each column, increasing and without repeats: bucketed by
  // column, then each (short) column sorted on its own. Linear but for those
  // sorts; one sort of all the pairs cost a millisecond of serial time per
  // step on a model of 10k blocks, whose contact pairs change every step.
  const int nb = blocks();
  std::vector<int> start(static_cast<std::size_t>(nb) + 1, 0);
  for (const auto& p : pairs) ++start[p.second + 1];
  for (int j = 0; j < nb; ++j) start[j + 1] += start[j];
  std::vector<int> rows(pairs.size());
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (const auto& p : pairs) rows[fill[p.second]++] = p.first;
  }
  int kept = 0;
  for (int j = 0, lo = 0; j < nb; ++j) {
    const int hi = start[j + 1];
    std::sort(rows.begin() + lo, rows.begin() + hi);
    const auto end = std::unique(rows.begin() + lo, rows.begin() + hi);
    start[j] = kept;
    kept = static_cast<int>(std::copy(rows.begin() + lo, end, rows.begin() + kept) - rows.begin());
    lo = hi;
  }
  start[nb] = kept;
  rows.resize(static_cast<std::size_t>(kept));
  if (start != col_start_ || rows != col_row_ || pattern_id_ == 0) {
    col_start_ = std::move(start);
    col_row_ = std::move(rows);
    pattern_id_ = next_pattern_id();
    // Transposed index, rows in increasing column order.
    row_start_.assign(static_cast<std::size_t>(nb) + 1, 0);
    for (const int i : col_row_) ++row_start_[i + 1];
    for (int i = 0; i < nb; ++i) row_start_[i + 1] += row_start_[i];
    row_col_.resize(col_row_.size());
    row_slot_.resize(col_row_.size());
    std::vector<int> fill(row_start_.begin(), row_start_.end() - 1);
    for (int j = 0; j < nb; ++j)
      for (int s = col_start_[j]; s < col_start_[j + 1]; ++s) {
        const int at = fill[col_row_[s]]++;
        row_col_[at] = j;
        row_slot_[at] = s;
      }
  }
  off_.resize(col_row_.size());
  set_zero(off_);
}

void BlockSystem::build_rounds() {
  const int n = static_cast<int>(items_.size());
  const int nb = blocks();
  // 1. Items inside one range of blocks.
  const int span = std::max(1, (nb + kParts - 1) / kParts);
  auto part = [&](int k) {
    const auto [a, b] = items_[k];
    const bool va = a >= 0 && a < nb, vb = b >= 0 && b < nb;
    if (!va || !vb) return va ? a / span : vb ? b / span : -1;
    return a / span == b / span ? a / span : -1;
  };
  part_start_.assign(kParts + 1, 0);
  for (int k = 0; k < n; ++k)
    if (const int p = part(k); p >= 0) ++part_start_[p + 1];
  for (int p = 0; p < kParts; ++p) part_start_[p + 1] += part_start_[p];
  part_item_.resize(static_cast<std::size_t>(part_start_[kParts]));
  {
    std::vector<int> fill(part_start_.begin(), part_start_.end() - 1);
    for (int k = 0; k < n; ++k)
      if (const int p = part(k); p >= 0) part_item_[fill[p]++] = k;
  }
  // 2. Greedy colouring of the others in item order: an item takes the
  // lowest colour free at both of its blocks; 3. items that find none of the
  // 64 run in the tail.
  std::vector<std::uint64_t> used(diag_.size(), 0);
  std::vector<int> colour(n, -1);
  std::vector<int> count(65, 0);
  tail_.clear();
  for (int k = 0; k < n; ++k) {
    const auto [a, b] = items_[k];
    const bool va = a >= 0 && a < blocks(), vb = b >= 0 && b < blocks();
    if (!va && !vb) {
      tail_.push_back(k);
      continue;
    }
    if (part(k) >= 0) continue;
    const std::uint64_t taken = (va ? used[a] : 0) | (vb ? used[b] : 0);
    if (taken == ~std::uint64_t{0}) {
      tail_.push_back(k);
      continue;
    }
    const int c = std::countr_one(taken);
    colour[k] = c;
    if (va) used[a] |= std::uint64_t{1} << c;
    if (vb) used[b] |= std::uint64_t{1} << c;
    ++count[c + 1];
  }
  int colours = 0;
  for (int c = 0; c < 64; ++c)
    if (count[c + 1] > 0) colours = c + 1;
  round_start_.assign(static_cast<std::size_t>(colours) + 1, 0);
  for (int c = 0; c < colours; ++c) round_start_[c + 1] = round_start_[c] + count[c + 1];
  round_item_.resize(static_cast<std::size_t>(round_start_.back()));
  std::vector<int> fill(round_start_.begin(), round_start_.end() - 1);
  for (int k = 0; k < n; ++k)
    if (colour[k] >= 0) round_item_[fill[colour[k]]++] = k;
}

void BlockSystem::scatter(const std::function<void(int)>& f, const std::vector<std::uint8_t>* only) {
  const int rounds_n = rounds();
  std::exception_ptr error;
  // Items left out are skipped before the call: the rounds stay those of all
  // the items, so each block still sees its items in the same order.
  auto call = [&](int k) {
    if (!only || (*only)[k]) f(k);
  };
  // Small loops are not worth waking the other threads for (with `only`,
  // counting the items flagged: a dozen rounds of a few straddling items
  // each cost more in barriers than they do in work); the serial loops go
  // through the items in the same order per block, so the result is the
  // same.
  const int small = 2 * grain;
  auto count = [&](const std::vector<int>& items) {
    if (!only) return static_cast<int>(items.size());
    int n = 0;
    for (const int k : items) n += (*only)[k] != 0;
    return n;
  };
  if (part_start_.empty() || count(part_item_) < small) {
    for (const int k : part_item_) call(k);
  } else {
#pragma omp parallel for schedule(dynamic, 1)
    for (int p = 0; p < kParts; ++p) {
      try {
        for (int q = part_start_[p]; q < part_start_[p + 1]; ++q) call(part_item_[q]);
      } catch (...) {
#pragma omp critical(dda_df_scatter_error)
        if (!error) error = std::current_exception();
      }
    }
  }
  if (error) std::rethrow_exception(error);
  if (count(round_item_) < small) {
    for (const int k : round_item_) call(k);
  } else {
    // Every round shared out, small ones too: the threads are awake and the
    // barrier after a round is paid either way (a round run by one thread
    // left the others waiting; on a 10k-block model the straddling items
    // are 8 % of all, in a dozen rounds of fewer than a thousand).
#pragma omp parallel
    for (int r = 0; r < rounds_n; ++r) {
#pragma omp for schedule(static)
      for (int q = round_start_[r]; q < round_start_[r + 1]; ++q) {
        try {
          call(round_item_[q]);
        } catch (...) {
#pragma omp critical(dda_df_scatter_error)
          if (!error) error = std::current_exception();
        }
      }
    }
  }
  if (error) std::rethrow_exception(error);
  for (const int k : tail_) call(k);
}

int BlockSystem::slot(int i, int j) const {
  const auto first = col_row_.begin() + col_start_[j], last = col_row_.begin() + col_start_[j + 1];
  const auto it = std::lower_bound(first, last, i);
  return (it != last && *it == i) ? static_cast<int>(it - col_row_.begin()) : -1;
}

void BlockSystem::clear_changes() const {
  std::fill(changed_.begin(), changed_.end(), 0);
  all_changed_ = false;
  change_record_ = next_pattern_id();  // one counter serves both: unique, never 0
}

void BlockSystem::add_coupling(int i, int j, const Matrix6d& kij) {
  changed_[i] = 1;
  changed_[j] = 1;
  if (i > j) {
    const int s = slot(i, j);
    if (s >= 0) {
      off_[s] += kij;
    } else {
      auto [it, fresh] = extra_.try_emplace(key(i, j), kij);
      if (!fresh) it->second += kij;
    }
  } else {
    const int s = slot(j, i);
    if (s >= 0) {
      off_[s] += kij.transpose();
    } else {
      auto [it, fresh] = extra_.try_emplace(key(j, i), kij.transpose());
      if (!fresh) it->second += kij.transpose();
    }
  }
}

void BlockSystem::merge_extra() const {
  if (extra_.empty()) return;
  // Rebuild the pattern with the extra pairs; keep the values already there.
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(col_row_.size() + extra_.size());
  std::vector<Matrix6d> values;
  values.reserve(col_row_.size() + extra_.size());
  const int nb = blocks();
  for (int j = 0; j < nb; ++j)
    for (int s = col_start_[j]; s < col_start_[j + 1]; ++s) pairs.emplace_back(col_row_[s], j);
  std::vector<Matrix6d> old = std::move(off_);
  for (const auto& [k, m] : extra_) {
    const std::pair<int, int> p(static_cast<int>(k >> 32), static_cast<int>(k & 0xffffffffu));
    pairs.push_back(p);
    sticky_.push_back(p);
  }
  std::sort(sticky_.begin(), sticky_.end());
  sticky_.erase(std::unique(sticky_.begin(), sticky_.end()), sticky_.end());
  auto* self = const_cast<BlockSystem*>(this);
  const std::vector<int> old_start = col_start_, old_row = col_row_;
  self->build_pattern(pairs);
  for (int j = 0; j < nb; ++j)
    for (int s = old_start[j]; s < old_start[j + 1]; ++s) off_[slot(old_row[s], j)] = old[s];
  for (const auto& [k, m] : extra_) off_[slot(static_cast<int>(k >> 32), static_cast<int>(k & 0xffffffffu))] += m;
  extra_.clear();
}

std::uint64_t BlockSystem::pattern_id() const {
  merge_extra();
  return pattern_id_;
}

const Eigen::SparseMatrix<double>& BlockSystem::csc() const {
  merge_extra();
  const int nb = blocks();
  const int n = kDofs * nb;
  if (csc_pattern_ != pattern_id_ || csc_.rows() != n) {
    // Block column j: per column c the lower part of the diagonal block
    // (rows c..5), then each coupled block (i, j), i > j, in increasing i;
    // the row indices of every column come out sorted.
    csc_pattern_ = pattern_id_;
    csc_.resize(n, n);
    const std::size_t nnz = static_cast<std::size_t>(nb) * 21 + col_row_.size() * 36;
    csc_.resizeNonZeros(static_cast<Eigen::Index>(nnz));
    csc_col_pos_.assign(static_cast<std::size_t>(nb) + 1, 0);
    int* outer = csc_.outerIndexPtr();
    int* inner = csc_.innerIndexPtr();
    int pos = 0;
    for (int j = 0; j < nb; ++j) {
      csc_col_pos_[j] = pos;
      for (int c = 0; c < kDofs; ++c) {
        outer[kDofs * j + c] = pos;
        for (int r = c; r < kDofs; ++r) inner[pos++] = kDofs * j + r;
        for (int s = col_start_[j]; s < col_start_[j + 1]; ++s)
          for (int r = 0; r < kDofs; ++r) inner[pos++] = kDofs * col_row_[s] + r;
      }
    }
    outer[n] = pos;
    csc_col_pos_[nb] = pos;
  }
  double* val = csc_.valuePtr();
#pragma omp parallel for schedule(static) if (nb > grain)
  for (int j = 0; j < nb; ++j) {
    int pos = csc_col_pos_[j];
    for (int c = 0; c < kDofs; ++c) {
      for (int r = c; r < kDofs; ++r) val[pos++] = diag_[j](r, c);
      for (int s = col_start_[j]; s < col_start_[j + 1]; ++s) {
        const double* col = off_[s].data() + kDofs * c;  // column-major
        for (int r = 0; r < kDofs; ++r) val[pos++] = col[r];
      }
    }
  }
  return csc_;
}

Eigen::SparseMatrix<double> BlockSystem::lower() const { return csc(); }

Eigen::SparseMatrix<double> BlockSystem::full() const {
  const Eigen::SparseMatrix<double>& l = csc();
  Eigen::SparseMatrix<double> f = l.selfadjointView<Eigen::Lower>();
  return f;
}

void BlockSystem::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y, const Matrix6d* symmetric_diagonal) const {
  merge_extra();
  const int nb = blocks();
  y.resize(static_cast<Eigen::Index>(kDofs) * nb);
#pragma omp parallel if (nb > grain)
  {
    const auto [first, last] = thread_share(nb);
    multiply_sweep(x, y, symmetric_diagonal, first, last, std::max(1, last - first), [](int, int) {});
  }
}

void BlockSystem::multiply_sweep(const Eigen::VectorXd& x, Eigen::VectorXd& y, const Matrix6d* symmetric_diagonal,
                                 int first, int last, int chunk, const std::function<void(int, int)>& done) const {
  // Row i of K x is D_i x_i, then K_ic x_c for every coupled column c < i
  // in increasing c, then the sum of K_ri^T x_r over the couplings stored
  // in column i (rows r > i). A sweep over the columns in increasing order
  // forms it so: column c adds K_ic x_c to row i (i > c) as it passes, and
  // row i is final once column i is done. The couplings of this range's
  // rows with columns before `first` belong to the sweep of another range;
  // they are added first, in increasing c, so the order of every row's sum
  // is that of one sweep over all columns, however the rows are shared out.
  auto x_of = [&](int i) { return x.segment<kDofs>(kDofs * i); };
  for (int i = first; i < last; ++i) {
    if (symmetric_diagonal) {
      y.segment<kDofs>(kDofs * i).noalias() = symmetric_diagonal[i] * x_of(i);
    } else {
      const Matrix6d d = diag_[i].selfadjointView<Eigen::Lower>();
      y.segment<kDofs>(kDofs * i).noalias() = d * x_of(i);
    }
    for (int q = row_start_[i]; q < row_start_[i + 1] && row_col_[q] < first; ++q)
      y.segment<kDofs>(kDofs * i).noalias() += off_[row_slot_[q]] * x_of(row_col_[q]);
  }
  int lo = first;
  for (int j = first; j < last; ++j) {
    const auto xj = x_of(j);
    Vector6d acc = Vector6d::Zero();
    for (int s = col_start_[j]; s < col_start_[j + 1]; ++s) {
      const int i = col_row_[s];
      acc.noalias() += off_[s].transpose() * x_of(i);
      if (i < last) y.segment<kDofs>(kDofs * i).noalias() += off_[s] * xj;  // rows past the range: their own sweep's
    }
    y.segment<kDofs>(kDofs * j) += acc;
    if (j + 1 - lo == chunk || j + 1 == last) {
      done(lo, j + 1);
      lo = j + 1;
    }
  }
}

Vector6d BlockSystem::multiply_row(int i, const Eigen::VectorXd& x, const Matrix6d* symmetric_diagonal) const {
  auto x_of = [&](int k) { return x.segment<kDofs>(kDofs * k); };
  Vector6d y;
  if (symmetric_diagonal) {
    y.noalias() = symmetric_diagonal[i] * x_of(i);
  } else {
    const Matrix6d d = diag_[i].selfadjointView<Eigen::Lower>();
    y.noalias() = d * x_of(i);
  }
  for (int q = row_start_[i]; q < row_start_[i + 1]; ++q) y.noalias() += off_[row_slot_[q]] * x_of(row_col_[q]);
  for (int s = col_start_[i]; s < col_start_[i + 1]; ++s) y.noalias() += off_[s].transpose() * x_of(col_row_[s]);
  return y;
}

BlockSystem BlockSystem::from_lower(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& rhs) {
  const int nb = static_cast<int>(lower.cols() / kDofs);
  std::vector<std::pair<int, int>> pairs;
  for (int col = 0; col < lower.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, col); it; ++it) {
      const int i = static_cast<int>(it.row()) / kDofs, j = col / kDofs;
      if (i > j && (pairs.empty() || pairs.back() != std::pair<int, int>(i, j))) pairs.emplace_back(i, j);
    }
  BlockSystem sys;
  sys.reset(nb, pairs);
  for (int col = 0; col < lower.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, col); it; ++it) {
      const int r = static_cast<int>(it.row());
      const int i = r / kDofs, j = col / kDofs;
      if (r < col) continue;  // upper part: ignored
      if (i == j) {
        sys.diag_[i](r % kDofs, col % kDofs) = it.value();
        sys.diag_[i](col % kDofs, r % kDofs) = it.value();
      } else {
        sys.off_[sys.slot(i, j)](r % kDofs, col % kDofs) = it.value();
      }
    }
  sys.rhs_ = rhs;
  return sys;
}

}  // namespace dda::df
