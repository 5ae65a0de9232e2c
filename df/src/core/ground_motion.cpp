// The ground motion's exact integrals and the table of earthquake modes
// (core/ground_motion.hpp).
#include "dda/df/core/ground_motion.hpp"

#include <algorithm>
#include <cmath>

#include "dda/common/error.hpp"

namespace dda::df {

template <int dim>
GroundMotion<dim>::GroundMotion(std::vector<double> t, std::vector<Vec> a, std::string source)
    : t_(std::move(t)), a_(std::move(a)), source_(std::move(source)) {
  if (t_.empty() || t_.size() != a_.size())
    throw InputError(source_ + ": give one acceleration per time, at least one.");
  for (std::size_t k = 0; k < t_.size(); ++k) {
    if (!std::isfinite(t_[k]) || !a_[k].allFinite())
      throw InputError(source_ + ": sample " + std::to_string(k + 1) + " is not a finite number.");
    if (k > 0 && !(t_[k] > t_[k - 1]))
      throw InputError(source_ + ": times must increase strictly (sample " + std::to_string(k + 1) + ").");
  }
  // a is linear on each interval, so v is quadratic and d cubic there:
  // these are their values at the samples, exactly.
  v_.assign(t_.size(), Vec::Zero());
  d_.assign(t_.size(), Vec::Zero());
  for (std::size_t k = 0; k + 1 < t_.size(); ++k) {
    const double h = t_[k + 1] - t_[k];
    const Vec da = a_[k + 1] - a_[k];
    v_[k + 1] = v_[k] + h * a_[k] + 0.5 * h * da;
    d_[k + 1] = d_[k] + h * v_[k] + 0.5 * h * h * a_[k] + h * h / 6 * da;
  }
}

template <int dim>
std::size_t GroundMotion<dim>::interval(double t) const {
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  return std::min<std::size_t>(static_cast<std::size_t>(it - t_.begin()) - 1, t_.size() - 2);
}

template <int dim>
typename GroundMotion<dim>::Vec GroundMotion<dim>::acceleration(double t) const {
  if (t_.empty() || t < t_.front() || t > t_.back()) return Vec::Zero();
  if (t_.size() == 1) return a_.front();
  const std::size_t k = interval(t);
  const double s = (t - t_[k]) / (t_[k + 1] - t_[k]);
  return (1 - s) * a_[k] + s * a_[k + 1];
}

template <int dim>
typename GroundMotion<dim>::Vec GroundMotion<dim>::velocity(double t) const {
  if (t_.size() < 2 || t <= t_.front()) return Vec::Zero();
  if (t >= t_.back()) return v_.back();
  const std::size_t k = interval(t);
  const double h = t_[k + 1] - t_[k], tau = t - t_[k];
  return v_[k] + tau * a_[k] + tau * tau / (2 * h) * (a_[k + 1] - a_[k]);
}

template <int dim>
typename GroundMotion<dim>::Vec GroundMotion<dim>::displacement(double t) const {
  if (t_.size() < 2 || t <= t_.front()) return Vec::Zero();
  if (t >= t_.back()) return d_.back() + (t - t_.back()) * v_.back();
  const std::size_t k = interval(t);
  const double h = t_[k + 1] - t_[k], tau = t - t_[k];
  return d_[k] + tau * v_[k] + 0.5 * tau * tau * a_[k] + tau * tau * tau / (6 * h) * (a_[k + 1] - a_[k]);
}

template <int dim>
typename GroundMotion<dim>::Vec GroundMotion<dim>::mean_acceleration(double t0, double t1) const {
  if (!(t1 > t0)) return acceleration(t0);
  return (velocity(t1) - velocity(t0)) / (t1 - t0);
}

template <int dim>
std::vector<double> GroundMotion<dim>::refined_times(double step) const {
  std::vector<double> out;
  if (t_.empty()) return out;
  out.push_back(t_.front());
  for (std::size_t i = 1; i < t_.size(); ++i) {
    const double span = t_[i] - t_[i - 1];
    // (1 - 1e-9): an interval of exactly n steps is split into n, not n + 1.
    const int parts = std::max(1, static_cast<int>(std::ceil(span / step * (1 - 1e-9))));
    for (int k = 1; k < parts; ++k) out.push_back(t_[i - 1] + static_cast<double>(k) / parts * span);
    out.push_back(t_[i]);
  }
  return out;
}

template <int dim>
void check_record_fits(const AccelRecord& record) {
  // The reader fills x, y, z; in the plane model y is vertical, and a z
  // would have no place (dropping it silently would lose part of the motion).
  for (int c = dim; c < 3; ++c)
    for (const double v : record.a[static_cast<std::size_t>(c)])
      if (v != 0.0)
        throw InputError(record.source + ": has a fourth column (az), which the 2D model cannot use; give t, ax, ay "
                                         "with ay vertical.");
}

template <int dim>
GroundMotion<dim> ground_motion_of(const AccelRecord& record) {
  check_record_fits<dim>(record);
  std::vector<typename GroundMotion<dim>::Vec> a(record.size());
  for (std::size_t i = 0; i < record.size(); ++i)
    for (int c = 0; c < dim; ++c) a[i][c] = record.a[static_cast<std::size_t>(c)][i];
  return GroundMotion<dim>(record.t, std::move(a), record.source);
}

template <int dim>
std::vector<std::pair<double, Eigen::Matrix<double, dim, 1>>> incident_velocity_rows(const GroundMotion<dim>& g,
                                                                                      double step) {
  std::vector<std::pair<double, Eigen::Matrix<double, dim, 1>>> rows;
  for (const double t : g.refined_times(step)) rows.emplace_back(t, 0.5 * g.velocity(t));
  rows.emplace_back(g.end() + step, Eigen::Matrix<double, dim, 1>::Zero());
  return rows;
}

namespace {

// The modes: one line each.
const std::vector<GroundMotionMode>& modes() {
  static const std::vector<GroundMotionMode> table{
      {"loading", GroundMotionRoute::body_force, 0},
      {"displacement", GroundMotionRoute::foundation, 3},
      {"incident", GroundMotionRoute::incident_wave, 3},
  };
  return table;
}

}  // namespace

const GroundMotionMode& ground_motion_mode(const std::string& name) {
  for (const GroundMotionMode& m : modes())
    if (m.name == name) return m;
  std::string known;
  for (const GroundMotionMode& m : modes()) known += (known.empty() ? "" : ", ") + m.name;
  throw InputError("Unknown earthquake mode '" + name + "' (known: " + known + ").");
}

std::vector<std::string> ground_motion_mode_names() {
  std::vector<std::string> names;
  for (const GroundMotionMode& m : modes()) names.push_back(m.name);
  return names;
}

template class GroundMotion<2>;
template class GroundMotion<3>;
template void check_record_fits<2>(const AccelRecord&);
template void check_record_fits<3>(const AccelRecord&);
template GroundMotion<2> ground_motion_of<2>(const AccelRecord&);
template GroundMotion<3> ground_motion_of<3>(const AccelRecord&);
template std::vector<std::pair<double, Eigen::Vector2d>> incident_velocity_rows<2>(const GroundMotion<2>&, double);
template std::vector<std::pair<double, Eigen::Vector3d>> incident_velocity_rows<3>(const GroundMotion<3>&, double);

}  // namespace dda::df
