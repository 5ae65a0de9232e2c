#pragma once
// What `dda study` says at its end, and its figures.
#include <filesystem>
#include <string>
#include <vector>

#include "dda/study/study.hpp"
#include "dda/study/summary.hpp"

namespace dda::cli {

// The 95 % Wilson score interval of a binomial proportion k of n (Wilson
// 1927): better than p +- 1.96 sqrt(p(1-p)/n) near 0 and 1, and never
// outside [0, 1].
struct Interval {
  double lo = 0, hi = 0;
};
Interval wilson_interval(std::size_t k, std::size_t n, double z = 1.959963984540054);

// Lines for the terminal: cases run and failed (with the first errors),
// each measure's mean, standard deviation and range over the cases that
// have it, and the probability of failure with its interval.
std::string describe_study(const study::Study& study, const std::vector<study::CaseRecord>& records, double seconds);

// OUTDIR/figures/*.png from summary.csv (tools/plot/dda_study_plot.py);
// a note instead when matplotlib is not installed.
void draw_study_figures(const study::Study& study, const std::filesystem::path& outdir, bool quiet);

}  // namespace dda::cli
