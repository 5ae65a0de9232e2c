#pragma once
// How far from the origin a model may lie.
//
// Why: every stage computes in doubles, which resolve 2.2e-16 of the
// coordinate. A 10 m box placed at x, y = 1e12 is resolved to 0.12 mm: its
// cut would have a snap length of 0.14 m, and a step's displacements of a
// micrometre would vanish when added to its corners. Such a model is
// refused where it is read, with the shift that brings it home, instead of
// being cut and run wrongly. The limits:
//  * every coordinate finite and within kFarthestCoordinate (1e9 m, far
//    beyond any rock mass in metres; areas and second moments then stay
//    finite);
//  * the largest coordinate at most kFarthestInSizes (1e7) times the
//    model's size (the diagonal of its box), so that doubles resolve 2e-9
//    of the model everywhere: a 1 m model in UTM coordinates (5e6 m) passes.
#include <string>
#include <vector>

#include "dda/common/fracture_model.hpp"
#include "dda/common/geometry.hpp"
#include "dda/common/geometry3.hpp"
#include "dda/common/line_model.hpp"

namespace dda {

inline constexpr double kFarthestCoordinate = 1e9;
inline constexpr double kFarthestInSizes = 1e7;

// Throws InputError naming `source` (a file, or a description such as
// "the domain") when the points break the limits above. Empty input passes.
void check_coordinate_range(const std::vector<Vec2>& points, const std::string& source);
void check_coordinate_range(const std::vector<Vec3>& points, const std::string& source);
// Every point of a model: domain, excavations, lines (fractures) and points.
void check_coordinate_range(const LineModel& model, const std::string& source);
void check_coordinate_range(const FractureModel& model, const std::string& source);

}  // namespace dda
