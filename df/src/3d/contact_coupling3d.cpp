#include "3d/contact_coupling3d.hpp"

#include <algorithm>

#include "dda/df/core/block_system.hpp"  // parallel_grain
#include "core/fixed_parts.hpp"

namespace dda::df3 {

void ContactCoupling3::set_springs(const std::vector<Contact3>& contacts, const std::vector<int>& dof,
                                   const std::vector<ContactSprings3>& springs) {
  contact_.clear();
  for (std::size_t k = 0; k < contacts.size(); ++k)
    if (dof[static_cast<std::size_t>(contacts[k].i)] >= 0 && dof[static_cast<std::size_t>(contacts[k].j)] >= 0)
      contact_.push_back(static_cast<int>(k));
  const int m = static_cast<int>(contact_.size());
  first_i_.resize(contact_.size());
  first_j_.resize(contact_.size());
  normal_.resize(contact_.size() * kNormal);
  shear_.resize(contact_.size() * kShear);
  kn_.resize(contact_.size());
  ps_.resize(contact_.size());
#pragma omp parallel for schedule(static) if (m > 20 * df::parallel_grain())
  for (int s = 0; s < m; ++s) {
    const Contact3& c = contacts[static_cast<std::size_t>(contact_[s])];
    first_i_[s] = dof[static_cast<std::size_t>(c.i)];
    first_j_[s] = dof[static_cast<std::size_t>(c.j)];
    const ContactSprings3& joint = springs[static_cast<std::size_t>(c.joint)];
    kn_[s] = joint.normal_spring(c.geo.dn0).k;  // fixed for the step (the law's tangent at its start)
    ps_[s] = joint.ps;
    double* normal = normal_.data() + static_cast<std::size_t>(s) * kNormal;
    std::copy(c.geo.en.data(), c.geo.en.data() + kDofs, normal);
    std::copy(c.geo.gn.data(), c.geo.gn.data() + kDofs, normal + kDofs);
    double* shear = shear_.data() + static_cast<std::size_t>(s) * kShear;
    std::copy(c.geo.es.data(), c.geo.es.data() + 2 * kDofs, shear);
    std::copy(c.geo.gs.data(), c.geo.gs.data() + 2 * kDofs, shear + 2 * kDofs);
  }
  set_states(contacts);
}

void ContactCoupling3::set_states(const std::vector<Contact3>& contacts) {
  const int m = static_cast<int>(contact_.size());
  state_.resize(contact_.size());
#pragma omp parallel for schedule(static) if (m > 20 * df::parallel_grain())
  for (int s = 0; s < m; ++s)
    state_[s] = static_cast<std::uint8_t>(contacts[static_cast<std::size_t>(contact_[s])].state);
}

void ContactCoupling3::add_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  using Row = Eigen::Map<const Vector12d>;
  using Rows = Eigen::Map<const Eigen::Matrix<double, 2, kDofs>>;
  const long m = static_cast<long>(contact_.size());
  constexpr auto kOpen = static_cast<std::uint8_t>(ContactState3::Open);
  constexpr auto kLocked = static_cast<std::uint8_t>(ContactState3::Locked);
  const bool parallel = m > 20 * df::parallel_grain();
  df::sum_in_fixed_parts(kParts, partial_, y, /*accumulate=*/true, parallel, [&](int part, auto yp) {
    for (long s = m * part / kParts; s < m * (part + 1) / kParts; ++s) {
      if (state_[static_cast<std::size_t>(s)] == kOpen) continue;
      const int fi = first_i_[static_cast<std::size_t>(s)], fj = first_j_[static_cast<std::size_t>(s)];
      const auto xi = x.segment<kDofs>(fi), xj = x.segment<kDofs>(fj);
      // K(i, j) x_j = p a^T (b x_j) and K(j, i) x_i = p b^T (a x_i), for each
      // spring row a (block i) and b (block j).
      const double* normal = normal_.data() + s * kNormal;
      const Row en(normal), gn(normal + kDofs);
      const double kn = kn_[static_cast<std::size_t>(s)];
      yp.template segment<kDofs>(fi).noalias() += (kn * gn.dot(xj)) * en;
      yp.template segment<kDofs>(fj).noalias() += (kn * en.dot(xi)) * gn;
      if (state_[static_cast<std::size_t>(s)] == kLocked) {
        const double* shear = shear_.data() + s * kShear;
        const Rows es(shear), gs(shear + 2 * kDofs);
        const double ps = ps_[static_cast<std::size_t>(s)];
        const Eigen::Vector2d sj = ps * (gs * xj), si = ps * (es * xi);
        yp.template segment<kDofs>(fi).noalias() += es.transpose() * sj;
        yp.template segment<kDofs>(fj).noalias() += gs.transpose() * si;
      }
    }
  });
}

}  // namespace dda::df3
