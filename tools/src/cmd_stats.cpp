// dda stats blocks.h5 [--json]
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/model_io3d.hpp"
#include "dda/common/output_guard.hpp"
#include "dda/dc/stats.hpp"
#include "dda/dc/stats3d.hpp"
#include "pipeline.hpp"
#include "pipeline3d.hpp"

namespace dda::cli {

namespace {

std::string distribution_row(const std::string& name, const std::string& unit, const nlohmann::json& d) {
  std::ostringstream s;
  s << "  " << std::left << std::setw(10) << name << std::setw(6) << unit << std::right;
  if (d.is_null()) return s.str() + "  (no blocks)\n";
  for (const char* k : {"min", "mean", "median", "max"}) s << std::setw(12) << std::setprecision(4) << d[k].get<double>();
  s << std::setw(12) << d["percentiles"]["p10"].get<double>() << std::setw(12) << d["percentiles"]["p90"].get<double>();
  return s.str() + "\n";
}

}  // namespace

std::string format_statistics(const nlohmann::json& st) {
  std::ostringstream s;
  s << "blocks: " << st["blocks"] << "   total area: " << st["total_area"].get<double>() << " m^2";
  if (st.contains("domain_area")) s << "   domain: " << st["domain_area"].get<double>() << " m^2";
  if (st.contains("excavated_area")) s << "   excavated: " << st["excavated_area"].get<double>() << " m^2";
  s << "\n  " << std::left << std::setw(16) << "measure" << std::right;
  for (const char* k : {"min", "mean", "median", "max", "p10", "p90"}) s << std::setw(12) << k;
  s << "\n";
  s << distribution_row("area", "m^2", st["area"]);
  s << distribution_row("width", "m", st["width"]);
  if (st.contains("min_feret")) s << distribution_row("min_feret", "m", st["min_feret"]);
  if (st.contains("per_layer") && st["per_layer"].is_array() && !st["per_layer"].empty()) {
    s << "  per layer (bottom..top: blocks, mean width):\n";
    for (const auto& l : st["per_layer"])
      s << "    " << l.value("layer", -1) << ": " << l.value("bottom", 0.0) << ".." << l.value("top", 0.0) << " m: "
        << l.value("blocks", 0) << " blocks, " << l.value("mean_width", 0.0) << " m\n";
  }
  return s.str();
}

void add_stats_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string input, output;
    bool json = false;
    int bins = 20;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("stats", "Block statistics: count, area (volume), width (size, aspect), per-layer distributions; 3D: block theory");
  cmd->add_option("blocks", opt->input, "Blocks file (2D or 3D) written by `dda dc`")->required();
  cmd->add_flag("--json", opt->json, "Print JSON (keys: blocks, total_area, area{...}, width{...}, ...)");
  cmd->add_option("--bins", opt->bins, "Histogram bins")->check(CLI::Range(1, 10000));
  cmd->add_option("-o,--output", opt->output, "Also write the JSON to this file");
  cmd->callback([opt, &global] {
    refuse_overwriting_inputs({opt->input}, {opt->output});
    const bool three_d = h5_format_of(opt->input) == "dda-blocks3d";
    const nlohmann::json st = three_d ? dc::block_statistics_3d(read_polyhedra_h5(opt->input), opt->bins)
                                      : dc::block_statistics(read_blocks_h5(opt->input), opt->bins);
    if (!opt->output.empty()) write_json(opt->output, st);
    if (opt->json)
      std::cout << st.dump(2) << "\n";
    else
      say(global.quiet, three_d ? format_statistics_3d(st) : format_statistics(st));
  });
}

}  // namespace dda::cli
