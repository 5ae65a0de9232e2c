// Earthquake input: reading and processing the record, the foundation, and
// the registry of modes (ground_motion.hpp).
#include "dda/df/2d/ground_motion.hpp"

#include <algorithm>

#include "dda/common/error.hpp"

namespace dda::df {

GroundMotion load_ground_motion(const GroundMotionSpec& spec) {
  RecordReadOptions options;
  options.units = spec.units;
  options.direction = Eigen::Vector3d(spec.direction.x(), spec.direction.y(), 0.0);
  AccelRecord rec = read_record(spec.path, options);
  // The CSV reader takes t, ax, ay, az for 3D input; in the plane model the
  // second and third columns are x and y (vertical), and a fourth has no
  // place (silently dropping it would lose part of the motion).
  for (const double v : rec.a[2])
    if (v != 0.0)
      throw InputError(rec.source + ": has a fourth column (az), which the 2D model cannot use; give t, ax, ay "
                                    "with ay vertical.");
  // The corrected acceleration is the ground motion of every mode (see the
  // header): the baseline correction removes P'' from it along with P from d.
  process_record(rec, spec.processing);

  GroundMotion g;
  g.source = rec.source;
  g.t = rec.t;
  for (std::size_t i = 0; i < rec.size(); ++i) g.acceleration.emplace_back(rec.a[0][i], rec.a[1][i]);
  return g;
}

TimeHistory acceleration_history(const GroundMotion& motion, double factor) {
  TimeHistory h;
  const std::size_t n = motion.t.size();
  if (n == 0) return h;
  // A record is zero outside its span; TimeHistory holds its end values, so
  // a non-zero end sample gets a zero row a millionth of a step outside.
  const double first_step = n > 1 ? motion.t[1] - motion.t[0] : 1.0;
  const double last_step = n > 1 ? motion.t[n - 1] - motion.t[n - 2] : 1.0;
  if (!motion.acceleration.front().isZero()) {
    h.t.push_back(motion.t.front() - 1e-6 * first_step);
    h.value.emplace_back(0, 0);
  }
  for (std::size_t i = 0; i < n; ++i) {
    h.t.push_back(motion.t[i]);
    h.value.push_back(factor * motion.acceleration[i]);
  }
  if (!motion.acceleration.back().isZero()) {
    h.t.push_back(motion.t.back() + 1e-6 * last_step);
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

AccelRecord refined_record(const GroundMotion& g, double h) {
  AccelRecord r;
  r.source = g.source;
  auto push = [&r](double t, const Vec2& a) {
    r.t.push_back(t);
    r.a[0].push_back(a.x());
    r.a[1].push_back(a.y());
    r.a[2].push_back(0.0);
  };
  push(g.t.front(), g.acceleration.front());
  for (std::size_t i = 1; i < g.t.size(); ++i) {
    const double span = g.t[i] - g.t[i - 1];
    const int parts = std::max(1, static_cast<int>(std::ceil(span / h * (1 - 1e-9))));
    for (int k = 1; k < parts; ++k) {
      const double w = static_cast<double>(k) / parts;
      push(g.t[i - 1] + w * span, (1 - w) * g.acceleration[i - 1] + w * g.acceleration[i]);
    }
    push(g.t[i], g.acceleration[i]);
  }
  return r;
}


std::vector<std::string> ground_motion_mode_names() { return {"loading", "displacement", "incident"}; }

std::unique_ptr<GroundMotionMode> make_ground_motion_mode(const std::string& name) {
  // One line per mode.
  if (name == "loading") return std::make_unique<LoadingMode>();
  if (name == "displacement") return std::make_unique<DisplacementMode>();
  if (name == "incident") return std::make_unique<IncidentWaveMode>();
  throw InputError("Unknown earthquake mode '" + name + "' (known: loading, displacement, incident).");
}

}  // namespace dda::df
