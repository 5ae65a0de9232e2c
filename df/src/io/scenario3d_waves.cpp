// `boundaries.viscous` and `boundaries.free_field` of a 3D scenario and the
// earthquake's incident mode (scenario3d_detail.hpp; keys in
// docs/scenario.md): the domain-boundary faces on the named sides of the
// blocks' bounding box get the dashpots of viscous_boundary3d.hpp; with
// `mode: incident` the wave enters through the bottom ones, and the
// free-field sides move with its free field.
#include <algorithm>
#include <cmath>

#include "dda/common/error.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "io/scenario3d_detail.hpp"
#include "io/scenario_record.hpp"

namespace dda::df3 {
namespace {

// Side name -> (axis, +1 for the high end / -1 for the low end).
struct Side {
  const char* name;
  int axis;
  int sign;
};
constexpr Side kSides[] = {{"bottom", 2, -1}, {"top", 2, 1},    {"west", 0, -1},
                           {"east", 0, 1},    {"south", 1, -1}, {"north", 1, 1}};

const Side* side_named(const std::string& s) {
  for (const Side& side : kSides)
    if (s == side.name) return &side;
  return nullptr;
}

}  // namespace

BoundarySides3 read_viscous_sides3(const YamlNode& root) {
  BoundarySides3 sides;
  const auto b = root.optional_child("boundaries");
  if (!b) return sides;
  b->allow({"viscous", "free_field"});
  for (const YamlNode& s : b->list_or_empty("viscous")) {
    const std::string side = s.as_text();
    if (!side_named(side)) s.fail("must be bottom, top, west, east, south or north, got '" + side + "'");
    if (std::find(sides.viscous.begin(), sides.viscous.end(), side) != sides.viscous.end())
      s.fail("repeats side " + side);
    sides.viscous.push_back(side);
  }
  for (const YamlNode& s : b->list_or_empty("free_field")) {
    const std::string side = s.as_text();
    const Side* named = side_named(side);
    if (!named || named->axis == 2)
      s.fail("must be west, east, south or north (free-field boundaries stand on the lateral sides), got '" + side +
             "'");
    if (std::find(sides.free_field.begin(), sides.free_field.end(), side) != sides.free_field.end())
      s.fail("repeats side " + side);
    if (std::find(sides.viscous.begin(), sides.viscous.end(), side) != sides.viscous.end())
      s.fail("is also in boundaries.viscous; a side has plain dashpots or free-field ones, not both");
    sides.free_field.push_back(side);
  }
  return sides;
}

void add_viscous_boundary3(const YamlNode& root, const PolyhedronModel& blocks, const std::string& blocks_path,
                           Model3& m) {
  const BoundarySides3 both = read_viscous_sides3(root);
  const std::vector<std::string>& sides = both.viscous;
  const bool incident = m.earthquake.mode && m.earthquake.mode->route == df::GroundMotionRoute::incident_wave;
  const auto earthquake = [&] { return root.child("loading").child("earthquake"); };
  df::require_incident_for_free_field(root, !both.free_field.empty(), incident);
  if (sides.empty()) {
    if (incident)
      earthquake().fail_key("mode", "incident sends the wave in through the viscous base, and boundaries.viscous "
                                    "does not list bottom (add it there)");
    return;
  }
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Polyhedron& p : blocks.blocks)
    for (const Vec3& v : p.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double tol = 1e-9 * std::max(1.0, (hi - lo).norm());
  ViscousBoundary3 v;
  v.base_z = lo.z();
  v.surface_z = -1e300;
  for (const bool free_field : {false, true})
    for (const std::string& name : free_field ? both.free_field : sides) {
      const Side& side = *side_named(name);
      const double plane = side.sign > 0 ? hi[side.axis] : lo[side.axis];
      const std::size_t before = v.faces.size();
      for (std::size_t b = 0; b < blocks.blocks.size(); ++b) {
        const Polyhedron& p = blocks.blocks[b];
        for (std::size_t f = 0; f < p.faces.size(); ++f) {
          if (p.faces[f].set != kBoundarySet) continue;
          const std::vector<int>& corners = p.faces[f].vertices;
          const auto at = [&](int k) -> const Vec3& { return p.vertices[static_cast<std::size_t>(k)]; };
          if (!std::all_of(corners.begin(), corners.end(),
                           [&](int k) { return std::abs(at(k)[side.axis] - plane) <= tol; }))
            continue;
          v.faces.push_back({static_cast<int>(b), static_cast<int>(f), incident && name == "bottom", free_field});
          // The free field's free surface: the top of the free-field sides (as 2D).
          if (free_field)
            for (const int k : corners) v.surface_z = std::max(v.surface_z, at(k).z());
        }
      }
      if (v.faces.size() == before)
        root.child("boundaries").fail_key(free_field ? "free_field" : "viscous",
                                          "lists " + name + ", but no block of " + blocks_path +
                                              " has a domain-boundary face on that side");
    }
  if (both.free_field.empty()) v.surface_z = 0;
  if (incident) {
    if (std::find(sides.begin(), sides.end(), "bottom") == sides.end())
      earthquake().fail_key("mode", "incident sends the wave in through the viscous base, and boundaries.viscous "
                                    "does not list bottom (add it there)");
    const double step = m.control.dt > 0 ? m.control.dt : 1e-3;
    for (const auto& [t, velocity] : df::incident_velocity_rows(*m.earthquake.motion, step)) {
      v.incident_velocity.t.push_back(t);
      v.incident_velocity.value.push_back(velocity);
    }
  }
  m.viscous = std::move(v);
}

}  // namespace dda::df3
