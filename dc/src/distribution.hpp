#pragma once
// Summary of a sample as the statistics JSON writes it (2D and 3D blocks):
// min, max, mean, std, median, percentiles {p5 .. p95} and a histogram
// {edges, counts}; null for an empty sample.
#include <nlohmann/json.hpp>
#include <vector>

namespace dda::dc::detail {

nlohmann::json distribution(std::vector<double> v, int bins);

}  // namespace dda::dc::detail
