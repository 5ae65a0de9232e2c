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

#include "dda/common/coordinate_range.hpp"
#include "dda/common/geometry.hpp"
#include "distribution.hpp"

namespace dda::dc {
namespace {

using nlohmann::json;

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
  j["area"] = detail::distribution(area, bins);
  j["width"] = detail::distribution(width, bins);
  j["min_feret"] = detail::distribution(min_feret, bins);
  j["aspect"] = detail::distribution(aspect, bins);

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
  const double level0 = level_along_beds(model.origin, model.bedding_dip_deg);  // the user's levels
  for (std::size_t i = 0; i < nl; ++i) {
    const Layer& l = model.layers[i];
    json e{{"layer", i},
           {"bottom", user_level(l.bottom, level0)},
           {"top", user_level(l.top, level0)},
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
