#pragma once
// Private to DL: the 3D model being built from the scenario sections, and the
// readers the sections share.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/common/fracture_model.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/dl/scenario3d.hpp"

namespace dda::dl::detail {

struct Builder3 {
  FractureModel model;
  nlohmann::json report = nlohmann::json::object();
  std::uint64_t seed = 1;
  std::vector<TracePlaneSpec> trace_planes;
  // Per set (index = Fracture3::set): the P32 the scenario asked for, if any.
  std::vector<std::optional<double>> asked_p32;

  // Adds a new set; a set of that name must not exist yet (node/key name the error).
  int add_new_set(const std::string& name, const std::string& origin, const YamlNode& node, const std::string& key);
  // Fails at node.key unless `name` is free (for sets that a library call adds).
  void check_set_name_free(const std::string& name, const YamlNode& node, const std::string& key) const;
  double diagonal() const { return (model.domain.hi - model.domain.lo).norm(); }
  // A position the user gave, about the model's local origin (the domain
  // chose it; coordinate_range.hpp).
  Vec3 local(const Vec3& user) const { return user - model.origin; }
};

// [x, y, z] at node.key, or the node itself.
Vec3 as_point3(const YamlNode& node);
Vec3 point3(const YamlNode& node, const std::string& key);
// Orientation keys: dip in [0, 90], dip direction in [0, 360].
double read_dip(const YamlNode& node, const std::string& key);
double read_dip(const YamlNode& node, const std::string& key, double fallback);
double read_dip_direction(const YamlNode& node, const std::string& key);
double read_dip_direction(const YamlNode& node, const std::string& key, double fallback);
// The `name` key: text, not empty; when absent, prefix + (index + 1) (F1, F2, ...).
std::string read_name(const YamlNode& node, const char* prefix, std::size_t index);

// Re-throws a library InputError (a whole sentence) as one naming the
// scenario file, line and key: "file:line: key <prefix>: <sentence>".
[[noreturn]] void fail_from(const YamlNode& node, const std::string& key, const std::string& prefix,
                            const InputError& e);

// "(x, y, z)"
std::string point_text(const Vec3& p);

// One function per section, in the order generate_3d_from_scenario calls
// them (the order that numbers the sets).
void read_domain3(const YamlNode& root, Builder3& b);
void read_fracture_sets3(const YamlNode& root, Builder3& b);
void read_persistent_sets3(const YamlNode& root, Builder3& b);
void read_planes3(const YamlNode& root, Builder3& b);
void read_layering3(const YamlNode& root, Builder3& b);
void read_fracture_files3(const YamlNode& root, Builder3& b);
void read_excavations3(const YamlNode& root, Builder3& b);
void read_points3(const YamlNode& root, Builder3& b);
void read_trace_planes3(const YamlNode& root, Builder3& b);
// Per-set measures (count, P32, P10, P21, size, orientation) and totals.
void add_measures_to_report3(Builder3& b);

}  // namespace dda::dl::detail
