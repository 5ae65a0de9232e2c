#pragma once
// The direction `dda compare` projects displacements on: in 2D a model
// direction (--dip D or --direction dx,dy); in 3D a direction given as a
// vector (--direction x,y,z), as trend/plunge (--trend-plunge T/P) or as the
// line of intersection of two planes (--intersection D/B D/B).
#include <Eigen/Core>
#include <string>
#include <vector>

namespace dda::cli {

struct CompareDirectionOptions {
  double dip = NAN;                         // 2D: down a plane dipping this many degrees towards +x
  std::vector<double> direction;            // 2 numbers (2D) or 3 (3D)
  std::string trend_plunge;                 // 3D: "T/P", degrees
  std::vector<std::string> intersection;    // 3D: two planes "D/B"
};

struct CompareDirection {
  Eigen::Vector3d unit;  // 2D: (ex, ey, 0); 3D: (ex, ey, ez), x east, y north, z up
  std::string how;       // in words, for the summary line ("(0.94, -0.34)", "line of 45/120 and 45/240 ...")
};

// The unit direction for a 2D (`three_d` false) or 3D results file;
// InputError naming the option when the choice is missing, doubled, of the
// wrong dimension or degenerate.
CompareDirection compare_direction(const CompareDirectionOptions& o, bool three_d);

// The line where two planes meet, pointing down (the way a wedge slides);
// a horizontal line points to the side its first plane dips towards.
Eigen::Vector3d intersection_line(const std::string& first, const std::string& second);

}  // namespace dda::cli
