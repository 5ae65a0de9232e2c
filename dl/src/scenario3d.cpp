// DL in 3D: the sections in order, and the readers they share.
#include "dda/dl/scenario3d.hpp"

#include <sstream>

#include "builder.hpp"  // detail::format_number
#include "dda/common/coordinate_range.hpp"
#include "dda/common/provenance.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/sentence_tail.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl {

namespace detail {

int Builder3::add_new_set(const std::string& name, const std::string& origin, const YamlNode& node,
                          const std::string& key) {
  check_set_name_free(name, node, key);
  model.sets.push_back({name, origin});
  asked_p32.emplace_back();
  return static_cast<int>(model.sets.size()) - 1;
}

void Builder3::check_set_name_free(const std::string& name, const YamlNode& node, const std::string& key) const {
  for (const JointSetInfo& s : model.sets)
    if (s.name == name) node.fail_key(key, "'" + name + "' is already the name of another set (" + s.origin + ")");
}

Vec3 as_point3(const YamlNode& node) {
  if (!node.is_sequence()) node.fail("must be a point [x, y, z]");
  const std::vector<double> v = node.as_numbers();
  if (v.size() != 3) node.fail("must be a point [x, y, z], got " + std::to_string(v.size()) + " numbers");
  return {v[0], v[1], v[2]};
}

Vec3 point3(const YamlNode& node, const std::string& key) { return as_point3(node.child(key)); }

double read_dip(const YamlNode& node, const std::string& key) { return node.number(key, Range::closed(0, 90)); }
double read_dip(const YamlNode& node, const std::string& key, double fallback) {
  return node.number(key, fallback, Range::closed(0, 90));
}
double read_dip_direction(const YamlNode& node, const std::string& key) {
  return node.number(key, Range::closed(0, 360));
}
double read_dip_direction(const YamlNode& node, const std::string& key, double fallback) {
  return node.number(key, fallback, Range::closed(0, 360));
}

std::string read_name(const YamlNode& node, const char* prefix, std::size_t index) {
  std::string fallback = prefix;  // appended, not prefix + ...: GCC 12 -Wrestrict false positive
  fallback += std::to_string(index + 1);
  const std::string name = node.text("name", fallback);
  if (name.empty()) node.fail_key("name", "must not be empty");
  return name;
}

void fail_from(const YamlNode& node, const std::string& key, const std::string& prefix, const InputError& e) {
  // The library's sentence becomes a clause: no capital (unless it starts an
  // acronym such as P32), no full stop; fail_key adds the one full stop.
  node.fail_key(key, prefix + ": " + with_lowered_start(sentence_tail(e)));
}

std::string point_text(const Vec3& p) {
  std::string s = "(";  // appended, not "(" + ...: GCC 12 -Wrestrict false positive
  s += format_number(p.x()) + ", " + format_number(p.y()) + ", " + format_number(p.z()) + ")";
  return s;
}

}  // namespace detail

int scenario_dimension(const YamlNode& root) {
  const auto node = root.optional_child("dimension");
  if (!node) return 2;
  const long long d = node->as_integer();
  if (d != 2 && d != 3) node->fail("must be 2 or 3, got " + std::to_string(d));
  return static_cast<int>(d);
}

DlResult3 generate_3d_from_scenario(const YamlNode& root) {
  // The sections a 3D job reads, `cutting`, which the 3D cutter reads from
  // the scenario stored in the fractures file, `output` (dda run) and the
  // forward run's (DF reads them, df/io/scenario3d.hpp). load_scenario names
  // the 2D-only sections more helpfully.
  root.allow({"name", "description", "seed", "dimension", "domain", "fracture_sets", "persistent_sets", "planes",
              "layering", "fracture_files", "excavations", "points", "trace_planes", "cutting", "output",
              "materials", "joints", "loading", "fixed", "water", "bolts", "boundaries", "control"});
  if (scenario_dimension(root) != 3)
    root.fail_key("dimension", "must be 3 for a 3D fracture network (add dimension: 3 at the top level)");
  detail::Builder3 b;
  b.seed = scenario_seed(root);
  b.report["dimension"] = 3;
  b.report["seed"] = b.seed;
  detail::read_domain3(root, b);
  // The domain first, before any fracture is generated in it; it chooses
  // the local origin every later position is read about.
  const std::vector<Vec3> domain =
      b.model.domain_surface ? b.model.domain_surface->vertices : std::vector<Vec3>{b.model.domain.lo, b.model.domain.hi};
  check_coordinate_range(domain, root.file());
  b.model.origin = choose_local_origin(domain);
  b.model.domain.lo -= b.model.origin, b.model.domain.hi -= b.model.origin;
  if (b.model.domain_surface)
    for (Vec3& v : b.model.domain_surface->vertices) v -= b.model.origin;
  detail::read_fracture_sets3(root, b);
  detail::read_persistent_sets3(root, b);
  detail::read_planes3(root, b);
  detail::read_layering3(root, b);
  detail::read_fracture_files3(root, b);
  detail::read_excavations3(root, b);
  detail::read_points3(root, b);
  detail::read_trace_planes3(root, b);
  detail::add_measures_to_report3(b);
  check_coordinate_range(b.model, root.file());

  Provenance& p = b.model.provenance;
  p.scenario_text = root.source_text();
  p.scenario_path = root.file();
  p.seed = b.seed;
  p.program_version = version_string();
  return {std::move(b.model), std::move(b.report), std::move(b.trace_planes)};
}

}  // namespace dda::dl
