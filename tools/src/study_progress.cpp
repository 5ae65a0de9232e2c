#include "study_progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "df_session.hpp"

namespace dda::cli {

StudyProgress::StudyProgress(bool quiet, std::size_t total, std::size_t skipped, std::size_t skipped_failed)
    : enabled_(!quiet && total > skipped),
      tty_(isatty(STDERR_FILENO) == 1),
      total_(total),
      skipped_(skipped),
      failed_(skipped_failed),
      start_(Clock::now()),
      interval_(Progress::progress_interval()) {
  if (!enabled_) return;
  if (skipped_ > 0)
    std::fprintf(stderr, "study: %zu of %zu cases already finished, %zu to run\n", skipped_, total_, total_ - skipped_);
  if (!tty_) thread_ = std::thread([this] { heartbeat(); });
}

std::string StudyProgress::text(Clock::time_point now) const {
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const std::size_t to_run = total_ - skipped_;
  const double left = done_ > 0 ? elapsed / static_cast<double>(done_) * static_cast<double>(to_run - done_) : NAN;
  char buf[160];
  std::snprintf(buf, sizeof buf, "%zu/%zu cases  %zu failed  %s elapsed  ETA %s", done_ + skipped_, total_, failed_,
                short_duration(elapsed).c_str(), short_duration(left).c_str());
  return buf;
}

void StudyProgress::case_done(bool ok) {
  if (!enabled_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  failed_ += !ok;
  if (!tty_) return;
  const auto now = Clock::now();
  if (std::chrono::duration<double>(now - last_draw_).count() < 0.2 && done_ + skipped_ < total_) return;
  last_draw_ = now;
  const int width = 30;
  const int filled = static_cast<int>(width * static_cast<double>(done_ + skipped_) / static_cast<double>(total_));
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(width, '-');
  std::fprintf(stderr, "\rstudy [%s]  %s   ", bar.c_str(), text(now).c_str());
  std::fflush(stderr);
}

void StudyProgress::heartbeat() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::duration<double>(interval_), [this] { return stop_; }))
    std::fprintf(stderr, "study: %s\n", text(Clock::now()).c_str());
}

void StudyProgress::finish() {
  if (!enabled_ || finished_) return;
  finished_ = true;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  if (tty_)
    std::fputs("\n", stderr);
  else
    std::fprintf(stderr, "study: %s\n", text(Clock::now()).c_str());
}

}  // namespace dda::cli
