#pragma once
// The global step system K d = F of the 3D solver, assembled from 12x12
// blocks (internal to df/src: simulation3d.cpp assembles the block terms,
// simulation3d_contacts.cpp the contact terms through this interface).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "dda/df/block3d.hpp"

namespace dda::df3 {

struct Contact3;
struct Model3;

// K and F over the unknowns of free blocks only (dof < 0: a fixed block,
// whose terms are dropped: its increment is zero).
struct Assembly3 {
  const std::vector<int>& dof;
  std::vector<Eigen::Triplet<double>> k;
  Eigen::VectorXd f;

  void add_k(int bi, int bj, const Matrix12d& m) {
    if (dof[bi] < 0 || dof[bj] < 0) return;
    for (int r = 0; r < kDofs; ++r)
      for (int c = 0; c < kDofs; ++c)
        if (m(r, c) != 0) k.emplace_back(dof[bi] + r, dof[bj] + c, m(r, c));
  }
  void add_f(int b, const Vector12d& v) {
    if (dof[b] >= 0) f.segment<kDofs>(dof[b]) += v;
  }
  // Penalty energy p/2 |s0 + A di + B dj|^2 (A, B with one row per spring).
  template <int R>
  void add_spring(int i, int j, double p, const Eigen::Matrix<double, R, 1>& s0,
                  const Eigen::Matrix<double, R, kDofs>& a, const Eigen::Matrix<double, R, kDofs>& b) {
    add_k(i, i, p * a.transpose() * a);
    add_k(j, j, p * b.transpose() * b);
    add_k(i, j, p * a.transpose() * b);
    add_k(j, i, p * b.transpose() * a);
    add_f(i, -p * a.transpose() * s0);
    add_f(j, -p * b.transpose() * s0);
  }
};

// The springs and friction forces of one contact in its current state
// (nothing while open).
void add_contact_terms(const Contact3& c, const Model3& m, Assembly3& sys);

}  // namespace dda::df3
