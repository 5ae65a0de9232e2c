// The 3D solver's PCG product through the contact springs
// (df/src/3d/contact_coupling3d.hpp) against the K the assembly builds from the
// same contacts (Assembly3, add_contact_springs): the coupling blocks of K
// times x, in every contact state, with fixed blocks, on one and two threads,
// with two joints of their own springs: a set with its own penalties and a
// default joint of the Oden-Martins law, whose tangent k differs from one
// contact to the next (it depends on the penetration at the step's start).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <random>
#include <utility>
#include <vector>

#include "3d/contact_coupling3d.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "forced_threads.hpp"
#include "3d/simulation3d_assembly.hpp"

namespace dda::df3 {
namespace {

struct Springs {
  std::vector<int> dof;
  int n_dofs = 0;
  std::vector<Contact3> contacts;
  Model3 model;
  std::vector<ContactSprings3> springs;  // per joint index
};

// Seven blocks, two of them fixed, and 60 contacts between random pairs with
// random spring rows, a third each open, sliding and locked.
Springs random_springs() {
  Springs s;
  s.dof = {0, -1, 12, 24, -1, 36, 48};
  s.n_dofs = 60;
  s.model.normal_penalty = 3.5;
  s.model.shear_penalty = 1.25;
  df::JointProperties own;
  own.normal_penalty = 7.0;
  own.shear_penalty = 0.5;
  s.model.joint_sets = {own};
  s.model.default_joint.normal_law = "oden_martins";
  s.model.default_joint.normal_parameters = {{"c_n", 2e3}, {"m_n", 2.5}};
  s.springs = contact_springs3(s.model);
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> block(0, 6), state(0, 2), joint(0, 1);
  std::uniform_real_distribution<double> gap(-1e-2, 0);
  for (int k = 0; k < 60; ++k) {
    Contact3 c;
    c.i = block(rng);
    do c.j = block(rng);
    while (c.j == c.i);
    const int st = state(rng);
    c.state = st == 0 ? ContactState3::Open : st == 1 ? ContactState3::Sliding : ContactState3::Locked;
    c.joint = joint(rng);
    c.geo.dn0 = gap(rng);
    c.geo.en.setRandom();
    c.geo.gn.setRandom();
    c.geo.es.setRandom();
    c.geo.gs.setRandom();
    s.contacts.push_back(c);
  }
  return s;
}

// (K - blockdiag(K)) x with K assembled from the contacts' springs.
Eigen::VectorXd assembled_coupling_product(const Springs& s, const Eigen::VectorXd& x) {
  std::vector<std::pair<int, int>> pairs;
  for (const Contact3& c : s.contacts) pairs.emplace_back(c.i, c.j);
  Eigen::SparseMatrix<double> lower = block_lower_pattern(s.dof, s.n_dofs, pairs);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(s.n_dofs);
  Assembly3 sys{s.dof, lower, f};
  for (const Contact3& c : s.contacts) add_contact_springs(c, c.state, 1.0, s.springs[static_cast<std::size_t>(c.joint)], sys);
  Eigen::MatrixXd k = Eigen::MatrixXd(lower);
  k += k.transpose().eval();
  k.diagonal() /= 2;
  for (int b = 0; b < s.n_dofs / kDofs; ++b) k.block<kDofs, kDofs>(kDofs * b, kDofs * b).setZero();
  return k * x;
}

TEST(ContactCoupling3, IsTheProductWithTheAssembledCouplingBlocks) {
  const Springs s = random_springs();
  int counted[3] = {0, 0, 0};
  for (const Contact3& c : s.contacts) ++counted[static_cast<int>(c.state)];
  ASSERT_GT(counted[0] * counted[1] * counted[2], 0);  // every state is there
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(s.n_dofs, -2, 3).array().sin();
  const Eigen::VectorXd expected = assembled_coupling_product(s, x);
  ASSERT_GT(expected.norm(), 1.0);
  ContactCoupling3 coupling;
  coupling.set_springs(s.contacts, s.dof, s.springs);
  Eigen::VectorXd y = Eigen::VectorXd::Constant(s.n_dofs, 0.5);  // it adds to y
  coupling.add_product(x, y);
  // The same terms summed in another order: round-off apart.
  EXPECT_LT((y.array() - 0.5 - expected.array()).abs().maxCoeff(), 1e-13 * expected.norm());

  // An open-close iterate later: new states, the same springs.
  Springs later = s;
  for (Contact3& c : later.contacts)
    c.state = c.state == ContactState3::Open      ? ContactState3::Locked
              : c.state == ContactState3::Locked  ? ContactState3::Sliding
                                                  : ContactState3::Open;
  coupling.set_states(later.contacts);
  const Eigen::VectorXd expected_later = assembled_coupling_product(later, x);
  Eigen::VectorXd y_later = Eigen::VectorXd::Zero(s.n_dofs);
  coupling.add_product(x, y_later);
  EXPECT_LT((y_later - expected_later).cwiseAbs().maxCoeff(), 1e-13 * expected_later.norm());
  EXPECT_GT((expected_later - expected).norm(), 0.1 * expected.norm());
}

TEST(ContactCoupling3, SameOnOneAndTwoThreads) {
  const Springs s = random_springs();
  ContactCoupling3 coupling;
  coupling.set_springs(s.contacts, s.dof, s.springs);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(s.n_dofs, 1, -4).array().cos();
  Eigen::VectorXd one = Eigen::VectorXd::Zero(s.n_dofs), two = one;
  {
    const df::testing::ForcedThreads forced(1);
    coupling.add_product(x, one);
  }
  {
    const df::testing::ForcedThreads forced(2);
    coupling.add_product(x, two);
  }
  EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace dda::df3
