#pragma once
// What `dda df` does around a forward run, 2D (cmd_df.cpp) and 3D
// (cmd_df3.cpp) alike: the progress bar, Ctrl-C / SIGTERM as a clean stop,
// the ParaView series, and the sentences that end a run.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dda/df/run_loop.hpp"
#include "dda/df/runaway.hpp"

namespace dda::cli {

// Progress on stderr: a bar redrawn in place on a terminal, a line every 10 %
// otherwise (once the run has taken more than a second), nothing when quiet.
class Progress {
 public:
  Progress(bool quiet, double start_fraction);
  ~Progress() { finish(); }
  // `fraction` of the run done (0..1), at the end of step `step`; `where`
  // says it in model terms ("t = 0.5/2 s" or "step 30/100").
  void update(double fraction, const std::string& where, int step);
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_, tty_;
  Clock::time_point start_, last_draw_{};
  double f0_;
  double next_decile_ = 1;
  bool drawn_ = false;
};

// "t = 0.5/2 s" for a run of total_time seconds, else "step 30/100".
std::string progress_where(double time, double total_time, int step, int steps);

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

// df_blocks_00012.vtu, df_contacts_00012.vtu.
std::string frame_name(const char* kind, std::size_t frame);
// df.pvd in `dir` listing the blocks (and contacts) frame files at `times`.
void write_pvd_series(const std::filesystem::path& dir, const std::vector<double>& times, bool contacts);

// The runaway as the one sentence `dda` ends with, saying where the results are.
[[noreturn]] void throw_runaway(const df::RunawayError& e, const std::string& results_path);

// Tells how the run ended: `summary` is "N steps to t = T s (...)". An
// interrupted run exits with status 130 after saying how to resume.
void report_run_end(df::RunEnd end, const std::string& summary, const DfStage& stage);

// A number in its shortest usual form.
std::string num(double v);

}  // namespace dda::cli
