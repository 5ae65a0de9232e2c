#pragma once
// A study's cases. Case i is grid point g, seed s and draw d with
// i = (g * S + s) * D + d: the grid's last key varies fastest, then the
// seeds, then the draws. Draw d takes its values from its own stream,
// dl::Stream(sample.seed, "study.sample", d), in the order of the study file
// (values, then the Fisher planes): the same draw gives the same values at
// every grid point and seed (common random numbers, so that a difference
// between grid points is not sampling noise), and any case can be made
// alone, by any process, from its index.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dda/study/study.hpp"

namespace dda::study {

struct Case {
  std::size_t index = 0;
  std::string id;                     // "c0042": zero-padded, so folders sort in case order
  std::optional<std::uint64_t> seed;  // the scenario's seed, when the study sets seeds
  std::optional<std::size_t> draw;    // the Monte Carlo draw, when the study samples
  std::vector<std::string> values;    // one per Study::value_columns()
  YAML::Node doc;                     // the base with the case's values set
};

Case make_case(const Study& study, std::size_t index);
std::string case_id(std::size_t index, std::size_t count);

}  // namespace dda::study
