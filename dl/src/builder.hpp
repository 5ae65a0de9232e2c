#pragma once
// Private to DL: the model being built from the scenario sections.
#include <nlohmann/json.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/line_model.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/dl/clip.hpp"
#include "dda/dl/layering.hpp"

namespace dda::dl::detail {

// The most lines one scenario may make (the limit): beyond it DC and
// DF would not finish, so the generator refuses before drawing them.
constexpr double kMaxLines = 5e6;

struct Builder {
  LineModel model;
  nlohmann::json report = nlohmann::json::object();
  std::uint64_t seed = 1;

  // Index of the set `name`, created with `origin` if new.
  int find_or_add_set(const std::string& name, const std::string& origin);
  // Adds a new set; a set of that name must not exist yet (node/key name the error).
  int add_new_set(const std::string& name, const std::string& origin, const YamlNode& node, const std::string& key);
  // Adds the parts of `s` inside the domain (all of it if the domain is empty).
  // Returns the number of pieces added.
  int add_clipped(const Segment& s, int set, LineKind kind = LineKind::Joint, int layer = -1);
  // Fails at node.key if `more` further lines would pass kMaxLines.
  void check_line_budget(double more, const YamlNode& node, const std::string& key, const std::string& what) const;
  double domain_area() const;
  // A position the user gave, about the model's local origin (the domain
  // chose it; coordinate_range.hpp).
  Vec2 local(const Vec2& user) const { return user - model.origin; }
};

// One function per scenario section, in the order generate_from_scenario calls them.
void read_domain(const YamlNode& root, Builder& b);
void read_excavations(const YamlNode& root, Builder& b);
void read_joint_sets(const YamlNode& root, Builder& b);
void read_layering(const YamlNode& root, Builder& b);
void read_user_lines(const YamlNode& root, Builder& b);
void read_traces(const YamlNode& root, Builder& b);
void read_geometry(const YamlNode& root, Builder& b);
void read_points(const YamlNode& root, Builder& b);
// A point's `kind` (fixed, load, measurement, hole; default measurement),
// and the report's count of points per kind (2D and 3D alike).
PointKind read_point_kind(const YamlNode& n);
nlohmann::json point_counts(const std::vector<PointKind>& kinds);
// An item of `points` placed on a block (it has `block`): the forward run
// places it on the blocks DC cuts (df/src/io/scenario_block_points.hpp), so
// DL leaves it out of the lines; without `control` there is no forward run
// to place it, which is an error naming the key.
bool placed_by_block(const YamlNode& root, const YamlNode& item);
// The `thickness` mapping of a layering section (2D and 3D alike).
ThicknessSpec read_thickness(const YamlNode& n);
// Per-set totals and overall totals, from the finished model.
void add_totals_to_report(Builder& b);

std::string format_number(double v, int precision = 4);

}  // namespace dda::dl::detail
