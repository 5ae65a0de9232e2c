#include "dda/common/yaml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/common/text_input.hpp"
#include "yaml_strict.hpp"

namespace dda {

namespace {

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Levenshtein distance, to suggest the key the user probably meant.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? sep : "") + v[i];
  return out;
}

std::string describe_scalar(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a mapping";
  return "nothing";
}

}  // namespace

bool Range::contains(double v) const {
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Range::describe() const {
  const bool has_lo = lo > -1e299, has_hi = hi < 1e299;
  if (has_lo && has_hi)
    return std::string("in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) +
           (hi_open ? ")" : "]");
  if (has_lo) return std::string(lo_open ? "> " : ">= ") + format_number(lo);
  if (has_hi) return std::string(hi_open ? "< " : "<= ") + format_number(hi);
  // Range::any() still bounds a number by +-1e300 (so that sums and squares
  // of inputs stay finite): say so, rather than "must be a number".
  return "at most 1e+300 in magnitude";
}

YamlNode::YamlNode(std::shared_ptr<const Document> doc, YAML::Node node, std::string path, int parent_line)
    : doc_(std::move(doc)), node_(std::move(node)), path_(std::move(path)), parent_line_(parent_line) {}

YamlNode YamlNode::load_file(const std::string& path) {
  return load_string(read_text_file(path, "scenario"), path);
}

YamlNode YamlNode::load_string(const std::string& text, const std::string& file_label) {
  auto doc = std::make_shared<Document>(Document{file_label, text});
  const YAML::Node root = yaml_strict::parse_document(text, file_label);
  YamlNode node(doc, root, "", 1);
  if (!root.IsMap()) node.fail("must be a mapping of sections (domain, joint_sets, ...) at the top level");
  return node;
}

int YamlNode::line() const {
  if (node_ && node_.Mark().line >= 0) return node_.Mark().line + 1;  // yaml-cpp counts from 0
  return parent_line_;
}

std::string YamlNode::child_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
std::string YamlNode::child_path(std::size_t index) const { return path_ + "[" + std::to_string(index) + "]"; }

void YamlNode::fail(const std::string& message) const {
  const std::string what = path_.empty() ? "the scenario" : path_;
  throw InputError(doc_->file + ":" + std::to_string(line()) + ": " + what + " " + message + ".");
}

void YamlNode::fail_key(const std::string& key, const std::string& message) const {
  if (has(key)) child(key).fail(message);
  throw InputError(doc_->file + ":" + std::to_string(line()) + ": " + child_path(key) + " " + message + ".");
}

bool YamlNode::has(const std::string& key) const { return node_.IsMap() && node_[key]; }

std::vector<std::string> YamlNode::keys() const {
  std::vector<std::string> out;
  if (!node_.IsMap()) return out;
  for (auto it = node_.begin(); it != node_.end(); ++it) out.push_back(it->first.Scalar());
  return out;
}

namespace {
thread_local std::function<void(const AllowedKeys&)> allowed_keys_observer;
}  // namespace

void observe_allowed_keys(std::function<void(const AllowedKeys&)> observer) {
  allowed_keys_observer = std::move(observer);
}

void YamlNode::allow(std::initializer_list<const char*> keys, const char* file, int line) const {
  allow(std::vector<std::string>(keys.begin(), keys.end()), file, line);
}

void YamlNode::allow(const std::vector<std::string>& keys, const char* file, int line) const {
  if (allowed_keys_observer) allowed_keys_observer({path_, keys, file, line});
  if (!node_.IsMap()) fail("must be a mapping with keys " + join(keys, ", ") + ", got " + describe_scalar(node_));
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string key = it->first.Scalar();
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
    std::string hint;
    std::size_t best = 3;
    for (const auto& k : keys) {
      const std::size_t d = edit_distance(key, k);
      if (d < best) {
        best = d;
        hint = k;
      }
    }
    const std::string where = doc_->file + ":" + std::to_string(it->first.Mark().line + 1) + ": ";
    throw InputError(where + "unknown key '" + child_path(key) + "'" +
                     (hint.empty() ? "" : " (did you mean '" + hint + "'?)") + "; allowed keys here are " +
                     join(keys, ", ") + ".");
  }
}

std::string YamlNode::one_of(std::initializer_list<const char*> keys) const {
  std::vector<std::string> present;
  for (const char* k : keys)
    if (has(k)) present.push_back(k);
  const std::vector<std::string> all(keys.begin(), keys.end());
  if (present.size() != 1)
    fail("must have exactly one of " + join(all, ", ") +
         (present.empty() ? ", none given" : ", got " + join(present, " and ")));
  return present.front();
}

YamlNode YamlNode::child(const std::string& key) const {
  if (!node_.IsMap()) fail("must be a mapping, got " + describe_scalar(node_));
  YAML::Node c = node_[key];
  if (!c) throw InputError(doc_->file + ":" + std::to_string(line()) + ": required key '" + child_path(key) + "' is missing.");
  return YamlNode(doc_, c, child_path(key), line());
}

std::optional<YamlNode> YamlNode::optional_child(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  YAML::Node c = node_[key];
  if (c.IsNull()) return std::nullopt;
  return YamlNode(doc_, c, child_path(key), line());
}

std::vector<YamlNode> YamlNode::items() const {
  if (!node_.IsSequence()) fail("must be a list, got " + describe_scalar(node_));
  std::vector<YamlNode> out;
  for (std::size_t i = 0; i < node_.size(); ++i) out.push_back(YamlNode(doc_, node_[i], child_path(i), line()));
  return out;
}

std::vector<YamlNode> YamlNode::list(const std::string& key) const { return child(key).items(); }

std::vector<YamlNode> YamlNode::list_or_empty(const std::string& key) const {
  auto c = optional_child(key);
  return c ? c->items() : std::vector<YamlNode>{};
}

double YamlNode::as_number(Range r) const {
  if (!node_.IsScalar()) fail("must be a number, got " + describe_scalar(node_));
  double v = 0;
  try {
    v = node_.as<double>();
  } catch (const YAML::Exception&) {
    fail("must be a number, got " + describe_scalar(node_));
  }
  if (!std::isfinite(v)) fail("must be a finite number, got " + describe_scalar(node_));
  if (!r.contains(v)) fail("must be " + r.describe() + ", got " + format_number(v));
  return v;
}

long long YamlNode::as_integer(Range r) const {
  if (!node_.IsScalar()) fail("must be a whole number, got " + describe_scalar(node_));
  long long v = 0;
  try {
    v = node_.as<long long>();
  } catch (const YAML::Exception&) {
    fail("must be a whole number, got " + describe_scalar(node_));
  }
  if (!r.contains(static_cast<double>(v))) fail("must be " + r.describe() + ", got " + std::to_string(v));
  return v;
}

std::string YamlNode::as_text() const {
  if (!node_.IsScalar()) fail("must be text, got " + describe_scalar(node_));
  return node_.Scalar();
}

bool YamlNode::as_bool() const {
  if (!node_.IsScalar()) fail("must be true or false, got " + describe_scalar(node_));
  try {
    return node_.as<bool>();
  } catch (const YAML::Exception&) {
    fail("must be true or false, got " + describe_scalar(node_));
  }
}

std::vector<double> YamlNode::as_numbers() const {
  std::vector<double> out;
  for (const YamlNode& item : items()) out.push_back(item.as_number());
  return out;
}

Vec2 YamlNode::as_point() const {
  if (!node_.IsSequence() || node_.size() != 2) fail("must be a point [x, y], got " + describe_scalar(node_));
  const auto v = as_numbers();
  return {v[0], v[1]};
}

Polygon2 YamlNode::as_polygon() const {
  Polygon2 poly;
  for (const YamlNode& item : items()) poly.push_back(item.as_point());
  if (poly.size() < 3) fail("must be a polygon of at least 3 points [[x, y], ...], got " + std::to_string(poly.size()));
  if (std::abs(signed_area(poly)) == 0) fail("must enclose a non-zero area");
  return poly;
}

double YamlNode::number(const std::string& key, Range r) const { return child(key).as_number(r); }
double YamlNode::number(const std::string& key, double fallback, Range r) const {
  auto c = optional_child(key);
  return c ? c->as_number(r) : fallback;
}
long long YamlNode::integer(const std::string& key, Range r) const { return child(key).as_integer(r); }
long long YamlNode::integer(const std::string& key, long long fallback, Range r) const {
  auto c = optional_child(key);
  return c ? c->as_integer(r) : fallback;
}
std::string YamlNode::text(const std::string& key) const { return child(key).as_text(); }
std::string YamlNode::text(const std::string& key, const std::string& fallback) const {
  auto c = optional_child(key);
  return c ? c->as_text() : fallback;
}
bool YamlNode::flag(const std::string& key, bool fallback) const {
  auto c = optional_child(key);
  return c ? c->as_bool() : fallback;
}

std::string YamlNode::choice(const std::string& key, std::initializer_list<const char*> choices) const {
  const YamlNode c = child(key);
  const std::string v = c.as_text();
  std::vector<std::string> all(choices.begin(), choices.end());
  if (std::find(all.begin(), all.end(), v) == all.end()) c.fail("must be one of " + join(all, ", ") + ", got '" + v + "'");
  return v;
}

std::string YamlNode::choice(const std::string& key, std::initializer_list<const char*> choices,
                             const std::string& fallback) const {
  return has(key) ? choice(key, choices) : fallback;
}

Vec2 YamlNode::point(const std::string& key) const { return child(key).as_point(); }
Polygon2 YamlNode::polygon(const std::string& key) const { return child(key).as_polygon(); }

}  // namespace dda
