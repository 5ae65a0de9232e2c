#pragma once
// How the 2D kernel takes an earthquake (core/ground_motion.hpp: the motion,
// the modes and their routes; docs/scenario.md: loading.earthquake).
//
// The 2D model already has a feature for each route, and the motion is put
// into it once, before the run:
//  * body force (ground_motion_loading.cpp): ModelInput::body_acceleration,
//    -a_g on every block outside the foundation, a table linear between the
//    record's samples, so that its mean over a step is the motion's exact
//    impulse;
//  * foundation (ground_motion_displacement.cpp): the foundation's fixed
//    points follow d_g(t) as moving points, a table whose rows (the record's
//    samples) carry d_g and, as rates, v_g, exactly: the C1 Hermite cubic
//    through them is then d_g itself, a cubic between the samples;
//  * incident wave (ground_motion_incident.cpp): the viscous boundary's
//    incident_velocity table (viscous_boundary.hpp), on the edges marked as
//    input.
//
// The foundation is a set of fixed points (by default every fixed point);
// its blocks are the blocks holding them.
#include <cstddef>
#include <vector>

#include "dda/df/2d/model.hpp"
#include "dda/df/core/ground_motion.hpp"

namespace dda::df {

// Puts the motion into `in` along the mode's route. `foundation`: indices
// into in.fixed_points. InputError for what the route cannot do (a
// foundation point that already moves along its own table, no foundation to
// move, no viscous input edge for the wave, a second body acceleration).
void apply_ground_motion(const GroundMotion<2>& motion, const GroundMotionMode& mode,
                         const std::vector<std::size_t>& foundation, ModelInput& in);

// The routes, one file each.
void apply_body_force(const GroundMotion<2>& motion, const std::vector<std::size_t>& foundation, ModelInput& in);
void apply_foundation_motion(const GroundMotion<2>& motion, const std::vector<std::size_t>& foundation,
                             ModelInput& in);
void apply_incident_wave(const GroundMotion<2>& motion, ModelInput& in);

// a_g(t) times `factor` as a piecewise-linear table, zero before the first
// and after the last sample (a zero row is added just outside a sample that
// is not zero).
TimeHistory acceleration_history(const GroundMotion<2>& motion, double factor = 1.0);

// The blocks holding the given fixed points (located by position when a
// point has no block yet), sorted, unique.
std::vector<int> foundation_blocks(const ModelInput& in, const std::vector<std::size_t>& foundation);

}  // namespace dda::df
