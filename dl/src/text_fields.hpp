#pragma once
// Private to DL: splitting the lines of the importers' text files (CSV
// traces, CSV polygons, FracMan .fab).
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace dda::dl::detail {

// Blanks are what split_fields splits on (std::isspace, form feed and
// vertical tab included), so a line that is not empty after trim has a
// field: a line of a lone form feed once reached fields[0] of no fields.
inline std::string trim(const std::string& s) {
  const auto blank = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  std::size_t b = 0, e = s.size();
  while (b < e && blank(s[b])) ++b;
  while (e > b && blank(s[e - 1])) --e;
  return s.substr(b, e - b);
}

inline std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Fields separated by commas or semicolons; if there are none, by blanks.
inline std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> out;
  if (line.find_first_of(",;") != std::string::npos) {
    std::string cur;
    for (const char c : line) {
      if (c == ',' || c == ';') {
        out.push_back(trim(cur));
        cur.clear();
      } else {
        cur += c;
      }
    }
    out.push_back(trim(cur));
    return out;
  }
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t b = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

// The whole field as a finite double.
inline bool parse_finite(const std::string& field, double& v) {
  if (field.empty()) return false;
  char* end = nullptr;
  errno = 0;
  v = std::strtod(field.c_str(), &end);
  return end == field.c_str() + field.size() && std::isfinite(v);
}

}  // namespace dda::dl::detail
