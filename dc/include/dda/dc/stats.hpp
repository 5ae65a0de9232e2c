#pragma once
// Block statistics: the structural characterisation engineers do before any
// forward run (`dda stats blocks.h5 --json`).
#include <nlohmann/json.hpp>

#include "dda/common/block_model.hpp"

namespace dda::dc {

// Keys: blocks, total_area, domain_area, excavated_area, area{...},
// width{...}, min_feret{...}, per_layer[...]. Each distribution holds
// min, max, mean, std, median, percentiles {p5, p10, p25, p50, p75, p90, p95}
// and a histogram {edges, counts} with `bins` bins.
nlohmann::json block_statistics(const BlockModel& model, int bins = 20);

}  // namespace dda::dc
