// Block statistics before any forward run: sizes and shapes of the blocks a
// cut produced. Definitions are written into the JSON itself ("definitions")
// and into docs/formats.md; tools/plot/dda_plot.py computes `width` the same
// way for its histograms.
#include "dda/dc/stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "dda/common/geometry.hpp"

namespace dda::dc {
namespace {

using nlohmann::json;

// Percentile p (0..100) of sorted values by linear interpolation between
// order statistics: h = (n-1) p/100, v[floor h] + (h - floor h)(v[floor h + 1]
// - v[floor h]) (Hyndman & Fan type 7, numpy's default "linear").
double percentile(const std::vector<double>& sorted, double p) {
  const std::size_t n = sorted.size();
  if (n == 1) return sorted[0];
  const double h = (static_cast<double>(n) - 1.0) * p / 100.0;
  const std::size_t lo = std::min(static_cast<std::size_t>(std::floor(h)), n - 1);
  if (lo + 1 >= n) return sorted[n - 1];
  const double frac = h - static_cast<double>(lo);
  return sorted[lo] + frac * (sorted[lo + 1] - sorted[lo]);
}

// Equal-width bins from min to max, the last bin closed (as numpy.histogram);
// when all values are equal the range is [v - 0.5, v + 0.5].
json histogram(const std::vector<double>& sorted, int bins) {
  double lo = sorted.front(), hi = sorted.back();
  if (!(hi > lo)) {
    lo -= 0.5;
    hi += 0.5;
  }
  std::vector<double> edges(static_cast<std::size_t>(bins) + 1);
  for (int i = 0; i <= bins; ++i) edges[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / bins;
  edges.back() = hi;
  std::vector<long long> counts(static_cast<std::size_t>(bins), 0);
  for (double x : sorted) {
    long long k = static_cast<long long>(std::floor((x - lo) / (hi - lo) * bins));
    k = std::clamp<long long>(k, 0, bins - 1);
    // Agree with the edges as written, whatever the rounding above did.
    while (k > 0 && x < edges[static_cast<std::size_t>(k)]) --k;
    while (k < bins - 1 && x >= edges[static_cast<std::size_t>(k) + 1]) ++k;
    ++counts[static_cast<std::size_t>(k)];
  }
  return json{{"edges", edges}, {"counts", counts}};
}

json distribution(std::vector<double> v, int bins) {
  if (v.empty()) return nullptr;
  std::sort(v.begin(), v.end());
  const double n = static_cast<double>(v.size());
  double sum = 0;
  for (double x : v) sum += x;
  const double mean = sum / n;
  double ss = 0;
  for (double x : v) ss += (x - mean) * (x - mean);
  json pct = json::object();
  static const std::pair<const char*, double> kPercentiles[] = {
      {"p5", 5}, {"p10", 10}, {"p25", 25}, {"p50", 50}, {"p75", 75}, {"p90", 90}, {"p95", 95}};
  for (const auto& [key, p] : kPercentiles) pct[key] = percentile(v, p);
  return json{{"min", v.front()},
              {"max", v.back()},
              {"mean", mean},
              {"std", std::sqrt(ss / n)},
              {"median", percentile(v, 50)},
              {"percentiles", pct},
              {"histogram", histogram(v, bins)}};
}

const char* const kDefinitions[][2] = {
    {"blocks", "number of blocks"},
    {"total_area", "sum of the block areas, m^2"},
    {"area", "block area, m^2"},
    {"width",
     "block width: extent of the block along the bedding direction (cos d, sin d), d = "
     "bedding_dip_deg, i.e. max - min of the vertices projected on that direction; the "
     "horizontal extent when the rock is not layered (d = 0), m"},
    {"min_feret", "minimum Feret diameter: the smallest distance between two parallel lines "
                  "enclosing the block (its minimum caliper width), m"},
    {"aspect", "elongation: caliper width perpendicular to the minimum-width direction divided by "
               "the minimum Feret diameter (1 for a square, L/W for an L x W rectangle); blocks "
               "of zero width are left out"},
    {"percentiles", "linear interpolation between order statistics: h = (n-1)p/100, value = "
                    "v[floor h] + (h - floor h)(v[floor h + 1] - v[floor h]) (numpy's default)"},
    {"std", "population standard deviation (divisor n)"},
    {"histogram", "bins equal-width bins from min to max (last bin closed, as numpy.histogram; "
                  "all values equal: range value +- 0.5); counts sum to the number of values"},
    {"per_layer", "one entry per bed of a layered model: blocks whose centroid lies in the bed "
                  "(Block::layer), their mean width and mean area (null if none)"},
};

}  // namespace

nlohmann::json block_statistics(const BlockModel& model, int bins) {
  bins = std::max(bins, 1);
  const double dip = deg2rad(model.bedding_dip_deg);
  const Vec2 bedding(std::cos(dip), std::sin(dip));

  const std::size_t n = model.blocks.size();
  std::vector<double> area, width, min_feret, aspect;
  area.reserve(n);
  width.reserve(n);
  min_feret.reserve(n);
  aspect.reserve(n);
  double total = 0;
  for (const Block& b : model.blocks) {
    area.push_back(b.area);
    total += b.area;
    width.push_back(extent_along(b.vertices, bedding));
    const FeretMeasures f = feret_measures(b.vertices);
    min_feret.push_back(f.min_width);
    if (f.min_width > 0) aspect.push_back(f.aspect);
  }

  json j;
  j["blocks"] = n;
  j["total_area"] = total;
  j["domain_area"] = model.domain_area;
  j["excavated_area"] = model.excavated_area;
  j["bedding_dip_deg"] = model.bedding_dip_deg;
  j["bins"] = bins;
  j["area"] = distribution(area, bins);
  j["width"] = distribution(width, bins);
  j["min_feret"] = distribution(min_feret, bins);
  j["aspect"] = distribution(aspect, bins);

  // Per bed: blocks whose Block::layer is that bed.
  const std::size_t nl = model.layers.size();
  std::vector<std::size_t> count(nl, 0);
  std::vector<double> sum_w(nl, 0.0), sum_a(nl, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const int l = model.blocks[k].layer;
    if (l < 0 || static_cast<std::size_t>(l) >= nl) continue;
    ++count[static_cast<std::size_t>(l)];
    sum_w[static_cast<std::size_t>(l)] += width[k];
    sum_a[static_cast<std::size_t>(l)] += area[k];
  }
  json layers = json::array();
  for (std::size_t i = 0; i < nl; ++i) {
    const Layer& l = model.layers[i];
    json e{{"layer", i},
           {"bottom", l.bottom},
           {"top", l.top},
           {"thickness", l.thickness()},
           {"blocks", count[i]}};
    const double c = static_cast<double>(count[i]);
    e["mean_width"] = count[i] ? json(sum_w[i] / c) : json(nullptr);
    e["mean_area"] = count[i] ? json(sum_a[i] / c) : json(nullptr);
    layers.push_back(std::move(e));
  }
  j["per_layer"] = std::move(layers);

  json defs = json::object();
  for (const auto& d : kDefinitions) defs[d[0]] = d[1];
  j["definitions"] = std::move(defs);
  return j;
}

}  // namespace dda::dc
