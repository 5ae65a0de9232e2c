#pragma once
// A key path into a YAML document, written as the scenario reader names
// keys in its messages: "control.total_time", "joint_sets[1].mean_length".
// A study varies a scenario (or a wedge) by setting values at key paths of
// a copy of its base document.
#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace dda::study {

struct KeyPath {
  std::vector<std::variant<std::string, std::size_t>> steps;  // a key, or an index into a list
  std::string text;                                           // as written
};

// nullopt when `text` is no key path (empty, an empty key, a bad index);
// `why` then says what is wrong.
std::optional<KeyPath> parse_key_path(const std::string& text, std::string* why);

// Sets `value` at `path` in `doc`. Every step but the last must exist; the
// last may name a key the mapping does not hold yet (whoever reads the
// document then decides whether it knows it) but an index must exist.
// Returns "" on success, otherwise what is missing ("the base has no
// joint_sets[3]").
std::string set_at(YAML::Node doc, const KeyPath& path, const YAML::Node& value);

// The node at `path`, if there is one.
std::optional<YAML::Node> get_at(const YAML::Node& doc, const KeyPath& path);

}  // namespace dda::study
