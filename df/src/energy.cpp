// Checking a run's energy balance (energy.hpp).
#include "dda/df/energy.hpp"

#include <algorithm>
#include <cmath>

namespace dda::df {

EnergyCreated most_energy_created(const std::vector<EnergyRecord>& log) {
  EnergyCreated worst;
  if (log.empty()) return worst;
  const double stored0 = log.front().stored();
  double scale = 0;
  for (std::size_t k = 1; k < log.size(); ++k) {
    const EnergyRecord& e = log[k];
    scale = std::max({scale, std::abs(e.input()), std::abs(e.stored() - stored0) + e.losses()});
    const EnergyCreated here{e.time, e.residual, scale};
    if (k == 1 || here.ratio() < worst.ratio()) worst = here;
  }
  return worst;
}

}  // namespace dda::df
