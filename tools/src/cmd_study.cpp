// dda study STUDY.yaml -o OUTDIR [-j N] [--yes]: parameter sweeps and Monte
// Carlo realisations of a scenario or of the analytical wedge (docs/studies.md).
//
// The study file is checked whole, every value through the reader a case
// would use, before any case runs. Pipeline cases then run in their own
// folders (OUTDIR/cases/<id>) as child processes of this program, locally
// on a pool (study_pool.hpp) or across MPI ranks (study_mpi.hpp); wedge
// cases run in-process. OUTDIR/summary.csv and OUTDIR/study.h5 hold one row
// per case, OUTDIR/figures the plots of tools/plot/dda_study_plot.py.
#include <chrono>
#include <cmath>
#include <filesystem>

#include "commands.hpp"
#include "dda/common/error.hpp"
#include "dda/common/output_guard.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/short_number.hpp"
#include "dda/dc/cut.hpp"
#include "dda/dc/cut3d.hpp"
#include "dda/df/scenario.hpp"
#include "dda/df/scenario3d.hpp"
#include "dda/dl/generate.hpp"
#include "dda/dl/scenario3d.hpp"
#include "dda/study/expand.hpp"
#include "dda/study/summary.hpp"
#include "dda/study/wedge_case.hpp"
#include "pipeline.hpp"
#include "plot_runner.hpp"
#include "study_mpi.hpp"
#include "study_pool.hpp"
#include "study_report.hpp"

namespace dda::cli {

namespace fs = std::filesystem;

namespace {

// A case's scenario read as `dda run` reads it, every stage's section
// checked (DL generates its lines: its reader checks as it goes).
void check_case_scenario(const YAML::Node& doc, const std::string& label) {
  YAML::Emitter e;
  e << doc;
  const YamlNode root = load_scenario_text(e.c_str(), label);
  parse_output_options(root);
  if (dl::scenario_dimension(root) == 3) {
    dl::generate_3d_from_scenario(root);
    dc::parse_cut3d_options(root.optional_child("cutting"));
    df3::check_df3_scenario(root);
  } else {
    dl::generate_from_scenario(root);
    dc::parse_cut_options(root.optional_child("cutting"));
    df::check_df_scenario(root);
  }
}

// Wedge cases, in-process: the limit equilibrium takes microseconds, so
// thousands of cases take seconds and need no folders.
std::vector<study::CaseRecord> run_wedge_cases(const study::Study& study, const std::vector<study::Case>& cases) {
  std::vector<study::CaseRecord> records;
  records.reserve(cases.size());
  for (const study::Case& c : cases) {
    const auto start = std::chrono::steady_clock::now();
    study::CaseRecord r;
    try {
      YAML::Emitter e;
      e << c.doc;
      const study::WedgeCase w = study::read_wedge_case(YamlNode::load_string(e.c_str(), study.file + " (case " + c.id + ")"));
      r.measures = study::wedge_measures(w, study.measures);
      r.ok = true;
    } catch (const std::exception& ex) {
      r.error = ex.what();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    records.push_back(std::move(r));
  }
  return records;
}

}  // namespace

void add_study_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string study, outdir;
    int jobs = 0;
    long long max_cases = -1;
    bool yes = false, retry_failed = false, no_plots = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "study",
      "Run a study: a grid of scenario values, realisation seeds and Monte Carlo draws, each case a full pipeline "
      "(or an analytical wedge), locally on a pool of processes or across MPI ranks (mpirun); one summary row per "
      "case (docs/studies.md)");
  cmd->add_option("study", opt->study, "Study file (.yaml)")->required();
  cmd->add_option("-o,--output", opt->outdir, "Output folder (created if missing; a rerun resumes it)")->required();
  cmd->add_option("-j,--jobs", opt->jobs,
                  "Cases run at once (default: one per core, one thread each; with -j N the cores are shared out)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--max-cases", opt->max_cases,
                  "Ask for --yes above this many cases (default 500 scenario cases, 1000000 wedge cases)")
      ->check(CLI::Range(1LL, 1000000000LL));
  cmd->add_flag("--yes", opt->yes, "Run however many cases the study makes");
  cmd->add_flag("--retry-failed", opt->retry_failed, "Run again the cases that failed in an earlier run");
  cmd->add_flag("--no-plots", opt->no_plots, "Do not draw the figures");
  cmd->callback([opt, &global] {
    const MpiWorld world;
    const bool root_rank = world.rank() == 0;
    const study::Study study = study::read_study(opt->study, check_case_scenario);
    const bool wedge = study.kind == study::CaseKind::wedge;
    const std::size_t count = study.case_count();
    const long long limit = opt->max_cases > 0 ? opt->max_cases : (wedge ? 1000000 : 500);
    if (!opt->yes && count > static_cast<std::size_t>(limit))
      throw InputError(opt->study + ": makes " + std::to_string(count) + " cases, more than " + std::to_string(limit) +
                       "; give --yes to run them all (or --max-cases N).");

    const fs::path out(opt->outdir);
    std::vector<std::string> inputs{opt->study};
    if (!wedge && study.base_label != study.file) inputs.push_back(study.base_label);
    refuse_overwriting_inputs(inputs, {opt->outdir, (out / "summary.csv").string(), (out / "study.h5").string()},
                              {(out / "cases").string(), (out / "figures").string()});
    std::vector<study::Case> cases;
    cases.reserve(count);
    for (std::size_t i = 0; i < count; ++i) cases.push_back(study::make_case(study, i));
    if (!wedge) {
      // The first case whole: values that pass one at a time may still clash.
      try {
        check_case_scenario(cases.front().doc, study.base_label);
      } catch (const InputError& e) {
        throw InputError(opt->study + ": its first case (" + cases.front().id + ") is refused: " + e.what());
      }
    }
    make_dir(out);

    const auto start = std::chrono::steady_clock::now();
    std::vector<study::CaseRecord> records;
    if (wedge) {
      if (root_rank) records = run_wedge_cases(study, cases);
    } else {
      PoolOptions pool = default_pool(opt->jobs);
      pool.quiet = global.quiet;
      pool.retry_failed = opt->retry_failed;
      if (world.size() > 1) {
        pool.threads = world.threads_per_rank();
        records = run_pipeline_cases_mpi(study, cases, out, pool, world);
      } else {
        say(global.quiet, "study: " + std::to_string(count) + " cases, " + std::to_string(pool.jobs) + " at once on " +
                              std::to_string(pool.threads) + " thread" + (pool.threads > 1 ? "s" : "") + " each\n");
        records = run_pipeline_cases(study, cases, out, pool);
      }
    }
    if (!root_rank) return;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    study::write_summary_csv((out / "summary.csv").string(), study, cases, records);
    study::write_study_h5((out / "study.h5").string(), study, cases, records);
    say(global.quiet, describe_study(study, records, seconds) + "summary written to " + (out / "summary.csv").string() +
                          " and " + (out / "study.h5").string() + "\n");
    if (!opt->no_plots) draw_study_figures(study, out, global.quiet);
  });
}

}  // namespace dda::cli
