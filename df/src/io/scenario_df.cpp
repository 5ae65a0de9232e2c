// The forward-run sections of the scenario (materials, joints, loading,
// fixed, control) into a ModelInput. Keys, units and defaults are documented
// in docs/scenario.md; keep the two in step.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "dda/common/coordinate_range.hpp"
#include "dda/common/error.hpp"
#include "dda/df/io/scenario.hpp"
#include "dda/df/core/time_step.hpp"
#include "io/scenario_block_points.hpp"
#include "io/scenario_earthquake.hpp"
#include "io/scenario_record.hpp"
#include "io/scenario_bolts.hpp"
#include "io/scenario_control.hpp"
#include "io/scenario_joints.hpp"
#include "io/scenario_points.hpp"
#include "io/scenario_water.hpp"

namespace dda::df {
namespace {

const Range kPoisson{-1, 0.5, true, true};

// A material with the per-block initial values it gives.
struct MaterialEntry {
  Material material;
  Vector3d stress = Vector3d::Zero();  // Pa
  Vector6d velocity = Vector6d::Zero();
};

Vector3d triple(const YamlNode& n, const std::string& key, const Vector3d& fallback) {
  if (!n.has(key)) return fallback;
  const YamlNode c = n.child(key);
  const std::vector<double> v = c.as_numbers();
  if (v.size() != 3) c.fail("must hold three numbers, got " + std::to_string(v.size()));
  for (double x : v)
    if (!std::isfinite(x)) c.fail("must hold finite numbers");
  return {v[0], v[1], v[2]};
}

MaterialEntry read_material(const YamlNode& n, const MaterialEntry& base) {
  MaterialEntry e = base;
  Material& m = e.material;
  m.density = n.number("density", base.material.density, Range::positive());
  m.young = n.number("young", base.material.young, Range::positive());
  m.poisson = n.number("poisson", base.material.poisson, kPoisson);
  const std::string plane = n.choice("plane", {"stress", "strain"},
                                     base.material.plane == PlaneMode::Stress ? "stress" : "strain");
  m.plane = plane == "stress" ? PlaneMode::Stress : PlaneMode::Strain;
  e.stress = triple(n, "initial_stress", base.stress);
  const Vector3d v = triple(n, "initial_velocity", base.velocity.head<3>());
  e.velocity.head<3>() = v;
  return e;
}

#define DDA_MATERIAL_KEYS "density", "young", "poisson", "plane", "initial_stress", "initial_velocity"

struct Zone {
  std::optional<std::pair<int, int>> layers;
  std::optional<Polygon2> polygon;
};

Zone read_zone(const YamlNode& z) {
  Zone out;
  const std::string which = z.one_of({"layers", "polygon"});
  if (which == "layers") {
    const YamlNode l = z.child("layers");
    const std::vector<double> v = l.as_numbers();
    if (v.size() != 2) l.fail("must be [first, last] (two bed indices), got " + std::to_string(v.size()) + " numbers");
    for (double x : v)
      if (x != std::floor(x) || x < 0) l.fail("must hold whole numbers >= 0 (bed indices, 0 = lowest bed)");
    if (v[1] < v[0]) l.fail("must be [first, last] with first <= last");
    out.layers = std::make_pair(static_cast<int>(v[0]), static_cast<int>(v[1]));
  } else {
    out.polygon = z.polygon("polygon");
    make_counter_clockwise(*out.polygon);
  }
  return out;
}

Vec2 vector2(const YamlNode& n, const std::string& key) {
  const Vec2 v = n.point(key);
  if (!std::isfinite(v.x()) || !std::isfinite(v.y())) n.fail_key(key, "must hold finite numbers");
  return v;
}

// A table [[t, a, b], ...] with t strictly increasing.
TimeHistory read_table(const YamlNode& n, const std::string& key) {
  TimeHistory h;
  const std::vector<YamlNode> rows = n.list(key);
  if (rows.empty()) n.fail_key(key, "must hold at least one row [t, x, y]");
  for (const YamlNode& row : rows) {
    const std::vector<double> v = row.as_numbers();
    if (v.size() != 3) row.fail("must be a row [t, x, y] of three numbers, got " + std::to_string(v.size()));
    for (double x : v)
      if (!std::isfinite(x)) row.fail("must hold finite numbers");
    if (!h.t.empty() && v[0] <= h.t.back())
      row.fail("must come later than the row before it (times must increase), got t = " + std::to_string(v[0]));
    h.t.push_back(v[0]);
    h.value.emplace_back(v[1], v[2]);
  }
  return h;
}

struct Parsed {
  std::vector<MaterialEntry> materials;
  std::vector<Zone> zones;             // zone k uses materials[k + 1]
  JointsSection joints;
  Vec2 gravity{0, -9.81};
  struct Load {
    YamlNode node;
    std::string point;
    Vec2 force{0, 0};
    std::optional<TimeHistory> history;
  };
  std::vector<Load> loads;
  std::optional<EarthquakeEntry> earthquake;  // loading.earthquake (scenario_earthquake.cpp)
  struct Fix {
    YamlNode node;
    std::string point;
    std::optional<double> penalty;
    std::optional<TimeHistory> displacement;
  };
  std::vector<std::pair<YamlNode, Bolt>> bolts;
  std::vector<Fix> fixes;
  std::vector<std::string> fixed_sides;
  std::optional<YamlNode> fixed_boundary_node;
  std::vector<std::string> viscous_sides;       // boundaries.viscous
  std::vector<std::string> free_field_sides;    // boundaries.free_field
  std::optional<YamlNode> viscous_node;
  std::optional<WaterTable<2>> water;
  Control control;
  OutputSchedule output;
};

// One side of the model's bounding box, not listed twice.
std::string read_side(const YamlNode& s, const std::vector<std::string>& so_far) {
  const std::string side = s.as_text();
  if (side != "bottom" && side != "top" && side != "left" && side != "right")
    s.fail("must be bottom, top, left or right, got '" + side + "'");
  if (std::find(so_far.begin(), so_far.end(), side) != so_far.end()) s.fail("repeats side " + side);
  return side;
}

Parsed parse(const YamlNode& root) {
  Parsed p;
  // materials
  MaterialEntry base;
  base.material.plane = PlaneMode::Strain;
  if (auto m = root.optional_child("materials")) {
    m->allow({"default", "zones"});
    if (auto d = m->optional_child("default")) {
      d->allow({DDA_MATERIAL_KEYS});
      base = read_material(*d, base);
    }
    p.materials.push_back(base);
    for (const YamlNode& z : m->list_or_empty("zones")) {
      z.allow({DDA_MATERIAL_KEYS, "layers", "polygon"});
      p.zones.push_back(read_zone(z));
      p.materials.push_back(read_material(z, base));
    }
  } else {
    p.materials.push_back(base);
  }

  p.joints = read_joints_section(root);

  // loading
  if (auto l = root.optional_child("loading")) {
    l->allow({"gravity", "point_loads", "earthquake"});
    if (l->has("earthquake")) p.earthquake = read_earthquake(l->child("earthquake"));
    if (l->has("gravity")) {
      const YamlNode g = l->child("gravity");
      if (g.is_sequence())
        p.gravity = vector2(*l, "gravity");
      else
        p.gravity = Vec2(0, -g.as_number(Range::non_negative()));
    }
    for (const YamlNode& item : l->list_or_empty("point_loads")) {
      item.allow({"point", "force", "history"});
      Parsed::Load load{item, item.text("point"), Vec2(0, 0), std::nullopt};
      if (item.one_of({"force", "history"}) == "force")
        load.force = vector2(item, "force");
      else
        load.history = read_table(item, "history");
      p.loads.push_back(load);
    }
  }

  // boundaries
  if (auto b = root.optional_child("boundaries")) {
    b->allow({"viscous", "free_field"});
    if (b->has("viscous")) {
      p.viscous_node = b->child("viscous");
      for (const YamlNode& s : b->list("viscous")) p.viscous_sides.push_back(read_side(s, p.viscous_sides));
    }
    for (const YamlNode& s : b->list_or_empty("free_field")) {
      const std::string side = read_side(s, p.free_field_sides);
      if (side != "left" && side != "right")
        s.fail("must be left or right (free-field boundaries stand on the lateral sides), got '" + side + "'");
      if (std::find(p.viscous_sides.begin(), p.viscous_sides.end(), side) != p.viscous_sides.end())
        s.fail("is also in boundaries.viscous; a side has plain dashpots or free-field ones, not both");
      p.free_field_sides.push_back(side);
    }
  }

  // fixed
  if (auto f = root.optional_child("fixed")) {
    f->allow({"boundary", "points"});
    if (f->has("boundary")) {
      p.fixed_boundary_node = f->child("boundary");
      for (const YamlNode& s : f->list("boundary")) p.fixed_sides.push_back(read_side(s, p.fixed_sides));
    }
    for (const YamlNode& item : f->list_or_empty("points")) {
      item.allow({"point", "penalty", "displacement"});
      Parsed::Fix fix{item, item.text("point"), std::nullopt, std::nullopt};
      if (item.has("penalty")) fix.penalty = item.number("penalty", Range::positive());
      if (item.has("displacement")) fix.displacement = read_table(item, "displacement");
      p.fixes.push_back(fix);
    }
  }

  // bolts
  for (const BoltEntry<Vec2>& e : read_bolt_entries<Vec2>(root, vector2)) {
    Bolt b;
    b.name = e.name;
    b.anchor = e.from;
    b.head = e.to;
    b.stiffness = e.stiffness;
    b.pretension = e.pretension;
    b.breaking_force = e.breaking_force;
    p.bolts.emplace_back(e.node, b);
  }

  p.water = read_water<2>(root);

  // control
  const YamlNode c = root.child("control");
  std::vector<std::string> keys{"w0", "dynamic", "max_open_close", "penalty_factor", "shear_ratio",
                                "fixed_penalty_factor", "solver", "initial_equilibrium", "contact_clusters",
                                "damping"};
  keys.insert(keys.end(), std::begin(kRunLengthKeys), std::end(kRunLengthKeys));
  c.allow(keys);
  Control& ctl = p.control;
  RunLength defaults;
  defaults.max_displacement_ratio = ctl.max_displacement_ratio;
  defaults.min_dt_ratio = ctl.min_dt_ratio;
  const RunLength run = read_run_length(c, defaults);
  ctl.dt = run.dt;
  ctl.total_time = run.total_time;
  ctl.steps = run.steps;
  ctl.max_displacement_ratio = run.max_displacement_ratio;
  ctl.min_dt_ratio = run.min_dt_ratio;
  p.output = run.output;
  if (c.has("w0")) ctl.w0 = c.number("w0", Range::positive());
  ctl.dynamic = c.number("dynamic", ctl.dynamic, Range::closed(0, 1));
  ctl.damping = read_damping(c);
  ctl.max_open_close = static_cast<int>(c.integer("max_open_close", ctl.max_open_close, Range::closed(1, 1000)));
  ctl.penalty_factor = c.number("penalty_factor", ctl.penalty_factor, Range::positive());
  ctl.shear_ratio = c.number("shear_ratio", ctl.shear_ratio, Range::positive());
  ctl.fixed_penalty_factor = c.number("fixed_penalty_factor", ctl.fixed_penalty_factor, Range::positive());
  ctl.solver = c.choice("solver", {"auto", "cholmod", "pcg"}, "auto");
  ctl.initial_equilibrium = c.flag("initial_equilibrium", true);
  ctl.contact_clusters = c.flag("contact_clusters", ctl.contact_clusters);
  return p;
}

// Every absolute position of the DF sections (zones, bolts' ends, the water
// table) is given in the user's coordinates: about the blocks' local origin
// (coordinate_range.hpp), as the blocks are. Points named from the blocks
// file are there already; displacements, forces and velocities do not move.
void move_to_origin(Parsed& p, const Vec2& o) {
  if (o == Vec2::Zero()) return;
  for (Zone& z : p.zones)
    if (z.polygon)
      for (Vec2& v : *z.polygon) v -= o;
  for (auto& entry : p.bolts) entry.second.anchor -= o, entry.second.head -= o;
  if (p.water) p.water->move_to_origin(o);
}

bool has_any_df_section(const YamlNode& root) {
  for (const char* k : {"materials", "joints", "loading", "fixed", "bolts", "boundaries", "water", "control"})
    if (root.has(k)) return true;
  return false;
}

// Fixed points at both ends of every domain-boundary edge on the given sides
// of the blocks' bounding box.
// The domain-boundary edges (block, edge) lying on one side of the model's
// bounding box: bottom, top, left or right.
std::vector<std::pair<int, int>> side_edges(const BlockModel& blocks, const std::string& side) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Block& b : blocks.blocks)
    for (const Vec2& v : b.vertices) {
      x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x());
      y0 = std::min(y0, v.y()), y1 = std::max(y1, v.y());
    }
  const double tol = 1e-9 * std::max(x1 - x0, y1 - y0);
  auto on = [&](const Vec2& v) {
    if (side == "bottom") return std::abs(v.y() - y0) <= tol;
    if (side == "top") return std::abs(v.y() - y1) <= tol;
    if (side == "left") return std::abs(v.x() - x0) <= tol;
    return std::abs(v.x() - x1) <= tol;
  };
  std::vector<std::pair<int, int>> out;
  for (std::size_t b = 0; b < blocks.blocks.size(); ++b) {
    const Block& blk = blocks.blocks[b];
    const std::size_t n = blk.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      const bool boundary = blk.edge_set.size() != n || blk.edge_set[k] == kBoundarySet;
      if (boundary && on(blk.vertices[k]) && on(blk.vertices[(k + 1) % n]))
        out.emplace_back(static_cast<int>(b), static_cast<int>(k));
    }
  }
  return out;
}

void add_boundary_fixes(const BlockModel& blocks, const std::vector<std::string>& sides, ModelInput& in) {
  for (const std::string& side : sides) {
    // Both ends of every boundary edge on the side, once per block.
    std::set<std::pair<int, std::size_t>> fixed_vertices;
    for (const auto& [b, k] : side_edges(blocks, side)) {
      const std::size_t n = blocks.blocks[b].vertices.size();
      fixed_vertices.insert({b, static_cast<std::size_t>(k)});
      fixed_vertices.insert({b, (static_cast<std::size_t>(k) + 1) % n});
    }
    for (const auto& [b, k] : fixed_vertices)
      in.fixed_points.push_back({"boundary_" + side + "_" + std::to_string(b) + "_" + std::to_string(k),
                                 blocks.blocks[b].vertices[k], b, std::nullopt});
  }
}

// Dashpots on every domain-boundary edge of the given sides, free-field
// ones on those of `free_field_sides`; the edges of each side by index into
// in.viscous_boundary->edges. The base of the incident wave is the bottom
// of the model, the free surface of the free field the highest point of
// the free-field sides.
ViscousSides add_viscous_boundary(const BlockModel& blocks, const std::vector<std::string>& sides,
                                  const std::vector<std::string>& free_field_sides, ModelInput& in) {
  ViscousSides by_side;
  if (sides.empty() && free_field_sides.empty()) return by_side;
  ViscousBoundary v;
  v.base_y = std::numeric_limits<double>::infinity();
  v.surface_y = -v.base_y;
  for (const Block& b : blocks.blocks)
    for (const Vec2& p : b.vertices) v.base_y = std::min(v.base_y, p.y());
  for (const bool free_field : {false, true})
    for (const std::string& side : free_field ? free_field_sides : sides)
      for (const auto& [b, k] : side_edges(blocks, side)) {
        by_side[side].push_back(v.edges.size());
        v.edges.push_back({b, k, false, free_field});
        if (free_field) {
          const Polygon2& poly = blocks.blocks[b].vertices;
          v.surface_y = std::max({v.surface_y, poly[k].y(), poly[(k + 1) % poly.size()].y()});
        }
      }
  if (free_field_sides.empty()) v.surface_y = 0;
  in.viscous_boundary = std::move(v);
  return by_side;
}

// The measurement points `points` places on a block
// (scenario_block_points.hpp): by id or by the block containing a point.
void add_block_points(const YamlNode& root, const BlockModel& blocks, const std::string& blocks_path,
                      ModelInput& in) {
  // A point on an edge, in rounding, is on it: 1e-9 of the model's size.
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Block& b : blocks.blocks)
    for (const Vec2& v : b.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double tolerance = 1e-9 * (hi - lo).norm();
  BlockCatalogue<Vec2> catalogue;
  catalogue.path = blocks_path;
  catalogue.count = blocks.blocks.size();
  catalogue.origin = blocks.origin;
  catalogue.centroid = [&](std::size_t b) { return blocks.blocks[b].centroid; };
  catalogue.contains = [&](std::size_t b, const Vec2& p) {
    const Polygon2& poly = blocks.blocks[b].vertices;
    return point_in_polygon(poly, p) || distance_to_boundary(poly, p) <= tolerance;
  };
  std::vector<std::string> taken;
  for (const LocatedPoint& lp : blocks.points) taken.push_back(lp.point.name);
  for (const BlockPoint<Vec2>& p : place_block_points(root, catalogue, taken))
    in.measurements.push_back({p.name, p.position, p.block});
}

}  // namespace

bool scenario_has_df(const YamlNode& root) { return root.has("control"); }

void check_df_scenario(const YamlNode& root) {
  if (!has_any_df_section(root)) return;
  if (!root.has("control"))
    root.fail_key("control", "is required for a forward run (the scenario has materials, joints, loading or fixed)");
  parse(root);
  check_block_points(root, 2, {}, [](const YamlNode&) {});
}

void check_blocks_for_df(const BlockModel& blocks, const std::string& blocks_path,
                         const std::optional<YamlNode>& root) {
  if (blocks.blocks.empty())
    throw InputError(blocks_path + ": has no blocks, so there is nothing to run (did the excavations remove "
                                   "everything, or do the lines enclose no area?).");
  for (const LocatedPoint& lp : blocks.points) {
    if (lp.point.kind == PointKind::Hole || lp.block >= 0) continue;
    const std::string what = std::string(to_string(lp.point.kind)) + " point '" + lp.point.name + "'";
    if (root) {
      if (auto n = scenario_point(*root, lp.point.name)) n->fail_key("at", "(" + what + ") lies outside every block");
      if (root->has("geometry"))
        root->child("geometry").fail("holds the " + what + ", which lies outside every block");
    }
    const Vec2 at = user_position(lp.point.p, blocks.origin);  // as the user gave it
    throw InputError(blocks_path + ": the " + what + " at (" + std::to_string(at.x()) + ", " +
                     std::to_string(at.y()) + ") lies outside every block.");
  }
}

DfScenario read_df_scenario(const YamlNode& root, const BlockModel& blocks, const std::string& blocks_path) {
  if (!root.has("control"))
    root.fail_key("control", "is required for a forward run (it gives the run length)");
  Parsed p = parse(root);
  move_to_origin(p, blocks.origin);
  check_blocks_for_df(blocks, blocks_path, root);

  DfScenario out;
  ModelInput& in = out.input;
  in.geometry = blocks;
  in.control = p.control;
  in.gravity = p.gravity;
  in.water = p.water;
  out.output = p.output;

  // Materials: the first zone a block's centroid (or bed) falls in, else the default.
  in.materials.clear();
  for (const MaterialEntry& e : p.materials) in.materials.push_back(e.material);
  const std::vector<YamlNode> zone_nodes =
      root.has("materials") ? root.child("materials").list_or_empty("zones") : std::vector<YamlNode>{};
  std::vector<int> zone_blocks(p.zones.size(), 0);
  in.block_material.assign(blocks.blocks.size(), 0);
  for (std::size_t b = 0; b < blocks.blocks.size(); ++b) {
    const Block& blk = blocks.blocks[b];
    for (std::size_t z = 0; z < p.zones.size(); ++z) {
      const Zone& zone = p.zones[z];
      const bool inside = zone.layers ? (blk.layer >= zone.layers->first && blk.layer <= zone.layers->second)
                                      : point_in_polygon(*zone.polygon, blk.centroid);
      if (inside) {
        in.block_material[b] = static_cast<int>(z + 1);
        ++zone_blocks[z];
        break;
      }
    }
  }
  for (std::size_t z = 0; z < p.zones.size(); ++z) {
    if (p.zones[z].layers && blocks.layers.empty())
      zone_nodes[z].fail_key("layers", "selects beds, but the blocks are not layered");
    if (zone_blocks[z] == 0)
      zone_nodes[z].fail("selects no block (check its " + std::string(p.zones[z].layers ? "layers" : "polygon") +
                         ")");
  }
  bool any_initial = false;
  for (const MaterialEntry& e : p.materials) any_initial = any_initial || !e.stress.isZero() || !e.velocity.isZero();
  if (any_initial) {
    for (std::size_t b = 0; b < blocks.blocks.size(); ++b) {
      in.initial_stress.push_back(p.materials[in.block_material[b]].stress);
      in.initial_velocity.push_back(p.materials[in.block_material[b]].velocity);
    }
  }

  // Joints: one entry per joint set of the blocks file, named ones from the
  // scenario, the rest (and boundary, excavation, artificial edges) default.
  in.default_joint = p.joints.default_joint;
  in.joint_sets = joints_by_set(p.joints, blocks.sets, blocks_path);

  // Points: every fixed and measurement point of the blocks file; load
  // points take their force from loading.point_loads.
  std::map<std::string, Vec2> forces;
  std::set<std::string> load_points, fixed_points;
  for (const LocatedPoint& lp : blocks.points) {
    if (lp.point.kind == PointKind::Load) load_points.insert(lp.point.name);
    if (lp.point.kind == PointKind::Fixed) fixed_points.insert(lp.point.name);
  }
  for (const Parsed::Load& l : p.loads) {
    if (!load_points.count(l.point))
      l.node.fail_key("point", "names '" + l.point + "', which is not a load point of " + blocks_path +
                                   " (its load points are " +
                                   join_names(std::vector<std::string>(load_points.begin(), load_points.end())) + ")");
    if (forces.count(l.point)) l.node.fail_key("point", "gives a second load for point '" + l.point + "'");
    forces[l.point] = l.force;
  }
  for (const std::string& name : load_points)
    if (!forces.count(name)) {
      const std::string msg = "has no entry for load point '" + name + "' (add {point: " + name + ", force: [fx, fy]})";
      if (root.has("loading")) root.child("loading").fail_key("point_loads", msg);
      root.fail_key("loading", "is required: load point '" + name + "' needs a force in loading.point_loads");
    }
  add_points_from_block_model(blocks, forces, in);
  add_block_points(root, blocks, blocks_path, in);
  for (const Parsed::Load& l : p.loads)
    for (PointLoad& pl : in.loads)
      if (pl.name == l.point) pl.history = l.history;
  std::set<std::string> seen;
  for (const Parsed::Fix& f : p.fixes) {
    if (!fixed_points.count(f.point))
      f.node.fail_key("point", "names '" + f.point + "', which is not a fixed point of " + blocks_path +
                                   " (its fixed points are " +
                                   join_names(std::vector<std::string>(fixed_points.begin(), fixed_points.end())) + ")");
    if (!seen.insert(f.point).second) f.node.fail_key("point", "names fixed point '" + f.point + "' a second time");
    for (FixedPoint& fp : in.fixed_points)
      if (fp.name == f.point) fp.penalty = f.penalty, fp.history = f.displacement;
  }
  add_boundary_fixes(blocks, p.fixed_sides, in);
  if (!p.fixed_sides.empty() && in.fixed_points.empty() && p.fixed_boundary_node)
    p.fixed_boundary_node->fail("fixes nothing: no block has a domain-boundary edge on those sides");
  const bool incident = p.earthquake && p.earthquake->record.mode.route == GroundMotionRoute::incident_wave;
  require_incident_for_free_field(root, !p.free_field_sides.empty(), incident);
  const ViscousSides viscous = add_viscous_boundary(blocks, p.viscous_sides, p.free_field_sides, in);
  if (p.viscous_node && !in.viscous_boundary->edges.size())
    p.viscous_node->fail("holds nothing: no block has a domain-boundary edge on those sides");
  if (p.earthquake) {
    // The modes refine the record to the step: the step first.
    choose_time_step(in, shortest_interval(p.earthquake->record.motion.times()));
    apply_earthquake(*p.earthquake, p.fixed_sides, viscous, in);  // needs every fixed point
  }

  // Bolts: both ends must lie in blocks, and in different ones.
  for (const auto& [node, bolt] : p.bolts) {
    int ends[2] = {-1, -1};
    const char* keys[2] = {"from", "to"};
    const Vec2 pts[2] = {bolt.anchor, bolt.head};
    for (int e = 0; e < 2; ++e) {
      for (std::size_t b = 0; b < blocks.blocks.size() && ends[e] < 0; ++b)
        if (point_in_polygon(blocks.blocks[b].vertices, pts[e])) ends[e] = static_cast<int>(b);
      if (ends[e] < 0) node.fail_key(keys[e], "lies outside every block");
    }
    if (ends[0] == ends[1]) node.fail_key("to", "lies in the same block as `from` (a bolt must join two blocks)");
    in.bolts.push_back(bolt);
  }

  // Anything build_model still refuses is a scenario problem of the whole run.
  try {
    build_model(in);
  } catch (const InputError& e) {
    throw InputError(root.file() + ": " + e.what());
  }
  return out;
}

}  // namespace dda::df
