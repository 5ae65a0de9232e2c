// The default time step (time_step.hpp).
#include "dda/df/core/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/common/short_number.hpp"

namespace dda::df {

double p_wave_speed(double young, double poisson, double density, bool plane_stress) {
  const double m = plane_stress ? young / (1 - poisson * poisson)
                                : young * (1 - poisson) / ((1 + poisson) * (1 - 2 * poisson));
  return std::sqrt(m / density);
}

TimeStepChoice default_time_step(std::vector<BlockCrossing> blocks, double loading_interval) {
  auto crossing = [](const BlockCrossing& b) { return b.size / b.speed; };
  std::erase_if(blocks, [&](const BlockCrossing& b) { return !(b.size > 0 && b.speed > 0 && std::isfinite(crossing(b))); });
  if (blocks.empty()) throw InputError("No block has a size and a wave speed to choose the time step from; give control.dt.");
  // The median, not the smallest: cutting leaves slivers, and one sliver
  // must not set the step of a whole model. Of an even count, the lower one.
  const auto mid = blocks.begin() + static_cast<std::ptrdiff_t>((blocks.size() - 1) / 2);
  std::nth_element(blocks.begin(), mid, blocks.end(),
                   [&](const BlockCrossing& a, const BlockCrossing& b) { return crossing(a) < crossing(b); });
  const double t_block = crossing(*mid);
  const std::string crossing_text = "a P wave (" + short_number(mid->speed) + " m/s) crosses the median block (" +
                                    short_number(mid->size) + " m) in " + short_number(t_block) + " s";
  TimeStepChoice c;
  if (loading_interval > 0 && loading_interval < t_block) {
    c.dt = loading_interval;
    c.basis = "the loading's sample interval, " + short_number(loading_interval) + " s (" + crossing_text + ")";
  } else {
    c.dt = t_block;
    c.basis = crossing_text;
  }
  return c;
}

double shortest_interval(const std::vector<double>& times) {
  double out = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < times.size(); ++k) out = std::min(out, times[k] - times[k - 1]);
  if (!std::isfinite(out)) return 0.0;
  // To 10 digits: the difference of two times read as decimals is the
  // interval as written only to rounding (0.3 - 0.2 is 0.09999999999999998),
  // and a record sampled at 1 kHz must give the step 0.001 exactly: the
  // stick-slip of a wedge near its yield acceleration follows round-off, so
  // a step 6e-16 s short (0.0009999999999994) moved the shaking-table example by 3 %.
  std::ostringstream s;
  s.precision(10);
  s << out;
  return std::stod(s.str());
}

}  // namespace dda::df
