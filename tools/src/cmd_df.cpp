// dda df SCENARIO.yaml|MODEL.ana --blocks blocks.h5 -o results.h5
// dda df --resume results.h5
//
// The forward run: reads the blocks and the DF sections of a scenario (or a
// DDA for Windows analysis file), steps the simulation to its end with a
// progress bar, and keeps results.h5 up to date (rewritten atomically every
// so often, with a checkpoint), so an interrupted run resumes where it was.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/vtk.hpp"
#include "dda/df/import_ana.hpp"
#include "dda/df/results.hpp"
#include "dda/df/runaway.hpp"
#include "dda/df/scenario.hpp"
#include "pipeline.hpp"

namespace dda::cli {

namespace fs = std::filesystem;

namespace {

volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_interrupt(int) { g_interrupted = 1; }

std::string duration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  const long t = std::lround(s);
  char buf[32];
  if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t % 3600) / 60);
  else if (t >= 60)
    std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%lds", t);
  return buf;
}

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Progress on stderr: a bar redrawn in place on a terminal, a line every 10 %
// otherwise (once the run has taken more than a second), nothing when quiet.
class Progress {
 public:
  Progress(bool quiet, double start_fraction)
      : enabled_(!quiet), tty_(isatty(STDERR_FILENO) == 1), start_(Clock::now()), f0_(start_fraction) {
    next_decile_ = std::floor(start_fraction * 10) + 1;
  }
  ~Progress() { finish(); }

  void update(const df::Simulation& sim) {
    if (!enabled_) return;
    const auto now = Clock::now();
    const double f = df::run_progress(sim);
    const double elapsed = seconds(now - start_);
    const double left = f > f0_ ? elapsed * (1 - f) / (f - f0_) : NAN;
    const int step = sim.log().empty() ? 0 : sim.log().back().step;
    const df::Control& c = sim.model().control;
    const std::string where = c.total_time > 0 ? "t = " + fixed(sim.time()) + "/" + num(c.total_time) + " s"
                                               : "step " + std::to_string(step) + "/" + std::to_string(c.steps);
    if (tty_) {
      if (seconds(now - last_draw_) < 0.2 && f < 1) return;
      last_draw_ = now;
      const int width = 30, filled = static_cast<int>(f * width);
      std::string bar(static_cast<std::size_t>(filled), '#');
      bar.resize(width, '-');
      std::fprintf(stderr, "\rDF [%s] %3d%%  %s  step %d  %s left   ", bar.c_str(), static_cast<int>(f * 100),
                   where.c_str(), step, duration(left).c_str());
      std::fflush(stderr);
      drawn_ = true;
    } else if (f * 10 >= next_decile_) {
      next_decile_ = std::floor(f * 10) + 1;
      if (elapsed < 1.0) return;
      std::fprintf(stderr, "DF: %3d%%  %s  step %d  %s elapsed, about %s left\n", static_cast<int>(f * 100),
                   where.c_str(), step, duration(elapsed).c_str(), duration(left).c_str());
    }
  }

  void finish() {
    if (drawn_) std::fprintf(stderr, "\n");
    drawn_ = false;
  }

 private:
  using Clock = std::chrono::steady_clock;
  static double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
  static std::string fixed(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
  }
  bool enabled_, tty_;
  Clock::time_point start_, last_draw_{};
  double f0_;
  double next_decile_ = 1;
  bool drawn_ = false;
};

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file.");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void make_dir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the output folder (" + ec.message() + ").");
}

// Everything a run needs, from a fresh start or a results file.
struct Job {
  df::Results results;
  df::DfScenario scenario;
  OutputOptions output;
};

std::string frame_name(const char* kind, std::size_t frame) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "df_%s_%05zu.vtu", kind, frame);
  return buf;
}

void write_pvd_series(const fs::path& dir, const std::vector<df::Frame>& frames, bool contacts) {
  std::vector<PvdEntry> entries;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    entries.push_back({frame_name("blocks", f), frames[f].time, 0, "blocks"});
    if (contacts) entries.push_back({frame_name("contacts", f), frames[f].time, 1, "contacts"});
  }
  write_pvd((dir / "df.pvd").string(), entries);
}

void execute(Job& job, const DfStage& stage, std::optional<df::SimulationState> resume_from) {
  df::Simulation sim(df::build_model(job.scenario.input));
  if (resume_from) sim.restore(*resume_from);

  df::RunControl rc;
  rc.checkpoint_seconds = job.output.checkpoint_seconds;
  rc.checkpoint_steps = job.output.checkpoint_steps;
  rc.stop_at_step = stage.stop_at_step;
  const fs::path vtk(stage.vtk_dir);
  if (!stage.vtk_dir.empty()) {
    make_dir(vtk);
    const bool contacts = job.output.vtk_contacts;
    rc.on_frame = [&job, vtk, contacts](const df::Simulation& s, std::size_t frame) {
      df::write_blocks_frame_vtu((vtk / frame_name("blocks", frame)).string(), s);
      if (contacts) df::write_contacts_vtu((vtk / frame_name("contacts", frame)).string(), s);
      write_pvd_series(vtk, job.results.frames, contacts);
    };
  }
  Progress progress(stage.quiet, df::run_progress(sim));
  rc.on_step = [&progress](const df::Simulation& s) { progress.update(s); };
  g_interrupted = 0;
  rc.interrupted = &g_interrupted;
  auto old_int = std::signal(SIGINT, on_interrupt);
  auto old_term = std::signal(SIGTERM, on_interrupt);
  df::RunEnd end;
  try {
    end = df::run_recorded(sim, job.results, stage.results_path, rc);
  } catch (const df::RunawayError& e) {
    std::signal(SIGINT, old_int);
    std::signal(SIGTERM, old_term);
    progress.finish();
    std::string sentence = e.what();
    if (!sentence.empty() && sentence.back() == '.') sentence.pop_back();
    throw InputError(sentence + "; " + stage.results_path + " holds the run up to the step before.");
  } catch (...) {
    std::signal(SIGINT, old_int);
    std::signal(SIGTERM, old_term);
    throw;
  }
  std::signal(SIGINT, old_int);
  std::signal(SIGTERM, old_term);
  progress.finish();

  int sliding = 0, locked = 0;
  if (!sim.log().empty()) sliding = sim.log().back().sliding, locked = sim.log().back().locked;
  const std::string summary = std::to_string(sim.log().size()) + " steps to t = " + num(sim.time()) + " s (" +
                              std::to_string(sliding) + " sliding and " + std::to_string(locked) +
                              " locked contacts at the end)";
  if (end == df::RunEnd::Interrupted) {
    std::cerr << "dda: interrupted after " << summary << "; " << stage.results_path
              << " holds the run so far (continue with `dda df --resume " << stage.results_path << "`).\n";
    std::exit(130);
  }
  if (end == df::RunEnd::Stopped)
    say(stage.quiet, "DF: stopped after " + summary + "; continue with `dda df --resume " + stage.results_path +
                         "`\n");
  else
    say(stage.quiet, "DF: " + summary + " written to " + stage.results_path + "\n");
}

Job job_from_scenario(const YamlNode& root, const BlockModel& blocks, const std::string& blocks_path) {
  Job job;
  job.scenario = df::read_df_scenario(root, blocks, blocks_path);
  job.output = parse_output_options(root);
  df::Results& r = job.results;
  r.source.provenance.scenario_path = root.file();
  r.source.provenance.scenario_text = root.source_text();
  r.source.provenance.seed = blocks.provenance.seed ? blocks.provenance.seed : scenario_seed(root);
  r.source.input_kind = "scenario";
  r.source.blocks_path = blocks_path;
  r.blocks = blocks;
  r.solver = job.scenario.input.control.solver;
  r.output = df::resolve_output_schedule(job.scenario.output, job.scenario.input.control);
  return job;
}

Job job_from_ana(const std::string& text, const std::string& label, const BlockModel& blocks,
                 const std::string& blocks_path, bool quiet) {
  Job job;
  df::AnaImport imp = df::import_ana(text, label, blocks, blocks_path);
  if (!quiet)
    for (const std::string& w : imp.warnings) std::cerr << "dda: note: " << w << "\n";
  job.scenario = std::move(imp.scenario);
  df::Results& r = job.results;
  r.source.provenance.scenario_path = label;
  r.source.provenance.scenario_text = text;
  r.source.provenance.seed = blocks.provenance.seed;
  r.source.input_kind = "ana";
  r.source.blocks_path = blocks_path;
  r.blocks = blocks;
  r.solver = job.scenario.input.control.solver;
  r.output = df::resolve_output_schedule(job.scenario.output, job.scenario.input.control);
  return job;
}

void resume(const std::string& path, DfStage stage) {
  df::Results saved = df::read_results_h5(path);
  if (stage.results_path.empty()) stage.results_path = path;
  const df::ResultsSource& src = saved.source;
  if (saved.complete) {
    say(stage.quiet, path + ": the run is already complete (" + std::to_string(saved.log.size()) +
                         " steps); nothing to resume.\n");
    return;
  }
  Job job;
  try {
    if (src.input_kind == "ana") {
      job = job_from_ana(src.provenance.scenario_text, src.provenance.scenario_path, saved.blocks, src.blocks_path,
                         true);
    } else {
      const YamlNode root = YamlNode::load_string(src.provenance.scenario_text, src.provenance.scenario_path);
      root.allow(scenario_sections());
      job = job_from_scenario(root, saved.blocks, src.blocks_path);
    }
  } catch (const InputError& e) {
    throw InputError(path + ": the scenario stored in the file no longer reads: " + e.what());
  }
  // What was saved wins: the schedule and solver the run started with.
  job.results.source = src;
  job.results.output = saved.output;
  job.results.frames = std::move(saved.frames);
  if (!stage.vtk_dir.empty() && !job.results.frames.empty())
    say(stage.quiet, "DF: resuming at frame " + std::to_string(job.results.frames.size()) +
                         "; earlier ParaView frames are expected in " + stage.vtk_dir + "\n");
  say(stage.quiet, "DF: resuming " + path + " at step " + std::to_string(saved.log.size()) + ", t = " +
                       num(saved.checkpoint->time) + " s\n");
  execute(job, stage, std::move(saved.checkpoint));
}

}  // namespace

void run_df_scenario(const YamlNode& root, const BlockModel& blocks, const std::string& blocks_path,
                     const DfStage& stage) {
  Job job = job_from_scenario(root, blocks, blocks_path);
  execute(job, stage, std::nullopt);
}

void add_df_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string input, blocks, output, resume, vtk;
    std::optional<int> stop_at_step;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "df", "Forward DDA run of a blocks file: `dda df SCENARIO.yaml --blocks blocks.h5 -o results.h5` "
            "(or MODEL.ana, a DDA for Windows analysis), or `dda df --resume results.h5`");
  cmd->add_option("input", opt->input,
                  "Scenario (.yaml) with materials, joints, loading, fixed and control; or a DDA for Windows "
                  "analysis file (.ana)");
  cmd->add_option("--blocks", opt->blocks, "Blocks file written by `dda dc`");
  cmd->add_option("-o,--output", opt->output,
                  "Results file to write (HDF5); with --resume, defaults to the file resumed");
  cmd->add_option("--resume", opt->resume, "Continue the run saved in this results file from its checkpoint");
  cmd->add_option("--vtk", opt->vtk, "Also write a ParaView series (df.pvd, blocks and contacts) into this folder");
  cmd->add_option("--stop-at-step", opt->stop_at_step,
                  "Stop once the run has this many steps (the results file then holds a checkpoint to resume)")
      ->check(CLI::PositiveNumber);
  cmd->callback([opt, &global] {
    DfStage stage;
    stage.results_path = opt->output;
    stage.vtk_dir = opt->vtk;
    stage.stop_at_step = opt->stop_at_step;
    stage.quiet = global.quiet;
    if (!opt->resume.empty()) {
      if (!opt->input.empty() || !opt->blocks.empty())
        throw InputError("--resume continues the run stored in " + opt->resume +
                         "; give no scenario or --blocks with it.");
      resume(opt->resume, stage);
      return;
    }
    if (opt->input.empty()) throw InputError("dda df needs a scenario (.yaml) or analysis (.ana) file, or --resume.");
    if (opt->blocks.empty()) throw InputError("dda df needs --blocks BLOCKS.h5 (written by `dda dc`).");
    if (opt->output.empty()) throw InputError("dda df needs -o RESULTS.h5, the results file to write.");
    if (!fs::exists(opt->input)) throw InputError(opt->input + ": no such file.");
    const BlockModel blocks = read_blocks_h5(opt->blocks);
    Job job;
    if (df::is_ana_path(opt->input)) {
      job = job_from_ana(read_text(opt->input), opt->input, blocks, opt->blocks, global.quiet);
    } else {
      const YamlNode root = load_scenario(opt->input);
      job = job_from_scenario(root, blocks, opt->blocks);
    }
    execute(job, stage, std::nullopt);
  });
}

}  // namespace dda::cli
