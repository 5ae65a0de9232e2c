// Validation of the forward-solver input and resolution of its defaults.
#include "dda/df/2d/model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/df/core/friction.hpp"
#include "dda/df/core/normal_law.hpp"
#include "dda/df/core/time_step.hpp"

namespace dda::df {
namespace {

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void require(bool ok, const std::string& sentence) {
  if (!ok) throw InputError(sentence);
}

bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

// Block containing p, or -1. A point on a shared edge goes to the first block.
int locate(const std::vector<Block>& blocks, const Vec2& p) {
  for (std::size_t b = 0; b < blocks.size(); ++b)
    if (point_in_polygon(blocks[b].vertices, p)) return static_cast<int>(b);
  return -1;
}

// Resolves `block` for a point: checks a given index, or finds the block.
int resolve_block(const std::vector<Block>& blocks, int block, const Vec2& p, const std::string& what) {
  require(finite(p), what + " has a position that is not a finite number.");
  if (block >= 0) {
    require(block < static_cast<int>(blocks.size()),
            what + " refers to block " + std::to_string(block) + " but the model has " +
                std::to_string(blocks.size()) + " blocks.");
    return block;
  }
  const int b = locate(blocks, p);
  require(b >= 0, what + " at (" + num(p.x()) + ", " + num(p.y()) + ") lies outside every block.");
  return b;
}

void check_material(const Material& m, std::size_t i) {
  const std::string w = "material " + std::to_string(i);
  require(std::isfinite(m.density) && m.density > 0, w + " has a non-positive density (" + num(m.density) + " kg/m^3).");
  require(std::isfinite(m.young) && m.young > 0, w + " has a non-positive Young's modulus (" + num(m.young) + " Pa).");
  require(std::isfinite(m.poisson) && m.poisson > -1 && m.poisson < 0.5,
          w + " has a Poisson's ratio outside (-1, 0.5) (" + num(m.poisson) + ").");
}

void check_joint(const JointProperties& j, const std::string& w) {
  require(std::isfinite(j.friction_deg) && j.friction_deg >= 0 && j.friction_deg < 90,
          w + " has a friction angle outside [0, 90) degrees (" + num(j.friction_deg) + ").");
  require(std::isfinite(j.cohesion) && j.cohesion >= 0, w + " has a negative cohesion (" + num(j.cohesion) + " Pa).");
  require(std::isfinite(j.tensile_strength) && j.tensile_strength >= 0,
          w + " has a negative tensile strength (" + num(j.tensile_strength) + " Pa).");
  require(!j.normal_penalty || (std::isfinite(*j.normal_penalty) && *j.normal_penalty > 0),
          w + " has a non-positive normal penalty.");
  require(!j.shear_penalty || (std::isfinite(*j.shear_penalty) && *j.shear_penalty > 0),
          w + " has a non-positive shear penalty.");
  make_friction_law(j);  // throws for an unknown law name
  make_normal_law(j, 1.0);  // throws for an unknown law or a bad parameter
}

void check_control(const Control& c) {
  require(std::isfinite(c.dt) && c.dt >= 0,
          "The time step dt must be positive, or 0 to take it from the model (got " + num(c.dt) + " s).");
  require(std::isfinite(c.total_time) && c.total_time >= 0, "The total time must not be negative.");
  require(c.steps >= 0, "The number of steps must not be negative.");
  require(std::isfinite(c.max_displacement_ratio) && c.max_displacement_ratio > 0 && c.max_displacement_ratio < 1,
          "The maximum displacement ratio g2 must lie in (0, 1) (got " + num(c.max_displacement_ratio) + ").");
  require(!c.w0 || (std::isfinite(*c.w0) && *c.w0 > 0), "The reference length w0 must be positive.");
  require(std::isfinite(c.dynamic) && c.dynamic >= 0 && c.dynamic <= 1,
          "The dynamic parameter k must lie in [0, 1] (got " + num(c.dynamic) + ").");
  require(c.max_open_close >= 1, "The open-close iteration limit must be at least 1.");
  require(std::isfinite(c.penalty_factor) && c.penalty_factor > 0, "The penalty factor must be positive.");
  require(std::isfinite(c.shear_ratio) && c.shear_ratio > 0, "The shear penalty ratio must be positive.");
  require(std::isfinite(c.fixed_penalty_factor) && c.fixed_penalty_factor > 0,
          "The fixed-point penalty factor must be positive.");
  require(std::isfinite(c.min_dt_ratio) && c.min_dt_ratio > 0 && c.min_dt_ratio <= 1,
          "The smallest time-step ratio must lie in (0, 1].");
}

void check_history(const std::optional<TimeHistory>& h, const std::string& what) {
  if (!h) return;
  require(!h->t.empty(), what + " has an empty time history.");
  require(h->t.size() == h->value.size(), what + " has a time history with " + std::to_string(h->t.size()) +
                                              " times but " + std::to_string(h->value.size()) + " values.");
  require(h->rate.empty() || h->rate.size() == h->t.size(),
          what + " has a time history with " + std::to_string(h->rate.size()) + " rates for " +
              std::to_string(h->t.size()) + " times.");
  for (const Vec2& r : h->rate) require(finite(r), what + " has a time history rate that is not a finite number.");
  for (std::size_t k = 0; k < h->t.size(); ++k) {
    require(std::isfinite(h->t[k]) && finite(h->value[k]),
            what + " has a time history entry that is not a finite number (row " + std::to_string(k + 1) + ").");
    require(k == 0 || h->t[k] > h->t[k - 1],
            what + " has time history times that do not increase (row " + std::to_string(k + 1) + ").");
  }
}

}  // namespace

void add_points_from_block_model(const BlockModel& geometry, const std::map<std::string, Vec2>& load_forces,
                                 ModelInput& input) {
  for (const LocatedPoint& lp : geometry.points) {
    const ModelPoint& p = lp.point;
    switch (p.kind) {
      case PointKind::Fixed:
        input.fixed_points.push_back({p.name, p.p, lp.block, std::nullopt});
        break;
      case PointKind::Measurement:
        input.measurements.push_back({p.name, p.p, lp.block});
        break;
      case PointKind::Load: {
        const auto it = load_forces.find(p.name);
        require(it != load_forces.end(), "Load point '" + p.name + "' has no force.");
        input.loads.push_back({p.name, p.p, it->second, lp.block});
        break;
      }
      case PointKind::Hole:
        break;  // consumed by the cutter
    }
  }
}

void choose_time_step(ModelInput& in, double record_interval) {
  if (in.control.dt != 0) return;
  std::vector<BlockCrossing> blocks;
  for (std::size_t b = 0; b < in.geometry.blocks.size(); ++b) {
    const std::size_t k = in.block_material.empty() ? 0 : static_cast<std::size_t>(in.block_material[b]);
    if (k >= in.materials.size()) continue;  // build_model says what is wrong with it
    const Material& mat = in.materials[k];
    blocks.push_back({std::sqrt(std::max(0.0, signed_area(in.geometry.blocks[b].vertices))),
                      p_wave_speed(mat.young, mat.poisson, mat.density, mat.plane == PlaneMode::Stress)});
  }
  // The loading tables' shortest sample interval (0: none).
  double interval = record_interval;
  auto take = [&](const std::vector<double>& t) {
    const double d = shortest_interval(t);
    if (d > 0) interval = interval > 0 ? std::min(interval, d) : d;
  };
  for (const FixedPoint& f : in.fixed_points)
    if (f.history) take(f.history->t);
  for (const PointLoad& l : in.loads)
    if (l.history) take(l.history->t);
  if (in.body_acceleration) take(in.body_acceleration->history.t);
  if (in.viscous_boundary) take(in.viscous_boundary->incident_velocity.t);
  const TimeStepChoice choice = default_time_step(blocks, interval);
  in.control.dt = choice.dt;
  in.control.dt_basis = choice.basis;
}

Model build_model(ModelInput in) {
  Model m;
  require(!in.geometry.blocks.empty(), "The model has no blocks.");
  const std::size_t nb = in.geometry.blocks.size();
  for (std::size_t b = 0; b < nb; ++b) {
    Block blk = in.geometry.blocks[b];
    require(blk.vertices.size() >= 3, "Block " + std::to_string(b) + " has fewer than three vertices.");
    for (const Vec2& v : blk.vertices) require(finite(v), "Block " + std::to_string(b) + " has a vertex that is not a finite number.");
    require(signed_area(blk.vertices) > 0,
            "Block " + std::to_string(b) + " is not counter-clockwise or has no area.");
    if (blk.edge_set.size() != blk.vertices.size()) blk.edge_set.assign(blk.vertices.size(), kBoundarySet);
    m.blocks.push_back(std::move(blk));
  }

  require(!in.materials.empty(), "The model has no material.");
  for (std::size_t i = 0; i < in.materials.size(); ++i) check_material(in.materials[i], i);
  m.origin = in.geometry.origin;
  m.materials = in.materials;
  if (in.block_material.empty()) in.block_material.assign(nb, 0);
  require(in.block_material.size() == nb, "The block material list has " + std::to_string(in.block_material.size()) +
                                              " entries for " + std::to_string(nb) + " blocks.");
  for (std::size_t b = 0; b < nb; ++b)
    require(in.block_material[b] >= 0 && in.block_material[b] < static_cast<int>(in.materials.size()),
            "Block " + std::to_string(b) + " refers to material " + std::to_string(in.block_material[b]) +
                ", which does not exist.");
  m.block_material = in.block_material;

  check_control(in.control);
  for (std::size_t j = 0; j < in.joint_sets.size(); ++j) check_joint(in.joint_sets[j], "Joint set " + std::to_string(j));
  check_joint(in.default_joint, "The default joint");
  m.joints = in.joint_sets;
  m.joints.push_back(in.default_joint);

  // Penalties: one global default, pn = factor * (largest E) per unit
  // thickness (the classic DDA choice of 10-100 E), ps = ratio * pn.
  double emax = 0;
  for (const Material& mat : m.materials) emax = std::max(emax, mat.young);
  const double pn_default = in.control.penalty_factor * emax;
  for (const JointProperties& j : m.joints) {
    const double pn = j.normal_penalty.value_or(pn_default);
    m.joint_pn.push_back(pn);
    m.joint_ps.push_back(j.shear_penalty.value_or(in.control.shear_ratio * pn));
  }

  require(finite(in.gravity), "The gravity vector is not a finite number.");
  m.gravity = in.gravity;

  for (FixedPoint f : in.fixed_points) {
    f.block = resolve_block(m.blocks, f.block, f.position, "Fixed point '" + f.name + "'");
    require(!f.penalty || (std::isfinite(*f.penalty) && *f.penalty > 0),
            "Fixed point '" + f.name + "' has a non-positive penalty.");
    if (!f.penalty) f.penalty = in.control.fixed_penalty_factor * pn_default;
    check_history(f.history, "Fixed point '" + f.name + "'");
    m.fixed_points.push_back(f);
  }
  for (PointLoad l : in.loads) {
    l.block = resolve_block(m.blocks, l.block, l.position, "Load point '" + l.name + "'");
    require(finite(l.force), "Load point '" + l.name + "' has a force that is not a finite number.");
    check_history(l.history, "Load point '" + l.name + "'");
    m.loads.push_back(l);
  }
  if (in.body_acceleration) {
    BodyAcceleration b = *in.body_acceleration;
    check_history(b.history, "The body acceleration (earthquake, loading mode)");
    std::sort(b.blocks.begin(), b.blocks.end());
    b.blocks.erase(std::unique(b.blocks.begin(), b.blocks.end()), b.blocks.end());
    for (const int i : b.blocks)
      require(i >= 0 && i < static_cast<int>(nb), "The body acceleration acts on block " + std::to_string(i) +
                                                      " but the model has " + std::to_string(nb) + " blocks.");
    m.body_acceleration = std::move(b);
  }
  if (in.viscous_boundary) {
    ViscousBoundary v = *in.viscous_boundary;
    require(!v.edges.empty(), "The viscous boundary has no edges.");
    for (const ViscousEdge& e : v.edges) {
      require(e.block >= 0 && e.block < static_cast<int>(nb),
              "A viscous boundary edge belongs to block " + std::to_string(e.block) + " but the model has " +
                  std::to_string(nb) + " blocks.");
      require(e.edge >= 0 && e.edge < static_cast<int>(m.blocks[e.block].vertices.size()),
              "A viscous boundary edge of block " + std::to_string(e.block) + " has index " +
                  std::to_string(e.edge) + ", which the block does not have.");
    }
    if (!v.incident_velocity.t.empty()) {
      std::optional<TimeHistory> h = v.incident_velocity;
      check_history(h, "The incident wave of the viscous boundary");
      require(std::any_of(v.edges.begin(), v.edges.end(), [](const ViscousEdge& e) { return e.input; }),
              "The viscous boundary has an incident wave but no edge it enters through.");
    }
    m.viscous_boundary = std::move(v);
  }
  for (Bolt b : in.bolts) {
    const std::string w = "Bolt '" + b.name + "'";
    b.anchor_block = resolve_block(m.blocks, b.anchor_block, b.anchor, w + " (anchor)");
    b.head_block = resolve_block(m.blocks, b.head_block, b.head, w + " (head)");
    require(b.anchor_block != b.head_block, w + " has both ends in block " + std::to_string(b.head_block) + ".");
    require((b.head - b.anchor).norm() > 0, w + " has zero length.");
    require(std::isfinite(b.stiffness) && b.stiffness > 0, w + " has a non-positive stiffness (" + num(b.stiffness) + " N/m).");
    require(std::isfinite(b.pretension) && b.pretension >= 0, w + " has a negative pretension (" + num(b.pretension) + " N).");
    require(!b.breaking_force || (std::isfinite(*b.breaking_force) && *b.breaking_force > 0),
            w + " has a non-positive breaking force.");
    m.bolts.push_back(b);
  }
  if (in.water) {
    const WaterTable<2>& w = *in.water;
    require(std::isfinite(w.unit_weight) && w.unit_weight >= 0,
            "The unit weight of water must be >= 0, got " + num(w.unit_weight) + " N/m^3.");
    require(std::isfinite(w.level), "The water level is not a finite number.");
    for (std::size_t k = 1; k < w.knots.size(); ++k)
      require(w.knots[k].x() > w.knots[k - 1].x(), "The water surface's points must have increasing x.");
    for (const JointProperties& j : m.joints)
      require(j.saturation >= 0 && j.saturation <= 1, "A joint saturation is outside [0, 1].");
    m.water = w;
  }
  for (MeasurementPoint p : in.measurements) {
    p.block = resolve_block(m.blocks, p.block, p.position, "Measurement point '" + p.name + "'");
    m.measurements.push_back(p);
  }

  if (in.initial_velocity.empty()) in.initial_velocity.assign(nb, Vector6d::Zero());
  require(in.initial_velocity.size() == nb, "The initial velocity list must have one entry per block.");
  for (const Vector6d& v : in.initial_velocity)
    require(v.allFinite(), "An initial block velocity is not a finite number.");
  m.initial_velocity = in.initial_velocity;
  if (in.initial_stress.empty()) in.initial_stress.assign(nb, Vector3d::Zero());
  require(in.initial_stress.size() == nb, "The initial stress list must have one entry per block.");
  for (const Vector3d& v : in.initial_stress) require(v.allFinite(), "An initial block stress is not a finite number.");
  m.initial_stress = in.initial_stress;

  // w0: half the model height unless given; it scales the displacement limit
  // and the contact search distance (2.5 times the allowed step movement).
  if (!in.control.w0) {
    double lo = m.blocks[0].vertices[0].y(), hi = lo;
    for (const Block& b : m.blocks)
      for (const Vec2& v : b.vertices) lo = std::min(lo, v.y()), hi = std::max(hi, v.y());
    in.control.w0 = 0.5 * (hi - lo);
  }
  choose_time_step(in);
  m.control = in.control;
  m.search_distance = 2.5 * m.control.max_displacement_ratio * *m.control.w0;
  m.contact_tolerance = 1e-12 * *m.control.w0;
  m.contact_update_tolerance = 1e-3 * m.contact_tolerance;
  return m;
}

}  // namespace dda::df
