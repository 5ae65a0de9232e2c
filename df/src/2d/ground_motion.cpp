// The 2D kernel's earthquake input: the route of each mode, the body
// acceleration table and the foundation's blocks (2d/ground_motion.hpp).
#include "dda/df/2d/ground_motion.hpp"

#include <algorithm>

namespace dda::df {

void apply_ground_motion(const GroundMotion<2>& motion, const GroundMotionMode& mode,
                         const std::vector<std::size_t>& foundation, ModelInput& in) {
  switch (mode.route) {
    case GroundMotionRoute::body_force: return apply_body_force(motion, foundation, in);
    case GroundMotionRoute::foundation: return apply_foundation_motion(motion, foundation, in);
    case GroundMotionRoute::incident_wave: return apply_incident_wave(motion, in);
  }
}

TimeHistory acceleration_history(const GroundMotion<2>& motion, double factor) {
  TimeHistory h;
  const std::vector<double>& t = motion.times();
  const std::vector<Vec2>& a = motion.samples();
  const std::size_t n = t.size();
  if (n == 0) return h;
  // A record is zero outside its span; TimeHistory holds its end values, so
  // a non-zero end sample gets a zero row a millionth of a step outside.
  const double first_step = n > 1 ? t[1] - t[0] : 1.0;
  const double last_step = n > 1 ? t[n - 1] - t[n - 2] : 1.0;
  if (!a.front().isZero()) {
    h.t.push_back(t.front() - 1e-6 * first_step);
    h.value.emplace_back(0, 0);
  }
  for (std::size_t i = 0; i < n; ++i) {
    h.t.push_back(t[i]);
    h.value.push_back(factor * a[i]);
  }
  if (!a.back().isZero()) {
    h.t.push_back(t.back() + 1e-6 * last_step);
    h.value.emplace_back(0, 0);
  }
  return h;
}

std::vector<int> foundation_blocks(const ModelInput& in, const std::vector<std::size_t>& foundation) {
  std::vector<int> blocks;
  for (const std::size_t k : foundation) {
    const FixedPoint& f = in.fixed_points.at(k);
    int b = f.block;
    for (std::size_t j = 0; b < 0 && j < in.geometry.blocks.size(); ++j)
      if (point_in_polygon(in.geometry.blocks[j].vertices, f.position)) b = static_cast<int>(j);
    if (b >= 0) blocks.push_back(b);  // a point outside every block is build_model's to report
  }
  std::sort(blocks.begin(), blocks.end());
  blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
  return blocks;
}

}  // namespace dda::df
