#pragma once
// The signals `dda spectra` analyses (docs/analytical.md, "Spectra"):
// measurement-point histories of a results file or of a `dda history --csv`
// file, columns of a CSV table with a header line, or an acceleration record
// (PEER .AT2, or a CSV read as `dda record` reads it when --units is given).
// Each is checked (times strictly increasing, values finite) and put on a
// uniform step.
#include <memory>
#include <string>
#include <vector>

#include "dda/analysis/sampling.hpp"
#include "dda/analysis/table.hpp"
#include "dda/common/record.hpp"
#include "dda/df/io/results.hpp"

namespace dda::cli {

enum class Quantity { displacement, velocity, acceleration };
Quantity parse_quantity(const std::string& text, const std::string& flag);
const char* quantity_name(Quantity q);

// A history as read, on its own (possibly uneven) times.
struct RawSignal {
  std::string label;  // slider.vx, a column name, record.x
  std::string units;  // m, m/s, m/s^2, or "" for a CSV column (its own units)
  std::vector<double> t, x;
  // x is a velocity whose derivative was asked for: central differences
  // after resampling (a results file stores no acceleration).
  bool differentiate = false;
};

// A signal on a uniform step, ready for a transform.
struct UniformSignal {
  std::string label, units;
  analysis::UniformSeries series;
};

// Fewest samples a spectrum or response spectrum is computed from.
constexpr std::size_t kMinSpectraSamples = 8;

class SignalSource {
 public:
  // A results file (.h5), a record (.at2; or a CSV when `record_units` is
  // not empty), or else a CSV table with a header line, t first.
  SignalSource(const std::string& path, const std::string& record_units);

  bool is_results() const { return results_ != nullptr; }
  bool is_record() const { return record_ != nullptr; }
  bool is_table() const { return table_ != nullptr; }
  const std::string& path() const { return path_; }

  // Component 'x' or 'y' of a measurement point: from a results file, or the
  // columns NAME.ux NAME.uy / NAME.vx NAME.vy of a `dda history --csv` file.
  RawSignal point(const std::string& name, char component, Quantity q) const;
  // A column of a CSV table.
  RawSignal column(const std::string& name) const;
  // Component 'x', 'y' or 'z' of a record (m/s^2).
  RawSignal record_component(char component) const;

 private:
  std::string path_;
  std::shared_ptr<const df::Results> results_;
  std::shared_ptr<const analysis::NamedTable> table_;
  std::shared_ptr<const AccelRecord> record_;
};

// The signals (all on one time axis) at the step `dt`, or at the median
// step of their times when dt is 0; linear interpolation only where the
// times are not already uniform at that step. Then the derivatives asked
// for. `resampled` tells whether interpolation happened. InputError naming
// the file when fewer than kMinSpectraSamples samples result.
std::vector<UniformSignal> make_uniform(const std::vector<RawSignal>& raw, double dt, const std::string& path,
                                        bool& resampled);

}  // namespace dda::cli
