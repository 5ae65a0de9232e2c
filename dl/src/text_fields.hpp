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

inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
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
