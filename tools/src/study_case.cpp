#include "study_case.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>

#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "study_measures.hpp"

extern char** environ;

namespace dda::cli {

namespace fs = std::filesystem;

namespace {

// Keys whose text is a path relative to the scenario's folder (the
// scenario readers resolve them with resolve_scenario_path).
bool names_a_file(const std::string& key) { return key == "file" || key == "geometry" || key == "record"; }

void make_paths_absolute(YAML::Node node, const fs::path& base_dir) {
  if (node.IsMap()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string key = it->first.Scalar();
      if (names_a_file(key) && it->second.IsScalar()) {
        const fs::path p(it->second.Scalar());
        if (p.is_relative()) it->second = (base_dir / p).lexically_normal().string();
      } else {
        make_paths_absolute(it->second, base_dir);
      }
    }
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) make_paths_absolute(node[i], base_dir);
  }
}

std::string self_executable() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw InputError("cannot find this program's own file (/proc/self/exe) to run the cases with.");
  return p.string();
}

// The last line of the case's log that `dda` wrote as its error, without
// the "dda: " in front.
std::string error_in_log(const fs::path& log) {
  std::ifstream in(log);
  std::string line, found;
  while (std::getline(in, line))
    if (line.rfind("dda: ", 0) == 0) found = line.substr(5);
  return found;
}

// Runs argv with stdout and stderr into `log` and OMP/BLAS threads set;
// returns the wait status. The child dies with the thread that started it
// (PR_SET_PDEATHSIG), so a killed study leaves no case running on.
int run_child(const std::vector<std::string>& args, const fs::path& log, int threads) {
  std::vector<std::string> env_text;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    if (entry.rfind("OMP_NUM_THREADS=", 0) == 0 || entry.rfind("OPENBLAS_NUM_THREADS=", 0) == 0) continue;
    env_text.push_back(entry);
  }
  env_text.push_back("OMP_NUM_THREADS=" + std::to_string(threads));
  env_text.push_back("OPENBLAS_NUM_THREADS=" + std::to_string(threads));
  std::vector<char*> argv, envp;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  for (const std::string& e : env_text) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  const std::string log_path = log.string();
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw InputError(std::string("cannot start a case: fork failed (") + std::strerror(errno) + ").");
  if (pid == 0) {
    // Only async-signal-safe calls between fork and exec.
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(127);
    const int fd = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) _exit(126);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    const int null_in = open("/dev/null", O_RDONLY);
    if (null_in >= 0) dup2(null_in, STDIN_FILENO);
    execve(argv[0], argv.data(), envp.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw InputError(std::string("lost a case's process: ") + std::strerror(errno) + ".");
  return status;
}

// The error with the case's folder left out of the paths it names
// ("scenario.yaml: ...", "results.h5: ..."): the summary row names the case,
// and the text is then the same whatever OUTDIR is (a local run and an MPI
// run into another folder give the same summary).
std::string relative_to_case(std::string text, const fs::path& dir) {
  const std::string prefix = dir.string() + "/";
  for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at))
    text.erase(at, prefix.size());
  return text;
}

}  // namespace

std::string case_scenario_text(const study::Study& study, const study::Case& c) {
  YAML::Node doc = YAML::Clone(c.doc);
  make_paths_absolute(doc, fs::absolute(fs::path(study.base_label)).parent_path());
  YAML::Emitter e;
  e << doc;
  return std::string(e.c_str()) + "\n";
}

std::optional<study::CaseRecord> finished_case(const fs::path& dir, const std::string& scenario_text,
                                               std::size_t measures, bool retry_failed) {
  std::error_code ec;
  if (!fs::exists(dir / "case.json", ec) || !fs::exists(dir / "scenario.yaml", ec)) return std::nullopt;
  std::ifstream scenario(dir / "scenario.yaml"), record(dir / "case.json");
  std::stringstream s, r;
  s << scenario.rdbuf();
  r << record.rdbuf();
  if (s.str() != scenario_text) return std::nullopt;
  const auto j = nlohmann::json::parse(r.str(), nullptr, false);
  if (j.is_discarded()) return std::nullopt;
  auto rec = study::record_from_json(j, measures);
  if (rec && retry_failed && !rec->ok) return std::nullopt;
  return rec;
}

study::CaseRecord run_pipeline_case(const study::Study& study, const std::string& scenario_text, const fs::path& dir,
                                    int threads) {
  const auto start = std::chrono::steady_clock::now();
  study::CaseRecord record;
  try {
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string scenario = (dir / "scenario.yaml").string();
    write_text_atomically(scenario, scenario_text);
    const int status = run_child({self_executable(), "run", scenario, "-o", dir.string(), "--no-plots", "--no-vtk",
                                  "--no-report"},
                                 dir / "log.txt", threads);
    if (WIFSIGNALED(status)) {
      record.error = "its dda run was killed by signal " + std::to_string(WTERMSIG(status)) + ".";
    } else if (WEXITSTATUS(status) != 0) {
      record.error = error_in_log(dir / "log.txt");
      if (record.error.empty())
        record.error = "its dda run ended with status " + std::to_string(WEXITSTATUS(status)) + " (see log.txt).";
    } else {
      record.measures = pipeline_measures(dir, study.measures);
      record.ok = true;
    }
  } catch (const std::exception& e) {
    record.ok = false;
    record.error = e.what();
  }
  if (!record.ok) {
    record.measures.clear();
    record.error = relative_to_case(record.error, dir);
  }
  record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  try {
    write_text_atomically((dir / "case.json").string(), study::record_json(record).dump(1) + "\n");
  } catch (const std::exception& e) {
    record.ok = false;
    record.error = std::string("its record could not be written: ") + e.what();
  }
  return record;
}

}  // namespace dda::cli
