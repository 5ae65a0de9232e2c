#pragma once
// DC: the 2D block cutter. Turns a LineModel into closed blocks with an
// exact arrangement of segments (CGAL); see cut_cgal.cpp.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "dda/common/block_model.hpp"
#include "dda/common/line_model.hpp"
#include "dda/common/yaml_reader.hpp"

namespace dda::dc {

struct SliverFilter {
  double min_area = 0;      // m^2; blocks smaller than this are slivers (0 = off)
  double max_aspect = 0;    // bounding-width ratio above which a block is a sliver (0 = off)
  bool merge = true;        // merge each sliver into its neighbour across its longest joint edge; else report only
};

struct CutOptions {
  // Segments shorter than this (m) are dropped and counted in the report.
  // Default: 1e-9 times the domain's diagonal, decided at cut time when 0.
  double min_segment_length = 0;
  SliverFilter sliver;
};

// The `cutting:` section of a scenario (absent = defaults).
CutOptions parse_cut_options(const std::optional<YamlNode>& cutting);

struct CutResult {
  BlockModel model;
  nlohmann::json report;  // counts of what was dropped, merged, removed, located
};

CutResult cut_blocks(const LineModel& lines, const CutOptions& options);

}  // namespace dda::dc
