#include "dda/common/scenario.hpp"

#include <filesystem>

namespace dda {

const std::vector<std::string>& scenario_sections() {
  static const std::vector<std::string> sections = {
      "name",       "description", "seed",     "domain",   "joint_sets", "layering",
      "excavations", "lines",      "traces",   "geometry", "points",     "cutting",
      "materials",  "joints",      "loading",  "fixed",    "bolts",      "boundaries",
      "control",    "output",     "water",
      // 3D (dimension: 3)
      "dimension", "fracture_sets", "persistent_sets", "planes", "fracture_files", "trace_planes"};
  return sections;
}

namespace {

// Sections that only one dimension reads. A section of the other dimension
// would be silently ignored, so it is an error naming it (with the section
// that does the job, where there is one). The forward run reads materials,
// joints, loading, fixed, bolts, boundaries and control in both (each
// dimension its own keys); `output` serves `dda run` in both.
struct OtherDimension {
  const char* key;
  const char* instead;  // "" if none
};
const OtherDimension kOnly2d[] = {
    {"joint_sets", "fracture_sets"}, {"lines", "planes"}, {"traces", "fracture_files"}, {"geometry", ""}};
const char* const kOnly3d[] = {"fracture_sets", "persistent_sets", "planes", "fracture_files", "trace_planes"};

void check_dimension(const YamlNode& root) {
  int dimension = 2;
  if (const auto node = root.optional_child("dimension")) {
    const long long d = node->as_integer();
    if (d != 2 && d != 3) node->fail("must be 2 or 3, got " + std::to_string(d));
    dimension = static_cast<int>(d);
  }
  if (dimension == 3) {
    for (const OtherDimension& o : kOnly2d)
      if (root.has(o.key))
        root.fail_key(o.key, std::string("is a 2D section, not read with dimension: 3") +
                                 (*o.instead ? std::string(" (in 3D, use ") + o.instead + ")" : std::string()));
  } else {
    for (const char* key : kOnly3d)
      if (root.has(key)) root.fail_key(key, "is a 3D section; add dimension: 3 at the top level to use it");
  }
}

}  // namespace

namespace {

YamlNode checked_sections(YamlNode root) {
  root.allow(scenario_sections());
  check_dimension(root);
  return root;
}

}  // namespace

YamlNode load_scenario(const std::string& path) { return checked_sections(YamlNode::load_file(path)); }

YamlNode load_scenario_text(const std::string& text, const std::string& file_label) {
  return checked_sections(YamlNode::load_string(text, file_label));
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
