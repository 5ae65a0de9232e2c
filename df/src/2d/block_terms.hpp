#pragma once
// Per-block and per-point contributions to K d = F (private to DF).
#include "dda/df/core/block_system.hpp"
#include "dda/df/2d/simulation.hpp"

namespace dda::df {

// Inertia (constant acceleration in the step), elasticity with its viscous
// damping (C = beta K_e, damping.hpp; beta 0 for none), the stress carried
// from earlier steps and the body force of block i.
void add_block_terms(int i, const BlockState& b, const Material& mat, const Matrix3d& emat, const Vec2& gravity,
                     double dt, double beta, BlockSystem& sys);

// Penalty spring p pulling material point `at` of block i by `gap` (the
// prescribed displacement of the step): energy p/2 |T d - gap|^2.
void add_point_spring(int i, const BlockState& b, const Vec2& at, const Vec2& gap, double p, BlockSystem& sys);

// Constant force at material point `at` of block i: F += T^T P.
void add_point_load(int i, const BlockState& b, const Vec2& at, const Vec2& force, BlockSystem& sys);

}  // namespace dda::df
