#pragma once
// Small linear-algebra vocabulary of the 2D forward solver.
//
// A 2D DDA block has six unknowns per step, referred to its centroid:
//   d = [u0, v0, r0, ex, ey, gxy]
// (rigid translation, rotation, normal strains, engineering shear strain).
// The same six numbers as rates form the block velocity.
#include <Eigen/Core>

#include "dda/common/geometry.hpp"

namespace dda::df {

constexpr int kDofs = 6;  // unknowns per 2D block

using Vector6d = Eigen::Matrix<double, kDofs, 1>;
using Matrix6d = Eigen::Matrix<double, kDofs, kDofs>;
using Matrix26d = Eigen::Matrix<double, 2, kDofs>;
using Vector3d = Eigen::Vector3d;  // stress or strain [xx, yy, xy]
using Matrix3d = Eigen::Matrix3d;

}  // namespace dda::df
