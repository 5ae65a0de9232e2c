#pragma once
// A strict reader for the scenario YAML.
//
// Every value is read through a YamlNode, which knows the file it came from,
// its key path ("joint_sets[1].mean_length") and its line. Anything wrong (an
// unknown key, a wrong type, a missing required key, a value out of range) is
// an InputError with one sentence of the form
//
//   scenario.yaml:12: joint_sets[1].mean_length must be > 0, got -3.
//
// A stage parses its section with a YamlNode: call allow() with the keys the
// section knows first, then read each key with a typed getter.
//
// Loading is strict too: a key given twice in one mapping, or a second YAML
// document after `---`, is an error (yaml-cpp alone would quietly keep the
// first value and ignore the rest; docs/reliability.md).
#include <yaml-cpp/yaml.h>

#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dda/common/geometry.hpp"

namespace dda {

// An interval for range checks. Bounds are inclusive unless marked open.
struct Range {
  double lo = -1e300, hi = 1e300;
  bool lo_open = false, hi_open = false;
  static Range any() { return {}; }
  static Range positive() { return {0, 1e300, true, false}; }
  static Range non_negative() { return {0, 1e300, false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range half_open(double a, double b) { return {a, b, false, true}; }  // [a, b)
  bool contains(double v) const;
  std::string describe() const;  // e.g. "> 0", "between 0 and 1"
};

// What one allow() call declared: the mapping's key path, the keys it
// allows, and the source file and line of the reader that declared them.
struct AllowedKeys {
  std::string path;
  std::vector<std::string> keys;
  std::string file;
  int line = 0;
};

// Hears every allow() call of this thread from now on (an empty function:
// none, the default). The readers keep their keys next to the code that
// reads them; this is how the check that every scenario key is documented
// (tests/df/test_scenario_keys_documented.cpp) collects them.
void observe_allowed_keys(std::function<void(const AllowedKeys&)> observer);

class YamlNode {
 public:
  // Parses a whole file; a syntax error, a duplicate key or a second document
  // is an InputError naming file and line.
  static YamlNode load_file(const std::string& path);
  static YamlNode load_string(const std::string& text, const std::string& file_label);

  // The whole text the node was read from (kept for provenance).
  const std::string& source_text() const { return doc_->text; }
  const std::string& file() const { return doc_->file; }
  const std::string& path() const { return path_; }  // "" for the root
  // The yaml-cpp node itself, for code that copies or edits documents (a
  // study builds each case's scenario from its base this way).
  const YAML::Node& yaml() const { return node_; }
  int line() const;                                   // 1-based

  bool is_map() const { return node_.IsMap(); }
  bool is_sequence() const { return node_.IsSequence(); }
  bool is_scalar() const { return node_.IsScalar(); }
  bool has(const std::string& key) const;
  // The keys of this mapping in file order (none if it is not a mapping).
  std::vector<std::string> keys() const;

  // Declares the keys this mapping may hold; any other key is an error that
  // names it (and the closest allowed key, if one is close). Also checks that
  // the node is a mapping. `file` and `line` are the reader's that declares
  // them (for observe_allowed_keys()); the defaults fill them in at the call
  // (compiler builtins: clang 14, the sanitizer build's, has no
  // std::source_location with libstdc++).
  void allow(std::initializer_list<const char*> keys, const char* file = __builtin_FILE(),
             int line = __builtin_LINE()) const;
  void allow(const std::vector<std::string>& keys, const char* file = __builtin_FILE(),
             int line = __builtin_LINE()) const;
  // Exactly one of `keys` must be present; returns it.
  std::string one_of(std::initializer_list<const char*> keys) const;

  // Children.
  YamlNode child(const std::string& key) const;                 // required
  std::optional<YamlNode> optional_child(const std::string& key) const;
  std::vector<YamlNode> items() const;                          // this node as a sequence
  std::vector<YamlNode> list(const std::string& key) const;     // required sequence
  std::vector<YamlNode> list_or_empty(const std::string& key) const;

  // Scalars of this node.
  double as_number(Range r = Range::any()) const;
  long long as_integer(Range r = Range::any()) const;
  std::string as_text() const;
  bool as_bool() const;
  Vec2 as_point() const;                 // [x, y]
  std::vector<double> as_numbers() const;
  Polygon2 as_polygon() const;           // [[x, y], [x, y], ...], at least 3 points

  // Scalars by key: required, or with a default when absent.
  double number(const std::string& key, Range r = Range::any()) const;
  double number(const std::string& key, double fallback, Range r) const;
  long long integer(const std::string& key, Range r = Range::any()) const;
  long long integer(const std::string& key, long long fallback, Range r) const;
  std::string text(const std::string& key) const;
  std::string text(const std::string& key, const std::string& fallback) const;
  bool flag(const std::string& key, bool fallback) const;
  // A text value that must be one of `choices`.
  std::string choice(const std::string& key, std::initializer_list<const char*> choices) const;
  std::string choice(const std::string& key, std::initializer_list<const char*> choices,
                     const std::string& fallback) const;
  Vec2 point(const std::string& key) const;
  Polygon2 polygon(const std::string& key) const;

  // Throws InputError "file:line: path message". `message` starts with a
  // verb phrase, e.g. "must be > 0, got -3".
  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void fail_key(const std::string& key, const std::string& message) const;

 private:
  struct Document {
    std::string file;
    std::string text;
  };
  YamlNode(std::shared_ptr<const Document> doc, YAML::Node node, std::string path, int parent_line);
  std::string child_path(const std::string& key) const;
  std::string child_path(std::size_t index) const;

  std::shared_ptr<const Document> doc_;
  YAML::Node node_;
  std::string path_;
  int parent_line_ = 0;  // for nodes that are absent or have no mark
};

}  // namespace dda
