#pragma once
// Where a model lies: the coordinates every stage accepts, and the local
// origin a model far from the global origin is computed about.
//
// Why a local origin: every stage computes in doubles, which resolve
// 2.2e-16 of a coordinate. A 10 m box at x, y = 1e12 is resolved to
// 0.12 mm there: its cut, its contacts and a step's micrometre
// displacements would be lost in rounding. About a local origin near its
// centre its coordinates are a few metres and keep their full precision.
//
// The rule (choose_local_origin):
//  * the origin stays exactly 0 unless the model's farthest coordinate
//    exceeds kLocalBeyondSizes (1e7) times its size (the diagonal of its
//    box) or kLocalBeyondMetres (1e9 m). Closer, doubles resolve at least
//    2.2e-9 of the model (the cutter's snap length needs 2e-9), so a shift
//    buys nothing that matters, and every model that ran before local
//    origins ran (all such models lay inside both limits) runs bit for bit
//    as before;
//  * beyond, each axis on which the whole model lies on one side of 0
//    within a factor 2 (lo > 0 and hi <= 2 lo, or the mirror) is shifted by
//    its centre rounded to a multiple of a power of two no larger than the
//    model's extent on that axis. That origin lies in [lo, hi], so for every
//    coordinate x of the model o / 2 <= x <= 2 o, and x - o is exact in
//    doubles (Sterbenz's lemma): the local model is the user's model, moved,
//    with not one bit lost. An axis that straddles 0 or spans more than a
//    factor 2 already has |x| <= 2 x its extent there and stays at 0.
//
// The checks (check_coordinate_range): every coordinate finite and within
// kFarthestCoordinate (1e15 m; doubles there are 0.125 m apart, and areas
// and second moments of the local model stay finite whatever the user
// wrote). Nothing else is refused.
#include <string>
#include <vector>

#include "dda/common/fracture_model.hpp"
#include "dda/common/geometry.hpp"
#include "dda/common/geometry3d.hpp"
#include "dda/common/line_model.hpp"

namespace dda {

inline constexpr double kFarthestCoordinate = 1e15;
inline constexpr double kLocalBeyondSizes = 1e7;
inline constexpr double kLocalBeyondMetres = 1e9;

// Throws InputError naming `source` (a file, or a description such as
// "the domain") when a point breaks the checks above. Empty input passes.
void check_coordinate_range(const std::vector<Vec2>& points, const std::string& source);
void check_coordinate_range(const std::vector<Vec3>& points, const std::string& source);
// Every point of a model: domain, excavations, lines (fractures) and points.
void check_coordinate_range(const LineModel& model, const std::string& source);
void check_coordinate_range(const FractureModel& model, const std::string& source);

// The local origin of these points by the rule above (zero for points near
// the origin, for empty input, and for non-finite input).
Vec2 choose_local_origin(const std::vector<Vec2>& points);
Vec3 choose_local_origin(const std::vector<Vec3>& points);

// Every absolute position of a model (domain, excavations, lines or
// fractures, points, bed levels), in the same list the checks see.
std::vector<Vec2> model_positions(const LineModel& model);
std::vector<Vec3> model_positions(const FractureModel& model);

// The level of point p along the normal (-sin dip, cos dip) of 2D beds
// dipping dip_deg: the coordinate LineModel::layers are given in (y itself,
// exactly, for horizontal beds). A bed level about a local origin o is the
// user's level less level_along_beds(o, dip).
double level_along_beds(const Vec2& p, double dip_deg);

// What the user reads back: a position (or a level) about a local origin
// in the user's coordinates, p + origin; p itself when the origin is 0, so
// that outputs of models near the origin stay bit for bit (adding 0 would
// turn -0 into 0).
template <class Point>
Point user_position(const Point& p, const Point& origin) {
  return origin == Point::Zero() ? p : Point(p + origin);
}
inline double user_level(double level, double level_of_origin) {
  return level_of_origin == 0 ? level : level + level_of_origin;
}

// Moves a model whose origin is still 0 to the local origin the rule
// chooses for it (nothing happens near the origin): subtracts it from every
// absolute position and records it in model.origin.
void move_to_local_origin(LineModel& model);
void move_to_local_origin(FractureModel& model);

}  // namespace dda
