// dda info FILE.h5: what a file is and what made it.
#include <charconv>
#include <iostream>

#include "commands.hpp"
#include "df_session.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/model_io3d.hpp"
#include "dda/df/io/results.hpp"
#include "dda/df/io/results3d.hpp"

namespace dda::cli {

namespace {
void print_provenance(const Provenance& p) {
  std::cout << "program version: " << p.program_version << "\n"
            << "created (UTC):   " << p.created_utc << "\n"
            << "scenario:        " << (p.scenario_path.empty() ? "(none)" : p.scenario_path) << "\n"
            << "seed:            " << p.seed << "\n";
}
// Positions in the file are about this origin (coordinate_range.hpp); said
// only when it is not zero, to the last digit (every coordinate the user
// reads back is position + origin).
template <class Point>
void print_origin(const Point& o) {
  if (o == Point::Zero()) return;
  std::cout << "local origin:    (";
  for (int k = 0; k < o.size(); ++k) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, o[k]);
    std::cout << (k ? ", " : "") << std::string(buf, r.ptr);
  }
  std::cout << ") m; positions in the file are about it\n";
}
}  // namespace

void add_info_command(CLI::App& app, const GlobalOptions&) {
  auto input = std::make_shared<std::string>();
  auto show_scenario = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("info", "Describe a lines, blocks, fractures, 3D blocks or results file: what it holds and what made it");
  cmd->add_option("file", *input, "File written by dda")->required();
  cmd->add_flag("--scenario", *show_scenario, "Print the scenario text stored in the file");
  cmd->callback([input, show_scenario] {
    const std::string format = h5_format_of(*input);
    if (format == "dda-lines") {
      const LineModel m = read_lines_h5(*input);
      std::cout << *input << ": dda-lines, " << m.lines.size() << " lines in " << m.sets.size() << " sets, "
                << m.excavations.size() << " excavations, " << m.points.size() << " points, " << m.layers.size()
                << " layers\n";
      print_provenance(m.provenance);
      print_origin(m.origin);
      if (*show_scenario) std::cout << "\n" << m.provenance.scenario_text;
    } else if (format == "dda-blocks") {
      const BlockModel m = read_blocks_h5(*input);
      std::cout << *input << ": dda-blocks, " << m.blocks.size() << " blocks, " << m.points.size() << " points\n";
      print_provenance(m.provenance);
      print_origin(m.origin);
      if (*show_scenario) std::cout << "\n" << m.provenance.scenario_text;
    } else if (format == "dda-fractures") {
      const FractureModel m = read_fractures_h5(*input);
      std::cout << *input << ": dda-fractures, " << m.fractures.size() << " fractures in " << m.sets.size()
                << " sets, " << m.excavations.size() << " excavations, " << m.points.size() << " points, "
                << m.layers.size() << " layers\n";
      print_provenance(m.provenance);
      print_origin(m.origin);
      if (*show_scenario) std::cout << "\n" << m.provenance.scenario_text;
    } else if (format == "dda-blocks3d") {
      const PolyhedronModel m = read_polyhedra_h5(*input);
      std::cout << *input << ": dda-blocks3d, " << m.bodies.size() << " bodies (" << m.blocks.size()
                << " convex parts), " << m.points.size() << " points\n";
      print_provenance(m.provenance);
      print_origin(m.origin);
      if (*show_scenario) std::cout << "\n" << m.provenance.scenario_text;
    } else if (format == "dda-results") {
      const df::Results r = df::read_results_h5(*input, df::ResultsParts::records());
      const double t_end = r.log.empty() ? 0.0 : r.log.back().time;
      std::cout << *input << ": dda-results (" << r.source.input_kind << "), " << r.block_count
                << " blocks, " << r.log.size() << " steps to t = " << t_end << " s, "
                << r.point_names.size() << " measurement points, " << r.bolt_names.size() << " bolts, "
                << (r.complete ? "complete" : "incomplete (resume with `dda df --resume`)") << "\n";
      std::cout << "energy:          " << energy_balance_line(r.energy, "J per m of thickness") << "\n";
      if (const std::string w = energy_created_warning(r.energy); !w.empty()) std::cout << "warning:         " << w << "\n";
      print_provenance(r.source.provenance);
      print_origin(r.blocks.origin);
      if (*show_scenario) std::cout << "\n" << r.source.provenance.scenario_text;
    } else if (format == df3::kResults3dFormat) {
      const df3::Results3 r = df3::read_results3_h5(*input, df::ResultsParts::records());
      const double t_end = r.log.empty() ? 0.0 : r.log.back().time;
      std::size_t held = 0;
      for (const bool f : r.fixed) held += f ? 1 : 0;
      std::cout << *input << ": dda-results3d (" << r.source.input_kind << "), " << r.fixed.size() << " blocks ("
                << held << " fixed), " << r.log.size() << " steps to t = " << t_end << " s, " << r.point_names.size()
                << " measurement points, " << r.bolt_names.size() << " bolts, "
                << (r.complete ? "complete" : "incomplete (resume with `dda df --resume`)") << "\n";
      std::cout << "blocks from:     " << (r.source.blocks_path.empty() ? "(unknown)" : r.source.blocks_path) << "\n";
      if (r.energy.empty()) {
        std::cout << "energy:          not recorded (the file was written before the 3D energy ledger)\n";
      } else {
        std::cout << "energy:          " << energy_balance_line(r.energy, "J") << "\n";
        if (const std::string w = energy_created_warning(r.energy); !w.empty()) std::cout << "warning:         " << w << "\n";
      }
      print_provenance(r.source.provenance);
      print_origin(r.blocks.origin);
      if (*show_scenario) std::cout << "\n" << r.source.provenance.scenario_text;
    } else {
      throw InputError(*input + ": is not a file written by dda (no `format` attribute).");
    }
  });
}

}  // namespace dda::cli
