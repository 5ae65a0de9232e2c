// The forward-run sections of a 3D scenario into a Model3 (scenario3d.hpp).
// Keys, units and defaults are documented in docs/scenario.md ("The 3D
// forward run"); keep the two in step. The joints, the earthquake record and
// the run length are read by the same code as in 2D.
#include "dda/df/io/scenario3d.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "dda/common/coordinate_range.hpp"
#include "dda/common/error.hpp"
#include "dda/df/core/time_step.hpp"
#include "io/scenario3d_detail.hpp"
#include "io/scenario_block_points.hpp"
#include "io/scenario_bolts.hpp"
#include "io/scenario_control.hpp"
#include "io/scenario_joints.hpp"
#include "io/scenario_water.hpp"
#include "io/scenario_points.hpp"
#include "io/scenario_record.hpp"

namespace dda::df3 {
namespace {

using df::join_names;

struct Parsed3 {
  MaterialsSpec3 materials;
  df::JointsSection joints;
  Vec3 gravity{0, 0, -9.81};
  struct Load {
    YamlNode node;
    std::string point;
    TimeHistory3 force;
  };
  std::vector<Load> loads;
  std::optional<YamlNode> earthquake_node;
  GroundInput3 earthquake;
  FixedSpec3 fixed;
  df::RunLength run;
  int max_open_close = 10;
  std::string solver = "auto";
  bool initial_equilibrium = Control3{}.initial_equilibrium;
  bool contact_clusters = Control3{}.contact_clusters;
  df::ViscousDamping damping;
  std::optional<double> normal_penalty, shear_penalty, contact_reach;
  std::optional<df::WaterTable<3>> water;
};

GroundInput3 read_earthquake3(const YamlNode& n) {
  if (n.is_map() && n.has("foundation"))
    n.fail_key("foundation", "is a 2D key: in 3D the foundation is the fixed blocks (see fixed)");
  n.allow({"record", "units", "direction", "components", "scale", "resample", "filter", "ramp", "baseline", "mode"});
  df::EarthquakeRecord<3> r = df::read_earthquake_record<3>(n);
  return {std::make_shared<GroundMotion3>(std::move(r.motion)), &df::ground_motion_mode(r.mode.name)};
}

void read_loading3(const YamlNode& root, Parsed3& p) {
  const auto l = root.optional_child("loading");
  if (!l) return;
  l->allow({"gravity", "point_loads", "earthquake"});
  if (l->has("gravity")) {
    const YamlNode g = l->child("gravity");
    p.gravity = g.is_sequence() ? read_vec3(*l, "gravity") : Vec3(0, 0, -g.as_number(Range::non_negative()));
  }
  for (const YamlNode& item : l->list_or_empty("point_loads")) {
    item.allow({"point", "force", "history"});
    Parsed3::Load load{item, item.text("point"), {}};
    if (item.one_of({"force", "history"}) == "force") {
      load.force.t = {0.0};
      load.force.value = {read_vec3(item, "force")};
    } else {
      load.force = read_history3(item, "history");
    }
    p.loads.push_back(load);
  }
  if (l->has("earthquake")) {
    p.earthquake_node = l->child("earthquake");
    p.earthquake = read_earthquake3(*p.earthquake_node);
  }
}

void read_control3(const YamlNode& root, Parsed3& p) {
  const YamlNode c = root.child("control");
  std::vector<std::string> keys{"max_open_close", "normal_penalty", "shear_penalty", "contact_reach", "solver",
                                "initial_equilibrium", "contact_clusters", "damping"};
  keys.insert(keys.end(), std::begin(df::kRunLengthKeys), std::end(df::kRunLengthKeys));
  c.allow(keys);
  const Control3 defaults3;
  df::RunLength defaults;
  defaults.max_displacement_ratio = defaults3.max_displacement_ratio;
  defaults.min_dt_ratio = defaults3.min_dt_ratio;
  p.run = df::read_run_length(c, defaults);
  p.max_open_close = static_cast<int>(c.integer("max_open_close", p.max_open_close, Range::closed(1, 1000)));
  if (c.has("normal_penalty")) p.normal_penalty = c.number("normal_penalty", Range::positive());
  if (c.has("shear_penalty")) p.shear_penalty = c.number("shear_penalty", Range::positive());
  if (c.has("contact_reach")) p.contact_reach = c.number("contact_reach", Range::positive());
  p.solver = c.choice("solver", {"auto", "cholmod", "pcg"}, "auto");
  p.initial_equilibrium = c.flag("initial_equilibrium", Control3{}.initial_equilibrium);
  p.contact_clusters = c.flag("contact_clusters", Control3{}.contact_clusters);
  p.damping = df::read_damping(c);
}

Parsed3 parse(const YamlNode& root) {
  Parsed3 p;
  p.materials = read_materials3(root);
  p.joints = df::read_joints_section(root);  // the 2D keys, all of them (normal laws and penalties per set too)
  read_loading3(root, p);
  p.fixed = read_fixed3(root);
  read_control3(root, p);
  p.water = df::read_water<3>(root);
  df::read_bolt_entries<Vec3>(root, read_vec3);  // checked here, placed in blocks by add_bolts3
  read_viscous_sides3(root);  // boundaries (scenario3d_waves.cpp)
  return p;
}

bool has_any_df_section(const YamlNode& root) {
  for (const char* k : {"materials", "joints", "loading", "fixed", "water", "bolts", "boundaries", "control"})
    if (root.has(k)) return true;
  return false;
}

// Half the largest side of the blocks' bounding box: the reference length
// of the step's displacement limit (as Simulation3 takes it).
double reference_length(const std::vector<Polyhedron>& blocks) {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Polyhedron& b : blocks)
    for (const Vec3& v : b.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  return blocks.empty() ? 1.0 : 0.5 * (hi - lo).maxCoeff();
}

// Young's modulus times the size of a typical moving block (the cube root of
// the free blocks' mean volume): a contact spring about as stiff as the
// blocks it joins. With zones, the largest modulus of the free blocks (as
// 2D takes the largest of its materials): a spring softer than the stiffest
// block would let that block sink into its neighbours further than it
// deforms itself; fixed blocks do not deform at all, so theirs does not count.
double default_normal_penalty(const Model3& m) {
  double volume = 0, young = 0;
  int count = 0;
  for (std::size_t b = 0; b < m.blocks.size(); ++b)
    if (!m.fixed[b]) volume += m.blocks[b].volume, ++count, young = std::max(young, m.material_of(b).young);
  if (count == 0) young = m.materials.front().young;  // not reached: fixing every block is refused
  return young * std::cbrt(count > 0 ? volume / count : 1.0);
}

// Point p lies inside (or on) every face plane of the convex block, within
// `tolerance` (m).
bool block_holds(const Polyhedron& poly, const Vec3& p, double tolerance) {
  if (poly.faces.empty()) return false;
  for (const PolyFace& f : poly.faces) {
    if (f.vertices.empty()) continue;
    const Vec3& on = poly.vertices[static_cast<std::size_t>(f.vertices.front())];
    if (f.normal.dot(p - on) > tolerance) return false;
  }
  return true;
}

// The keys a point placed by block may select with besides an id and
// `containing`: those of `fixed` but `blocks` (an id is `block: ID`).
const std::vector<std::string> kPointSelectionKeys{"bodies", "below", "box", "outside", "removability"};

// The measurement points `points` places on a block (scenario_block_points.hpp).
void add_block_points(const YamlNode& root, const PolyhedronModel& blocks, const std::string& blocks_path,
                      double tolerance, Model3& m) {
  df::BlockCatalogue<Vec3> catalogue;
  catalogue.path = blocks_path;
  catalogue.count = blocks.blocks.size();
  catalogue.origin = blocks.origin;
  catalogue.centroid = [&](std::size_t b) { return blocks.blocks[b].centroid; };
  catalogue.contains = [&](std::size_t b, const Vec3& p) { return block_holds(blocks.blocks[b], p, tolerance); };
  catalogue.selection_keys = kPointSelectionKeys;
  catalogue.select = [&](const YamlNode& n) {
    return select_blocks(read_block_selection(n), n, blocks, blocks_path);
  };
  std::vector<std::string> taken;
  for (const ModelPoint3& pt : blocks.points) taken.push_back(pt.name);
  for (const df::BlockPoint<Vec3>& p : df::place_block_points(root, catalogue, taken))
    m.measurements.push_back({p.name, p.block, p.position});
}

// Measurement, fixed and load points of the blocks file, each in the block
// that holds it, then the measurement points the scenario places by block.
void add_points(const Parsed3& p, const YamlNode& root, const PolyhedronModel& blocks, const std::string& blocks_path,
                Model3& m) {
  const double tolerance = 1e-9 * reference_length(blocks.blocks);
  std::map<std::string, const Parsed3::Load*> loads;
  std::set<std::string> load_names, fixed_names;
  for (const ModelPoint3& pt : blocks.points) {
    if (pt.kind == PointKind::Load) load_names.insert(pt.name);
    if (pt.kind == PointKind::Fixed) fixed_names.insert(pt.name);
  }
  for (const Parsed3::Load& l : p.loads) {
    if (!load_names.count(l.point))
      l.node.fail_key("point", "names '" + l.point + "', which is not a load point of " + blocks_path +
                                   " (its load points are " +
                                   join_names(std::vector<std::string>(load_names.begin(), load_names.end())) + ")");
    if (loads.count(l.point)) l.node.fail_key("point", "gives a second load for point '" + l.point + "'");
    loads[l.point] = &l;
  }
  std::map<std::string, const FixedSpec3::Point*> settings;
  for (const FixedSpec3::Point& f : p.fixed.points) {
    if (!fixed_names.count(f.point))
      f.node.fail_key("point", "names '" + f.point + "', which is not a fixed point of " + blocks_path +
                                   " (its fixed points are " +
                                   join_names(std::vector<std::string>(fixed_names.begin(), fixed_names.end())) + ")");
    if (settings.count(f.point)) f.node.fail_key("point", "names fixed point '" + f.point + "' a second time");
    settings[f.point] = &f;
  }

  for (const ModelPoint3& pt : blocks.points) {
    if (pt.kind == PointKind::Hole) continue;
    const std::string what = std::string(to_string(pt.kind)) + " point '" + pt.name + "'";
    const std::optional<YamlNode> placed = df::scenario_point(root, pt.name);
    const int b = block_containing(blocks.blocks, pt.p, tolerance);
    if (b < 0) {
      if (placed) placed->fail_key("at", "(" + what + ") lies outside every block");
      const Vec3 at = user_position(pt.p, blocks.origin);  // as the user gave it
      throw InputError(blocks_path + ": the " + what + " at (" + std::to_string(at.x()) + ", " +
                       std::to_string(at.y()) + ", " + std::to_string(at.z()) + ") lies outside every block.");
    }
    const bool held = m.fixed[static_cast<std::size_t>(b)];
    const std::string in_fixed = "lies in block " + std::to_string(b) + ", which is fixed, so ";
    if (pt.kind == PointKind::Measurement) {
      m.measurements.push_back({pt.name, b, pt.p});
    } else if (pt.kind == PointKind::Load) {
      const auto it = loads.find(pt.name);
      if (it == loads.end()) {
        const std::string msg = "has no entry for load point '" + pt.name + "' (add {point: " + pt.name +
                                ", force: [fx, fy, fz]})";
        if (root.has("loading")) root.child("loading").fail_key("point_loads", msg);
        root.fail_key("loading", "is required: load point '" + pt.name + "' needs a force in loading.point_loads");
      }
      if (held) it->second->node.fail_key("point", "names '" + pt.name + "', which " + in_fixed + "its load would do nothing");
      m.loads.push_back({b, pt.p, it->second->force});
    } else {  // fixed
      const auto it = settings.find(pt.name);
      const FixedSpec3::Point* s = it == settings.end() ? nullptr : it->second;
      if (held) {
        // A point spring on a block that has no unknowns adds nothing; a
        // moving one would be ignored, which the user must hear about.
        if (s && s->displacement)
          s->node.fail_key("displacement", "moves point '" + pt.name + "', which " + in_fixed + "it cannot move");
        continue;
      }
      FixedPoint3 fp;
      fp.block = b;
      fp.position = pt.p;
      if (s) fp.penalty = s->penalty, fp.motion = s->displacement;
      m.fixed_points.push_back(fp);
    }
  }
  add_block_points(root, blocks, blocks_path, tolerance, m);
}

}  // namespace

Vec3 read_vec3(const YamlNode& n, const std::string& key) {
  const YamlNode c = n.child(key);
  const std::vector<double> v = c.as_numbers();
  if (v.size() != 3) c.fail("must be [x, y, z] (three numbers), got " + std::to_string(v.size()));
  for (double x : v)
    if (!std::isfinite(x)) c.fail("must hold finite numbers");
  return {v[0], v[1], v[2]};
}

TimeHistory3 read_history3(const YamlNode& n, const std::string& key) {
  TimeHistory3 h;
  const std::vector<YamlNode> rows = n.list(key);
  if (rows.empty()) n.fail_key(key, "must hold at least one row [t, x, y, z]");
  for (const YamlNode& row : rows) {
    const std::vector<double> v = row.as_numbers();
    if (v.size() != 4) row.fail("must be a row [t, x, y, z] of four numbers, got " + std::to_string(v.size()));
    for (double x : v)
      if (!std::isfinite(x)) row.fail("must hold finite numbers");
    if (!h.t.empty() && v[0] <= h.t.back())
      row.fail("must come later than the row before it (times must increase), got t = " + std::to_string(v[0]));
    h.t.push_back(v[0]);
    h.value.emplace_back(v[1], v[2], v[3]);
  }
  return h;
}

int block_containing(const std::vector<Polyhedron>& blocks, const Vec3& p, double tolerance) {
  for (std::size_t b = 0; b < blocks.size(); ++b)
    if (block_holds(blocks[b], p, tolerance)) return static_cast<int>(b);
  return -1;
}

void check_df3_scenario(const YamlNode& root) {
  if (!has_any_df_section(root)) return;
  if (!root.has("control"))
    root.fail_key("control", "is required for a forward run (the scenario has materials, joints, loading or fixed)");
  parse(root);
  df::check_block_points(root, 3, kPointSelectionKeys, [](const YamlNode& n) { read_block_selection(n); });
}

DfScenario3 read_df3_scenario(const YamlNode& root, const PolyhedronModel& blocks, const std::string& blocks_path) {
  if (!root.has("control"))
    root.fail_key("control", "is required for a forward run (it gives the run length)");
  const Parsed3 p = parse(root);
  if (blocks.blocks.empty())
    throw InputError(blocks_path + ": has no blocks, so there is nothing to run (did the excavations remove "
                                   "everything?).");
  DfScenario3 out;
  Model3& m = out.model;
  m.blocks = blocks.blocks;
  // Positions the scenario gives (water table, bolts' ends, `at`, levels
  // and boxes of selections) are in the user's coordinates: each reader
  // below takes them about the blocks' local origin (coordinate_range.hpp).
  m.origin = blocks.origin;
  m.default_joint = p.joints.default_joint;
  m.joint_sets = df::joints_by_set(p.joints, blocks.sets, blocks_path);
  m.gravity = p.gravity;
  m.water = p.water;
  if (m.water) m.water->move_to_origin(m.origin);
  m.fixed = select_fixed_blocks(p.fixed, blocks, blocks_path);
  assign_materials3(p.materials, blocks, blocks_path, m);  // after m.fixed: fixed blocks start at rest
  add_points(p, root, blocks, blocks_path, m);
  add_bolts3(root, m.blocks, 1e-9 * reference_length(m.blocks), m);
  if (p.earthquake_node) {
    const bool any_fixed = std::find(m.fixed.begin(), m.fixed.end(), true) != m.fixed.end();
    if (!any_fixed && p.earthquake.mode->route == df::GroundMotionRoute::foundation)
      p.earthquake_node->fail_key("mode", "displacement moves the fixed blocks (the foundation), but fixed holds no "
                                          "block");
    m.earthquake = p.earthquake;
  }
  Control3& c = m.control;
  c.dt = p.run.dt;
  if (c.dt == 0) {  // not given: from the free blocks and the earthquake record (time_step.hpp)
    std::vector<df::BlockCrossing> crossings;
    for (std::size_t b = 0; b < m.blocks.size(); ++b)
      if (!m.fixed[b]) {
        const Material3& mat = m.material_of(b);
        crossings.push_back({std::cbrt(m.blocks[b].volume), df::p_wave_speed(mat.young, mat.poisson, mat.density, false)});
      }
    const double record = m.earthquake.motion ? df::shortest_interval(m.earthquake.motion->times()) : 0.0;
    const df::TimeStepChoice choice = df::default_time_step(crossings, record);
    c.dt = choice.dt;
    c.dt_basis = choice.basis;
  }
  c.total_time = p.run.total_time;
  c.steps = p.run.steps;
  c.max_displacement_ratio = p.run.max_displacement_ratio;
  c.min_dt_ratio = p.run.min_dt_ratio;
  c.solver = p.solver;
  c.initial_equilibrium = p.initial_equilibrium;
  c.contact_clusters = p.contact_clusters;
  c.damping = p.damping;
  add_viscous_boundary3(root, blocks, blocks_path, m);  // after the earthquake and dt
  m.max_iterations = p.max_open_close;
  m.normal_penalty = p.normal_penalty ? *p.normal_penalty : default_normal_penalty(m);
  m.shear_penalty = p.shear_penalty ? *p.shear_penalty : m.normal_penalty;
  // As in 2D: the contacts a step can reach, 2.5 times the largest step.
  m.contact_reach = p.contact_reach ? *p.contact_reach : 2.5 * c.max_displacement_ratio * reference_length(m.blocks);
  out.output = p.run.output;

  // Anything the solver still refuses is a scenario problem of the whole run.
  try {
    Simulation3 check(m);
  } catch (const InputError& e) {
    throw InputError(root.file() + ": " + e.what());
  }
  return out;
}

df::OutputSchedule resolve_output_schedule(df::OutputSchedule s, const Control3& control) {
  return df::resolve_output_schedule(s, control.total_time, control.steps);
}

}  // namespace dda::df3
