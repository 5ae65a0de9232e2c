#pragma once
// The scenario's `joints` section, 2D and 3D alike (private to DF; keys in
// docs/scenario.md): `default` and one entry per joint set name, each a
// JointProperties with its friction law.
#include <string>
#include <vector>

#include "dda/common/line_model.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/df/2d/model.hpp"

namespace dda::df {

struct JointsSection {
  JointProperties default_joint;
  struct Named {
    YamlNode node;
    std::string name;
    JointProperties joint;  // the default's values for every key it does not give
  };
  std::vector<Named> sets;  // in file order
};

// The keys a joint entry may hold.
const std::vector<std::string>& joint_keys();

// Reads `joints` of the scenario root (absent: the default joint only).
JointsSection read_joints_section(const YamlNode& root);

// One JointProperties per joint set of the blocks file (index = set id):
// the named ones from the scenario, the others the default. A name the
// blocks do not have is an error naming `blocks_path` and its sets.
std::vector<JointProperties> joints_by_set(const JointsSection& joints, const std::vector<JointSetInfo>& sets,
                                           const std::string& blocks_path);

// "a, b, c", or "none".
std::string join_names(const std::vector<std::string>& names);

}  // namespace dda::df
