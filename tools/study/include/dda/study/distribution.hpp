#pragma once
// The draws of a study's `sample:` section (docs/studies.md): a numeric
// value from a normal, log-normal or uniform law, each optionally truncated
// to [min, max]; and the Fisher scatter of a plane's pole about its mean.
// Every draw comes from a dl::Stream, so a study's draws are the same on
// every run and every machine that runs it (random.hpp says how far).
#include <limits>
#include <string>

#include "dda/analysis/orientation.hpp"
#include "dda/common/yaml_reader.hpp"
#include "dda/dl/random.hpp"

namespace dda::study {

struct Distribution {
  enum class Law { normal, lognormal, uniform };
  Law law = Law::normal;
  // normal and lognormal: the mean and standard deviation of the value
  // itself (a log-normal's log then has sigma^2 = ln(1 + std^2/mean^2) and
  // mu = ln(mean) - sigma^2/2).
  double mean = 0, std = 0;
  double from = 0, to = 0;  // uniform: its ends
  double lo = -std::numeric_limits<double>::infinity();  // truncation, inclusive
  double hi = std::numeric_limits<double>::infinity();

  // Draws until a value falls within [lo, hi] (rejection; the reader refuses
  // a window that keeps less than kMinKept of the law).
  double draw(dl::Stream& stream) const;
  // The probability the untruncated law gives to [lo, hi].
  double kept() const;
  // A value the case reader can be tried with before any case runs: the
  // mean (or midpoint) moved into [lo, hi].
  double typical() const;
};

inline constexpr double kMinKept = 1e-3;

// `{distribution: normal|lognormal|uniform|truncated_normal, mean, std,
// min, max}`; InputError naming the file, line and key for anything wrong.
Distribution read_distribution(const YamlNode& node);

// A plane whose pole is scattered about the pole of `mean` by a Fisher law of
// concentration kappa (> 0): the angle theta from the mean pole has
// cos(theta) = 1 + ln(U + (1 - U) exp(-2 kappa)) / kappa with U uniform on
// (0, 1], and its azimuth about the mean pole is uniform. The drawn pole is
// taken upward, so the plane's dip stays in [0, 90].
analysis::Plane fisher_draw(const analysis::Plane& mean, double kappa, dl::Stream& stream);

}  // namespace dda::study
