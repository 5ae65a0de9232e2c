// 2D scenarios: the strict YAML loader, DL's generation of the lines (every
// section: domain, joint sets, layering, lines, points; files a scenario
// names are read too) and DF's check of its sections.
#include "dda/common/yaml_reader.hpp"
#include "dda/df/io/scenario.hpp"
#include "dda/dl/generate.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = dda::fuzz::as_text(data, size);
  dda::fuzz::refuse_only_with_input_errors([&] {
    const dda::YamlNode root = dda::YamlNode::load_string(text, "s.yaml");
    if (dda::df::scenario_has_df(root)) dda::df::check_df_scenario(root);
    dda::dl::generate_from_scenario(root);
  });
  return 0;
}
