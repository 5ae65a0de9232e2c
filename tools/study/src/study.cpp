#include "dda/study/study.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "dda/common/error.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/sentence_tail.hpp"
#include "dda/common/short_number.hpp"
#include "dda/study/number_text.hpp"
#include "dda/study/wedge_case.hpp"

namespace dda::study {

namespace fs = std::filesystem;

bool Failure::failed(double value) const {
  if (std::isnan(value)) return false;
  return (below && value < *below) || (above && value > *above);
}

std::size_t Study::grid_points() const {
  std::size_t n = 1;
  for (const VariedKey& v : vary) n *= v.values.size();
  return n;
}

std::size_t Study::case_count() const { return grid_points() * std::max<std::size_t>(1, seeds.size()) * draws; }

std::vector<std::string> Study::value_columns() const {
  std::vector<std::string> out;
  for (const VariedKey& v : vary)
    for (const KeyPath& p : v.paths) out.push_back(p.text);
  for (const SampledKey& s : sampled) out.push_back(s.path.text);
  for (const SampledPlane& p : planes) {
    out.push_back(p.dip.text);
    out.push_back(p.dip_direction.text);
  }
  return out;
}

void check_wedge_document(const YAML::Node& doc, const std::string& label) {
  YAML::Emitter e;
  e << doc;
  read_wedge_case(YamlNode::load_string(e.c_str(), label));
}

namespace {

// The case reader's message without "LABEL:LINE: ": that line is one of the
// document built for the check, which the user never sees.
std::string without_label(const std::string& message, const std::string& label) {
  if (message.rfind(label + ":", 0) != 0) return message;
  std::size_t i = label.size() + 1;
  while (i < message.size() && std::isdigit(static_cast<unsigned char>(message[i]))) ++i;
  if (i + 1 < message.size() && message[i] == ':' && message[i + 1] == ' ') return message.substr(i + 2);
  return message;
}

std::string without_full_stop(std::string s) {
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

KeyPath key_path_of(const YamlNode& where, const std::string& text) {
  std::string why;
  auto p = parse_key_path(text, &why);
  if (!p) where.fail("is no key path: '" + text + "' " + why);
  return *p;
}

std::string text_of(const YAML::Node& n) {
  if (n.IsScalar()) return n.Scalar();
  YAML::Emitter e;
  e << YAML::Flow << n;
  return e.c_str();
}

// Sets each value at its path in a copy of the base and reads it as a case
// would; `where` (the study file's node) takes the blame for anything wrong.
void try_values(const Study& s, const CaseCheck& check, const YamlNode& where,
                const std::vector<std::pair<KeyPath, YAML::Node>>& settings, const std::string& shown) {
  YAML::Node doc = YAML::Clone(s.base);
  for (const auto& [path, value] : settings) {
    const std::string missing = set_at(doc, path, value);
    if (!missing.empty())
      where.fail((settings.size() > 1 ? "sets " + path.text + ", which names" : std::string("names")) +
                 " no key of the base (" + missing + ")");
  }
  try {
    check(doc, s.base_label);
  } catch (const InputError& e) {
    where.fail("= " + shown + " is refused by the " + (s.kind == CaseKind::wedge ? "wedge" : "scenario") +
               " reader: " + without_full_stop(without_label(e.what(), s.base_label)));
  }
}

void try_value(const Study& s, const CaseCheck& check, const YamlNode& where, const KeyPath& path,
               const YAML::Node& value, const std::string& shown) {
  try_values(s, check, where, {{path, value}}, shown);
}

// "a, b" -> the key paths a and b.
std::vector<KeyPath> key_paths_of(const YamlNode& where, const std::string& text) {
  std::vector<KeyPath> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string part = text.substr(start, comma - start);
    part.erase(0, part.find_first_not_of(' '));
    part.erase(part.find_last_not_of(' ') + 1);
    out.push_back(key_path_of(where, part));
    start = comma + 1;
  }
  return out;
}


void read_base(Study& s, const YamlNode& root) {
  const std::string which = root.one_of({"scenario", "wedge"});
  const YamlNode node = root.child(which);
  if (which == "wedge") {
    s.kind = CaseKind::wedge;
    if (!node.is_map()) node.fail("must be a mapping (plane1, plane2, phi, ...)");
    s.base = YAML::Clone(node.yaml());
    s.base_label = s.file;
    return;
  }
  s.kind = CaseKind::pipeline;
  if (node.is_map()) {
    s.base = YAML::Clone(node.yaml());
    s.base_label = s.file;
    return;
  }
  const std::string path = resolve_scenario_path(node, node.as_text());
  if (!fs::exists(path)) node.fail("names " + path + ", which does not exist");
  s.base = YAML::Clone(load_scenario(path).yaml());
  s.base_label = path;
}

void read_vary(Study& s, const YamlNode& root, const CaseCheck& check) {
  const auto vary = root.optional_child("vary");
  if (!vary) return;
  if (!vary->is_map()) vary->fail("must be a mapping of key paths to lists of values");
  if (vary->keys().empty()) vary->fail("is empty: give at least one key path with its values, or leave vary out");
  for (const std::string& key : vary->keys()) {
    const YamlNode list = vary->child(key);
    VariedKey v{key_paths_of(list, key), {}, {}};
    for (const KeyPath& p : v.paths)
      if (s.kind == CaseKind::pipeline && p.text == "seed") list.fail("is what seeds: sets; vary the seed there");
    const std::vector<YamlNode> items = list.items();
    if (items.empty()) list.fail("has no values: an empty list makes an empty grid");
    for (const YamlNode& item : items) {
      std::vector<YamlNode> parts{item};
      if (v.paths.size() > 1) {
        parts = item.items();
        if (parts.size() != v.paths.size())
          item.fail("must be a list of " + std::to_string(v.paths.size()) + " values, one per key path, got " +
                    std::to_string(parts.size()));
      }
      std::vector<std::pair<KeyPath, YAML::Node>> settings;
      std::vector<YAML::Node> nodes;
      std::vector<std::string> texts;
      for (std::size_t k = 0; k < parts.size(); ++k) {
        settings.emplace_back(v.paths[k], parts[k].yaml());
        nodes.push_back(YAML::Clone(parts[k].yaml()));
        texts.push_back(text_of(parts[k].yaml()));
      }
      try_values(s, check, item, settings, text_of(item.yaml()));
      v.values.push_back(std::move(nodes));
      v.texts.push_back(std::move(texts));
    }
    s.vary.push_back(std::move(v));
  }
}

void read_seeds(Study& s, const YamlNode& root) {
  const auto node = root.optional_child("seeds");
  if (!node) return;
  if (s.kind == CaseKind::wedge)
    node->fail("is for scenario realisations; a wedge case draws nothing itself (use sample.draws)");
  if (node->is_scalar()) {
    const long long n = node->as_integer(Range::closed(1, 1e9));
    for (long long k = 1; k <= n; ++k) s.seeds.push_back(static_cast<std::uint64_t>(k));
    return;
  }
  const auto items = node->items();
  if (items.empty()) node->fail("is an empty list: it makes an empty study");
  for (const YamlNode& item : items)
    s.seeds.push_back(static_cast<std::uint64_t>(item.as_integer(Range::non_negative())));
}

void read_sample(Study& s, const YamlNode& root, const CaseCheck& check) {
  const auto node = root.optional_child("sample");
  if (!node) return;
  node->allow({"seed", "draws", "values", "fisher"});
  s.sample_seed = static_cast<std::uint64_t>(node->integer("seed", Range::non_negative()));
  s.draws = static_cast<std::size_t>(node->integer("draws", Range::closed(1, 1e9)));
  if (const auto values = node->optional_child("values")) {
    if (!values->is_map()) values->fail("must be a mapping of key paths to distributions");
    for (const std::string& key : values->keys()) {
      const YamlNode law = values->child(key);
      SampledKey k{key_path_of(law, key), read_distribution(law)};
      try_value(s, check, law, k.path, YAML::Node(round_trip(k.law.typical())), round_trip(k.law.typical()));
      s.sampled.push_back(std::move(k));
    }
  }
  for (const YamlNode& item : node->list_or_empty("fisher")) {
    item.allow({"dip", "dip_direction", "kappa"});
    SampledPlane p{key_path_of(item.child("dip"), item.text("dip")),
                   key_path_of(item.child("dip_direction"), item.text("dip_direction")),
                   item.number("kappa", Range::positive())};
    for (const auto& [key, path] : {std::pair{"dip", &p.dip}, std::pair{"dip_direction", &p.dip_direction}}) {
      const auto value = get_at(s.base, *path);
      if (!value || !value->IsScalar()) item.fail_key(key, "names no number of the base: '" + path->text + "'");
      try_value(s, check, item.child(key), *path, *value, value->Scalar());
    }
    s.planes.push_back(std::move(p));
  }
  if (s.sampled.empty() && s.planes.empty()) node->fail("needs values or fisher: it samples nothing");
}

void read_measures(Study& s, const YamlNode& root) {
  const auto items = root.list("measure");
  if (items.empty()) root.child("measure").fail("is empty: a study needs at least one measure");
  for (const YamlNode& item : items) {
    MeasureSpec m = read_measure(item, s.kind);
    for (const MeasureSpec& other : s.measures)
      if (other.name == m.name) item.fail("repeats the measure name '" + m.name + "'");
    s.measures.push_back(std::move(m));
  }
}

void read_failure(Study& s, const YamlNode& root) {
  const auto node = root.optional_child("failure");
  if (!node) return;
  node->allow({"measure", "below", "above"});
  Failure f;
  f.measure = node->text("measure");
  bool known = false;
  for (const MeasureSpec& m : s.measures) known = known || m.name == f.measure;
  if (!known) node->fail_key("measure", "names no measure of the study: '" + f.measure + "'");
  if (node->has("below")) f.below = node->number("below");
  if (node->has("above")) f.above = node->number("above");
  if (f.below.has_value() == f.above.has_value()) node->fail("needs exactly one of below and above");
  s.failure = f;
}

}  // namespace

Study read_study(const std::string& path, const CaseCheck& scenario_check) {
  if (!fs::exists(path)) throw InputError(path + ": no such file.");
  const YamlNode root = YamlNode::load_file(path);
  root.allow({"name", "description", "scenario", "wedge", "vary", "seeds", "sample", "measure", "failure"});
  Study s;
  s.file = path;
  s.text = root.source_text();
  read_base(s, root);
  const CaseCheck check = s.kind == CaseKind::wedge ? CaseCheck(check_wedge_document) : scenario_check;
  try {
    check(s.base, s.base_label);
  } catch (const InputError& e) {
    root.child(s.kind == CaseKind::wedge ? "wedge" : "scenario")
        .fail("is refused by its reader: " + without_full_stop(without_label(e.what(), s.base_label)));
  }
  read_seeds(s, root);
  read_vary(s, root, check);
  read_sample(s, root, check);
  read_measures(s, root);
  read_failure(s, root);
  // A key set in two places would take the value of whichever comes last.
  std::vector<std::string> columns = s.value_columns();
  std::sort(columns.begin(), columns.end());
  for (std::size_t k = 1; k < columns.size(); ++k)
    if (columns[k] == columns[k - 1])
      throw InputError(path + ": sets the key path '" + columns[k] +
                       "' twice (vary, sample.values and sample.fisher together): give it its values in one place.");
  return s;
}

}  // namespace dda::study
