#include "study_measures.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/common/text_input.hpp"
#include "dda/df/results.hpp"
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

// The results file, read once and only as far as the measures need.
class ResultsOnDemand {
 public:
  explicit ResultsOnDemand(fs::path path) : path_(std::move(path)) {}
  const df::Results& get(const study::MeasureSpec& m, bool frames) {
    if (!results_ || (frames && !with_frames_)) {
      if (!fs::exists(path_))
        throw InputError(path_.string() + " is missing: the measure '" + m.name +
                         "' needs a forward run (a control section in the scenario).");
      results_ = df::read_results_h5(path_.string(), frames);
      with_frames_ = frames;
    }
    return *results_;
  }
  const std::string path() const { return path_.string(); }

 private:
  fs::path path_;
  std::optional<df::Results> results_;
  bool with_frames_ = false;
};

}  // namespace

std::vector<double> pipeline_measures(const fs::path& case_dir, const std::vector<study::MeasureSpec>& measures) {
  std::optional<nlohmann::json> stats;
  ResultsOnDemand results(case_dir / "results.h5");
  std::vector<double> out;
  for (const study::MeasureSpec& m : measures) {
    if (m.kind == "stats") {
      const std::string path = (case_dir / "stats.json").string();
      if (!stats) stats = nlohmann::json::parse(read_text_file(path, "statistics"));
      out.push_back(stats_number(*stats, m.key, path));
    } else if (m.kind == "point_displacement") {
      const df::Results& r = results.get(m, false);
      const auto& history = r.histories[measurement_point_index(r, m.point, results.path())];
      double value = 0;
      for (const auto& sample : history) {
        const double d = sample.displacement.norm();
        value = m.of == "peak" ? std::max(value, d) : d;
      }
      out.push_back(value);
    } else if (m.kind == "kinetic_energy") {
      const df::Results& r = results.get(m, false);
      out.push_back(r.energy.empty() ? 0.0 : r.energy.back().kinetic);
    } else if (m.kind == "blocks_displaced" || m.kind == "blocks_below") {
      const df::Results& r = results.get(m, true);
      if (r.frames.empty()) throw InputError(results.path() + ": holds no block frames for the measure '" + m.name + "'.");
      const std::vector<Vec2> start = centroids(r.frames.front(), r.blocks);
      const std::vector<Vec2> end = centroids(r.frames.back(), r.blocks);
      double count = 0;
      for (std::size_t i = 0; i < std::min(start.size(), end.size()); ++i) {
        if (m.kind == "blocks_displaced")
          count += (end[i] - start[i]).norm() > m.value;
        else
          count += start[i].y() >= m.value && end[i].y() < m.value;
      }
      out.push_back(count);
    } else {
      throw InputError("the measure kind '" + m.kind + "' is not one of a scenario study.");
    }
  }
  return out;
}

}  // namespace dda::cli
