// Earthquake, route incident wave (the incident mode): the record is the
// motion a free surface of the base rock would have (the outcrop motion);
// a free surface doubles an incident wave, so the wave sent up through the
// viscous base has half its velocity, v_in = v_g / 2 (viscous_boundary.hpp).
// The base stays free to move: what the model sends back down leaves
// through the dashpots.
#include <algorithm>

#include "dda/common/error.hpp"
#include "dda/df/2d/ground_motion.hpp"

namespace dda::df {

void apply_incident_wave(const GroundMotion<2>& motion, ModelInput& in) {
  const bool has_input = in.viscous_boundary && std::any_of(in.viscous_boundary->edges.begin(),
                                                             in.viscous_boundary->edges.end(),
                                                             [](const ViscousEdge& e) { return e.input; });
  if (!has_input)
    throw InputError("The incident mode sends the wave in through a viscous boundary, and the model has none on "
                     "the side it enters (add that side to boundaries.viscous).");
  TimeHistory v;
  for (const auto& [t, velocity] : incident_velocity_rows(motion, in.control.dt)) {
    v.t.push_back(t);
    v.value.push_back(velocity);
  }
  in.viscous_boundary->incident_velocity = std::move(v);
}

}  // namespace dda::df
