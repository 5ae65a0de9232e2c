#pragma once
// The one place the project turns YAML text into a yaml-cpp tree.
//
// yaml-cpp reads more than a scenario may hold: it keeps every pair of a
// mapping that gives a key twice (and a lookup then quietly answers with the
// first), and YAML::Load stops after the first document of a file that has
// several. Both hide a user's edit: the second `dt:` or everything after a
// stray `---` would be ignored without a word. This parser refuses them.
#include <yaml-cpp/yaml.h>

#include <string>

namespace dda::yaml_strict {

// Parses `text`, the whole of `file_label`, as exactly one YAML document.
// Throws InputError for a syntax error, a second document, or a key given
// twice in one mapping (naming the key path and both lines).
YAML::Node parse_document(const std::string& text, const std::string& file_label);

}  // namespace dda::yaml_strict
