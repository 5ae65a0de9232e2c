#pragma once
// What the 2D and the 3D results files (results_h5.cpp, results3d_h5.cpp)
// and their checkpoints share: the root attributes (format, provenance,
// schedule, how far the run got) and strict readers of datasets of a known
// shape. Private to DF; layouts in docs/formats.md.
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/geometry.hpp"
#include "dda/common/geometry3.hpp"
#include "dda/common/h5_util.hpp"
#include "dda/df/results.hpp"

namespace dda::df::h5io {

constexpr int kResultsFormatVersion = 1;

// Rows of x y (z), for an (n, 2) or (n, 3) dataset.
std::vector<double> flat(const std::vector<Vec2>& v);
std::vector<double> flat(const std::vector<Vec3>& v);

// /points: name, block and initial position ((n, dim) flat rows) of every
// measurement point, in the order of the /series columns.
void write_points(h5::Writer& w, const std::vector<std::string>& names, const std::vector<std::int32_t>& blocks,
                  const std::vector<double>& initial, hsize_t dim);

// The times of the /series samples: those of the first point's history, or
// with no points the start and the end of every step of the log.
template <class Histories, class Log>
std::vector<double> series_times(const Histories& histories, const Log& log, double now) {
  std::vector<double> time;
  if (!histories.empty()) {
    for (const auto& m : histories[0]) time.push_back(m.time);
  } else {
    time.push_back(log.empty() ? now : log.front().time - log.front().dt);
    for (const auto& s : log) time.push_back(s.time);
  }
  return time;
}

// A group below `parent`.
h5::Id subgroup(hid_t parent, const std::string& name);

// format, format_version, units, provenance (program version and time
// filled in), input_kind, blocks_path, output_interval, output_every,
// complete, time, steps.
void write_root(h5::Writer& w, const char* format, const char* units, const ResultsSource& source,
                const OutputSchedule& output, bool complete, double time, int steps);

struct RootInfo {
  ResultsSource source;
  OutputSchedule output;
  bool complete = false;
};
// Checks `format` and its version, and reads the rest of write_root's attributes.
RootInfo read_root(const h5::Reader& r, const char* format);

// A float64 dataset of exactly this shape.
std::vector<double> read_f64(const h5::Reader& r, const std::string& name, const std::vector<hsize_t>& dims);
// An integer dataset of exactly n values.
std::vector<std::int64_t> read_i64(const h5::Reader& r, const std::string& name, std::size_t n);
// The first dimension of a dataset (an error for a scalar).
std::size_t length(const h5::Reader& r, const std::string& name);
// The first dimension of a dataset, 0 for a scalar.
std::size_t rows_of(const h5::Reader& r, const std::string& name);

}  // namespace dda::df::h5io
