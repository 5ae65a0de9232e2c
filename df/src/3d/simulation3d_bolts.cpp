// Rock bolts in the 3D step (bolts3d.hpp; the law is bolt_law.hpp, shared
// with 2D): checked and started with the model, in K and F as one axial
// spring, moved with their blocks after each step, booked in the ledger.
#include <cmath>
#include <string>

#include "dda/common/error.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "3d/contact_coupling3d.hpp"
#include "3d/simulation3d_assembly.hpp"

namespace dda::df3 {

BoltRows3 bolt_rows3(const BoltState3& s, const Vec3& ca, const Vec3& ch) {
  const Vec3 u = (s.head - s.anchor).normalized();
  return {-displacement_matrix(s.anchor, ca).transpose() * u, displacement_matrix(s.head, ch).transpose() * u};
}

namespace {

// The contact springs' coupling plus that of the bolts between two free
// blocks, k e_a e_h^T and its transpose, for PCG (linear_solver.hpp).
class CouplingWithBolts final : public df::SpringCoupling {
 public:
  struct Row {
    int first_a, first_h;  // first unknowns of the two free blocks
    double k;
    Vector12d ea, eh;
  };
  CouplingWithBolts(const df::SpringCoupling& contacts, std::vector<Row> rows)
      : contacts_(contacts), rows_(std::move(rows)) {}
  void add_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const override {
    contacts_.add_product(x, y);
    for (const Row& r : rows_) {  // in bolt order: the same on any number of threads
      const double from_h = r.k * r.eh.dot(x.segment<kDofs>(r.first_h));
      const double from_a = r.k * r.ea.dot(x.segment<kDofs>(r.first_a));
      y.segment<kDofs>(r.first_a) += from_h * r.ea;
      y.segment<kDofs>(r.first_h) += from_a * r.eh;
    }
  }

 private:
  const df::SpringCoupling& contacts_;
  std::vector<Row> rows_;
};

}  // namespace

void Simulation3::start_bolts() {
  const int n = static_cast<int>(model_.blocks.size());
  for (const Bolt3& b : model_.bolts) {
    const std::string what = "Bolt '" + b.name + "'";
    for (const int block : {b.anchor_block, b.head_block})
      if (block < 0 || block >= n) throw InputError(what + ": block " + std::to_string(block) + " does not exist.");
    if (b.anchor_block == b.head_block)
      throw InputError(what + " has both ends in block " + std::to_string(b.head_block) + ".");
    if (model_.fixed[static_cast<std::size_t>(b.anchor_block)] && model_.fixed[static_cast<std::size_t>(b.head_block)])
      throw InputError(what + " joins two fixed blocks, so it would do nothing.");
    if (!b.anchor.allFinite() || !b.head.allFinite() || !((b.head - b.anchor).norm() > 0))
      throw InputError(what + " has zero length or an end that is not a finite number.");
    if (!std::isfinite(b.stiffness) || !(b.stiffness > 0))
      throw InputError(what + " has a stiffness that is not positive.");
    if (!std::isfinite(b.pretension) || b.pretension < 0) throw InputError(what + " has a negative pretension.");
    if (b.breaking_force && !(std::isfinite(*b.breaking_force) && *b.breaking_force > 0))
      throw InputError(what + " has a breaking force that is not positive.");
    bolts_.push_back(df::initial_bolt_state(b, b.anchor, b.head));
  }
  restart_bolt_histories();
}

void Simulation3::restart_bolt_histories() {
  bolt_histories_.assign(bolts_.size(), {});
  for (std::size_t k = 0; k < bolts_.size(); ++k) bolt_histories_[k].push_back(df::bolt_sample(time_, bolts_[k]));
}

void Simulation3::add_bolt_pairs(std::vector<std::pair<int, int>>& pairs) const {
  // Broken bolts too: K's pattern (and the solver's analysis) then holds.
  for (const Bolt3& b : model_.bolts)
    if (dof_[static_cast<std::size_t>(b.anchor_block)] >= 0 && dof_[static_cast<std::size_t>(b.head_block)] >= 0)
      pairs.emplace_back(b.anchor_block, b.head_block);
}

void Simulation3::add_bolt_terms(Assembly3& sys) const {
  using Row = Eigen::Matrix<double, 1, kDofs>;
  for (std::size_t k = 0; k < bolts_.size(); ++k) {
    const Bolt3& b = model_.bolts[k];
    const BoltState3& s = bolts_[k];
    if (s.broken) continue;
    const auto a = static_cast<std::size_t>(b.anchor_block), h = static_cast<std::size_t>(b.head_block);
    const BoltRows3 e = bolt_rows3(s, model_.blocks[a].centroid, model_.blocks[h].centroid);
    // T dL + k/2 dL^2 = k/2 (T/k + dL)^2 + const: a spring stretched by T/k,
    // and by the known increment of a fixed end (a moving foundation).
    double stretch = s.force / b.stiffness;
    if (dof_[a] < 0) stretch += e.anchor.dot(known_[a]);
    if (dof_[h] < 0) stretch += e.head.dot(known_[h]);
    const Row ra = e.anchor.transpose(), rh = e.head.transpose();
    sys.add_spring_k<1>(b.anchor_block, b.head_block, b.stiffness, ra, rh);
    sys.add_spring_f<1>(b.anchor_block, b.head_block, b.stiffness, Eigen::Matrix<double, 1, 1>(stretch), ra, rh);
  }
}

Eigen::VectorXd Simulation3::solve_system(const Eigen::VectorXd& f, double dt) {
  std::vector<CouplingWithBolts::Row> rows;
  for (std::size_t k = 0; k < bolts_.size(); ++k) {
    const Bolt3& b = model_.bolts[k];
    const auto a = static_cast<std::size_t>(b.anchor_block), h = static_cast<std::size_t>(b.head_block);
    if (bolts_[k].broken || dof_[a] < 0 || dof_[h] < 0) continue;
    const BoltRows3 e = bolt_rows3(bolts_[k], model_.blocks[a].centroid, model_.blocks[h].centroid);
    rows.push_back({dof_[a], dof_[h], b.stiffness, e.anchor, e.head});
  }
  if (rows.empty()) return solver_->solve_step(k_lower_, *coupling_, f, dt);
  const CouplingWithBolts coupling(*coupling_, std::move(rows));
  return solver_->solve_step(k_lower_, coupling, f, dt);
}

void Simulation3::advance_bolts(const std::vector<Vector12d>& d, const std::vector<Vec3>& old_centroid) {
  bolt_released_.assign(bolts_.size(), 0.0);  // booked when the ledger closes the step
  for (std::size_t k = 0; k < bolts_.size(); ++k) {
    const Bolt3& b = model_.bolts[k];
    BoltState3& s = bolts_[k];
    const auto a = static_cast<std::size_t>(b.anchor_block), h = static_cast<std::size_t>(b.head_block);
    s.anchor = move_point(old_centroid[a], d[a], s.anchor);
    s.head = move_point(old_centroid[h], d[h], s.head);
    bolt_released_[k] = df::update_bolt_force(b, s);
    bolt_histories_[k].push_back(df::bolt_sample(time_, s));
  }
}

double Simulation3::bolt_ground_work(const std::vector<Vector12d>& d) const {
  // A fixed end moved by the ground stretches the bolt by e . d against
  // its force at the end of the step (as the contacts' springs, add_step_work).
  double work = 0;
  for (std::size_t k = 0; k < bolts_.size(); ++k) {
    const Bolt3& b = model_.bolts[k];
    const BoltState3& s = bolts_[k];
    const auto a = static_cast<std::size_t>(b.anchor_block), h = static_cast<std::size_t>(b.head_block);
    const bool a_moved = dof_[a] < 0 && !d[a].isZero(), h_moved = dof_[h] < 0 && !d[h].isZero();
    if (s.broken || !(a_moved || h_moved)) continue;
    const BoltRows3 e = bolt_rows3(s, model_.blocks[a].centroid, model_.blocks[h].centroid);
    const double force = s.force + b.stiffness * (e.anchor.dot(d[a]) + e.head.dot(d[h]));
    if (a_moved) work += force * e.anchor.dot(d[a]);
    if (h_moved) work += force * e.head.dot(d[h]);
  }
  return work;
}

}  // namespace dda::df3
