// dda study STUDY.yaml -o OUTDIR [-j N] [--yes]: parameter sweeps and Monte
// Carlo realisations of a scenario or of the analytical wedge (docs/studies.md).
//
// The study file is checked whole, every value through the reader a case
// would use, before any case runs. Pipeline cases then run in their own
// folders (OUTDIR/cases/<id>) as child processes of this program, locally
// on a pool (study_pool.hpp) or across MPI ranks (study_mpi.hpp); wedge
// cases run in-process. OUTDIR/summary.csv and OUTDIR/study.h5 hold one row
// per case, OUTDIR/figures the plots of tools/plot/dda_study_plot.py.
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <thread>

#include "commands.hpp"
#include "dda/common/error.hpp"
#include "dda/common/output_guard.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/short_number.hpp"
#include "dda/dc/cut.hpp"
#include "dda/dc/cut3d.hpp"
#include "dda/df/io/scenario.hpp"
#include "dda/df/io/scenario3d.hpp"
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

// One wedge case, in-process: the limit equilibrium takes microseconds, so
// thousands of cases take seconds and need no folders.
study::CaseRecord run_wedge_case(const study::Study& study, const study::Case& c) {
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
  return r;
}

// The wedge cases on `jobs` threads, each taking the next block of cases;
// a case writes only its own record, so the records do not depend on the
// number of threads.
std::vector<study::CaseRecord> run_wedge_cases(const study::Study& study, const std::vector<study::Case>& cases,
                                               int jobs) {
  std::vector<study::CaseRecord> records(cases.size());
  constexpr std::size_t kBlock = 64;  // cases a thread takes at once: microseconds each
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t first; (first = next.fetch_add(kBlock)) < cases.size();)
      for (std::size_t i = first; i < std::min(first + kBlock, cases.size()); ++i)
        records[i] = run_wedge_case(study, cases[i]);
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < jobs; ++t) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  return records;
}

struct StudyOptions {
  std::string study, outdir;
  int jobs = 0;
  long long max_cases = -1;
  bool yes = false, retry_failed = false, no_plots = false;
};

// The study and its cases, every value checked before any case runs.
struct PreparedStudy {
  study::Study study;
  std::vector<study::Case> cases;
};

PreparedStudy prepare_study(const StudyOptions& opt) {
  PreparedStudy p{study::read_study(opt.study, check_case_scenario), {}};
  const study::Study& study = p.study;
  const bool wedge = study.kind == study::CaseKind::wedge;
  const std::size_t count = study.case_count();
  const long long limit = opt.max_cases > 0 ? opt.max_cases : (wedge ? 1000000 : 500);
  if (!opt.yes && count > static_cast<std::size_t>(limit))
    throw InputError(opt.study + ": makes " + std::to_string(count) + " cases, more than " + std::to_string(limit) +
                     "; give --yes to run them all (or --max-cases N).");

  const fs::path out(opt.outdir);
  std::vector<std::string> inputs{opt.study};
  if (!wedge && study.base_label != study.file) inputs.push_back(study.base_label);
  refuse_overwriting_inputs(inputs, {opt.outdir, (out / "summary.csv").string(), (out / "study.h5").string()},
                            {(out / "cases").string(), (out / "figures").string()});
  p.cases.reserve(count);
  for (std::size_t i = 0; i < count; ++i) p.cases.push_back(study::make_case(study, i));
  if (!wedge) {
    // The first case whole: values that pass one at a time may still clash.
    try {
      check_case_scenario(p.cases.front().doc, study.base_label);
    } catch (const InputError& e) {
      throw InputError(opt.study + ": its first case (" + p.cases.front().id + ") is refused: " + e.what());
    }
  }
  make_dir(out);
  return p;
}

void run_study(const StudyOptions& opt, const GlobalOptions& global, const MpiWorld& world, const PreparedStudy& p) {
  const study::Study& study = p.study;
  const std::vector<study::Case>& cases = p.cases;
  const fs::path out(opt.outdir);
  const auto start = std::chrono::steady_clock::now();
  std::vector<study::CaseRecord> records;
  if (study.kind == study::CaseKind::wedge) {
    if (world.size() > 1)
      records = run_even_cases_mpi(cases.size(), study.measures.size(),
                                   [&](std::size_t i) { return run_wedge_case(study, cases[i]); }, world);
    else
      records = run_wedge_cases(study, cases, default_pool(opt.jobs).jobs);
  } else {
    PoolOptions pool = default_pool(opt.jobs);
    pool.quiet = global.quiet;
    pool.retry_failed = opt.retry_failed;
    if (world.size() > 1) {
      pool.threads = world.threads_per_rank();
      records = run_pipeline_cases_mpi(study, cases, out, pool, world);
    } else {
      say(global.quiet, "study: " + std::to_string(cases.size()) + " cases, " + std::to_string(pool.jobs) +
                            " at once on " + std::to_string(pool.threads) + " thread" + (pool.threads > 1 ? "s" : "") +
                            " each\n");
      records = run_pipeline_cases(study, cases, out, pool);
    }
  }
  if (world.rank() != 0) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  study::write_summary_csv((out / "summary.csv").string(), study, cases, records);
  study::write_study_h5((out / "study.h5").string(), study, cases, records);
  say(global.quiet, describe_study(study, records, seconds) + "summary written to " + (out / "summary.csv").string() +
                        " and " + (out / "study.h5").string() + "\n");
  if (!opt.no_plots) draw_study_figures(study, out, global.quiet);
}

}  // namespace

void add_study_command(CLI::App& app, const GlobalOptions& global) {
  auto opt = std::make_shared<StudyOptions>();
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
    // Every rank reads the study and checks it. Where all fail alike (the
    // same files on a shared filesystem), rank 0 alone says why; a rank
    // that fails alone (a file its node cannot see) says so with its rank.
    std::optional<PreparedStudy> prepared;
    std::string error;
    try {
      prepared = prepare_study(*opt);
    } catch (const InputError& e) {
      error = e.what();
    }
    const int failed = world.count_ranks(!error.empty());
    if (failed > 0) {
      std::string says;
      if (!error.empty() && world.rank() == 0)
        says = error;
      else if (!error.empty() && failed < world.size())
        says = "rank " + std::to_string(world.rank()) + ": " + error;
      else if (world.rank() == 0)
        says = std::to_string(failed) + " of the " + std::to_string(world.size()) +
               " ranks could not read the study (their errors are above); rank 0 could.";
      if (!says.empty()) std::cerr << "dda: " << says << std::endl;
      // mpirun ends the whole job at the first rank that exits non-zero:
      // every rank says what it has to before any of them exits.
      world.barrier();
      throw ReportedElsewhere{1};
    }
    if (world.size() == 1) return run_study(*opt, global, world, *prepared);
    // A rank that fails now may leave the others waiting for it: it ends them.
    try {
      run_study(*opt, global, world, *prepared);
    } catch (const InputError& e) {
      std::cerr << "dda: rank " << world.rank() << ": " << e.what() << "\n";
      world.abort(1);
    } catch (const std::exception& e) {
      std::cerr << "dda: rank " << world.rank() << ": internal error: " << e.what() << " (please report this)\n";
      world.abort(3);
    }
  });
}

}  // namespace dda::cli
