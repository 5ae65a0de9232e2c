#include "dda/analysis/friction.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda::analysis {

FrictionLaw FrictionLaw::constant_angle(double phi_deg) {
  FrictionLaw f;
  f.kind = Kind::constant;
  f.phi_deg = phi_deg;
  return f;
}

FrictionLaw FrictionLaw::log_velocity(double a, double b, double v_ref, double v_min) {
  FrictionLaw f;
  f.kind = Kind::log_velocity;
  f.a = a;
  f.b = b;
  f.v_ref = v_ref;
  f.v_min = v_min;
  return f;
}

FrictionLaw FrictionLaw::table(std::vector<double> times, std::vector<double> phis_deg, const std::string& what) {
  if (times.empty() || times.size() != phis_deg.size())
    throw InputError(what + ": the friction table is empty.");
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i]) || !std::isfinite(phis_deg[i]) || phis_deg[i] < 0.0 || phis_deg[i] >= 90.0)
      throw InputError(what + ": row " + std::to_string(i + 1) + " of the friction table needs a finite time and an "
                       "angle in 0..90 degrees.");
    if (i > 0 && times[i] < times[i - 1])
      throw InputError(what + ": the times of the friction table decrease at row " + std::to_string(i + 1) + ".");
  }
  FrictionLaw f;
  f.kind = Kind::table;
  f.times = std::move(times);
  f.phis_deg = std::move(phis_deg);
  return f;
}

double FrictionLaw::mu(double t, double speed) const {
  switch (kind) {
    case Kind::constant:
      return std::tan(deg2rad(phi_deg));
    case Kind::table: {
      if (t <= times.front()) return std::tan(deg2rad(phis_deg.front()));
      if (t >= times.back()) return std::tan(deg2rad(phis_deg.back()));
      const auto j = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
      const std::size_t i = j - 1;
      const double w = (t - times[i]) / (times[j] - times[i]);
      return std::tan(deg2rad((1.0 - w) * phis_deg[i] + w * phis_deg[j]));
    }
    case Kind::log_velocity:
      return std::max(0.0, a + b * std::log(std::max(speed, v_min) / v_ref));
  }
  return 0.0;
}

std::string FrictionLaw::describe() const {
  std::ostringstream s;
  switch (kind) {
    case Kind::constant:
      s << "phi = " << phi_deg << " deg";
      break;
    case Kind::table:
      s << "phi(t) table of " << times.size() << " points";
      break;
    case Kind::log_velocity:
      s << "mu = " << a << " + " << b << " ln(max(v, " << v_min << ") / " << v_ref << ")";
      break;
  }
  return s.str();
}

}  // namespace dda::analysis
