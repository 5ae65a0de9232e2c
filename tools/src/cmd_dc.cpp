// dda dc lines.h5 -o blocks.h5
#include "commands.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/vtk.hpp"
#include "dda/dc/cut.hpp"
#include "pipeline.hpp"

namespace dda::cli {

void add_dc_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string input, output, vtk, report;
    SliverOverrides slivers;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("dc", "Cut the lines of a lines file into blocks");
  cmd->add_option("lines", opt->input, "Lines file written by `dda dl`")->required();
  cmd->add_option("-o,--output", opt->output, "Blocks file to write (HDF5)")->required();
  cmd->add_option("--vtk", opt->vtk, "Also write the blocks for ParaView (.vtu)");
  cmd->add_option("--report", opt->report, "Write the cutting report as JSON");
  add_sliver_options(cmd, opt->slivers);
  cmd->callback([opt, &global] {
    const LineModel lines = read_lines_h5(opt->input);
    dc::CutOptions options = cut_options_of(lines);
    apply(opt->slivers, options);
    const dc::CutResult cut = dc::cut_blocks(lines, options);
    write_blocks_h5(opt->output, cut.model);
    if (!opt->vtk.empty()) write_blocks_vtu(opt->vtk, cut.model);
    if (!opt->report.empty()) write_json(opt->report, cut.report);
    say(global.quiet, describe_cut(cut.model, opt->output));
  });
}

}  // namespace dda::cli
