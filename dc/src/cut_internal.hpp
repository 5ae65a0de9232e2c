#pragma once
// Plain interfaces between the stages of the 2D block cutter. Nothing here
// sees CGAL: cut_cgal.cpp is the only translation unit that does.
//
//   cut.cpp          orchestration, points, report
//   prepare.cpp      lines -> input segments (clip, extend, drop short)
//   near_crossings.cpp  crossings closer than the snap length -> one point
//   cut_cgal.cpp     exact arrangement: build, prune, classify, hole points,
//                    sliver merging, artificial cuts, face extraction
//   blocks.cpp       faces (doubles) -> Blocks (clean, check, moments, layer)
//   shape.cpp        Feret diameters and the sliver aspect ratio
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dda/common/block_model.hpp"
#include "dda/common/line_model.hpp"
#include "dda/dc/cut.hpp"

namespace dda::dc::detail {

// Where an input segment came from. Every segment inserted in the arrangement
// carries the index of its Origin; an arrangement edge keeps the list of all
// origins that cover it (overlapping collinear segments share an edge).
struct Origin {
  enum class Kind : std::uint8_t { Boundary, Excavation, Line, Artificial };
  Kind kind = Kind::Line;
  int set = 0;         // joint set for lines, else the reserved set id
  int index = -1;      // line index, excavation index, or -1
  bool lex_forward = true;  // (a < b) lexicographically in (x, y): the direction
                            // in which the segment was given, for inside tests
};

// The segment from a + t0 (b - a) to a + t1 (b - a). The end points are
// constructed exactly in the arrangement, so a line extended past its ends
// (t0 < 0, t1 > 1) or clipped keeps exactly its supporting line: collinear
// input stays collinear.
struct InputSegment {
  Vec2 a{0, 0};
  Vec2 b{0, 0};
  double t0 = 0, t1 = 1;
  int origin = 0;
  // A piece of a segment rerouted through merged crossings
  // (near_crossings.cpp) starts or ends at such a point instead of at
  // a + t0 (b - a) or a + t1 (b - a).
  bool moved_start = false, moved_end = false;
  Vec2 start{0, 0}, end{0, 0};
};

struct PreparedInput {
  std::vector<InputSegment> segments;
  std::vector<Origin> origins;   // origins.back() is the artificial-cut origin
  int artificial_origin = -1;
  bool has_domain = false;
  double scale = 1;              // diagonal of the domain (or of the lines' box)
  double min_segment_length = 0;
  double snap = 0;               // each line is extended by this at both ends
  // counts for the report
  long long input_lines = 0;
  long long segments_too_short = 0;
  long long lines_outside_domain = 0;
  long long lines_clipped = 0;
};

PreparedInput prepare_segments(const LineModel& lines, const CutOptions& options);

// Crossings of the input segments that lie within the snap length of each
// other (joints that nearly meet at one point) are merged into one point,
// and every segment through them is rerouted through it (near_crossings.cpp).
struct NearCrossings {
  long long crossings = 0;  // crossings of the input segments found (doubles)
  long long merged = 0;     // groups of near crossings merged into one point
  long long rerouted = 0;   // segments rerouted through a merged point
};
NearCrossings merge_near_crossings(PreparedInput& in);
// True when the lines of the segments of every pair cross at one and the
// same point, in exact arithmetic (cut_cgal.cpp). The segments are taken
// as given by prepare_segments (not yet rerouted).
bool crossings_coincide(const PreparedInput& in, const std::vector<std::pair<int, int>>& pairs);

// The rule that gives an edge covered by several origins one set: the domain
// boundary wins, then excavation outlines, then the lowest joint set id, then
// artificial cuts.
int edge_set_of(const std::vector<int>& origin_ids, const std::vector<Origin>& origins);

// ---------------------------------------------------------------------------
// What the exact stage hands back.
struct RawFace {
  std::vector<int> vertex;      // indices into ArrangementResult::points, CCW
  std::vector<int> edge_set;    // edge i: vertex[i] -> vertex[i+1]
  std::vector<std::uint8_t> straight;  // vertex i lies inside one input segment
                                       // that carries both of its edges
  bool has_holes = false;       // still not simply connected (should not happen)
  bool repeated_vertex = false; // outer boundary visits a vertex twice
};

// Owns the arrangement after the exact stage; freeing it takes ~15% of a
// large cut, so the caller may do it on another thread while it builds the
// blocks (it touches nothing else).
struct ArrangementOwner {
  virtual ~ArrangementOwner() = default;
};

struct ArrangementResult {
  std::unique_ptr<ArrangementOwner> owner;
  std::vector<Vec2> points;       // every arrangement vertex, rounded once
  std::vector<RawFace> faces;     // the blocks, in a deterministic order
  std::vector<int> point_face;    // per located point: index in faces or -1
  std::vector<int> point_where;   // 0 block, 1 excavation, 2 outside, 3 removed by a hole point
  double domain_area = 0;         // area of the domain, from the faces
  double excavated_area = 0;      // faces inside excavations or removed by hole points
  long long arrangement_vertices = 0;
  long long arrangement_edges = 0;
  long long arrangement_faces = 0;
  long long dangling_edges_removed = 0;
  long long isolated_vertices_removed = 0;
  long long bounded_faces = 0;    // after pruning
  long long faces_in_excavations = 0;
  long long faces_outside_domain = 0;
  long long removed_by_hole_points = 0;
  long long artificial_cuts = 0;
  long long faces_with_holes = 0;
  long long slivers_merged = 0;
  long long sliver_merge_failed = 0;
  std::vector<std::string> warnings;
  double seconds_arrangement = 0;
  double seconds_topology = 0;  // prune + classify + hole points + slivers + cuts
  double seconds_prune = 0;
  double seconds_classify = 0;
  double seconds_cuts = 0;
  double seconds_curves = 0;    // making the exact input curves (part of arrangement)
  double seconds_extract = 0;
};

// Builds the arrangement of `in.segments` and returns its block faces.
// `hole_points` remove the block that contains them; `locate` are located in
// the final faces. hole_where gets, per hole point, 0 (removed a block),
// 1 (in an excavation), 2 (outside the domain) or 3 (block already removed).
ArrangementResult cut_arrangement(const PreparedInput& in, const std::vector<Vec2>& hole_points,
                                  const std::vector<Vec2>& locate, const SliverFilter& sliver,
                                  std::vector<int>& hole_where);

// ---------------------------------------------------------------------------
// Faces -> blocks (blocks.cpp).
struct DegenerateBlock {
  Vec2 near{0, 0};        // a vertex of the face
  std::size_t vertices = 0;
  double area = 0;        // signed area after rounding
  std::string reason;
};
struct BlockBuild {
  std::vector<Block> blocks;            // sorted by centroid (y, then x)
  std::vector<int> face_block;          // per raw face: block index or -1 (degenerate)
  std::vector<DegenerateBlock> degenerate;
  long long collinear_vertices_removed = 0;
  long long duplicate_vertices_removed = 0;
};
// Layer of a point: the bed whose [bottom, top) holds the coordinate along
// the bed normal n = (-sin d, cos d) (y when d = 0); -1 if none.
int layer_of(const Vec2& p, const std::vector<Layer>& layers, double dip_deg);
BlockBuild build_blocks(const ArrangementResult& ar, const std::vector<Layer>& layers, double dip_deg);

// ---------------------------------------------------------------------------
// Shape measures (shape.cpp).
struct ShapeMeasures {
  double max_feret = 0;   // largest distance between two vertices
  double min_feret = 0;   // smallest caliper width (over convex-hull edges)
  double aspect = 0;      // dda::FeretMeasures::aspect: length across / min_feret
};
ShapeMeasures shape_measures(const Polygon2& poly);
bool is_sliver(double area, double aspect, const SliverFilter& f);

// Simple-polygon test on doubles: no two non-adjacent edges meet, adjacent
// edges meet only at their shared vertex, no zero-length edge.
bool is_simple_polygon(const Polygon2& poly);

}  // namespace dda::dc::detail
