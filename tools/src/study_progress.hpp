#pragma once
// Progress of a study on stderr, nothing when quiet: on a terminal a bar
// redrawn in place,
//   study [#########---------------------]  12/40 cases  1 failed  1m30s elapsed  ETA 3m30s
// and otherwise (a log file, a pipe, a batch job) the same as a line at
// least every DDA_PROGRESS_SECONDS (default 30 s) and at the end. The ETA
// is the mean time per case run so far times the cases left, over the
// cases running at once.
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>
#include <thread>

namespace dda::cli {

class StudyProgress {
 public:
  // `total` cases, `skipped` of them already finished (a resumed study),
  // `skipped_failed` of those failed.
  StudyProgress(bool quiet, std::size_t total, std::size_t skipped, std::size_t skipped_failed);
  ~StudyProgress() { finish(); }
  StudyProgress(const StudyProgress&) = delete;
  StudyProgress& operator=(const StudyProgress&) = delete;
  void case_done(bool ok);
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::string text(Clock::time_point now) const;  // holding mutex_
  void heartbeat();
  bool enabled_, tty_;
  std::size_t total_, skipped_, failed_, done_ = 0;
  Clock::time_point start_, last_draw_{};
  double interval_;
  bool stop_ = false, finished_ = false;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
};


}  // namespace dda::cli
