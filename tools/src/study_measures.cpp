#include "study_measures.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/common/geometry3d.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/text_input.hpp"
#include "dda/df/io/results.hpp"
#include "dda/df/io/results3d.hpp"
#include "results_points.hpp"

namespace dda::cli {

namespace fs = std::filesystem;

namespace {

double stats_number(const nlohmann::json& stats, const std::string& key, const std::string& path) {
  const nlohmann::json* node = &stats;
  std::size_t start = 0;
  while (start <= key.size()) {
    const std::size_t dot = std::min(key.find('.', start), key.size());
    const std::string part = key.substr(start, dot - start);
    if (!node->is_object() || !node->contains(part)) break;
    node = &(*node)[part];
    start = dot + 1;
    if (dot == key.size()) {
      if (node->is_number()) return node->get<double>();
      break;
    }
  }
  throw InputError(path + ": has no number at '" + key + "' for the measure of kind stats.");
}

// Centroid of every block in a frame (the frame lists all blocks' vertices
// one after another, in the order of the model's blocks).
std::vector<Vec2> centroids(const df::Frame& frame, const BlockModel& blocks) {
  std::vector<Vec2> out;
  std::size_t at = 0;
  for (const Block& b : blocks.blocks) {
    const std::size_t n = b.vertices.size();
    if (at + n > frame.vertices.size()) break;
    const Polygon2 poly(frame.vertices.begin() + static_cast<std::ptrdiff_t>(at),
                        frame.vertices.begin() + static_cast<std::ptrdiff_t>(at + n));
    out.push_back(polygon_moments(poly).centroid);
    at += n;
  }
  return out;
}
// The same for polyhedra: the volume centroid with the frame's vertices.
std::vector<Vec3> centroids(const df3::Frame3& frame, const PolyhedronModel& blocks) {
  std::vector<Vec3> out;
  std::size_t at = 0;
  for (const Polyhedron& b : blocks.blocks) {
    const std::size_t n = b.vertices.size();
    if (at + n > frame.vertices.size()) break;
    const std::vector<Vec3> vertices(frame.vertices.begin() + static_cast<std::ptrdiff_t>(at),
                                     frame.vertices.begin() + static_cast<std::ptrdiff_t>(at + n));
    std::vector<std::vector<int>> faces;
    for (const PolyFace& f : b.faces) faces.push_back(f.vertices);
    out.push_back(polyhedron_moments(vertices, faces).centroid);
    at += n;
  }
  return out;
}

// The parts of results.h5 the measures read. A long run's file is mostly
// its per-step records; a point's history is a tenth of it (the 2D incline
// of bench/study_overhead.sh: 26 MB in all).
df::ResultsParts parts_for(const std::vector<study::MeasureSpec>& measures) {
  df::ResultsParts parts = df::ResultsParts::none();
  for (const study::MeasureSpec& m : measures) {
    if (m.kind == "point_displacement") parts.series = true;
    if (m.kind == "kinetic_energy") parts.energy = true;
    if (m.kind == "blocks_displaced" || m.kind == "blocks_below") parts.frames = true;
  }
  return parts;
}

// What the scenario measures need of a results file, in 2D (x, y; y up)
// and 3D (x, y, z; z up) alike.
struct RunMeasures {
  std::vector<std::string> point_names;
  std::vector<std::vector<double>> point_displacement;  // per point, |displacement| per sample
  std::optional<double> final_kinetic_energy;           // J (2D: per metre of thickness)
  std::vector<double> displacement;                     // per block, of its centroid from the first frame to the last
  std::vector<double> start_height, end_height;         // per block, of its centroid
  bool has_frames = false;
};

template <class Results>
void take_points(const Results& r, RunMeasures& out) {
  out.point_names = r.point_names;
  for (const auto& history : r.histories) {
    std::vector<double>& norms = out.point_displacement.emplace_back();
    for (const auto& sample : history) norms.push_back(sample.displacement.norm());
  }
}

template <class Frames, class Blocks>
void take_frames(const Frames& frames, const Blocks& blocks, RunMeasures& out) {
  out.has_frames = !frames.empty();
  if (!out.has_frames) return;
  const auto start = centroids(frames.front(), blocks), end = centroids(frames.back(), blocks);
  constexpr int up = std::decay_t<decltype(start.front())>::RowsAtCompileTime - 1;
  for (std::size_t i = 0; i < std::min(start.size(), end.size()); ++i) {
    out.displacement.push_back((end[i] - start[i]).norm());
    out.start_height.push_back(start[i][up]);
    out.end_height.push_back(end[i][up]);
  }
}

// The measures' values of a 2D or 3D results file, read as far as `parts`.
template <class Results>
void take_run(const Results& r, RunMeasures& out) {
  take_points(r, out);
  if (!r.energy.empty()) out.final_kinetic_energy = r.energy.back().kinetic;
  take_frames(r.frames, r.blocks, out);
}

RunMeasures read_run_measures(const std::string& path, const df::ResultsParts& parts) {
  RunMeasures out;
  if (h5_format_of(path) == df3::kResults3dFormat)
    take_run(df3::read_results3_h5(path, parts), out);
  else
    take_run(df::read_results_h5(path, parts), out);
  return out;
}

// Whether the measures read results.h5 at all (stats alone read stats.json).
bool reads_results(const df::ResultsParts& p) {
  return p.series || p.log || p.energy || p.bolts || p.frames || p.checkpoint;
}

}  // namespace

std::vector<double> pipeline_measures(const fs::path& case_dir, const std::vector<study::MeasureSpec>& measures) {
  std::optional<nlohmann::json> stats;
  const std::string results_path = (case_dir / "results.h5").string();
  std::optional<RunMeasures> run;
  const df::ResultsParts parts = parts_for(measures);
  if (reads_results(parts)) {
    if (!fs::exists(results_path))
      throw InputError(results_path + " is missing: the measures of the results need a forward run (a control section in "
                                      "the scenario).");
    run = read_run_measures(results_path, parts);
  }
  std::vector<double> out;
  for (const study::MeasureSpec& m : measures) {
    if (m.kind == "stats") {
      const std::string path = (case_dir / "stats.json").string();
      if (!stats) stats = nlohmann::json::parse(read_text_file(path, "statistics"));
      out.push_back(stats_number(*stats, m.key, path));
    } else if (m.kind == "point_displacement") {
      const std::vector<double>& norms = run->point_displacement[measurement_point_index(run->point_names, m.point, results_path)];
      double value = 0;
      for (const double d : norms) value = m.of == "peak" ? std::max(value, d) : d;
      out.push_back(value);
    } else if (m.kind == "kinetic_energy") {
      if (!run->final_kinetic_energy)
        throw InputError(results_path + ": holds no kinetic energy for the measure '" + m.name +
                         "' (a 3D results file written before the 3D energy ledger; run the case again).");
      out.push_back(*run->final_kinetic_energy);
    } else if (m.kind == "blocks_displaced" || m.kind == "blocks_below") {
      if (!run->has_frames) throw InputError(results_path + ": holds no block frames for the measure '" + m.name + "'.");
      double count = 0;
      for (std::size_t i = 0; i < run->displacement.size(); ++i) {
        if (m.kind == "blocks_displaced")
          count += run->displacement[i] > m.value;
        else
          count += run->start_height[i] >= m.value && run->end_height[i] < m.value;
      }
      out.push_back(count);
    } else {
      throw InputError("the measure kind '" + m.kind + "' is not one of a scenario study.");
    }
  }
  return out;
}

}  // namespace dda::cli
