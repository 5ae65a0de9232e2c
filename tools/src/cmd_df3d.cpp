// The 3D forward run behind `dda df` (a dda-blocks3d file), `dda df --resume`
// (a dda-results3d file) and `dda run` (a dimension: 3 scenario with a
// control section): the job of df_job.hpp, shared with 2D, with the 3D
// types (Simulation3 and its results file, df/io/results3d.hpp).
#include "commands.hpp"
#include "dda/df/io/results3d.hpp"
#include "dda/df/io/scenario3d.hpp"
#include "df_job.hpp"

namespace dda::cli {

namespace {

// The 3D side of df_job.hpp.
struct Df3 {
  using Simulation = df3::Simulation3;
  using Results = df3::Results3;
  using Scenario = df3::DfScenario3;
  using State = df3::SimulationState3;
  static Results read_results(const std::string& path) { return df3::read_results3_h5(path); }
  static DfJob<Df3> job_from_saved(const Results& saved);
  static const df3::Model3& model_of(const DfJob<Df3>& job) { return job.scenario.model; }
};
using Job3 = DfJob<Df3>;

Job3 job_from_scenario3(const YamlNode& root, const PolyhedronModel& blocks, const std::string& blocks_path) {
  Job3 job;
  job.scenario = df3::read_df3_scenario(root, blocks, blocks_path);
  fill_job_from_scenario(job, root, blocks, blocks_path);
  job.results.output = df3::resolve_output_schedule(job.scenario.output, job.scenario.model.control);
  return job;
}

Job3 Df3::job_from_saved(const Results& saved) {
  return job_from_scenario3(stored_scenario(saved.source), saved.blocks, saved.source.blocks_path);
}

}  // namespace

void run_df3_scenario(const YamlNode& root, const PolyhedronModel& blocks, const std::string& blocks_path,
                      const DfStage& stage) {
  Job3 job = job_from_scenario3(root, blocks, blocks_path);
  execute_job<Df3>(job, stage, std::nullopt);
}

void resume_df3(const std::string& path, DfStage stage) { resume_job<Df3>(path, stage); }

}  // namespace dda::cli
