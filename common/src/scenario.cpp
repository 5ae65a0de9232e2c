#include "dda/common/scenario.hpp"

#include <filesystem>

namespace dda {

const std::vector<std::string>& scenario_sections() {
  static const std::vector<std::string> sections = {
      "name",       "description", "seed",     "domain",   "joint_sets", "layering",
      "excavations", "lines",      "traces",   "geometry", "points",     "cutting",
      "materials",  "joints",      "loading",  "fixed",    "bolts",      "boundaries",
      "control",    "output"};
  return sections;
}

YamlNode load_scenario(const std::string& path) {
  YamlNode root = YamlNode::load_file(path);
  root.allow(scenario_sections());
  return root;
}

std::uint64_t scenario_seed(const YamlNode& root) {
  return static_cast<std::uint64_t>(root.integer("seed", 1, Range::non_negative()));
}

std::string resolve_scenario_path(const YamlNode& node, const std::string& relative) {
  namespace fs = std::filesystem;
  const fs::path p(relative);
  if (p.is_absolute()) return p.string();
  return (fs::path(node.file()).parent_path() / p).lexically_normal().string();
}

}  // namespace dda
