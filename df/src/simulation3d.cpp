// The 3D time step: assembly of K d = F with 12x12 blocks, open-close
// iteration, and the end-of-step update (simulation3d.hpp).
#include "dda/df/simulation3d.hpp"

#include "simulation3d_assembly.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <stdexcept>

namespace dda::df3 {

namespace {

// Newell's normal of a face loop, unit (outward for the stored loop order).
Vec3 face_normal(const std::vector<Vec3>& v, const std::vector<int>& loop) {
  Vec3 n(0, 0, 0);
  for (size_t k = 0; k < loop.size(); ++k) n += v[loop[k]].cross(v[loop[(k + 1) % loop.size()]]);
  return n.normalized();
}

// Volume, centroid, second moment and face normals from the vertices.
void refresh(Polyhedron& p) {
  const BlockGeometry3 g = block_geometry(p.vertices, p.faces);
  p.volume = g.volume;
  p.centroid = g.centroid;
  p.second_moment = g.second_moment;
  for (auto& f : p.faces) f.normal = face_normal(p.vertices, f.vertices);
}

}  // namespace

Simulation3::Simulation3(Model3 model) : model_(std::move(model)) {
  const size_t n = model_.blocks.size();
  if (model_.fixed.empty()) model_.fixed.assign(n, false);
  if (model_.fixed.size() != n) throw std::invalid_argument("Model3: fixed must have one entry per block");
  for (size_t b = 0; b < n; ++b) {
    refresh(model_.blocks[b]);
    dof_.push_back(model_.fixed[b] ? -1 : n_dofs_);
    if (!model_.fixed[b]) n_dofs_ += kDofs;
  }
  velocity_.assign(n, Vector12d::Zero());
  stress_.assign(n, Vector6d::Zero());
}

std::vector<Vector12d> Simulation3::solve(double dt) const {
  Assembly3 sys{dof_, {}, Eigen::VectorXd::Zero(n_dofs_)};
  for (size_t b = 0; b < model_.blocks.size(); ++b) {
    if (dof_[b] < 0) continue;
    const BlockGeometry3 g = block_geometry(model_.blocks[b]);
    Matrix12d k = Matrix12d::Zero();
    Vector12d f = Vector12d::Zero();
    add_inertia(g, model_.material.density, velocity_[b], dt, k, f);
    add_elasticity(g, model_.material, stress_[b], k, f);
    add_body_force(g, model_.material.density, model_.gravity, f);
    sys.add_k(static_cast<int>(b), static_cast<int>(b), k);
    sys.add_f(static_cast<int>(b), f);
  }
  for (const Contact3& c : contacts_) add_contact_terms(c, model_, sys);
  Eigen::SparseMatrix<double> k(n_dofs_, n_dofs_);
  k.setFromTriplets(sys.k.begin(), sys.k.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(k);
  if (ldlt.info() != Eigen::Success) throw std::runtime_error("Simulation3: K is singular");
  const Eigen::VectorXd x = ldlt.solve(sys.f);
  std::vector<Vector12d> d(model_.blocks.size(), Vector12d::Zero());
  for (size_t b = 0; b < d.size(); ++b)
    if (dof_[b] >= 0) d[b] = x.segment<kDofs>(dof_[b]);
  return d;
}

StepInfo3 Simulation3::step(double dt) {
  contacts_ = detect_contacts3(model_.blocks, contacts_, model_.contact_reach);
  StepInfo3 info;
  std::vector<Vector12d> d;
  std::vector<int> changes(contacts_.size(), 0);  // state changes of each contact in this step
  while (info.iterations < model_.max_iterations) {
    ++info.iterations;
    d = solve(dt);
    bool settled = true;
    for (size_t k = 0; k < contacts_.size(); ++k) {
      Contact3& c = contacts_[k];
      const ContactState3 s = update_contact3(c, model_, d[c.i], d[c.j], changes[k] >= 2, settled);
      if (s != c.state) {
        settled = false;
        ++changes[k];
      }
      c.state = s;
    }
    if (settled) {
      info.converged = true;
      break;
    }
  }
  // If not settled, d is from states one update behind the stored ones; the
  // step is accepted anyway (no dt cut in this increment).
  finish_step(d, dt);
  for (const Contact3& c : contacts_) {
    if (c.state == ContactState3::Open) ++info.open;
    if (c.state == ContactState3::Sliding) ++info.sliding;
    if (c.state == ContactState3::Locked) ++info.locked;
  }
  return info;
}

void Simulation3::finish_step(const std::vector<Vector12d>& d, double dt) {
  const Matrix6d dmat = elastic_matrix(model_.material);
  std::vector<Vec3> old_centroid;
  for (const auto& b : model_.blocks) old_centroid.push_back(b.centroid);
  for (Contact3& c : contacts_) {
    // Shear anchors ride on block j (before its centroid moves).
    c.ref_j = move_point(old_centroid[c.j], d[c.j], c.ref_j);
    // A contact still sliding forwards slides on along this step's slip.
    if (c.state == ContactState3::Sliding && c.slip.dot(c.slip_dir) > model_.tolerance)
      c.slip_dir = c.slip.normalized();
  }
  for (size_t b = 0; b < model_.blocks.size(); ++b) {
    if (dof_[b] < 0) continue;
    velocity_[b] = 2.0 / dt * d[b] - velocity_[b];  // constant acceleration in the step
    stress_[b] += dmat * d[b].segment<6>(kStrain);
    Polyhedron& p = model_.blocks[b];
    for (auto& v : p.vertices) v = move_point(old_centroid[b], d[b], v);  // exact rotation
    refresh(p);
  }
  time_ += dt;
}

}  // namespace dda::df3
