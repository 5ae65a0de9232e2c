#include "io/scenario_points.hpp"

namespace dda::df {

std::optional<YamlNode> scenario_point(const YamlNode& root, const std::string& name) {
  if (!root.has("points")) return std::nullopt;
  for (const YamlNode& p : root.list("points"))
    if (p.is_map() && p.has("name") && p.child("name").is_scalar() && p.child("name").as_text() == name) return p;
  return std::nullopt;
}

}  // namespace dda::df
