#pragma once
// The forward run behind `dda df`, `dda df --resume` and `dda run`, one
// piece for 2D (cmd_df.cpp) and 3D (cmd_df3d.cpp): what a run needs (the
// Job), running it in the session of df_session.hpp, and resuming a saved
// run from its results file.
//
// What differs by dimension comes from a traits type Dim:
//   using Simulation, Results, Scenario, State;  the solver, its results, its scenario, its checkpoint
//   static Results read_results(const std::string& path);    a saved run, with its checkpoint
//   static DfJob<Dim> job_from_saved(const Results& saved);  the saved run's job, read again from
//                                                            the scenario stored in the file
//   static <model> model_of(const DfJob<Dim>& job);          what the Simulation is built from
// (what a run writes is df_outputs.hpp's, through the dimension's hooks).
#include <optional>
#include <string>
#include <utility>

#include "commands.hpp"
#include "dda/common/error.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/df/io/results.hpp"
#include "df_session.hpp"
#include "pipeline.hpp"

namespace dda::cli {

template <class Dim>
struct DfJob {
  typename Dim::Results results;
  typename Dim::Scenario scenario;
  OutputOptions output;
  std::string input_files;  // what an error of the model is said after
};

// The part of a job from a scenario that both dimensions fill alike: the
// output options, where the run comes from and the blocks it starts with.
template <class Dim, class Blocks>
void fill_job_from_scenario(DfJob<Dim>& job, const YamlNode& root, const Blocks& blocks, const std::string& blocks_path) {
  job.output = parse_output_options(root);
  job.input_files = root.file();
  job.results.source = scenario_source(root, blocks.provenance.seed, blocks_path);
  job.results.blocks = blocks;
}

// The scenario stored in a results file, read again as `dda run` reads one
// (its sections checked); an InputError says what no longer reads.
YamlNode stored_scenario(const df::ResultsSource& source);

// Builds the simulation, puts back `resume_from` if given, and runs it to
// its end with everything `dda df` does around a run (run_session).
template <class Dim>
void execute_job(DfJob<Dim>& job, const DfStage& stage, std::optional<typename Dim::State> resume_from) {
  typename Dim::Simulation sim(Dim::model_of(job));
  if (resume_from) sim.restore(*resume_from);
  run_session(sim, job.results, job.output, stage);
}

// `dda df --resume path`: continues the run saved in `path` from its
// checkpoint (into stage.results_path, by default `path` itself), with the
// output schedule and solver it started with; a complete run is left as it
// is, with a note.
template <class Dim>
void resume_job(const std::string& path, DfStage stage) {
  typename Dim::Results saved = Dim::read_results(path);
  if (stage.results_path.empty()) stage.results_path = path;
  if (saved.complete) {
    say(stage.quiet, path + ": the run is already complete (" + std::to_string(saved.log.size()) +
                         " steps); nothing to resume.\n");
    return;
  }
  DfJob<Dim> job;
  try {
    job = Dim::job_from_saved(saved);
  } catch (const InputError& e) {
    throw InputError(path + ": the scenario stored in the file no longer reads: " + e.what());
  }
  // What was saved wins: the schedule (and solver) the run started with.
  adopt_saved(job.results, saved, path, stage);
  execute_job<Dim>(job, stage, std::move(saved.checkpoint));
}

}  // namespace dda::cli
