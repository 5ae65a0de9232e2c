// Measurement points placed on a block (scenario_block_points.hpp; keys in
// docs/scenario.md, "points").
#include "io/scenario_block_points.hpp"

#include <cmath>
#include <optional>
#include <set>

#include "dda/common/coordinate_range.hpp"
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/common/geometry3d.hpp"
#include "dda/common/short_number.hpp"
#include "io/scenario_joints.hpp"  // join_names

namespace dda::df {
namespace {

// An item of `points` with a `block`, read but not yet placed.
struct BlockPointSpec {
  YamlNode item;
  std::string name;
  YamlNode block;                          // the `block` value
  std::optional<long long> id;             // `block: ID`
  std::string key;                         // or the one key of the selection mapping
  std::vector<double> containing;          // with key `containing`: the point
  std::optional<std::vector<double>> at;   // the start position, if not the centroid
};

std::string coordinates_text(const std::vector<double>& v) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + short_number(v[i]);
  return s + ")";
}

// `key` of `n`: [x, y] in 2D, [x, y, z] in 3D, finite.
std::vector<double> read_position(const YamlNode& n, const std::string& key, int dimension) {
  const YamlNode c = n.child(key);
  const std::vector<double> v = c.as_numbers();
  if (static_cast<int>(v.size()) != dimension)
    c.fail(std::string(dimension == 2 ? "must be [x, y] (two numbers)" : "must be [x, y, z] (three numbers)") +
           ", got " + std::to_string(v.size()) + " numbers");
  for (double x : v)
    if (!std::isfinite(x)) c.fail("must hold finite numbers");
  return v;
}

BlockPointSpec read_spec(const YamlNode& item, int dimension, const std::vector<std::string>& selection_keys) {
  item.allow({"name", "kind", "at", "block"});
  BlockPointSpec s{item, item.text("name"), item.child("block"), std::nullopt, "", {}, std::nullopt};
  if (s.name.empty()) item.fail_key("name", "must not be empty");
  // A fixed or load point acts where the engineer puts it; only a
  // measurement point is the block's to carry wherever it is.
  const std::string kind = item.text("kind", "measurement");
  if (kind != "measurement")
    item.fail_key("kind", "is '" + kind + "', but only a measurement point can be placed by block (give a " + kind +
                              " point its position in at, without block)");
  std::vector<std::string> keys{"containing"};
  keys.insert(keys.end(), selection_keys.begin(), selection_keys.end());
  const std::string example = dimension == 2 ? "{containing: [x, y]}" : "{containing: [x, y, z]}";
  const YamlNode& b = s.block;
  if (b.is_scalar()) {
    try {
      s.id = b.as_integer(Range::non_negative());
    } catch (const InputError&) {
      b.fail("must be a block id (a whole number >= 0: its index in the blocks file, its block_id in ParaView) or "
             "a selection such as " + example + ", got '" + b.as_text() + "'");
    }
  } else if (b.is_map()) {
    b.allow(keys);
    std::vector<std::string> present;
    for (const std::string& k : keys)
      if (b.has(k)) present.push_back(k);
    if (present.size() != 1)
      b.fail("must select one block with exactly one of " + join_names(keys) +
             (present.empty() ? ", none given" : ", got " + join_names(present)));
    s.key = present.front();
    if (s.key == "containing") s.containing = read_position(b, "containing", dimension);
  } else {
    b.fail("must be a block id or a selection such as " + example);
  }
  if (item.has("at")) s.at = read_position(item, "at", dimension);
  return s;
}

template <class Vec>
Vec to_vec(const std::vector<double>& v) {
  Vec p;
  for (int i = 0; i < p.size(); ++i) p[i] = v[static_cast<std::size_t>(i)];
  return p;
}

template <class Vec>
std::vector<double> from_vec(const Vec& p) {
  return std::vector<double>(p.data(), p.data() + p.size());
}

std::string ids_text(const std::vector<std::size_t>& ids) {
  std::vector<std::string> names;
  for (std::size_t b : ids) names.push_back(std::to_string(b));
  return join_names(names);
}

// The one block the spec names.
template <class Vec>
std::size_t resolve_block(const BlockPointSpec& s, const BlockCatalogue<Vec>& blocks) {
  if (s.id) {
    if (*s.id >= static_cast<long long>(blocks.count))
      s.block.fail("is block " + std::to_string(*s.id) + ", but " + blocks.path + " has " +
                   std::to_string(blocks.count) + " blocks (ids 0 to " + std::to_string(blocks.count - 1) + ")");
    return static_cast<std::size_t>(*s.id);
  }
  std::vector<std::size_t> picked;
  if (s.key == "containing") {
    const Vec p = to_vec<Vec>(s.containing) - blocks.origin;
    for (std::size_t b = 0; b < blocks.count; ++b)
      if (blocks.contains(b, p)) picked.push_back(b);
    if (picked.empty())
      s.block.fail_key("containing", "puts " + coordinates_text(s.containing) + " outside every block of " +
                                         blocks.path);
    if (picked.size() > 1)
      s.block.fail_key("containing", "puts " + coordinates_text(s.containing) + " on the boundary between blocks " +
                                         ids_text(picked) + " of " + blocks.path +
                                         ", so it names no one block: move it inside one of them or give its id "
                                         "(block: " + std::to_string(picked.front()) + ")");
    return picked.front();
  }
  const std::vector<bool> selected = blocks.select(s.block);  // refuses a selection of no block
  for (std::size_t b = 0; b < selected.size(); ++b)
    if (selected[b]) picked.push_back(b);
  if (picked.size() > 1)
    s.block.fail_key(s.key, "selects " + std::to_string(picked.size()) + " blocks of " + blocks.path + " (" +
                                ids_text(picked) + "), but a point rides with one: narrow the selection or give "
                                "the block's id (block: " + std::to_string(picked.front()) + ")");
  return picked.front();
}

std::vector<BlockPointSpec> read_specs(const YamlNode& root, int dimension,
                                       const std::vector<std::string>& selection_keys) {
  std::vector<BlockPointSpec> out;
  for (const YamlNode& item : root.list_or_empty("points"))
    if (item.is_map() && item.has("block")) out.push_back(read_spec(item, dimension, selection_keys));
  return out;
}

}  // namespace

void check_block_points(const YamlNode& root, int dimension, const std::vector<std::string>& selection_keys,
                        const std::function<void(const YamlNode&)>& check_selection) {
  for (const BlockPointSpec& s : read_specs(root, dimension, selection_keys))
    if (!s.id && s.key != "containing") check_selection(s.block);
}

template <class Vec>
std::vector<BlockPoint<Vec>> place_block_points(const YamlNode& root, const BlockCatalogue<Vec>& blocks,
                                                const std::vector<std::string>& taken) {
  const int dimension = static_cast<int>(Vec::RowsAtCompileTime);
  std::set<std::string> names(taken.begin(), taken.end());
  std::vector<BlockPoint<Vec>> out;
  for (const BlockPointSpec& s : read_specs(root, dimension, blocks.selection_keys)) {
    if (!names.insert(s.name).second)
      s.item.fail_key("name", "'" + s.name + "' is already the name of another point (of " + blocks.path +
                                  " or of this list)");
    const std::size_t b = resolve_block(s, blocks);
    Vec position = blocks.centroid(b);
    if (s.at) {
      position = to_vec<Vec>(*s.at) - blocks.origin;
      if (!blocks.contains(b, position))
        s.item.fail_key("at", "puts point '" + s.name + "' at " + coordinates_text(*s.at) + ", outside block " +
                                  std::to_string(b) + " (centroid " + coordinates_text(from_vec<Vec>(user_position<Vec>(blocks.centroid(b), blocks.origin))) +
                                  "), the block it names");
    }
    out.push_back({s.name, static_cast<int>(b), position});
  }
  return out;
}

template std::vector<BlockPoint<Vec2>> place_block_points(const YamlNode&, const BlockCatalogue<Vec2>&,
                                                          const std::vector<std::string>&);
template std::vector<BlockPoint<Vec3>> place_block_points(const YamlNode&, const BlockCatalogue<Vec3>&,
                                                          const std::vector<std::string>&);

}  // namespace dda::df
