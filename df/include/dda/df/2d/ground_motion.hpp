#pragma once
// Earthquake input of the 2D solver (scenario key loading.earthquake,
// documented in docs/scenario.md).
//
// A GroundMotion is the processed ground acceleration a_g(t) in model axes
// (x horizontal, y up), m/s^2, sampled at the record's times, which are model
// times (zero before the first and after the last sample). How it reaches
// the blocks is a GroundMotionMode, one small type per mode behind this
// interface, each turning the motion into features the solver already has:
//  * loading (ground_motion_loading.cpp): the blocks feel it in the frame
//    of the ground, as a body force -rho a_g(t) added to gravity on every
//    block outside the foundation (ModelInput::body_acceleration); the
//    foundation is held where it is.
//  * displacement (ground_motion_displacement.cpp): the foundation's fixed
//    points follow the ground displacement d_g(t), the acceleration
//    integrated twice (trapezoidal rule, from rest), as moving fixed points.
//  * incident (ground_motion_incident.cpp): the record is the outcrop
//    motion of the base rock, and half its velocity enters the model as an
//    incident wave through the viscous boundary of the base
//    (viscous_boundary.hpp), which also lets out what comes back down.
// For a rigid foundation the two give the same motion relative to the
// foundation, as long as they see the same a_g: the baseline correction
// (which changes a_g by -P''(t), record.hpp) is part of the processing and
// applies in both modes alike.
//
// The foundation is a set of fixed points (by default every fixed point);
// its blocks are the blocks holding them.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dda/common/record.hpp"
#include "dda/df/2d/model.hpp"

namespace dda::df {

// What to read and how to process it: read (units, the direction of a
// one-component record), then RecordProcessing (record.hpp: components,
// scale, resample, filter, ramp up, baseline correction). Components x
// (horizontal) and y (vertical): the model's axes.
struct GroundMotionSpec {
  std::string path;                        // record file: CSV t, ax[, ay] or t, a; or PEER NGA AT2
  AccelUnits units = AccelUnits::unspecified;  // required for CSV; AT2 is g
  Vec2 direction{1, 0};                    // model direction of a one-component record
  RecordProcessing processing;
};

struct GroundMotion {
  std::vector<double> t;                   // s, strictly increasing
  std::vector<Vec2> acceleration;          // a_g, m/s^2, model axes
  std::string source;                      // the record file, for messages
};

// Reads and processes a record; InputError naming the record file for a bad
// record (empty, a time that does not increase, NaN, wrong units), or one
// with a z column (the 2D model has no use for it).
GroundMotion load_ground_motion(const GroundMotionSpec& spec);

// The record with every interval split into equal parts no longer than `h`
// (linear interpolation, original samples kept): the trapezoidal rule then
// integrates a coarse record (an AT2 file at 0.01-0.02 s) as finely as the
// solver steps through it.
AccelRecord refined_record(const GroundMotion& motion, double h);

// a_g(t) as a piecewise-linear table, zero before the first and after the
// last sample (a zero row is added just outside a sample that is not zero).
TimeHistory acceleration_history(const GroundMotion& motion, double factor = 1.0);

class GroundMotionMode {
 public:
  virtual ~GroundMotionMode() = default;
  virtual std::string name() const = 0;
  // Baseline correction degree when the scenario gives none.
  virtual int default_baseline() const = 0;
  // Puts the motion into `in`. `foundation`: indices into in.fixed_points.
  // InputError for what the mode cannot do (e.g. a foundation point that
  // already moves along its own table).
  virtual void apply(const GroundMotion& motion, const std::vector<std::size_t>& foundation,
                     ModelInput& in) const = 0;
};

// Body force -rho a_g(t) on every block outside the foundation
// (ground_motion_loading.cpp). No baseline correction by default: the
// record acts as given.
class LoadingMode final : public GroundMotionMode {
 public:
  std::string name() const override { return "loading"; }
  int default_baseline() const override { return 0; }
  void apply(const GroundMotion& motion, const std::vector<std::size_t>& foundation, ModelInput& in) const override;
};

// The foundation points follow d_g(t) (ground_motion_displacement.cpp).
// Baseline correction of degree 3 by default, so that the ground does not
// drift away with the record's mean velocity.
class DisplacementMode final : public GroundMotionMode {
 public:
  std::string name() const override { return "displacement"; }
  int default_baseline() const override { return 3; }
  void apply(const GroundMotion& motion, const std::vector<std::size_t>& foundation, ModelInput& in) const override;
};

// The incident wave v_in(t) = v_g(t) / 2 on the viscous boundary edges
// marked as input (ground_motion_incident.cpp); the foundation is not used.
// Baseline correction of degree 3 by default, so that the base is not
// pushed on for ever by the record's mean velocity.
class IncidentWaveMode final : public GroundMotionMode {
 public:
  std::string name() const override { return "incident"; }
  int default_baseline() const override { return 3; }
  void apply(const GroundMotion& motion, const std::vector<std::size_t>& foundation, ModelInput& in) const override;
};

// "loading", "displacement" or "incident"; InputError naming the known modes otherwise.
std::unique_ptr<GroundMotionMode> make_ground_motion_mode(const std::string& name);
std::vector<std::string> ground_motion_mode_names();

// The blocks holding the given fixed points (located by position when a
// point has no block yet), sorted, unique.
std::vector<int> foundation_blocks(const ModelInput& in, const std::vector<std::size_t>& foundation);

}  // namespace dda::df
