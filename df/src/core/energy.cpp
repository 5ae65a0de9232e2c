// Checking a run's energy balance (energy.hpp).
#include "dda/df/core/energy.hpp"

#include <algorithm>
#include <cmath>

namespace dda::df {

double energy_moved(const EnergyRecord& start, const EnergyRecord& e) {
  return std::max(std::abs(e.input()), std::abs(e.stored() - start.stored()) + e.losses());
}

EnergyCreated most_energy_created(const std::vector<EnergyRecord>& log) {
  EnergyCreated worst;
  double scale = 0;
  for (std::size_t k = 1; k < log.size(); ++k) {
    const EnergyRecord& e = log[k];
    scale = std::max(scale, energy_moved(log.front(), e));
    const EnergyCreated here{e.time, e.residual, scale};
    if (k == 1 || here.ratio() < worst.ratio()) worst = here;
  }
  return worst;
}

}  // namespace dda::df
