#pragma once
// The coupling part of the 3D step matrix, K - blockdiag(K), as the contact
// springs that make it (df::SpringCoupling), for block-Jacobi PCG.
//
// A closed contact's normal spring adds k en gn^T to K(i, j) (and its
// transpose to K(j, i)); a locked contact's shear springs add ps es^T gs
// (Assembly3::add_spring_k). The product y += (K - D) x is formed from those
// rows: 24 values for a sliding contact and 72 for a locked one, against a
// 12 x 12 block (144 values) for each pair of blocks read from K, and the
// product, most of the step on large models, is bound by memory traffic.
// The rows are copied out of the contacts (960 bytes each, of which the
// product needs a fifth) once per attempt: a contact's linearised geometry
// is fixed for the step; only the states change from one iterate to the next.
//
// Internal to df/src.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "dda/df/core/linear_solver.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df3 {

class ContactCoupling3 final : public df::SpringCoupling {
 public:
  // The spring rows of the contacts between two free blocks (`dof`: first
  // unknown of each block, -1 if fixed; a fixed block's side of a spring is
  // in the diagonal and the loads only), their stiffnesses over the step
  // (`springs`: per joint index, ContactSprings3), and their states.
  void set_springs(const std::vector<Contact3>& contacts, const std::vector<int>& dof,
                   const std::vector<ContactSprings3>& springs);
  // The contacts' states, for the same contacts as set_springs.
  void set_states(const std::vector<Contact3>& contacts);

  // The springs are cut into kParts fixed ranges (sum_in_fixed_parts), so
  // the result does not depend on the number of threads.
  void add_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const override;

 private:
  static constexpr int kParts = 8;  // fixed: it sets the summation order
  static constexpr int kNormal = 2 * kDofs;  // en, gn
  static constexpr int kShear = 4 * kDofs;   // es, gs (2 x 12 each, column-major)
  std::vector<int> contact_;                 // the contact of each spring set
  std::vector<int> first_i_, first_j_;       // first unknowns of its blocks
  std::vector<std::uint8_t> state_;          // ContactState3 of the contact
  std::vector<double> normal_, shear_;       // kNormal and kShear values per set
  std::vector<double> kn_, ps_;              // the normal spring's k over the step and ps, per set
  mutable Eigen::MatrixXd partial_;          // y of each part
};

}  // namespace dda::df3
