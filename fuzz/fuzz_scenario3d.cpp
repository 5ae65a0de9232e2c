// 3D scenarios: the strict YAML loader, DL's generation of the fractures
// (domain, fracture sets, planes, layering, excavations, trace planes) and
// DF's check of its 3D sections.
#include "dda/common/yaml_reader.hpp"
#include "dda/df/io/scenario3d.hpp"
#include "dda/dl/scenario3d.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = dda::fuzz::as_text(data, size);
  dda::fuzz::refuse_only_with_input_errors([&] {
    const dda::YamlNode root = dda::YamlNode::load_string(text, "s.yaml");
    dda::df3::check_df3_scenario(root);
    dda::dl::generate_3d_from_scenario(root);
  });
  return 0;
}
