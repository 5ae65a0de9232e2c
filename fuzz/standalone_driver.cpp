// Runs one fuzz target without libFuzzer (docs/reliability.md, "Fuzzing"):
// the same fuzz_NAME.cpp, compiled by any compiler and linked with this
// main, so that CI's gcc build runs every target for a fixed number of
// inputs. It feeds LLVMFuzzerTestOneInput every seed file it is given, then
// `--runs` mutants of them (mutations.hpp), each made from `--seed` and its
// number alone: a run is the same every time.
//
// A finding is what libFuzzer would call a crash: an exception other than
// the reader's InputError escaping the target (fuzz_support.hpp), a signal
// (segfault, abort, ...), an input that takes more than `--timeout`
// seconds, or memory beyond `--memory-mb` (a std::bad_alloc that escapes).
// It prints the seed and the mutation's number, writes the input to
// `--artifacts`/finding-NAME-... so that it can be replayed here or under
// the clang build, and exits 1. Without AddressSanitizer this finds no
// silent memory error: only what crashes or escapes.
//
// Usage: fuzz_NAME_standalone [--runs N] [--seed S] [--iteration I]
//          [--artifacts DIR] [--timeout SECONDS] [--memory-mb MB] PATH...
// PATH is a seed file or a folder of them. --iteration runs that one
// mutant alone; --runs 0 runs the given files only (a replay).
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <cxxabi.h>
#include <exception>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <typeinfo>
#include <vector>

#include "mutations.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;
using dda::fuzz::Bytes;

constexpr const char* kTarget = DDA_FUZZ_TARGET;  // the NAME of fuzz_NAME.cpp (CMake)

struct Options {
  std::uint64_t runs = 1000;
  std::uint64_t seed = 1;
  std::optional<std::uint64_t> iteration;
  std::string artifacts = ".";
  unsigned timeout_s = 20;        // scripts/fuzz.sh gives libFuzzer the same
  std::uint64_t memory_mb = 2048;  // as scripts/fuzz.sh's -rss_limit_mb
  std::vector<std::string> paths;
};

struct Seed {
  std::string name;
  Bytes bytes;
};

// What the signal handler needs about the input being run, prepared before
// the run: a handler may only write and rename, not format or allocate.
struct Current {
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
  char what[512] = {};
  char path[4096] = {};
  char temp_path[4200] = {};
};
Current current;

void say(const char* text) {
  for (std::size_t n = std::strlen(text); n > 0;) {
    const ssize_t w = ::write(STDERR_FILENO, text, n);
    if (w <= 0) return;
    text += w;
    n -= static_cast<std::size_t>(w);
  }
}

// Writes the current input under a temporary name and renames it: the
// finding's file is whole or absent. Raw system calls, not AtomicOutput,
// because this runs inside a signal handler too.
bool save_current_input() {
  const int fd = ::open(current.temp_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return false;
  const std::uint8_t* p = current.data;
  std::size_t left = current.size;
  while (left > 0) {
    const ssize_t w = ::write(fd, p, left);
    if (w <= 0) {
      ::close(fd);
      return false;
    }
    p += w;
    left -= static_cast<std::size_t>(w);
  }
  return ::fsync(fd) == 0 && ::close(fd) == 0 && std::rename(current.temp_path, current.path) == 0;
}

void report_finding(const char* problem) {
  say("fuzz_");
  say(kTarget);
  say(": FINDING on ");
  say(current.what);
  say(": the target ");
  say(problem);
  say(".\n");
  if (save_current_input()) {
    say("The input is in ");
    say(current.path);
    say("; replay it with this program (--runs 0 FILE) or under the clang build "
        "(build-sanitize/fuzz/fuzz_");
    say(kTarget);
    say(" FILE, made by scripts/fuzz.sh).\n");
  } else {
    say("The input could not be written to ");
    say(current.path);
    say(".\n");
  }
}

void on_signal(int sig) {
  switch (sig) {
    case SIGALRM: report_finding("took longer than the time limit (a hang)"); break;
    case SIGSEGV: report_finding("crashed with a segmentation fault"); break;
    case SIGBUS: report_finding("crashed with a bus error"); break;
    case SIGFPE: report_finding("crashed with an arithmetic exception"); break;
    case SIGILL: report_finding("crashed with an illegal instruction"); break;
    default: report_finding("aborted"); break;
  }
  if (sig == SIGALRM) ::_exit(1);
  std::signal(sig, SIG_DFL);  // then die of it, as the crash would
  std::raise(sig);
}

void install_handlers() {
  // Its own stack, so that a stack overflow is reported too.
  static std::vector<char> alt_stack(1 << 16);
  stack_t ss{};
  ss.ss_sp = alt_stack.data();
  ss.ss_size = alt_stack.size();
  sigaltstack(&ss, nullptr);
  struct sigaction sa{};
  sa.sa_handler = on_signal;
  sa.sa_flags = SA_ONSTACK;
  sigemptyset(&sa.sa_mask);
  for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGALRM}) sigaction(sig, &sa, nullptr);
}

// The address space is capped, so that a reader that allocates without
// bound meets a std::bad_alloc (a finding) rather than the machine's limit.
// Not under AddressSanitizer, which reserves terabytes of shadow memory.
#if defined(__SANITIZE_ADDRESS__)
#define DDA_FUZZ_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DDA_FUZZ_UNDER_ASAN 1
#endif
#endif
void limit_memory(std::uint64_t mb) {
#if !defined(DDA_FUZZ_UNDER_ASAN)
  const rlim_t bytes = static_cast<rlim_t>(std::min<std::uint64_t>(mb, std::uint64_t{1} << 30)) << 20;
  const rlimit limit{bytes, bytes};
  if (setrlimit(RLIMIT_AS, &limit) != 0)
    std::fprintf(stderr, "fuzz_%s: the address space could not be capped at %llu MB; a reader that allocates "
                 "without bound will meet the machine's limit instead.\n", kTarget, static_cast<unsigned long long>(mb));
#endif
}

std::string type_name(const std::type_info& type) {
  int status = 0;
  char* name = abi::__cxa_demangle(type.name(), nullptr, nullptr, &status);
  std::string result = status == 0 && name ? name : type.name();
  std::free(name);
  return result;
}

// Runs the target on one input; exits 1 after reporting a finding.
void run_one(const Bytes& input, const std::string& what, const std::string& file_name, const Options& o) {
  current.data = input.data();
  current.size = input.size();
  std::snprintf(current.what, sizeof current.what, "%s", what.c_str());
  const std::string path = o.artifacts + "/" + file_name;
  std::snprintf(current.path, sizeof current.path, "%s", path.c_str());
  std::snprintf(current.temp_path, sizeof current.temp_path, "%s.part", path.c_str());
  alarm(o.timeout_s);
  std::string escaped;
  try {
    LLVMFuzzerTestOneInput(input.data(), input.size());
  } catch (const std::exception& e) {
    escaped = "let a " + type_name(typeid(e)) + " escape (\"" + e.what() + "\")";
  } catch (...) {
    escaped = "let an exception that is not a std::exception escape";
  }
  alarm(0);
  if (!escaped.empty()) {
    report_finding(escaped.c_str());
    std::exit(1);
  }
}

[[noreturn]] void usage_error(const std::string& sentence) {
  std::fprintf(stderr,
               "fuzz_%s_standalone: %s\nusage: fuzz_%s_standalone [--runs N] [--seed S] [--iteration I] "
               "[--artifacts DIR] [--timeout SECONDS] [--memory-mb MB] PATH...\n",
               kTarget, sentence.c_str(), kTarget);
  std::exit(2);
}

std::uint64_t whole_number(const std::string& option, const char* text) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text, &end, 10);
  if (!*text || *end || errno || text[0] == '-') usage_error(option + " needs a whole number, not '" + text + "'.");
  return v;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--", 0) != 0) {
      o.paths.push_back(a);
      continue;
    }
    if (i + 1 >= argc) usage_error(a + " needs a value.");
    const char* v = argv[++i];
    if (a == "--runs") o.runs = whole_number(a, v);
    else if (a == "--seed") o.seed = whole_number(a, v);
    else if (a == "--iteration") o.iteration = whole_number(a, v);
    else if (a == "--artifacts") o.artifacts = v;
    else if (a == "--timeout") o.timeout_s = static_cast<unsigned>(std::min<std::uint64_t>(whole_number(a, v), 86400));
    else if (a == "--memory-mb") o.memory_mb = whole_number(a, v);
    else usage_error("unknown option " + a + ".");
  }
  if (o.paths.empty()) usage_error("no seed file or folder was given.");
  if (o.timeout_s == 0) usage_error("--timeout must be at least 1 second.");
  return o;
}

Bytes read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  Bytes b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) usage_error("cannot read " + path.string() + ".");
  return b;
}

// The seeds of every PATH, each folder's files in name order (a folder
// lists them in any order; the run must not depend on it).
std::vector<Seed> load_seeds(const std::vector<std::string>& paths) {
  std::vector<Seed> seeds;
  for (const std::string& p : paths) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<fs::path> files;
      for (const auto& entry : fs::directory_iterator(p, ec))
        if (entry.is_regular_file()) files.push_back(entry.path());
      std::sort(files.begin(), files.end());
      for (const auto& f : files) seeds.push_back({f.string(), read_bytes(f)});
    } else if (fs::is_regular_file(p, ec)) {
      seeds.push_back({p, read_bytes(p)});
    } else {
      usage_error(p + " is neither a file nor a folder.");
    }
  }
  if (seeds.empty()) usage_error("the folders given hold no seed file.");
  return seeds;
}

std::string finding_file(const Options& o, std::uint64_t iteration) {
  return "finding-" + std::string(kTarget) + "-seed" + std::to_string(o.seed) + "-iteration" +
         std::to_string(iteration);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const std::vector<Seed> seeds = load_seeds(o.paths);
  std::error_code ec;
  fs::create_directories(o.artifacts, ec);
  install_handlers();
  limit_memory(o.memory_mb);

  std::size_t largest = 0;
  for (const Seed& s : seeds) largest = std::max(largest, s.bytes.size());
  // Room to grow, as libFuzzer's -max_len leaves, without letting stacked
  // insertions make inputs no reader would meet.
  const std::size_t max_size = std::max<std::size_t>(2 * largest, 4096);

  const auto mutant_of = [&](std::uint64_t i) {
    dda::fuzz::Rng rng = dda::fuzz::Rng::for_iteration(o.seed, i);
    const Seed& base = seeds[rng.below(seeds.size())];
    const Seed& other = seeds[rng.below(seeds.size())];
    return std::make_pair(dda::fuzz::mutant(base.bytes, other.bytes, max_size, rng), &base);
  };
  const auto mutant_what = [&](std::uint64_t i, const Seed& base) {
    return "mutation " + std::to_string(i) + " (--seed " + std::to_string(o.seed) + " --iteration " +
           std::to_string(i) + ", made from " + base.name + ")";
  };

  if (o.iteration) {
    const auto [input, base] = mutant_of(*o.iteration);
    run_one(input, mutant_what(*o.iteration, *base), finding_file(o, *o.iteration), o);
    std::printf("fuzz_%s: mutation %llu of seed %llu: no finding\n", kTarget,
                static_cast<unsigned long long>(*o.iteration), static_cast<unsigned long long>(o.seed));
    return 0;
  }
  for (std::size_t k = 0; k < seeds.size(); ++k)
    run_one(seeds[k].bytes, "input " + seeds[k].name, "finding-" + std::string(kTarget) + "-input" + std::to_string(k), o);
  for (std::uint64_t i = 0; i < o.runs; ++i) {
    const auto [input, base] = mutant_of(i);
    run_one(input, mutant_what(i, *base), finding_file(o, i), o);
  }
  std::printf("fuzz_%s: %zu inputs and %llu mutations of them (seed %llu): no finding\n", kTarget, seeds.size(),
              static_cast<unsigned long long>(o.runs), static_cast<unsigned long long>(o.seed));
  return 0;
}
