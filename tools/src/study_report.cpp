#include "study_report.hpp"

#include <cmath>
#include <cstdio>

#include "pipeline.hpp"
#include "plot_runner.hpp"

namespace dda::cli {

namespace fs = std::filesystem;
using study::KeyPath;

Interval wilson_interval(std::size_t k, std::size_t n, double z) {
  if (n == 0) return {0, 1};
  const double nn = static_cast<double>(n), p = static_cast<double>(k) / nn, z2 = z * z;
  const double centre = (p + z2 / (2 * nn)) / (1 + z2 / nn);
  const double half = z / (1 + z2 / nn) * std::sqrt(p * (1 - p) / nn + z2 / (4 * nn * nn));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

namespace {

std::string g4(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

std::string describe_study(const study::Study& study, const std::vector<study::CaseRecord>& records, double seconds) {
  std::size_t ok = 0;
  for (const auto& r : records) ok += r.ok;
  char head[160];
  std::snprintf(head, sizeof head, "study: %zu cases, %zu ok, %zu failed, in %.3g s\n", records.size(), ok,
                records.size() - ok, seconds);
  std::string text = head;
  std::size_t shown = 0;
  for (std::size_t i = 0; i < records.size() && shown < 3; ++i)
    if (!records[i].ok) {
      text += "  case " + study::case_id(i, records.size()) + " failed: " + records[i].error + "\n";
      ++shown;
    }
  for (std::size_t k = 0; k < study.measures.size(); ++k) {
    double sum = 0, sum2 = 0, lo = INFINITY, hi = -INFINITY;
    std::size_t n = 0;
    for (const auto& r : records)
      if (r.ok && std::isfinite(r.measures[k])) {
        const double v = r.measures[k];
        sum += v;
        sum2 += v * v;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        ++n;
      }
    if (n == 0) {
      text += "  " + study.measures[k].name + ": no case has a finite value\n";
      continue;
    }
    const double mean = sum / static_cast<double>(n);
    const double sd = n > 1 ? std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / static_cast<double>(n - 1))) : 0.0;
    text += "  " + study.measures[k].name + ": mean " + g4(mean) + ", std " + g4(sd) + ", from " + g4(lo) + " to " +
            g4(hi) + " (" + std::to_string(n) + " cases)\n";
  }
  if (study.failure) {
    std::size_t k = 0;
    while (study.measures[k].name != study.failure->measure) ++k;
    std::size_t n = 0, failed = 0;
    for (const auto& r : records)
      if (r.ok && !std::isnan(r.measures[k])) {
        ++n;
        failed += study.failure->failed(r.measures[k]);
      }
    const Interval ci = wilson_interval(failed, n);
    const std::string rule = study.failure->below ? " < " + g4(*study.failure->below) : " > " + g4(*study.failure->above);
    text += "  probability of failure P(" + study.failure->measure + rule + ") = " +
            g4(n ? static_cast<double>(failed) / static_cast<double>(n) : NAN) + " (" + std::to_string(failed) +
            " of " + std::to_string(n) + " cases; 95 % interval " + g4(ci.lo) + " to " + g4(ci.hi) + ")\n";
  }
  return text;
}

void draw_study_figures(const study::Study& study, const fs::path& outdir, bool quiet) {
  if (!plotting_available()) {
    say(quiet, "figures skipped: /usr/bin/python3 with matplotlib and h5py is not installed\n");
    return;
  }
  const fs::path figures = outdir / "figures";
  make_dir(figures);
  std::vector<std::string> args{(outdir / "summary.csv").string(), "-o", figures.string()};
  for (const std::string& c : study.value_columns()) args.insert(args.end(), {"--value", c});
  for (const auto& m : study.measures) args.insert(args.end(), {"--measure", m.name});
  for (const study::VariedKey& v : study.vary) {
    if (v.paths.size() < 2) continue;
    std::string keys;
    for (const KeyPath& p : v.paths) keys += (keys.empty() ? "" : ",") + p.text;
    args.insert(args.end(), {"--linked", keys});
  }
  if (study.failure)
    args.insert(args.end(), {"--failure", study.failure->measure,
                             study.failure->below ? "below" : "above",
                             std::to_string(study.failure->below ? *study.failure->below : *study.failure->above)});
  if (study.kind == study::CaseKind::wedge) args.push_back("--wedge");
  run_script("dda_study_plot.py", args);
  say(quiet, "figures written to " + figures.string() + "\n");
}

}  // namespace dda::cli
