#include "dda/study/measure.hpp"

#include <vector>

#include "dda/study/study.hpp"

namespace dda::study {

namespace {

// Every measure kind, once: the case kind it applies to, the key it needs
// besides kind and name (if any), and what it is (docs/studies.md).
struct KindInfo {
  const char* name;
  CaseKind applies_to;
  const char* needs;  // "" for none
};
const std::vector<KindInfo>& kinds() {
  static const std::vector<KindInfo> table = {
      // Pipeline: DC's stats.json, DF's results.h5.
      {"stats", CaseKind::pipeline, "key"},                  // a number of stats.json
      {"point_displacement", CaseKind::pipeline, "point"},   // |displacement| of a measurement point, final or peak
      {"blocks_displaced", CaseKind::pipeline, "threshold"}, // blocks whose centroid moved more than threshold
      {"blocks_below", CaseKind::pipeline, "level"},         // blocks that started above y = level and ended below
      {"kinetic_energy", CaseKind::pipeline, ""},            // J per m, at the end of the run
      // Wedge: dda wedge's limit equilibrium.
      {"fs", CaseKind::wedge, ""},
      {"yield_acceleration", CaseKind::wedge, ""},  // g; empty when none up to 10 g
      {"wedge_factor", CaseKind::wedge, ""},
      {"critical_friction", CaseKind::wedge, ""},   // deg
      {"trend", CaseKind::wedge, ""},               // of the line of intersection, deg
      {"plunge", CaseKind::wedge, ""},
  };
  return table;
}

std::string kind_names(CaseKind kind) {
  std::string out;
  for (const KindInfo& k : kinds())
    if (k.applies_to == kind) out += (out.empty() ? "" : ", ") + std::string(k.name);
  return out;
}

const char* case_kind_name(CaseKind kind) { return kind == CaseKind::wedge ? "a wedge study" : "a scenario study"; }

}  // namespace

MeasureSpec read_measure(const YamlNode& node, CaseKind kind) {
  MeasureSpec m;
  if (node.is_scalar()) {
    m.kind = node.as_text();
    m.name = m.kind;
  } else {
    node.allow({"kind", "name", "key", "point", "of", "threshold", "level"});
    m.kind = node.text("kind");
    m.name = node.text("name", m.kind);
  }
  const KindInfo* info = nullptr;
  for (const KindInfo& k : kinds())
    if (m.kind == k.name) info = &k;
  if (!info || info->applies_to != kind)
    node.fail("names the measure kind '" + m.kind + "', which " + case_kind_name(kind) + " does not have; its kinds are " +
              kind_names(kind));
  const std::string needs = info->needs;
  if (!needs.empty() && node.is_scalar()) node.fail("needs " + needs + ": write {kind: " + m.kind + ", " + needs + ": ...}");
  if (!node.is_scalar()) {
    for (const char* key : {"key", "point", "of", "threshold", "level"}) {
      const bool wanted = needs == key || (m.kind == "point_displacement" && std::string(key) == "of");
      if (node.has(key) && !wanted) node.fail_key(key, "is not a key of the measure kind " + m.kind);
    }
    if (needs == "key") m.key = node.text("key");
    if (needs == "point") {
      m.point = node.text("point");
      m.of = node.choice("of", {"final", "peak"}, "final");
    }
    if (needs == "threshold") m.value = node.number("threshold", Range::positive());
    if (needs == "level") m.value = node.number("level");
  }
  if (m.name.empty() || m.name.find_first_of(",\"\n") != std::string::npos)
    node.fail("needs a name without commas, quotes or line breaks, got '" + m.name + "'");
  return m;
}

}  // namespace dda::study
