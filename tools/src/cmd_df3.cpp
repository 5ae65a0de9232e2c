// The 3D forward run behind `dda df` (a dda-blocks3d file), `dda df --resume`
// (a dda-results3d file) and `dda run` (a dimension: 3 scenario with a
// control section): the 2D run's session (df_session.hpp) around a
// Simulation3 and its results file (df/results3d.hpp).
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "dda/common/error.hpp"
#include "dda/common/scenario.hpp"
#include "dda/df/results3d.hpp"
#include "dda/df/scenario3d.hpp"
#include "df_session.hpp"
#include "pipeline.hpp"

namespace dda::cli {

namespace fs = std::filesystem;

namespace {

struct Job3 {
  df3::Results3 results;
  df3::DfScenario3 scenario;
  OutputOptions output;
};

Job3 job_from_scenario3(const YamlNode& root, const PolyhedronModel& blocks, const std::string& blocks_path) {
  Job3 job;
  job.scenario = df3::read_df3_scenario(root, blocks, blocks_path);
  job.output = parse_output_options(root);
  df3::Results3& r = job.results;
  r.source = scenario_source(root, blocks.provenance.seed, blocks_path);
  r.blocks = blocks;
  r.output = df3::resolve_output_schedule(job.scenario.output, job.scenario.model.control);
  return job;
}

void execute3(Job3& job, const DfStage& stage, const std::optional<df3::Simulation3State>& resume_from) {
  df3::Simulation3 sim(job.scenario.model);
  if (resume_from) sim.restore(*resume_from);
  run_session(sim, job.results, job.output, stage,
              [&job](const df3::Simulation3& s, const std::string& blocks, const std::string& contacts) {
                df3::write_blocks3_frame_vtu(blocks, s, job.results.blocks.blocks);
                if (!contacts.empty()) df3::write_contacts3_vtu(contacts, s);
              });
}

}  // namespace

void run_df3_scenario(const YamlNode& root, const PolyhedronModel& blocks, const std::string& blocks_path,
                      const DfStage& stage) {
  Job3 job = job_from_scenario3(root, blocks, blocks_path);
  execute3(job, stage, std::nullopt);
}

void resume_df3(const std::string& path, DfStage stage) {
  df3::Results3 saved = df3::read_results3_h5(path);
  if (stage.results_path.empty()) stage.results_path = path;
  const df::ResultsSource& src = saved.source;
  if (saved.complete) {
    say(stage.quiet, path + ": the run is already complete (" + std::to_string(saved.log.size()) +
                         " steps); nothing to resume.\n");
    return;
  }
  Job3 job;
  try {
    const YamlNode root = YamlNode::load_string(src.provenance.scenario_text, src.provenance.scenario_path);
    root.allow(scenario_sections());
    job = job_from_scenario3(root, saved.blocks, src.blocks_path);
  } catch (const InputError& e) {
    throw InputError(path + ": the scenario stored in the file no longer reads: " + e.what());
  }
  // What was saved wins: the schedule (and solver) the run started with.
  adopt_saved(job.results, saved, path, stage);
  execute3(job, stage, saved.checkpoint);
}

}  // namespace dda::cli
