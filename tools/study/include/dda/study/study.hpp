#pragma once
// A study file (docs/studies.md): a base case, a grid of values over key
// paths (`vary`), realisation seeds (`seeds`), Monte Carlo draws
// (`sample`), and what each case reports (`measure`).
//
// read_study() checks all of it before any case runs: the keys of the study
// file itself, and every value of `vary` and a typical value of every
// sampled key by reading the base with that value set, through the reader
// a case would use (the scenario reader for a pipeline, the wedge reader for
// a wedge). Anything wrong is one InputError naming the study file, the
// line and the key.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dda/study/distribution.hpp"
#include "dda/study/key_path.hpp"
#include "dda/study/measure.hpp"

namespace dda::study {

enum class CaseKind {
  pipeline,  // a scenario run by `dda run` in its own folder (DL -> DC -> DF)
  wedge,     // the analytical wedge of `dda wedge`, run in-process
};

// One axis of the grid: a key path and its values, or several key paths
// that change together ("a, b": [[a1, b1], [a2, b2]]), for values tied to
// each other such as a joint bridge that is a fraction of the trace length.
struct VariedKey {
  std::vector<KeyPath> paths;
  std::vector<std::vector<YAML::Node>> values;   // per grid value, one node per path
  std::vector<std::vector<std::string>> texts;   // the same as the summary shows them
};

struct SampledKey {
  KeyPath path;
  Distribution law;
};

// Fisher scatter of one plane given by two key paths of the base.
struct SampledPlane {
  KeyPath dip, dip_direction;
  double kappa = 0;
};

struct Failure {
  std::string measure;
  std::optional<double> below, above;  // failed when the measure is < below (or > above)
  bool failed(double value) const;
};

struct Study {
  std::string file;  // the study file
  std::string text;  // its whole text (kept in study.h5)
  CaseKind kind = CaseKind::pipeline;
  YAML::Node base;          // the base document: a scenario, or the mapping under `wedge`
  std::string base_label;   // what case documents are named after: the base scenario's path, or the study file
  std::vector<VariedKey> vary;
  std::vector<std::uint64_t> seeds;  // empty: the base's own seed, one realisation
  std::uint64_t sample_seed = 1;
  std::size_t draws = 1;
  std::vector<SampledKey> sampled;
  std::vector<SampledPlane> planes;
  std::vector<MeasureSpec> measures;
  std::optional<Failure> failure;

  std::size_t grid_points() const;
  std::size_t case_count() const;
  // The names of the value columns: varied keys, sampled keys, then each
  // scattered plane's dip and dip direction keys.
  std::vector<std::string> value_columns() const;
};

// Reads the document of a case the way a case would (throws InputError,
// whose text then goes into the study's own message). `label` is the file
// the document stands for.
using CaseCheck = std::function<void(const YAML::Node& doc, const std::string& label)>;

// `scenario_check` reads a scenario study's cases (it needs the stages, in
// tools/src); a wedge study's cases are read by check_wedge_document.
Study read_study(const std::string& path, const CaseCheck& scenario_check);

void check_wedge_document(const YAML::Node& doc, const std::string& label);

}  // namespace dda::study
