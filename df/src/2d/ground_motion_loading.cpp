// Earthquake, route body force (the loading mode): the blocks feel the
// ground motion in the frame of the ground, as the inertial body force
// -rho a_g(t) added to gravity. The foundation's blocks are left out: they
// are held by their fixed points, and loading their springs with the force
// would only stretch them.
#include <algorithm>

#include "dda/common/error.hpp"
#include "dda/df/2d/ground_motion.hpp"

namespace dda::df {

void apply_body_force(const GroundMotion<2>& motion, const std::vector<std::size_t>& foundation, ModelInput& in) {
  if (in.body_acceleration) throw InputError("The model already has a body acceleration (one earthquake at most).");
  const std::vector<int> held = foundation_blocks(in, foundation);
  BodyAcceleration b;
  b.history = acceleration_history(motion, -1.0);
  for (int i = 0; i < static_cast<int>(in.geometry.blocks.size()); ++i)
    if (!std::binary_search(held.begin(), held.end(), i)) b.blocks.push_back(i);
  in.body_acceleration = std::move(b);
}

}  // namespace dda::df
