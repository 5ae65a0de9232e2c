#pragma once
// Dynamic input of the analytical solutions.
//
// Everything is per unit mass. The block's resultant acceleration
//   r(t) = (0, 0, -g) + b(t)
// is gravity plus the body (inertial) acceleration b(t) it feels in the frame
// of the moving foundation. For a ground (foundation) acceleration a_g(t),
// b(t) = -a_g(t) (the DDA "loading mode": body force -rho a_g). An input given
// as body acceleration is used as is. Axes x east, y north, z up; m/s^2.
#include <functional>
#include <memory>
#include <string>

#include "dda/analysis/orientation.hpp"
#include "dda/common/record.hpp"

namespace dda::analysis {

enum class InputMeaning { ground, body };
InputMeaning parse_input_meaning(const std::string& text, const std::string& what);

struct Excitation {
  // Body acceleration b(t), m/s^2 (gravity not included).
  std::function<Vec3(double)> body;
  double duration = 0.0;  // natural end of the input (s), 0 if unbounded
  std::string description;
};

// A record, read as ground or body acceleration (zero outside its time span).
Excitation excitation_from_record(std::shared_ptr<const AccelRecord> record, InputMeaning meaning);
// A sinusoid amplitude * sin(omega t) along `direction` (unit vector),
// multiplied by a linear ramp over `ramp` seconds; amplitude in m/s^2.
Excitation sinusoid(const Vec3& direction, double amplitude, double omega, double ramp, InputMeaning meaning);
// No input: gravity alone.
Excitation no_input();

}  // namespace dda::analysis
