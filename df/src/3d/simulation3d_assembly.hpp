#pragma once
// The global step system K d = F of the 3D solver, assembled from 12x12
// blocks (internal to df/src: simulation3d.cpp assembles the block terms,
// simulation3d_contacts.cpp the contact terms through this interface).
//
// K is kept as its lower triangle in CSC form with a fixed pattern of 12x12
// blocks (block_lower_pattern), and the blocks are added straight into its
// values: no triplet list to sort and sum, and the pattern stays the same
// from one open-close iterate to the next (and across steps while the same
// pairs of blocks touch), so CHOLMOD analyses it once and only refactorises.
// Only the lower triangle is stored or read, as Eigen's SimplicialLDLT read
// it before: the upper half of K is its mirror.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <limits>
#include <utility>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/df/3d/block3d.hpp"

namespace dda::df3 {

struct Contact3;
struct Model3;

// The zero lower triangle of K over the unknowns of the free blocks (dof[b]:
// first unknown of block b, -1 if fixed): the whole lower part of every free
// block's diagonal block, and the 12x12 block of every pair of `pairs` whose
// blocks are both free (repeats and either order allowed). Column dof[b] + c
// holds rows dof[b] + c .. dof[b] + 11, then the 12 rows of each neighbour
// block after b, in increasing dof (Assembly3 relies on that layout).
Eigen::SparseMatrix<double> block_lower_pattern(const std::vector<int>& dof, int n_dofs,
                                                const std::vector<std::pair<int, int>>& pairs);

// K (lower triangle, pattern from block_lower_pattern) and F over the
// unknowns of free blocks only (dof < 0: a fixed block, whose terms are
// dropped: its increment is zero).
//
// An Assembly3 may own only the columns [first_owned, end_owned) of K and the same rows
// of F and drop the rest, so that several add the same terms in parallel,
// each into its own columns: every entry is then still summed in the order
// the terms come, whatever the number of threads.
struct Assembly3 {
  const std::vector<int>& dof;
  Eigen::SparseMatrix<double>& k;
  Eigen::VectorXd& f;
  int first_owned = 0;                               // first unknown owned
  int end_owned = std::numeric_limits<int>::max();   // one past the last

  // Block b's column of K and rows of F are this assembly's to write.
  bool owns(int b) const { return dof[b] >= first_owned && dof[b] < end_owned; }

  // K(block bi, block bj) += m. Only entries in the lower triangle are kept:
  // K is symmetric and its callers add the mirror add_k(bj, bi, m^T) too.
  // Different diagonal blocks may be added from different threads.
  void add_k(int bi, int bj, const Matrix12d& m) {
    const int row = dof[bi], col = dof[bj];
    if (row < 0 || col < first_owned || col >= end_owned || row < col) return;
    double* values = k.valuePtr();
    const int* outer = k.outerIndexPtr();
    if (row == col) {
      for (int c = 0; c < kDofs; ++c)
        for (int r = c; r < kDofs; ++r) values[outer[col + c] + r - c] += m(r, c);
      return;
    }
    const int offset = neighbour_offset(col, row);
    for (int c = 0; c < kDofs; ++c)
      Eigen::Map<Vector12d>(values + outer[col + c] + (kDofs - c) + offset) += m.col(c);
  }
  void add_f(int b, const Vector12d& v) {
    if (owns(b)) f.segment<kDofs>(dof[b]) += v;
  }
  // Penalty energy p/2 |s0 + A di + B dj|^2 (A, B with one row per spring):
  // its stiffness p [A B]^T [A B] (add_spring_k) and its load -p [A B]^T s0
  // (add_spring_f). Only the blocks that land in the owned part of the
  // stored triangle are formed.
  template <int R>
  void add_spring_k(int i, int j, double p, const Eigen::Matrix<double, R, kDofs>& a,
                    const Eigen::Matrix<double, R, kDofs>& b) {
    if (owns(i)) add_k(i, i, p * a.transpose() * a);
    if (owns(j)) add_k(j, j, p * b.transpose() * b);
    if (dof[i] >= 0 && dof[j] >= 0) {
      if (dof[i] > dof[j]) {
        if (owns(j)) add_k(i, j, p * a.transpose() * b);
      } else {
        if (owns(i)) add_k(j, i, p * b.transpose() * a);
      }
    }
  }
  template <int R>
  void add_spring_f(int i, int j, double p, const Eigen::Matrix<double, R, 1>& s0,
                    const Eigen::Matrix<double, R, kDofs>& a, const Eigen::Matrix<double, R, kDofs>& b) {
    if (owns(i)) add_f(i, -p * a.transpose() * s0);
    if (owns(j)) add_f(j, -p * b.transpose() * s0);
  }

 private:
  // Where block row `row` starts among the rows below the diagonal block in
  // the columns of block column `col` (12 x its rank among the neighbours).
  int neighbour_offset(int col, int row) const {
    const int* inner = k.innerIndexPtr();
    const int first = k.outerIndexPtr()[col] + kDofs;  // first neighbour row of column `col`
    int lo = 0, hi = (k.outerIndexPtr()[col + 1] - first) / kDofs;
    const int count = hi;
    while (lo < hi) {  // neighbour starts inner[first + 12 n] increase with n
      const int mid = (lo + hi) / 2;
      if (inner[first + kDofs * mid] < row)
        lo = mid + 1;
      else
        hi = mid;
    }
    if (lo == count || inner[first + kDofs * lo] != row)
      throw InternalError("Assembly3: a pair of blocks outside K's pattern");
    return kDofs * lo;
  }
};

// What one contact adds to the step system, in two parts, so that an
// open-close iterate can keep K and swap only the springs of the contacts
// whose state changed (Simulation3::assemble):
// * the stiffness of its springs in `state` (nothing while open; the normal
//   spring, and the shear springs while locked), times `sign` (+1 adds
//   them, -1 takes them out again);
// * its loads in its current state: the springs' initial stretch and the
//   friction of a sliding contact. `known`: the increments of fixed blocks
//   (a moving foundation), folded into the stretch; free blocks' entries
//   are not read.
// `springs`: the contact's joint's (ContactSprings3).
void add_contact_springs(const Contact3& c, ContactState3 state, double sign, const ContactSprings3& springs,
                         Assembly3& sys);
void add_contact_loads(const Contact3& c, const ContactSprings3& springs, const std::vector<Vector12d>& known,
                       Assembly3& sys);

}  // namespace dda::df3
