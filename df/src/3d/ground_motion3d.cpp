// Exact integrals of a piecewise-linear ground acceleration (ground_motion3d.hpp).
#include "dda/df/3d/ground_motion3d.hpp"

#include <algorithm>

#include "dda/common/error.hpp"

namespace dda::df3 {

GroundMotion3::GroundMotion3(std::vector<double> t, std::vector<Vec3> a) : t_(std::move(t)), a_(std::move(a)) {
  if (t_.empty() || t_.size() != a_.size())
    throw InputError("Ground motion: give one acceleration per time, at least one.");
  for (std::size_t k = 1; k < t_.size(); ++k)
    if (!(t_[k] > t_[k - 1]))
      throw InputError("Ground motion: times must increase strictly (row " + std::to_string(k + 1) + ").");
  v_.assign(t_.size(), Vec3::Zero());
  d_.assign(t_.size(), Vec3::Zero());
  for (std::size_t k = 0; k + 1 < t_.size(); ++k) {
    const double h = t_[k + 1] - t_[k];
    const Vec3 da = a_[k + 1] - a_[k];
    v_[k + 1] = v_[k] + h * a_[k] + 0.5 * h * da;
    d_[k + 1] = d_[k] + h * v_[k] + 0.5 * h * h * a_[k] + h * h / 6 * da;
  }
}

std::size_t GroundMotion3::interval(double t) const {
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  return std::min<std::size_t>(static_cast<std::size_t>(it - t_.begin()) - 1, t_.size() - 2);
}

Vec3 GroundMotion3::acceleration(double t) const {
  if (t < t_.front() || t > t_.back()) return Vec3::Zero();
  if (t_.size() == 1) return a_.front();
  const std::size_t k = interval(t);
  const double s = (t - t_[k]) / (t_[k + 1] - t_[k]);
  return (1 - s) * a_[k] + s * a_[k + 1];
}

Vec3 GroundMotion3::velocity(double t) const {
  if (t <= t_.front() || t_.size() == 1) return Vec3::Zero();
  if (t >= t_.back()) return v_.back();
  const std::size_t k = interval(t);
  const double h = t_[k + 1] - t_[k], tau = t - t_[k];
  return v_[k] + tau * a_[k] + tau * tau / (2 * h) * (a_[k + 1] - a_[k]);
}

Vec3 GroundMotion3::displacement(double t) const {
  if (t <= t_.front() || t_.size() == 1) return Vec3::Zero();
  if (t >= t_.back()) return d_.back() + (t - t_.back()) * v_.back();
  const std::size_t k = interval(t);
  const double h = t_[k + 1] - t_[k], tau = t - t_[k];
  return d_[k] + tau * v_[k] + 0.5 * tau * tau * a_[k] + tau * tau * tau / (6 * h) * (a_[k + 1] - a_[k]);
}

Vec3 GroundMotion3::mean_acceleration(double t0, double t1) const {
  if (!(t1 > t0)) return acceleration(t0);
  return (velocity(t1) - velocity(t0)) / (t1 - t0);
}

std::shared_ptr<const GroundMotionMode3> make_ground_motion_mode3(const std::string& name) {
  if (name == "loading") return std::make_shared<LoadingMode3>();
  if (name == "displacement") return std::make_shared<DisplacementMode3>();
  if (name == "incident") return std::make_shared<IncidentWaveMode3>();
  throw InputError("Earthquake mode '" + name + "': use loading, displacement or incident.");
}

}  // namespace dda::df3
