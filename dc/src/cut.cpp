// cut_blocks: lines -> blocks. Orchestrates the stages listed in
// cut_internal.hpp and writes the report.
//
// Report keys (all counts unless stated):
//   input_lines, segments_too_short, lines_outside_domain, lines_clipped,
//   min_segment_length (m), snap_length (m),
//   near_crossings {crossings, merged, segments_rerouted}  (near_crossings.cpp),
//   arrangement {vertices, edges, faces}   right after insertion,
//   dangling_edges_removed, isolated_vertices_removed,
//   faces               bounded faces after pruning,
//   faces_outside_domain, removed_in_excavations, removed_by_hole_points,
//   faces_with_holes, artificial_cuts,
//   slivers_merged, sliver_merge_failed, slivers_reported, slivers [{block, area, aspect}],
//   degenerate_blocks, degenerate [{x, y, vertices, area, reason}],
//   collinear_vertices_removed, duplicate_vertices_removed,
//   blocks, block_area, domain_area, excavated_area (m^2), located_points,
//   warnings [text], seconds (total), seconds_detail {prepare, near_crossings, arrangement,
//   topology, extract, blocks}.
#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

#include "cut_internal.hpp"
#include "dda/common/coordinate_range.hpp"
#include "dda/common/error.hpp"
#include "dda/dc/cut.hpp"

namespace dda::dc {

namespace {
// The point as the user gave it: its position about the model's local origin, plus the origin.
std::string describe(const ModelPoint& p, const Vec2& origin) {
  const Vec2 at = user_position(p.p, origin);
  std::ostringstream s;
  s.precision(origin == Vec2::Zero() ? 10 : 15);
  s << to_string(p.kind) << " point '" << p.name << "' at (" << at.x() << ", " << at.y() << ")";
  return s.str();
}
}  // namespace

CutResult cut_blocks(const LineModel& lines, const CutOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto t_start = Clock::now();
  auto secs = [](Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); };

  for (const ModelPoint& p : lines.points)
    if (!std::isfinite(p.p.x()) || !std::isfinite(p.p.y()))
      throw InputError("The " + describe(p, lines.origin) + " has a coordinate that is not a finite number.");

  detail::PreparedInput in = detail::prepare_segments(lines, options);
  const double t_prepare = secs(t_start);
  const auto t_near = Clock::now();
  const detail::NearCrossings near = detail::merge_near_crossings(in);
  const double t_near_crossings = secs(t_near);

  std::vector<Vec2> holes, locate;
  std::vector<std::size_t> hole_index, locate_index;
  for (std::size_t i = 0; i < lines.points.size(); ++i) {
    if (lines.points[i].kind == PointKind::Hole) {
      holes.push_back(lines.points[i].p);
      hole_index.push_back(i);
    } else {
      locate.push_back(lines.points[i].p);
      locate_index.push_back(i);
    }
  }

  std::vector<int> hole_where;
  detail::ArrangementResult ar = detail::cut_arrangement(in, holes, locate, options.sliver, hole_where);
  for (std::size_t k = 0; k < holes.size(); ++k)
    if (hole_where[k] == 2)
      throw InputError("The " + describe(lines.points[hole_index[k]], lines.origin) + " lies outside the domain.");

  // Free the arrangement on another thread while the blocks are built (it
  // shares nothing with them).
  double t_release = 0;
  std::thread releaser([&ar, &t_release] {
    const auto t = Clock::now();
    ar.owner.reset();
    t_release = std::chrono::duration<double>(Clock::now() - t).count();
  });
  struct Join {
    std::thread& t;
    ~Join() {
      if (t.joinable()) t.join();
    }
  } join{releaser};

  auto t0 = Clock::now();
  detail::BlockBuild bb = detail::build_blocks(ar, lines.layers, lines.bedding_dip_deg);
  const double t_blocks = secs(t0);

  CutResult result;
  BlockModel& m = result.model;
  m.blocks = std::move(bb.blocks);
  m.sets = lines.sets;
  m.layers = lines.layers;
  m.bedding_dip_deg = lines.bedding_dip_deg;
  m.origin = lines.origin;
  m.provenance = lines.provenance;
  m.domain_area = in.has_domain ? std::abs(signed_area(lines.domain)) : ar.domain_area;
  m.excavated_area = ar.excavated_area;

  for (std::size_t k = 0; k < locate.size(); ++k) {
    const ModelPoint& p = lines.points[locate_index[k]];
    const int face = ar.point_face[k];
    const int block = face >= 0 ? bb.face_block[static_cast<std::size_t>(face)] : -1;
    if (block < 0) {
      const int w = ar.point_where[k];
      const char* why = face >= 0                ? "it falls in a block that degenerated when rounded"
                        : w == 1                  ? "it is inside an excavation"
                        : w == 3                  ? "it is in a block removed by a hole point"
                                                  : "it is outside the domain";
      throw InputError("The " + describe(p, lines.origin) + " lies in no block: " + why + ".");
    }
    m.points.push_back({p, block});
  }

  // Slivers still present (all of them when merge is off).
  nlohmann::json slivers = nlohmann::json::array();
  if (options.sliver.min_area > 0 || options.sliver.max_aspect > 0) {
    for (std::size_t i = 0; i < m.blocks.size(); ++i) {
      const detail::ShapeMeasures sm = detail::shape_measures(m.blocks[i].vertices);
      if (detail::is_sliver(m.blocks[i].area, sm.aspect, options.sliver))
        slivers.push_back({{"block", i}, {"area", m.blocks[i].area}, {"aspect", sm.aspect}});
    }
  }
  nlohmann::json degenerate = nlohmann::json::array();
  for (const auto& d : bb.degenerate)
    degenerate.push_back({{"x", d.near.x()},
                          {"y", d.near.y()},
                          {"vertices", d.vertices},
                          {"area", d.area},
                          {"reason", d.reason}});
  double block_area = 0;
  for (const Block& b : m.blocks) block_area += b.area;

  releaser.join();
  nlohmann::json& r = result.report;
  r["input_lines"] = in.input_lines;
  r["segments_too_short"] = in.segments_too_short;
  r["lines_outside_domain"] = in.lines_outside_domain;
  r["lines_clipped"] = in.lines_clipped;
  r["min_segment_length"] = in.min_segment_length;
  r["snap_length"] = in.snap;
  r["near_crossings"] = {{"crossings", near.crossings}, {"merged", near.merged}, {"segments_rerouted", near.rerouted}};
  r["arrangement"] = {{"vertices", ar.arrangement_vertices},
                      {"edges", ar.arrangement_edges},
                      {"faces", ar.arrangement_faces}};
  r["dangling_edges_removed"] = ar.dangling_edges_removed;
  r["isolated_vertices_removed"] = ar.isolated_vertices_removed;
  r["faces"] = ar.bounded_faces;
  r["faces_outside_domain"] = ar.faces_outside_domain;
  r["removed_in_excavations"] = ar.faces_in_excavations;
  r["removed_by_hole_points"] = ar.removed_by_hole_points;
  r["faces_with_holes"] = ar.faces_with_holes;
  r["artificial_cuts"] = ar.artificial_cuts;
  r["slivers_merged"] = ar.slivers_merged;
  r["sliver_merge_failed"] = ar.sliver_merge_failed;
  r["slivers_reported"] = slivers.size();
  r["slivers"] = std::move(slivers);
  r["degenerate_blocks"] = bb.degenerate.size();
  r["degenerate"] = std::move(degenerate);
  r["collinear_vertices_removed"] = bb.collinear_vertices_removed;
  r["duplicate_vertices_removed"] = bb.duplicate_vertices_removed;
  r["blocks"] = m.blocks.size();
  r["block_area"] = block_area;
  r["domain_area"] = m.domain_area;
  r["excavated_area"] = m.excavated_area;
  r["located_points"] = m.points.size();
  r["warnings"] = ar.warnings;
  r["seconds"] = secs(t_start);
  r["seconds_detail"] = {{"prepare", t_prepare},
                         {"near_crossings", t_near_crossings},
                         {"arrangement", ar.seconds_arrangement},
                         {"topology", ar.seconds_topology},
                         {"prune", ar.seconds_prune},
                         {"classify", ar.seconds_classify},
                         {"cuts", ar.seconds_cuts},
                         {"curves", ar.seconds_curves},
                         {"release", t_release},
                         {"extract", ar.seconds_extract},
                         {"blocks", t_blocks}};
  return result;
}

}  // namespace dda::dc
