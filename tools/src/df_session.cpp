#include "df_session.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/vtk.hpp"
#include "pipeline.hpp"

namespace dda::cli {

namespace {

volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_interrupt(int) { g_interrupted = 1; }

double seconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

std::string short_duration(double s) {
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

namespace {

// "t = 0.5/2 s" for a run of total_time seconds, else "t = 0.5 s" (the step
// count goes with the step number).
std::string model_time(const ProgressSample& s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", s.time);
  return "t = " + std::string(buf) + (s.total_time > 0 ? "/" + num(s.total_time) : std::string()) + " s";
}

std::string step_of(int step, const ProgressSample& s) {
  return "step " + std::to_string(step) + (s.total_time > 0 ? std::string() : "/" + std::to_string(s.steps));
}

// Whole percent, a run at t = 0.99999999 of 1 s included.
int percent_done(double f) { return static_cast<int>(f * 100 + 1e-6); }

}  // namespace

double Progress::progress_interval() {
  if (const char* v = std::getenv("DDA_PROGRESS_SECONDS")) {
    char* end = nullptr;
    const double s = std::strtod(v, &end);
    if (end != v && *end == '\0' && s > 0 && std::isfinite(s)) return s;
  }
  return 30;
}

Progress::Progress(bool quiet, const ProgressSample& start, double interval)
    : enabled_(!quiet),
      tty_(isatty(STDERR_FILENO) == 1),
      start_(Clock::now()),
      last_line_(start_),
      last_step_at_(start_),
      f0_(start.fraction),
      interval_(interval),
      now_(start),
      at_line_(start) {
  if (enabled_ && !tty_) thread_ = std::thread([this] { heartbeat(); });
}

void Progress::update(const ProgressSample& s) {
  if (!enabled_) return;
  const auto now = Clock::now();
  if (!tty_) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (s.step != now_.step) last_step_at_ = now;
    now_ = s;
    return;
  }
  const double f = s.fraction;
  if (seconds(now - last_draw_) < 0.2 && f < 1) return;
  last_draw_ = now;
  const double elapsed = seconds(now - start_);
  const double left = f > f0_ ? elapsed * (1 - f) / (f - f0_) : NAN;
  const int width = 30, filled = static_cast<int>(f * width);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(width, '-');
  const std::string where = s.total_time > 0 ? model_time(s) : step_of(s.step, s);
  std::fprintf(stderr, "\rDF [%s] %3d%%  %s  step %d  %s left   ", bar.c_str(), percent_done(f),
               where.c_str(), s.step, short_duration(left).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

std::string Progress::line(Clock::time_point now) {
  const double f = now_.fraction;
  const double elapsed = seconds(now - start_);
  const double left = f > f0_ ? elapsed * (1 - f) / (f - f0_) : NAN;
  char dt[32], pace[64];
  std::snprintf(dt, sizeof dt, "%.4g", now_.dt);
  std::string text = "DF: " + std::to_string(percent_done(f)) + " %  " + step_of(now_.step, now_) + "  " +
                     model_time(now_) + "  dt = " + dt + " s  ";
  if (now_.step > at_line_.step) {
    std::snprintf(pace, sizeof pace, "%.1f solves/step",
                  static_cast<double>(now_.solves - at_line_.solves) / (now_.step - at_line_.step));
    text += pace;
  } else {
    text += step_of(now_.step + 1, now_) + " under way for " + short_duration(seconds(now - last_step_at_));
  }
  return text + "  " + short_duration(elapsed) + " elapsed  ETA " + short_duration(left) + "\n";
}

void Progress::heartbeat() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    const auto due = last_line_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(interval_));
    if (wake_.wait_until(lock, due, [this] { return stop_; })) return;
    const auto now = Clock::now();
    if (now < due) continue;
    last_line_ = now;
    // At the end the run writes its results and says so itself.
    if (now_.finished && now_.step == at_line_.step) continue;
    const std::string text = line(now);
    std::fputs(text.c_str(), stderr);
    std::fflush(stderr);
    at_line_ = now_;
  }
}

void Progress::finish() {
  if (thread_.joinable()) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

InterruptGuard::InterruptGuard() {
  g_interrupted = 0;
  old_int_ = std::signal(SIGINT, on_interrupt);
  old_term_ = std::signal(SIGTERM, on_interrupt);
}

InterruptGuard::~InterruptGuard() {
  std::signal(SIGINT, old_int_);
  std::signal(SIGTERM, old_term_);
}

const volatile std::sig_atomic_t* InterruptGuard::flag() const { return &g_interrupted; }

void throw_runaway(const df::RunawayError& e, const std::string& results_path) {
  std::string sentence = e.what();
  if (!sentence.empty() && sentence.back() == '.') sentence.pop_back();
  throw InputError(sentence + "; " + results_path + " holds the run up to the step before.");
}

void report_run_end(df::RunEnd end, const std::string& summary, const DfStage& stage) {
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

namespace {
std::string joules(double e) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g J", e);
  return buf;
}
std::string percent(double r) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g %%", 100 * r);
  return buf;
}
}  // namespace

std::string energy_balance_line(const std::vector<df::EnergyRecord>& log, const std::string& unit) {
  if (log.size() < 2) return "no steps";
  const df::EnergyRecord& e = log.back();
  const double scale = df::energy_moved(log.front(), e);
  return "at t = " + num(e.time) + " s, work done " + joules(e.input()) + ", stored " +
         joules(e.stored() - log.front().stored()) + " more than at the start, losses " + joules(e.losses()) +
         " (friction, damping, breakage, radiation), residual " + joules(e.residual) + " (" +
         percent(scale > 0 ? e.residual / scale : 0.0) +
         " of the energy moved; what the penalty springs and the implicit step dissipate, " + unit + ")";
}

std::string energy_created_warning(const std::vector<df::EnergyRecord>& log) {
  const df::EnergyCreated worst = df::most_energy_created(log);
  if (!(worst.ratio() < -df::kEnergyCreatedWarning)) return "";
  return "the run created energy: at t = " + num(worst.time) + " s its energy residual was " +
         joules(worst.residual) + " for " + joules(worst.scale) + " moved (" + percent(worst.ratio()) +
         "), where contacts and the implicit step only dissipate (sound runs stay above -2 %); look for contacts "
         "that start deep in a block (overlapping blocks, or slivers thinner than the contact search distance: "
         "`dda dc --min-area A --slivers merge` merges them) or a step too long for the penalty stiffness.";
}

df::ResultsSource scenario_source(const YamlNode& root, std::uint64_t blocks_seed, const std::string& blocks_path) {
  df::ResultsSource src;
  src.provenance.scenario_path = root.file();
  src.provenance.scenario_text = root.source_text();
  src.provenance.seed = blocks_seed ? blocks_seed : scenario_seed(root);
  src.input_kind = "scenario";
  src.blocks_path = blocks_path;
  return src;
}

}  // namespace dda::cli
