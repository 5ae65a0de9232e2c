#include "plot_runner.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"

extern char** environ;

namespace dda::cli {

namespace fs = std::filesystem;

namespace {

std::string find_plot_script() {
  if (const char* env = std::getenv("DDA_PLOT_SCRIPT")) return env;
  // Installed layout: PREFIX/bin/dda and PREFIX/share/dda/dda_plot.py.
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = self.parent_path().parent_path() / "share" / "dda" / "dda_plot.py";
    if (fs::exists(installed)) return installed.string();
  }
#ifdef DDA_PLOT_SCRIPT
  if (fs::exists(DDA_PLOT_SCRIPT)) return DDA_PLOT_SCRIPT;
#endif
  throw InputError("cannot find the plot script dda_plot.py (set DDA_PLOT_SCRIPT to its path).");
}

// The other scripts (dda_report.py) live next to dda_plot.py.
std::string find_script(const std::string& name) {
  if (name == "dda_plot.py") return find_plot_script();
  const fs::path path = fs::path(find_plot_script()).parent_path() / name;
  if (!fs::exists(path)) throw InputError("cannot find the script " + path.string() + ".");
  return path.string();
}

std::string find_python() {
  // Debian's interpreter carries python3-matplotlib and python3-h5py; another
  // python3 earlier on PATH usually does not.
  if (const char* env = std::getenv("DDA_PYTHON")) return env;
  if (fs::exists("/usr/bin/python3")) return "/usr/bin/python3";
  return "python3";
}

// Runs argv, capturing stderr into `err`; returns the exit status.
int spawn_and_wait(const std::vector<std::string>& argv, std::string& err) {
  char tmpl[] = "/tmp/dda-plot-XXXXXX";
  const int fd = mkstemp(tmpl);
  if (fd < 0) throw InputError("cannot create a temporary file for the plot script's messages.");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fd, STDERR_FILENO);
  std::vector<char*> cargv;
  for (const auto& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
  cargv.push_back(nullptr);
  setenv("MPLBACKEND", "Agg", 1);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, cargv[0], &actions, nullptr, cargv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 127;
  if (rc == 0) waitpid(pid, &status, 0);
  close(fd);
  std::ifstream in(tmpl);
  std::ostringstream text;
  text << in.rdbuf();
  err = text.str();
  std::remove(tmpl);
  if (rc != 0) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

std::string last_line(const std::string& text) {
  std::string s = text;
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  const auto pos = s.rfind('\n');
  return pos == std::string::npos ? s : s.substr(pos + 1);
}

}  // namespace

void run_plot_script(const std::vector<std::string>& args) { run_script("dda_plot.py", args); }

void run_report_script(const std::vector<std::string>& args) { run_script("dda_report.py", args); }

void run_script(const std::string& script, const std::vector<std::string>& args) {
  std::vector<std::string> argv{find_python(), find_script(script)};
  argv.insert(argv.end(), args.begin(), args.end());
  std::string err;
  const int status = spawn_and_wait(argv, err);
  if (status == 127) throw InputError("cannot run " + argv[0] + " to draw the figures (is python3 installed?).");
  if (status != 0) {
    std::string msg = last_line(err);
    // The scripts start their one-line messages with their name.
    for (const std::string& prefix : {script + ": ", std::string("dda_plot: ")})
      if (msg.rfind(prefix, 0) == 0) msg = msg.substr(prefix.size());
    while (!msg.empty() && msg.back() == '.') msg.pop_back();
    throw InputError(msg.empty() ? "the plot script failed." : msg + ".");
  }
}

void plot_csv(const std::string& csv, const std::string& written, const std::vector<std::string>& args) {
  std::vector<std::string> argv{written};
  if (written.empty())
    argv[0] = (fs::temp_directory_path() / ("dda-plot-" + std::to_string(::getpid()) + ".csv")).string();
  argv.insert(argv.end(), args.begin(), args.end());
  if (!written.empty()) return run_plot_script(argv);
  write_text_atomically(argv[0], csv);
  try {
    run_plot_script(argv);
  } catch (...) {
    fs::remove(argv[0]);
    throw;
  }
  fs::remove(argv[0]);
}

bool plotting_available() {
  std::string err;
  return spawn_and_wait({find_python(), "-c", "import h5py, matplotlib"}, err) == 0;
}

}  // namespace dda::cli
