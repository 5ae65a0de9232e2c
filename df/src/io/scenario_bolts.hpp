#pragma once
// The `bolts` section, read the same way in 2D and 3D (docs/scenario.md):
// a list of {name, from, to, stiffness, pretension, breaking_force}, `from`
// and `to` points of the dimension ([x, y] or [x, y, z]). Which blocks the
// ends lie in is the caller's (each dimension finds its own blocks). Private
// to DF.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "dda/common/yaml_reader.hpp"

namespace dda::df {

template <class Point>
struct BoltEntry {
  YamlNode node;  // the list item, for errors about where its ends lie
  std::string name;
  Point from, to;
  double stiffness = 0;
  double pretension = 0;
  std::optional<double> breaking_force;
};

// `read_point(item, key)` reads one end, failing on the key if it is not a point.
template <class Point, class ReadPoint>
std::vector<BoltEntry<Point>> read_bolt_entries(const YamlNode& root, ReadPoint read_point) {
  std::vector<BoltEntry<Point>> out;
  std::set<std::string> names;
  for (const YamlNode& item : root.list_or_empty("bolts")) {
    item.allow({"name", "from", "to", "stiffness", "pretension", "breaking_force"});
    BoltEntry<Point> b{item, item.text("name", "bolt" + std::to_string(out.size() + 1)), read_point(item, "from"),
                       read_point(item, "to"), 0, 0, std::nullopt};
    if (!names.insert(b.name).second) item.fail_key("name", "repeats the bolt name '" + b.name + "'");
    if (b.from == b.to) item.fail_key("to", "must differ from `from` (the bolt has zero length)");
    b.stiffness = item.number("stiffness", Range::positive());
    b.pretension = item.number("pretension", 0, Range::non_negative());
    if (item.has("breaking_force")) b.breaking_force = item.number("breaking_force", Range::positive());
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace dda::df
