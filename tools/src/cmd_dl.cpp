// dda dl SCENARIO.yaml -o lines.h5   (or a DDA-for-Windows MODEL.geo)
#include "commands.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/vtk.hpp"
#include "dda/dl/generate.hpp"
#include "pipeline.hpp"

namespace dda::cli {

void add_dl_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string input, output, vtk, report;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "dl", "Generate the joint traces (lines) of a scenario, or import a DDA-for-Windows .geo file");
  cmd->add_option("input", opt->input, "Scenario (.yaml) or DDA-for-Windows geometry (.geo)")->required();
  cmd->add_option("-o,--output", opt->output, "Lines file to write (HDF5)")->required();
  cmd->add_option("--vtk", opt->vtk, "Also write the lines for ParaView (.vtu)");
  cmd->add_option("--report", opt->report, "Write the generated-versus-asked report as JSON");
  cmd->callback([opt, &global] {
    DlOutcome dl = run_dl(opt->input);
    write_lines_h5(opt->output, dl.lines);
    if (!opt->vtk.empty()) write_lines_vtu(opt->vtk, dl.lines);
    if (!opt->report.empty()) write_json(opt->report, dl.report);
    if (dl.report.contains("sets") || dl.report.contains("layers"))
      say(global.quiet, dl::format_report(dl.report));
    say(global.quiet, std::to_string(dl.lines.lines.size()) + " lines written to " + opt->output + "\n");
  });
}

}  // namespace dda::cli
