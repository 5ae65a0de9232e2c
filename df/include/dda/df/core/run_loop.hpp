#pragma once
// The recorded run, one loop for the 2D and the 3D solver: step to the end,
// save a block frame on the output schedule, rewrite the results file
// atomically every so often (so an interrupted run leaves the last complete
// file, ready to resume), stop cleanly on request, and on a runaway keep
// the results up to the step before.
//
// The loop is a template over the simulation and its results; what differs
// between the dimensions it calls by name, found next to the simulation type
// (argument-dependent lookup):
//   bool run_finished(const Sim&);              the run has reached its end
//   void run_step(Sim&);                        one step toward the end, as an uninterrupted run takes it
//   int last_step(const Sim&);                  number of the last step (0 before the first)
//   Frame make_frame(const Sim&);               the block states now
//   void write_results(path, const Results&, const Sim&, bool complete);
// Results has `frames` (each with `step` and `time`) and `output` (an OutputSchedule).
//
// What the run writes goes through one interface, RunWriter: the results
// file with its checkpoint (ResultsFileWriter, the hook write_results) and
// whatever else the caller registers (`dda df`'s ParaView series,
// tools/src/df_outputs.hpp).
#include <chrono>
#include <cmath>
#include <csignal>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dda/df/core/runaway.hpp"

namespace dda::df {

enum class RunEnd { Finished, Stopped, Interrupted };

template <class Sim>
struct BasicRunControl {
  double checkpoint_seconds = 60;       // rewrite the results file at least this often (wall clock); 0: only at the end
  int checkpoint_steps = 0;             // and every this many steps (0: off)
  std::optional<int> stop_at_step;      // stop (with a checkpoint) once the run has this many steps
  std::function<void(const Sim&, std::size_t frame)> on_frame;  // after each saved frame
  std::function<void(const Sim&)> on_step;                      // after each step
  const volatile std::sig_atomic_t* interrupted = nullptr;     // set by a signal handler: stop cleanly
};

namespace detail {

// A frame is due every `output.every` steps, or at each multiple of
// `output.interval` in model time the run has passed since the last frame.
template <class Sim, class Results>
bool frame_due(const Sim& sim, const Results& r, double time) {
  if (r.frames.empty()) return true;
  if (r.output.every > 0) return last_step(sim) % r.output.every == 0;
  const double interval = r.output.interval;
  const double eps = 1e-9 * interval;
  return std::floor((time + eps) / interval) > std::floor((r.frames.back().time + eps) / interval);
}

}  // namespace detail

// One output of a recorded run. The loop tells every writer, in the order
// given, when a frame has been added to `results.frames` and when the run
// so far is due on disk: on the checkpoint schedule, before a runaway is
// rethrown (the results up to the step before) and at the end (`complete`
// when the run reached its end).
template <class Sim, class Results>
class RunWriter {
 public:
  virtual ~RunWriter() = default;
  virtual void frame(const Sim& /*sim*/, const Results& /*results*/, std::size_t /*index*/) {}
  virtual void save(const Sim& /*sim*/, const Results& /*results*/, bool /*complete*/) {}
};

// The results file at `path`, rewritten atomically with its checkpoint at
// each save (the dimension's write_results).
template <class Sim, class Results>
class ResultsFileWriter : public RunWriter<Sim, Results> {
 public:
  explicit ResultsFileWriter(std::string path) : path_(std::move(path)) {}
  void save(const Sim& sim, const Results& results, bool complete) override {
    write_results(path_, results, sim, complete);
  }

 private:
  std::string path_;
};

// Steps `sim` to its end, saving frames into `results.frames` and telling
// `writers` of each, and saving through them on the schedule of `control`
// and once more at the end. A RunawayError from a step is rethrown after
// the results up to the step before it are saved.
template <class Sim, class Results>
RunEnd run_recorded_loop(Sim& sim, Results& results, const std::vector<RunWriter<Sim, Results>*>& writers,
                         const BasicRunControl<Sim>& control) {
  using Clock = std::chrono::steady_clock;
  auto record = [&] {
    results.frames.push_back(make_frame(sim));
    for (RunWriter<Sim, Results>* w : writers) w->frame(sim, results, results.frames.size() - 1);
    if (control.on_frame) control.on_frame(sim, results.frames.size() - 1);
  };
  auto save = [&](bool complete) {
    for (RunWriter<Sim, Results>* w : writers) w->save(sim, results, complete);
  };
  if (results.frames.empty()) record();
  auto last_write = Clock::now();
  int steps_since_write = 0;
  RunEnd end = RunEnd::Finished;
  while (!run_finished(sim)) {
    if (control.interrupted && *control.interrupted) {
      end = RunEnd::Interrupted;
      break;
    }
    if (control.stop_at_step && last_step(sim) >= *control.stop_at_step) {
      end = RunEnd::Stopped;
      break;
    }
    try {
      run_step(sim);
    } catch (const RunawayError&) {
      // The failed step was not accepted: keep what the run did before it.
      save(false);
      throw;
    }
    ++steps_since_write;
    if (control.on_step) control.on_step(sim);
    if (detail::frame_due(sim, results, sim.time())) record();
    const double since = std::chrono::duration<double>(Clock::now() - last_write).count();
    if ((control.checkpoint_steps > 0 && steps_since_write >= control.checkpoint_steps) ||
        (control.checkpoint_seconds > 0 && since >= control.checkpoint_seconds)) {
      save(false);
      last_write = Clock::now();
      steps_since_write = 0;
    }
  }
  if (end == RunEnd::Finished && results.frames.back().step != last_step(sim)) record();  // the end is always a frame
  save(end == RunEnd::Finished);
  return end;
}

// The run with one output, the results file at `path`.
template <class Sim, class Results>
RunEnd run_recorded_loop(Sim& sim, Results& results, const std::string& path, const BasicRunControl<Sim>& control) {
  ResultsFileWriter<Sim, Results> file(path);
  return run_recorded_loop(sim, results, {&file}, control);
}

}  // namespace dda::df
