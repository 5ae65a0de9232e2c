// dda trace fractures.h5 --point X Y Z --dip D --dip-direction A -o section.h5
// The hybrid workflow's bridge: a 3D network cut by a plane becomes a 2D
// lines file that `dda dc` cuts like any other.
#include <sstream>

#include "commands.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/model_io3d.hpp"
#include "dda/common/output_guard.hpp"
#include "dda/common/vtk.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/polygon3d.hpp"
#include "dda/dl/trace_plane.hpp"
#include "pipeline.hpp"

namespace dda::cli {

void add_trace_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string input, output, vtk;
    std::vector<double> point;
    double dip = 0, dip_direction = 0;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "trace", "Cut a 3D fractures file by a plane into a 2D lines file (in the plane's u, v coordinates) for dda dc");
  cmd->add_option("fractures", opt->input, "Fractures file written by `dda dl` from a 3D scenario")->required();
  cmd->add_option("--point", opt->point, "A point of the plane: x y z (m)")->required()->expected(3);
  cmd->add_option("--dip", opt->dip, "Dip of the plane (degrees, 0 to 90)")->required()->check(CLI::Range(0.0, 90.0));
  cmd->add_option("--dip-direction", opt->dip_direction, "Dip direction of the plane (degrees, 0 to 360)")
      ->required()
      ->check(CLI::Range(0.0, 360.0));
  cmd->add_option("-o,--output", opt->output, "Lines file to write (HDF5)")->required();
  cmd->add_option("--vtk", opt->vtk, "Also write the section's lines for ParaView (.vtu)");
  cmd->callback([opt, &global] {
    refuse_overwriting_inputs({opt->input}, {opt->output, opt->vtk});
    const FractureModel model = read_fractures_h5(opt->input);
    const Vec3 point(opt->point[0], opt->point[1], opt->point[2]);
    // The point is in the user's coordinates, the fractures about their local origin.
    const dl::TraceFrame frame = dl::trace_frame(point - model.origin, opt->dip, opt->dip_direction);
    // Checked here so that the sentence names the file whose domain is missed.
    const dl::Polygon3 section = dl::plane_in_box(frame.n, frame.n.dot(frame.origin), model.domain);
    if (section.empty()) {
      std::ostringstream s;
      s << opt->input << ": the plane through (" << point.x() << ", " << point.y() << ", " << point.z()
        << ") misses the domain of the fractures.";
      throw InputError(s.str());
    }
    const LineModel lines = dl::trace_section(model, frame);
    write_lines_h5(opt->output, lines);
    if (!opt->vtk.empty()) write_lines_vtu(opt->vtk, lines);
    std::ostringstream s;
    s << lines.lines.size() << " lines (section of " << dl::polygon_area(section) << " m^2) written to " << opt->output
      << "\n";
    say(global.quiet, s.str());
  });
}

}  // namespace dda::cli
