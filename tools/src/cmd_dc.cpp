// dda dc lines.h5 -o blocks.h5       (2D)
// dda dc fractures.h5 -o blocks3d.h5  (3D)
#include "commands.hpp"
#include "dda/common/coordinate_range.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/model_io3d.hpp"
#include "dda/common/output_guard.hpp"
#include "dda/common/vtk.hpp"
#include "dda/common/vtk3d.hpp"
#include "dda/dc/cut.hpp"
#include "dda/dc/cut3d.hpp"
#include "pipeline.hpp"
#include "pipeline3d.hpp"

namespace dda::cli {

void add_dc_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string input, output, vtk, report, finite;
    SliverOverrides slivers;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "dc", "Cut the lines of a lines file into blocks (2D), or the fractures of a fractures file into polyhedra (3D)");
  cmd->add_option("lines", opt->input, "Lines or fractures file written by `dda dl`")->required();
  cmd->add_option("-o,--output", opt->output, "Blocks file to write (HDF5)")->required();
  cmd->add_option("--vtk", opt->vtk, "Also write the blocks for ParaView (.vtu)");
  cmd->add_option("--report", opt->report, "Write the cutting report as JSON");
  add_sliver_options(cmd, opt->slivers);
  cmd->add_option("--finite-fractures", opt->finite,
                  "3D: glue (a fracture that ends inside a body splits it into glued parts) or through "
                  "(it leaves the block whole)")
      ->check(CLI::IsMember({"glue", "through"}));
  cmd->callback([opt, &global] {
    refuse_overwriting_inputs({opt->input}, {opt->output, opt->vtk, opt->report});
    if (h5_format_of(opt->input) == "dda-fractures") {
      if (opt->slivers.min_area || opt->slivers.max_aspect || opt->slivers.action)
        throw InputError("--min-area, --max-aspect and --slivers apply to 2D cuts; " + opt->input +
                         " is a 3D fractures file.");
      FractureModel fractures = read_fractures_h5(opt->input);
      check_coordinate_range(fractures, opt->input);
      // A file written far from the origin without one (by hand, or another tool).
      if (fractures.origin == Vec3::Zero()) move_to_local_origin(fractures);
      dc::Cut3dOptions options = cut3d_options_of(fractures);
      if (!opt->finite.empty())
        options.finite_fractures = opt->finite == "glue" ? dc::FiniteFractures::Glue : dc::FiniteFractures::Through;
      const dc::Cut3dResult cut = naming_input(opt->input, [&] { return dc::cut_blocks_3d(fractures, options); });
      write_polyhedra_h5(opt->output, cut.model);
      if (!opt->vtk.empty()) write_polyhedra_vtu(opt->vtk, cut.model);
      if (!opt->report.empty()) write_json(opt->report, cut.report);
      say(global.quiet, describe_cut3d(cut.model, opt->output));
      return;
    }
    if (!opt->finite.empty())
      throw InputError("--finite-fractures applies to 3D cuts; " + opt->input + " is not a fractures file.");
    LineModel lines = read_lines_h5(opt->input);
    check_coordinate_range(lines, opt->input);
    if (lines.origin == Vec2::Zero()) move_to_local_origin(lines);
    dc::CutOptions options = cut_options_of(lines);
    apply(opt->slivers, options);
    const dc::CutResult cut = naming_input(opt->input, [&] { return dc::cut_blocks(lines, options); });
    write_blocks_h5(opt->output, cut.model);
    if (!opt->vtk.empty()) write_blocks_vtu(opt->vtk, cut.model);
    if (!opt->report.empty()) write_json(opt->report, cut.report);
    say(global.quiet, describe_cut(cut.model, opt->output));
    warn_of_lost_area(cut.model);
  });
}

}  // namespace dda::cli
