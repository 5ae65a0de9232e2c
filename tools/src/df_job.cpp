// What the 2D and 3D forward runs share that needs no template (df_job.hpp).
#include "df_job.hpp"

#include "dda/common/scenario.hpp"

namespace dda::cli {

YamlNode stored_scenario(const df::ResultsSource& source) {
  YamlNode root = YamlNode::load_string(source.provenance.scenario_text, source.provenance.scenario_path);
  root.allow(scenario_sections());
  return root;
}

}  // namespace dda::cli
