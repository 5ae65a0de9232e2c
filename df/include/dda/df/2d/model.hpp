#pragma once
// Input of the 2D forward solver: blocks plus everything physical about them.
//
// A ModelInput is filled by the caller (later: the scenario reader) and turned
// into a validated Model by build_model(), which resolves every default
// (penalties, w0), locates points in blocks and throws InputError with one
// sentence for anything a user could have got wrong. The solver only ever sees
// a Model, so it never re-checks input.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dda/df/core/joint_properties.hpp"
#include "dda/common/block_model.hpp"
#include "dda/df/core/damping.hpp"
#include "dda/df/core/types.hpp"
#include "dda/df/core/water.hpp"

namespace dda::df {

enum class PlaneMode { Stress, Strain };

// Elastic rock of a block, per unit thickness.
struct Material {
  double density = 2600;   // kg/m^3
  double young = 1e9;      // Pa
  double poisson = 0.25;
  PlaneMode plane = PlaneMode::Strain;
};

// A piecewise-linear table of a 2D quantity against time: (t_k, x_k, y_k),
// t strictly increasing. Before the first time it holds the first value,
// after the last the last one (a load stays on, a moving point stops).
// Implemented in df/src/2d/time_history.cpp; build_model() checks it.
//
// With `rate` (the derivative at each row, e.g. the ground velocity of an
// earthquake's displacement table) the table is a C1 cubic Hermite curve
// between the rows instead, and before the first row / after the last it
// continues along the first / last rate. A DDA block pulled along a
// moving point follows the point's velocity only if the point moves
// smoothly: a piecewise-linear path changes velocity abruptly at the rows,
// and where the rows do not coincide with step ends the block's velocity
// (v1 = 2 d / dt - v0) starts an undamped step-to-step ripple.
struct TimeHistory {
  std::vector<double> t;             // s, strictly increasing, at least one entry
  std::vector<Vec2> value;           // one per time (N for loads, m for displacements)
  std::vector<Vec2> rate{};          // empty, or one per time: d value / dt

  Vec2 at(double time) const;        // linear (or Hermite) interpolation
  // Mean value over [t0, t1] (exact integral of the table divided by
  // t1 - t0); at(t0) when t1 <= t0.
  Vec2 average(double t0, double t1) const;
};

// A point of a block held by a penalty spring at its initial position, or,
// with a history, at initial position + u(t) (a moving fixed point: the
// prescribed displacement table t, ux, uy; piecewise linear).
struct FixedPoint {
  std::string name;
  Vec2 position{0, 0};
  int block = -1;                    // -1: the block containing `position`
  std::optional<double> penalty;     // N/m; default Control::fixed_penalty_factor * pn
  std::optional<TimeHistory> history = std::nullopt;  // prescribed displacement u(t), m
};

// A force applied at a material point of a block (it moves with it):
// `force`, or, with a history, the table t, fx, fy (piecewise linear; each
// step applies the table's mean over the step, so a ramp is integrated exactly).
struct PointLoad {
  std::string name;
  Vec2 position{0, 0};
  Vec2 force{0, 0};                  // N per unit thickness
  int block = -1;
  std::optional<TimeHistory> history = std::nullopt;  // force F(t), N; replaces `force`
};

// A body acceleration b(t) (m/s^2) added to gravity on some blocks only: an
// earthquake in loading mode puts b = -a_g(t) here for every block outside
// the foundation (ground_motion.hpp). Each step applies the mean of the
// table over the step (a piecewise-linear record is integrated exactly).
struct BodyAcceleration {
  TimeHistory history;               // b(t), m/s^2; give zero rows to end it (the last value is held)
  std::vector<int> blocks;           // the blocks it acts on
};

// Non-reflecting boundary (viscous_boundary.hpp): Lysmer-Kuhlemeyer
// dashpots on edges of the model's outer boundary, of the material of the
// block they belong to, and optionally an incident wave entering through
// some of them (a compliant base for seismic input).
struct ViscousEdge {
  int block = -1;
  int edge = -1;                     // vertex edge -> edge + 1 of the block
  bool input = false;                // the incident wave enters here
  bool free_field = false;           // a lateral edge: dashpots relative to the incident wave's free field
};
struct ViscousBoundary {
  std::vector<ViscousEdge> edges;
  // v_in(t), m/s, model axes: particle velocity of the incident wave (half
  // the outcrop motion). No rows: no incident wave.
  TimeHistory incident_velocity;
  // Heights of the base the wave enters through and of the free surface
  // above the free-field edges (viscous_boundary.hpp), m.
  double base_y = 0, surface_y = 0;
};

// Where a fixed point's spring pulls it at time t: its initial position
// `anchor`, plus u(t) for a moving one.
Vec2 fixed_point_target(const FixedPoint& f, const Vec2& anchor, double t);
// The force a load applies over the step [t0, t1] (its table's mean there).
Vec2 load_force(const PointLoad& l, double t0, double t1);

// A rock bolt: an elastic bar between a point of one block (the anchor) and
// a point of another; both ends ride with their blocks. Its axial force,
// tension positive, is T = pretension + stiffness * (L - L0), L the current
// and L0 the initial length, acting along the current bolt direction (it
// pushes back when compressed below L0 - pretension / stiffness). Once T
// exceeds the breaking force the bolt breaks, for ever. See bolts.hpp.
struct Bolt {
  std::string name;
  Vec2 anchor{0, 0};                 // end in `anchor_block`
  Vec2 head{0, 0};                   // end in `head_block`
  int anchor_block = -1;             // -1: the block containing the point
  int head_block = -1;
  double stiffness = 0;              // N/m per unit thickness, > 0
  double pretension = 0;             // N, >= 0, the force at the initial length
  std::optional<double> breaking_force;  // N; none: never breaks
};

// A material point whose history is recorded every step.
struct MeasurementPoint {
  std::string name;
  Vec2 position{0, 0};
  int block = -1;
};

struct Control {
  double dt = 0;                     // s, the largest (and first) time step; 0: from the model (time_step.hpp)
  std::string dt_basis;              // choose_time_step: why the model chose dt (empty when it was given)
  double total_time = 0;             // s; run() stops here (or after `steps`)
  int steps = 0;                     // used by run() when total_time is 0
  double max_displacement_ratio = 0.01;  // g2: no vertex moves more than g2 * w0 per step
  std::optional<double> w0;          // m; default half the model height
  double dynamic = 1.0;              // k in [0, 1]: fraction of the end velocity carried on
  ViscousDamping damping;            // of the blocks' deformation (damping.hpp); none by default
  int max_open_close = 6;            // open-close iterations before dt is cut
  // Settle state changes on the blocks around them between global solves
  // (contact_clusters.hpp); false: every iterate solves the whole system.
  // With it, the tunnel-roof example runs at its dt with the default 6
  // iterations; without, its dt was cut to 1e-4 s (docs/solver2d.md).
  bool contact_clusters = true;
  double penalty_factor = 50;        // default pn = penalty_factor * largest E (unit thickness)
  double shear_ratio = 1.0;          // default ps = shear_ratio * pn
  double fixed_penalty_factor = 10;  // default fixed-point penalty = factor * pn
  double min_dt_ratio = 1e-3;        // dt is never cut below min_dt_ratio * dt
  // Start from equilibrium (the default): before the first step, the model
  // is relaxed statically under its loads, first with every closed contact
  // stuck, then with the joints' friction (blocks in contact settle into
  // their penalty springs and take their stresses; contacts asked for more
  // shear than their friction gives slip; blocks touching nothing stay
  // where they are), time stays 0, velocities are reset to the initial
  // ones. Without it the loads are switched on at t = 0: a block placed on
  // a slope starts with no contact force, falls into its springs, and the
  // bounce can walk it down a slope it should stay on (see settle.cpp and
  // tests/df/test_friction_limit.cpp).
  bool initial_equilibrium = true;
  std::string solver = "auto";       // "auto" | "cholmod" | "pcg" (see linear_solver.hpp)
};

struct ModelInput {
  BlockModel geometry;
  std::vector<Material> materials{Material{}};
  std::vector<int> block_material;          // empty: every block uses materials[0]
  std::vector<JointProperties> joint_sets;  // index = joint set id of the edges
  JointProperties default_joint;            // edges with a negative set id or no entry above
  Vec2 gravity{0, -9.81};                   // m/s^2
  std::vector<FixedPoint> fixed_points;
  std::vector<PointLoad> loads;
  std::optional<BodyAcceleration> body_acceleration;  // e.g. an earthquake in loading mode
  std::optional<ViscousBoundary> viscous_boundary;
  std::vector<Bolt> bolts;
  std::optional<WaterTable<2>> water;       // hydrostatic joint water (docs/formulation.md)
  std::vector<MeasurementPoint> measurements;
  std::vector<Vector6d> initial_velocity;   // empty, or one per block [u, v, r, ex, ey, gxy] rates
  std::vector<Vector3d> initial_stress;     // empty, or one per block [sx, sy, txy]
  Control control;
};

// Fixed and measurement points of a blocks file become FixedPoint and
// MeasurementPoint entries; load points take their force from `load_forces`
// by name (a load point without a force is an InputError).
void add_points_from_block_model(const BlockModel& geometry,
                                 const std::map<std::string, Vec2>& load_forces, ModelInput& input);

// Everything resolved: the solver reads only this.
struct Model {
  std::vector<Block> blocks;                // initial geometry (CCW)
  std::vector<Material> materials;
  std::vector<int> block_material;          // one per block
  std::vector<JointProperties> joints;      // joint_sets, then the default joint (last)
  std::vector<double> joint_pn, joint_ps;   // resolved penalties, one per joint
  Vec2 gravity{0, -9.81};
  std::vector<FixedPoint> fixed_points;     // block and penalty resolved
  std::vector<PointLoad> loads;             // block resolved
  std::optional<BodyAcceleration> body_acceleration;  // blocks checked, sorted, unique
  std::optional<ViscousBoundary> viscous_boundary;    // edges checked
  std::vector<Bolt> bolts;                  // blocks resolved
  std::optional<WaterTable<2>> water;       // none: dry joints (and no cost)
  std::vector<MeasurementPoint> measurements;
  std::vector<Vector6d> initial_velocity;   // one per block
  std::vector<Vector3d> initial_stress;     // one per block
  Control control;                          // w0 resolved
  Vec2 origin{0, 0};                        // local origin of every position (BlockModel::origin)
  double search_distance = 0;               // m, 2.5 * g2 * w0
  // m, the open-close dead band (ContactLaw::tolerance): 1e-12 * w0, far
  // above the rounding of dn (1e-20 m on a 40 m model) and far below any
  // displacement that matters (a pull of pn * 2e-11 m is 15 N at pn = 50 E,
  // E = 15 GPa: 0.07 % of the weight of a 1 m^2 block).
  double contact_tolerance = 0;
  // m: after a trial solve, the open-close iteration updates only the
  // contacts of blocks that may have moved more than this since their
  // contacts were last updated (and those that changed state or whose
  // friction lags); after the first and every full solve, all of them
  // (moved_blocks.hpp). 1e-3 * contact_tolerance; 0 updates every contact
  // after every solve.
  double contact_update_tolerance = 0;

  int block_count() const { return static_cast<int>(blocks.size()); }
  // Joint index for an edge's set id (the default joint for negative or unknown ids).
  int joint_for_set(int set) const {
    const int n = static_cast<int>(joints.size()) - 1;
    return (set >= 0 && set < n) ? set : n;
  }
};

// Validates the input and resolves defaults; throws InputError.
Model build_model(ModelInput input);

// control.dt 0 (not given): sets it from the model (time_step.hpp: the
// P-wave crossing time of the median block, or the loading tables' shortest
// sample interval, or `record_interval`, if shorter) with its dt_basis.
// build_model() calls it; a reader calls it first when something it builds
// depends on dt (an earthquake record refined to the step).
void choose_time_step(ModelInput& in, double record_interval = 0);

}  // namespace dda::df
