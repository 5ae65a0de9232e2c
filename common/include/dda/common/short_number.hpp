#pragma once
// A number to three significant digits, for sentences that explain a choice
// or a refusal ("dt 0.000194 s", "lies up to 5e+08 m"): what the user reads,
// not the number the program uses.
#include <sstream>
#include <string>

namespace dda {

inline std::string short_number(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

}  // namespace dda
