#include "standard_output.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <streambuf>

namespace dda::cli {

namespace {

// std::cout's buffer: 64 KiB, written with write(2), keeping the errno of the
// first write that failed. Output that cannot be written is dropped, as
// stdio would drop it, but the failure is not forgotten.
class WatchedOutput : public std::streambuf {
 public:
  WatchedOutput() { setp(buffer_, buffer_ + sizeof buffer_); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (write_out() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return write_out(); }

 private:
  int write_out() {
    const char* p = pbase();
    std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    setp(buffer_, buffer_ + sizeof buffer_);
    while (n > 0) {
      const ssize_t w = ::write(STDOUT_FILENO, p, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        if (error_ == 0) error_ = w < 0 ? errno : EIO;
        return -1;
      }
      p += w;
      n -= static_cast<std::size_t>(w);
    }
    return 0;
  }

  char buffer_[1 << 16];
  int error_ = 0;
};

// Never destroyed: std::cout is flushed once more after static objects are
// gone, and must not find its buffer destroyed.
WatchedOutput& watched() {
  static WatchedOutput* const buffer = new WatchedOutput;
  return *buffer;
}

}  // namespace

void watch_standard_output() { std::cout.rdbuf(&watched()); }

std::optional<std::string> standard_output_failure() {
  std::cout.flush();
  int err = watched().error();
  errno = 0;
  if (std::fflush(stdout) != 0 && err == 0) err = errno != 0 ? errno : EIO;
  if (err == 0 && !std::cout.fail() && !std::ferror(stdout)) return std::nullopt;
  return std::string(std::strerror(err != 0 ? err : EIO));
}

}  // namespace dda::cli
