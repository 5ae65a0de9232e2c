// Earthquake, incident mode: the record is the motion a free surface of the
// base rock would have (the outcrop motion); a free surface doubles an
// incident wave, so the wave sent up through the viscous base has half its
// velocity, v_in = v_g / 2 (viscous_boundary.hpp). The base stays free to
// move: what the model sends back down leaves through the dashpots.
#include <algorithm>

#include "dda/common/error.hpp"
#include "dda/df/2d/ground_motion.hpp"

namespace dda::df {

void IncidentWaveMode::apply(const GroundMotion& motion, const std::vector<std::size_t>& /*foundation*/,
                             ModelInput& in) const {
  const bool has_input = in.viscous_boundary && std::any_of(in.viscous_boundary->edges.begin(),
                                                             in.viscous_boundary->edges.end(),
                                                             [](const ViscousEdge& e) { return e.input; });
  if (!has_input)
    throw InputError("The incident mode sends the wave in through a viscous boundary, and the model has none on "
                     "the side it enters (add that side to boundaries.viscous).");
  // The baseline correction, if any, is already in the acceleration.
  const IntegratedRecord ir = integrate_record(refined_record(motion, in.control.dt), 0);
  TimeHistory v;
  for (std::size_t i = 0; i < ir.t.size(); ++i) {
    v.t.push_back(ir.t[i]);
    v.value.emplace_back(0.5 * ir.v[0][i], 0.5 * ir.v[1][i]);
  }
  // After the record the incident wave stops.
  v.t.push_back(ir.t.back() + in.control.dt);
  v.value.emplace_back(0.0, 0.0);
  in.viscous_boundary->incident_velocity = std::move(v);
}

}  // namespace dda::df
