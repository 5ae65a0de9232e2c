#pragma once
// How the 3D kernel takes an earthquake (core/ground_motion.hpp: the motion,
// the modes and their routes; docs/scenario.md: loading.earthquake). The
// foundation is the fixed blocks, and each step asks the mode for its
// routes directly (Simulation3::prepare_input): the body acceleration over
// the step on every free block, and the foundation's translation over the
// step, from the motion's exact integrals; the incident wave's table is put
// on the viscous boundary's input faces by the scenario reader.
#include <memory>

#include "dda/df/core/ground_motion.hpp"

namespace dda::df3 {

using GroundMotion3 = df::GroundMotion<3>;

// The earthquake of a 3D model: the motion and its mode (an entry of the
// modes' table, df::ground_motion_mode).
struct GroundInput3 {
  std::shared_ptr<const GroundMotion3> motion;
  const df::GroundMotionMode* mode = nullptr;
};

}  // namespace dda::df3
