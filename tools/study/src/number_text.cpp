#include "dda/study/number_text.hpp"

#include <charconv>
#include <cmath>

namespace dda::study {

std::string round_trip(double v) {
  if (std::isnan(v)) return "";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest round-trip form
  return std::string(buf, r.ptr);
}

}  // namespace dda::study
