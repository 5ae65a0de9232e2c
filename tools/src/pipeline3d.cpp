#include "pipeline3d.hpp"

#include <iomanip>
#include <sstream>

#include "dda/common/yaml_reader.hpp"

namespace dda::cli {

dc::Cut3dOptions cut3d_options_of(const FractureModel& fractures) {
  const std::string& text = fractures.provenance.scenario_text;
  if (text.empty()) return dc::parse_cut3d_options(std::nullopt);
  const std::string label =
      fractures.provenance.scenario_path.empty() ? "scenario" : fractures.provenance.scenario_path;
  const YamlNode root = YamlNode::load_string(text, label);
  return dc::parse_cut3d_options(root.optional_child("cutting"));
}

std::string describe_cut3d(const PolyhedronModel& blocks, const std::string& path) {
  double volume = 0;
  for (const auto& b : blocks.blocks) volume += b.volume;
  std::ostringstream s;
  s << blocks.bodies.size() << " bodies (" << blocks.blocks.size() << " convex parts, total volume " << volume
    << " m^3) written to " << path << "\n";
  if (blocks.unfinished_cuts > 0)
    s << "  " << blocks.unfinished_cuts << " finite fractures end inside a body (see the report)\n";
  return s.str();
}

namespace {

std::string row(const std::string& name, const std::string& unit, const nlohmann::json& d) {
  std::ostringstream s;
  s << "  " << std::left << std::setw(20) << name << std::setw(6) << unit << std::right;
  if (d.is_null()) return s.str() + "  (no bodies)\n";
  for (const char* k : {"min", "mean", "median", "max"}) s << std::setw(12) << std::setprecision(4) << d[k].get<double>();
  s << std::setw(12) << d["percentiles"]["p10"].get<double>() << std::setw(12) << d["percentiles"]["p90"].get<double>();
  return s.str() + "\n";
}

}  // namespace

std::string format_statistics_3d(const nlohmann::json& st) {
  std::ostringstream s;
  s << "bodies: " << st["bodies"] << " (" << st["blocks"] << " convex parts)   total volume: "
    << st["total_volume"].get<double>() << " m^3   domain: " << st["domain_volume"].get<double>()
    << " m^3   excavated: " << st["excavated_volume"].get<double>() << " m^3\n";
  s << "  " << std::left << std::setw(26) << "measure" << std::right;
  for (const char* k : {"min", "mean", "median", "max", "p10", "p90"}) s << std::setw(12) << k;
  s << "\n";
  s << row("volume", "m^3", st["volume"]);
  s << row("equivalent_diameter", "m", st["equivalent_diameter"]);
  s << row("aspect", "1", st["aspect"]);
  s << row("faces per part", "", st["faces"]);
  s << "  block theory:";
  for (const auto& [mode, count] : st["removability"].items()) s << " " << mode << " " << count;
  s << "\n  volume gravity moves (falls or slides): " << st["removable_volume"].get<double>() << " m^3\n";
  if (st["unfinished_cuts"].get<int>() > 0)
    s << "  finite fractures ending inside a body: " << st["unfinished_cuts"] << "\n";
  return s.str();
}

}  // namespace dda::cli
