#include "pipeline.hpp"

#include <cctype>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "dda/common/atomic_file.hpp"
#include "dda/common/coordinate_range.hpp"
#include "dda/common/error.hpp"
#include "dda/common/scenario.hpp"
#include "dda/dl/generate.hpp"
#include "dda/dl/scenario3d.hpp"

namespace dda::cli {

namespace {
bool has_extension(const std::string& path, const std::string& ext) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e == ext;
}
}  // namespace

DlOutcome run_dl(const std::string& input_path) {
  if (!std::filesystem::exists(input_path)) throw InputError(input_path + ": no such file.");
  if (has_extension(input_path, ".geo")) {
    DlOutcome out{dl::import_geo(input_path), nlohmann::json::object()};
    check_coordinate_range(out.lines, input_path);
    move_to_local_origin(out.lines);  // a .geo far from the origin is cut and run about a local one
    out.report["imported_from"] = input_path;
    out.report["lines"] = out.lines.lines.size();
    out.report["points"] = out.lines.points.size();
    return out;
  }
  const YamlNode root = load_scenario(input_path);
  dl::DlResult result = dl::generate_from_scenario(root);
  return {std::move(result.model), std::move(result.report)};
}

int dl_input_dimension(const std::string& input_path) {
  if (has_extension(input_path, ".geo") || !std::filesystem::exists(input_path)) return 2;
  return dl::scenario_dimension(load_scenario(input_path));
}

dl::DlResult3 run_dl3(const std::string& input_path) {
  if (!std::filesystem::exists(input_path)) throw InputError(input_path + ": no such file.");
  return dl::generate_3d_from_scenario(load_scenario(input_path));
}

std::string section_path(const std::string& base, const std::string& name, const std::string& suffix) {
  const std::filesystem::path p(base);
  return (p.parent_path() / (p.stem().string() + "." + name + suffix)).string();
}

dc::CutOptions cut_options_of(const LineModel& lines) {
  const std::string& text = lines.provenance.scenario_text;
  if (text.empty()) return dc::parse_cut_options(std::nullopt);
  const std::string label = lines.provenance.scenario_path.empty() ? "scenario" : lines.provenance.scenario_path;
  const YamlNode root = YamlNode::load_string(text, label);
  // A section of a 3D network keeps the 3D scenario, whose `cutting:` holds
  // the 3D cutter's keys: the 2D cut of the section takes the defaults.
  if (dl::scenario_dimension(root) == 3) return dc::parse_cut_options(std::nullopt);
  return dc::parse_cut_options(root.optional_child("cutting"));
}

void apply(const SliverOverrides& o, dc::CutOptions& options) {
  if (o.min_area) options.sliver.min_area = *o.min_area;
  if (o.max_aspect) options.sliver.max_aspect = *o.max_aspect;
  if (o.action) options.sliver.merge = (*o.action == "merge");
}

void add_sliver_options(CLI::App* cmd, SliverOverrides& o) {
  cmd->add_option("--min-area", o.min_area, "Sliver filter: blocks below this area (m^2) are slivers")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-aspect", o.max_aspect, "Sliver filter: blocks above this aspect ratio are slivers")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--slivers", o.action, "What to do with slivers: merge them into a neighbour, or report them")
      ->check(CLI::IsMember({"merge", "report"}));
}

namespace {

double total_area(const BlockModel& blocks) {
  double area = 0;
  for (const Block& b : blocks.blocks) area += b.area;
  return area;
}

}  // namespace

std::string describe_cut(const BlockModel& blocks, const std::string& path) {
  std::ostringstream s;
  s << blocks.blocks.size() << " blocks (total area " << total_area(blocks) << " m^2) written to " << path << "\n";
  return s.str();
}

void warn_of_lost_area(const BlockModel& blocks) {
  const double area = total_area(blocks);
  const double rock = blocks.domain_area - blocks.excavated_area, lost = rock - area;
  if (!(lost > 1e-9 * blocks.domain_area)) return;
  std::ostringstream s;
  s << "dda: warning: the blocks cover " << area << " of the " << rock << " m^2 cut; " << lost << " m^2 ("
    << 100 * lost / rock << " %) were dropped as degenerate faces (joints nearly meeting at one point); "
    << "the cut report (--report) lists them under `degenerate`\n";
  std::cerr << s.str();
}

void make_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the output folder (" + ec.message() + ").");
}

void say(bool quiet, const std::string& text) {
  if (!quiet) std::cout << text << std::flush;
}

void write_json(const std::string& path, const nlohmann::json& doc) {
  write_text_atomically(path, doc.dump(2) + "\n");
}

}  // namespace dda::cli
