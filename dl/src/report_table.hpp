#pragma once
// Private to DL: the plain-text tables of the terminal reports (2D and 3D).
#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "builder.hpp"

namespace dda::dl::detail {

// A table with right-aligned columns (the first left-aligned).
class Table {
 public:
  explicit Table(std::vector<std::string> header) { rows_.push_back(std::move(header)); }
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  std::string str() const {
    std::vector<std::size_t> width;
    for (const auto& r : rows_)
      for (std::size_t c = 0; c < r.size(); ++c) {
        if (width.size() <= c) width.push_back(0);
        width[c] = std::max(width[c], r[c].size());
      }
    std::ostringstream out;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      const auto& r = rows_[i];
      std::string line = "  ";
      for (std::size_t c = 0; c < r.size(); ++c) {
        const std::string pad(width[c] - r[c].size(), ' ');
        line += (c == 0 ? r[c] + pad : pad + r[c]) + (c + 1 < r.size() ? "  " : "");
      }
      out << line << "\n";
      if (i == 0) {
        std::size_t total = 0;
        for (std::size_t w : width) total += w + 2;
        out << "  " << std::string(total - 2, '-') << "\n";
      }
    }
    return out.str();
  }

 private:
  std::vector<std::vector<std::string>> rows_;
};

inline std::string num(const nlohmann::json& v, int precision = 4) {
  if (v.is_null()) return "-";
  if (v.is_number_integer() || v.is_number_unsigned()) return std::to_string(v.get<long long>());
  if (v.is_number()) return detail::format_number(v.get<double>(), precision);
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

}  // namespace dda::dl::detail
