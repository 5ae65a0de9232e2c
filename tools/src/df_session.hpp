#pragma once
// What `dda df` does around a forward run, 2D (cmd_df.cpp) and 3D
// (cmd_df3d.cpp) alike: the progress bar, Ctrl-C / SIGTERM as a clean stop,
// the ParaView series, and the sentences that end a run.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "commands.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/df/core/damping.hpp"
#include "dda/df/core/energy.hpp"
#include "dda/df/io/results.hpp"
#include "pipeline.hpp"
#include "dda/df/core/run_loop.hpp"
#include "dda/df/core/run_threads.hpp"
#include "dda/df/core/runaway.hpp"
#include "df_outputs.hpp"

namespace dda::cli {

// What the end of a step tells the progress report.
struct ProgressSample {
  double fraction = 0;     // of the run done, 0..1
  int step = 0;            // the step just done (0 before the first)
  double time = 0;         // s of model time at its end
  double dt = 0;           // s, its length
  long solves = 0;         // linear solves since the run (or the resume) began
  double total_time = 0;   // s, the run's end in model time (0: it ends at a step count)
  int steps = 0;           // that step count
  bool finished = false;   // the run has reached its end
};

// Progress on stderr, nothing when quiet. On a terminal a bar redrawn in
// place; otherwise (a log file, a pipe, a batch job) a line at least every
// `interval` seconds of wall time:
//   DF: 12 %  step 1200  t = 0.6/5 s  dt = 0.0005 s  3.2 solves/step  1m30s elapsed  ETA 11m02s
// with the solves per step averaged over the steps since the last line.
// The lines come from a helper thread that sleeps in between, so a step
// longer than the interval still gets its line ("step 1201 under way for
// 45s" in place of the solves).
class Progress {
 public:
  // `start`: where the run (or the resumed run) begins.
  Progress(bool quiet, const ProgressSample& start, double interval = progress_interval());
  ~Progress() { finish(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void update(const ProgressSample& s);
  void finish();

  // DDA_PROGRESS_SECONDS if it is a positive number, else 30.
  static double progress_interval();

 private:
  using Clock = std::chrono::steady_clock;
  void heartbeat();
  std::string line(Clock::time_point now);  // holding mutex_
  bool enabled_, tty_;
  Clock::time_point start_, last_draw_{}, last_line_, last_step_at_;
  double f0_, interval_;
  bool drawn_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  ProgressSample now_, at_line_;  // the last step, and the last step at the last line
  std::thread thread_;
};

// SIGINT and SIGTERM set a flag (a clean stop at the end of the step) while
// this lives; the previous handlers come back after.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  const volatile std::sig_atomic_t* flag() const;

 private:
  void (*old_int_)(int);
  void (*old_term_)(int);
};

// The runaway as the one sentence `dda` ends with, saying where the results are.
[[noreturn]] void throw_runaway(const df::RunawayError& e, const std::string& results_path);

// Tells how the run ended: `summary` is "N steps to t = T s (...)". An
// interrupted run exits with status 130 after saying how to resume.
void report_run_end(df::RunEnd end, const std::string& summary, const DfStage& stage);

// A run's energy balance in a line ("work done ..., residual ... (x % of
// the energy moved)"), and a warning sentence when the run created more
// energy than df::kEnergyCreatedWarning of what it moved (empty otherwise;
// see df::most_energy_created).
// `unit` says how the energies count: "J per m of thickness" in 2D, "J" in 3D.
std::string energy_balance_line(const std::vector<df::EnergyRecord>& log, const std::string& unit);
std::string energy_created_warning(const std::vector<df::EnergyRecord>& log);

// A number in its shortest usual form.
std::string num(double v);
// A duration for progress lines: "1m30s", "2h05m", "12s" ("?" if unknown).
std::string short_duration(double seconds);

// Where a run from a scenario comes from (the results file's root
// attributes): the scenario's path and text, the seed of the blocks (else
// the scenario's), and the blocks file as given.
df::ResultsSource scenario_source(const YamlNode& root, std::uint64_t blocks_seed, const std::string& blocks_path);

// A resumed run keeps what its results file saved: where it came from, the
// output schedule it started with and the frames so far; says where it
// resumes. `saved` is a Results (2D) or Results3 read back with its state.
template <class Results>
void adopt_saved(Results& results, Results& saved, const std::string& path, const DfStage& stage) {
  results.source = saved.source;
  results.output = saved.output;
  results.frames = std::move(saved.frames);
  if (!stage.vtk_dir.empty() && !results.frames.empty())
    say(stage.quiet, "DF: resuming at frame " + std::to_string(results.frames.size()) +
                         "; earlier ParaView frames are expected in " + stage.vtk_dir + "\n");
  say(stage.quiet, "DF: resuming " + path + " at step " + std::to_string(saved.log.size()) + ", t = " +
                       num(saved.checkpoint->time) + " s\n");
}

// The settings the run's answer hangs on, said before it starts: the
// contact springs (from the model unless the scenario gave them), the
// time step and the contact iteration.
template <class Sim>
std::string contact_settings(const Sim& sim) {
  const auto& m = sim.model();
  std::string line;
  if constexpr (requires { m.joint_pn; }) {
    if (m.joint_pn.empty()) return "no joints";
    const auto [pn_lo, pn_hi] = std::minmax_element(m.joint_pn.begin(), m.joint_pn.end());
    const auto [ps_lo, ps_hi] = std::minmax_element(m.joint_ps.begin(), m.joint_ps.end());
    auto range = [](double lo, double hi) { return lo == hi ? num(lo) : num(lo) + " to " + num(hi); };
    line = "contact springs pn " + range(*pn_lo, *pn_hi) + " N/m, ps " + range(*ps_lo, *ps_hi) + " N/m (per m of thickness); dt " +
           num(m.control.dt) + " s; up to " + std::to_string(m.control.max_open_close) + " open-close iterations a step" +
           (m.control.contact_clusters ? ", contact clusters on" : ", contact clusters off");
  } else {
    // Per joint (a joint set may give its own springs and normal law).
    double pn_lo = 1e300, pn_hi = 0, ps_lo = 1e300, ps_hi = 0;
    std::string laws;
    for (const auto& j : contact_springs3(m)) {  // dda::df3, found by the model's namespace
      pn_lo = std::min(pn_lo, j.pn), pn_hi = std::max(pn_hi, j.pn);
      ps_lo = std::min(ps_lo, j.ps), ps_hi = std::max(ps_hi, j.ps);
      if (!j.normal->linear() && laws.find(j.normal->name()) == std::string::npos)
        laws += (laws.empty() ? "" : ", ") + j.normal->name();
    }
    auto range = [](double lo, double hi) { return lo == hi ? num(lo) : num(lo) + " to " + num(hi); };
    line = "contact springs pn " + range(pn_lo, pn_hi) + " N/m, ps " + range(ps_lo, ps_hi) + " N/m (per contact point" +
           (laws.empty() ? "" : "; normal law " + laws + " where a joint gives it") + "); dt " + num(m.control.dt) +
           " s; up to " + std::to_string(m.max_iterations) + " open-close iterations a step";
  }
  return line;
}

template <class Sim>
bool model_asks_for_equilibrium(const Sim& sim) {
  return sim.model().control.initial_equilibrium && sim.log().empty();
}

// A prepared forward run, 2D or 3D alike, with everything `dda df` does
// around it: the threads for the model's size (df::RunThreads, said in the
// run's first line), the outputs of df_outputs.hpp (the results file with
// checkpoints on the output options' schedule, the ParaView series), the
// progress bar, a clean stop on Ctrl-C, the runaway sentence and the
// closing one. The dimension's run loop hooks and run_progress are found by
// argument-dependent lookup (df:: for Simulation, df3:: for Simulation3).
template <class Sim, class Results>
void run_session(Sim& sim, Results& results, const OutputOptions& output, const DfStage& stage) {
  const int blocks = static_cast<int>(sim.blocks().size());
  const df::RunThreads threads(blocks);
  say(stage.quiet, "DF: " + std::to_string(blocks) + " blocks on " + std::to_string(threads.threads()) +
                       (threads.threads() == 1 ? " thread\n" : " threads\n"));
  say(stage.quiet, "DF: " + contact_settings(sim) + "\n");
  // A step the model chose says why, so that a user can judge it.
  if (const auto& c = sim.model().control; !c.dt_basis.empty())
    say(stage.quiet, "DF: dt " + num(c.dt) + " s from the model (control.dt not given): " + c.dt_basis + "\n");
  if constexpr (requires { sim.model().control.dynamic; }) {
    // A dynamic parameter below 1 damps every motion, free falls included,
    // which the classic examples' 0.99 hid: falling roof beds moved at a
    // constant 0.45 m/s. Say what it does before the run.
    const auto& c = sim.model().control;
    const double k = c.dynamic, g = sim.model().gravity.norm();
    if (k == 0)
      say(stage.quiet, "DF: note: control.dynamic 0 starts every step from rest: a static relaxation, whose "
                       "path to equilibrium is not the motion in time\n");
    else if (k < 1 && g > 0)
      say(stage.quiet, "DF: note: control.dynamic " + num(k) + " keeps " + num(100 * k) +
                           " % of the velocity from one step to the next: it damps every motion, and caps a free "
                           "fall at g dt / (1 - dynamic) = " + num(g * c.dt / (1 - k)) + " m/s at dt " + num(c.dt) +
                           " s; give 1 (the default) where the motion matters\n");
  }
  if (const df::ViscousDamping& v = sim.model().control.damping; v.on()) {
    // Stiffness-proportional damping is a ratio at one frequency only: say
    // what other frequencies get, so nobody reads it as frequency-free.
    say(stage.quiet, "DF: viscous damping " + num(100 * v.ratio) + " % of critical at " + num(v.frequency) +
                         " Hz on the blocks' deformation (beta = " + num(v.beta()) + " s; " +
                         num(100 * v.ratio_at(v.frequency / 2)) + " % at " + num(v.frequency / 2) + " Hz, " +
                         num(100 * v.ratio_at(2 * v.frequency)) + " % at " + num(2 * v.frequency) +
                         " Hz); rigid motion and the contact springs are not damped\n");
  }
  if constexpr (requires { sim.start_up(); }) {
    // The start-up relaxation runs before frame 0, so that the first frame
    // is the state the run starts from.
    // It can take minutes on a large model (a 1,601-brick wall: 41 static
    // solves, over a minute), so the user is told first what is running.
    const bool relaxing = model_asks_for_equilibrium(sim);
    if (relaxing)
      say(stage.quiet, "DF: relaxing the model under its loads before t = 0 (control.initial_equilibrium: at most 50 "
                       "static solves with the contacts stuck, then 50 with friction)\n");
    // Off a terminal as on it, a line at least every progress interval
    // while it lasts (after the solve that passes it).
    auto last_line = std::chrono::steady_clock::now();
    const double interval = Progress::progress_interval();
    if (relaxing && !stage.quiet)
      sim.observe_start_up([&](bool contacts_stick, int solves, double moved) {
        const auto now = std::chrono::steady_clock::now();
        if (std::chrono::duration<double>(now - last_line).count() < interval) return;
        last_line = now;
        std::cerr << "DF: relaxing: " << solves << " static solves "
                  << (contacts_stick ? "with the contacts stuck" : "with friction") << " so far, the last moved a vertex "
                  << num(moved) << " m\n";
      });
    sim.start();
    sim.observe_start_up({});
    const auto& s = sim.start_up();
    if (relaxing)
      say(stage.quiet,
          "DF: initial equilibrium: " + std::to_string(s.stuck_iterations) + " static solves with the contacts stuck" +
              (s.stuck_equilibrium ? "" : " (not settled: a block falls, topples or keeps moving)") + ", " +
              std::to_string(s.friction_iterations) + " with friction; " +
              (s.frictional_equilibrium ? "the run starts at rest in frictional equilibrium\n"
                                        : "no equilibrium found: the run starts from the last static state\n"));
  }
  df::BasicRunControl<Sim> rc;
  rc.checkpoint_seconds = output.checkpoint_seconds;
  rc.checkpoint_steps = output.checkpoint_steps;
  rc.stop_at_step = stage.stop_at_step;
  const RunOutputs<Sim, Results> outputs(stage, output);
  const auto& control = sim.model().control;
  ProgressSample start;
  start.fraction = run_progress(sim);
  start.step = sim.log().empty() ? 0 : sim.log().back().step;
  start.time = sim.time();
  start.total_time = control.total_time;
  start.steps = control.steps;
  start.solves = sim.timings().solves;
  Progress progress(stage.quiet, start);
  rc.on_step = [&progress, start](const Sim& s) {
    ProgressSample p = start;
    p.fraction = run_progress(s);
    if (!s.log().empty()) p.step = s.log().back().step, p.dt = s.log().back().dt;
    p.time = s.time();
    p.solves = s.timings().solves;
    p.finished = run_finished(s);
    progress.update(p);
  };
  df::RunEnd end;
  {
    InterruptGuard guard;
    rc.interrupted = guard.flag();
    try {
      end = df::run_recorded_loop(sim, results, outputs.writers(), rc);
    } catch (const df::RunawayError& e) {
      progress.finish();
      throw_runaway(e, stage.results_path);
    }
  }
  progress.finish();
  if constexpr (requires { sim.energy_log(); }) {
    // Printed even when quiet: the results are suspect.
    if (const std::string w = energy_created_warning(sim.energy_log()); !w.empty()) std::cerr << "dda: warning: " << w << "\n";
  }
  int sliding = 0, locked = 0;
  if (!sim.log().empty()) sliding = sim.log().back().sliding, locked = sim.log().back().locked;
  // 3D: the locked contacts that are glued across the cutter's artificial
  // faces (one piece of rock each side), so that nobody reads them as joints.
  std::string glued;
  if constexpr (requires { sim.glued_contacts(); })
    if (const int g = sim.glued_contacts(); g > 0) glued = ", " + std::to_string(g) + " of them glued across artificial cuts";
  report_run_end(end,
                 std::to_string(sim.log().size()) + " steps to t = " + num(sim.time()) + " s (" +
                     std::to_string(sliding) + " sliding and " + std::to_string(locked) + " locked contacts at the end" +
                     glued + ")",
                 stage);
}

}  // namespace dda::cli
