// The `joints` section of the scenario (scenario_joints.hpp); keys in
// docs/scenario.md.
#include "io/scenario_joints.hpp"

#include <algorithm>

#include "dda/common/error.hpp"
#include "dda/df/core/friction.hpp"
#include "dda/df/core/normal_law.hpp"

namespace dda::df {
namespace {

// friction_law as a mapping: the law's name and its own numbers and words
// (FrictionLawSpec); ranges are checked here, the rest by the law itself.
void read_friction_law(const YamlNode& f, JointProperties& j) {
  const std::string name = f.text("name");
  const FrictionLawEntry* law = find_friction_law(name);
  if (!law) {
    std::string known;
    for (const FrictionLawEntry& e : friction_laws()) known += (known.empty() ? "" : ", ") + e.name;
    f.fail_key("name", "must be a known friction law (" + known + "), got '" + name + "'");
  }
  const FrictionLawSpec spec = law->spec();
  std::vector<std::string> keys{"name"};
  for (const FrictionParameter& p : spec.numbers) keys.push_back(p.key);
  for (const FrictionOption& w : spec.words) keys.push_back(w.key);
  f.allow(keys);
  j.friction_law = name;
  j.friction_parameters.clear();
  j.friction_options.clear();
  for (const FrictionParameter& p : spec.numbers)
    if (f.has(p.key)) j.friction_parameters[p.key] = f.number(p.key, p.range);
  for (const FrictionOption& w : spec.words)
    if (f.has(w.key)) j.friction_options[w.key] = f.text(w.key);
}

// normal_law: a name, or {name: ..., <parameter>: value, ...}; a set that
// names the base's law keeps its numbers, as for friction_law.
void read_normal_law(const YamlNode& n, JointProperties& j, const JointProperties& base) {
  const YamlNode f = n.child("normal_law");
  const std::string name = f.is_map() ? f.text("name") : f.as_text();
  const NormalLawEntry* law = find_normal_law(name);
  if (!law) {
    std::string known;
    for (const NormalLawEntry& e : normal_laws()) known += (known.empty() ? "" : ", ") + e.name;
    const std::string phrase = "must be a known normal law (" + known + "), got '" + name + "'";
    if (f.is_map()) f.fail_key("name", phrase);
    n.fail_key("normal_law", phrase);
  }
  j.normal_law = name;
  if (!f.is_map()) {
    if (name != base.normal_law) j.normal_parameters.clear();
  } else {
    std::vector<std::string> keys{"name"};
    for (const NormalLawParameter& p : law->numbers) keys.push_back(p.key);
    f.allow(keys);
    j.normal_parameters.clear();
    for (const NormalLawParameter& p : law->numbers) j.normal_parameters[p.key] = f.number(p.key, p.range);
  }
  try {
    make_normal_law(j, 1.0);
  } catch (const InputError& e) {
    n.fail_key("normal_law", std::string("is not usable: ") + e.what());
  }
}

JointProperties read_joint(const YamlNode& n, const JointProperties& base) {
  JointProperties j = base;
  j.friction_deg = n.number("friction_deg", base.friction_deg, Range::half_open(0, 90));
  j.cohesion = n.number("cohesion", base.cohesion, Range::non_negative());
  j.tensile_strength = n.number("tensile_strength", base.tensile_strength, Range::non_negative());
  j.saturation = n.number("saturation", base.saturation, Range::closed(0, 1));
  if (n.has("normal_penalty")) j.normal_penalty = n.number("normal_penalty", Range::positive());
  if (n.has("shear_penalty")) j.shear_penalty = n.number("shear_penalty", Range::positive());
  // friction_law: a name (keeping the parameters of the base, if any, when
  // it names the base's law), or {name: ..., <parameter>: value, ...}.
  std::optional<YamlNode> law_node;
  if (n.has("friction_law")) {
    const YamlNode f = n.child("friction_law");
    if (f.is_map()) {
      read_friction_law(f, j);
      law_node = f;
    } else {
      j.friction_law = f.as_text();
      if (j.friction_law != base.friction_law) j.friction_parameters.clear(), j.friction_options.clear();
    }
  }
  if (n.has("normal_law")) read_normal_law(n, j, base);
  try {
    make_friction_law(j);
  } catch (const FrictionParameterError& e) {
    if (law_node) law_node->fail_key(e.key(), e.phrase());
    n.fail_key("friction_law", std::string("is not usable: ") + e.what());
  } catch (const InputError& e) {
    n.fail_key("friction_law", std::string("is not usable: ") + e.what());
  }
  return j;
}

}  // namespace

const std::vector<std::string>& joint_keys() {
  static const std::vector<std::string> keys{"friction_deg",  "cohesion",     "tensile_strength", "normal_penalty",
                                             "shear_penalty", "friction_law", "normal_law",     "saturation"};
  return keys;
}

std::string join_names(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
  return s.empty() ? "none" : s;
}

JointsSection read_joints_section(const YamlNode& root) {
  JointsSection out;
  const auto j = root.optional_child("joints");
  if (!j) return out;
  if (!j->is_map()) j->fail("must be a mapping of joint set names (and default) to joint properties");
  if (auto d = j->optional_child("default")) {
    d->allow(joint_keys());
    out.default_joint = read_joint(*d, out.default_joint);
  }
  for (const std::string& name : j->keys()) {  // in file order
    if (name == "default") continue;
    const YamlNode n = j->child(name);
    bool given = false;
    for (const std::string& k : joint_keys()) given = given || n.has(k);
    if (!given) {
      if (n.is_map()) n.allow(joint_keys());
      n.fail("gives no joint properties (give at least one of " + join_names(joint_keys()) + ")");
    }
    n.allow(joint_keys());
    out.sets.push_back({n, name, read_joint(n, out.default_joint)});
  }
  return out;
}

std::vector<JointProperties> joints_by_set(const JointsSection& joints, const std::vector<JointSetInfo>& sets,
                                           const std::string& blocks_path) {
  std::vector<std::string> names;
  for (const JointSetInfo& s : sets) names.push_back(s.name);
  std::vector<JointProperties> out(sets.size(), joints.default_joint);
  for (const JointsSection::Named& named : joints.sets) {
    const auto it = std::find(names.begin(), names.end(), named.name);
    if (it == names.end())
      named.node.fail("names a joint set that " + blocks_path + " does not have (its sets are " + join_names(names) +
                      ")");
    out[static_cast<std::size_t>(it - names.begin())] = named.joint;
  }
  return out;
}

}  // namespace dda::df
