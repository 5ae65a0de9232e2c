// dda dl SCENARIO.yaml -o lines.h5   (or a DDA-for-Windows MODEL.geo)
// dda dl SCENARIO3D.yaml -o fractures.h5   (a scenario with dimension: 3)
#include "commands.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/model_io3d.hpp"
#include "dda/common/output_guard.hpp"
#include "dda/common/vtk.hpp"
#include "dda/common/vtk3d.hpp"
#include "dda/dl/generate.hpp"
#include "dda/dl/scenario3d.hpp"
#include "dda/dl/trace_plane.hpp"
#include "pipeline.hpp"

namespace dda::cli {

namespace {

struct Options {
  std::string input, output, vtk, report;
};

// The 3D job: the fractures file, and each scenario trace plane's section as
// a 2D lines file next to it (<stem>.<name>.lines.h5), ready for `dda dc`.
void run_dl_3d(const Options& opt, const GlobalOptions& global) {
  const dl::DlResult3 dl = run_dl3(opt.input);
  // Sections first: a plane that cannot be cut must not leave a fractures
  // file behind that looks like a finished run.
  std::vector<LineModel> sections;
  std::vector<std::string> section_files;  // their names come from the scenario: guarded once it is read
  for (const dl::TracePlaneSpec& t : dl.trace_planes) {
    sections.push_back(dl::trace_section(dl.model, dl::trace_frame(t.point, t.dip_deg, t.dip_direction_deg)));
    section_files.push_back(section_path(opt.output, t.name, ".lines.h5"));
    if (!opt.vtk.empty()) section_files.push_back(section_path(opt.vtk, t.name, ".lines.vtu"));
  }
  refuse_overwriting_inputs({opt.input}, section_files);
  write_fractures_h5(opt.output, dl.model);
  if (!opt.vtk.empty()) write_fractures_vtu(opt.vtk, dl.model);
  if (!opt.report.empty()) write_json(opt.report, dl.report);
  say(global.quiet, dl::format_report3(dl.report));
  say(global.quiet, std::to_string(dl.model.fractures.size()) + " fractures written to " + opt.output + "\n");
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const std::string& name = dl.trace_planes[i].name;
    const std::string path = section_path(opt.output, name, ".lines.h5");
    write_lines_h5(path, sections[i]);
    if (!opt.vtk.empty()) write_lines_vtu(section_path(opt.vtk, name, ".lines.vtu"), sections[i]);
    say(global.quiet,
        "trace plane " + name + ": " + std::to_string(sections[i].lines.size()) + " lines written to " + path + "\n");
  }
}

}  // namespace

void add_dl_command(CLI::App& app, const GlobalOptions& global) {
  auto opt = std::make_shared<Options>();
  CLI::App* cmd =
      app.add_subcommand("dl",
                         "Generate the joint traces (lines) of a scenario, or import a DDA-for-Windows .geo file; "
                         "for a scenario with dimension: 3, the 3D fractures");
  cmd->add_option("input", opt->input, "Scenario (.yaml) or DDA-for-Windows geometry (.geo)")->required();
  cmd->add_option("-o,--output", opt->output, "Lines file to write (HDF5); fractures file in 3D")->required();
  cmd->add_option("--vtk", opt->vtk, "Also write the lines (3D: the fractures) for ParaView (.vtu)");
  cmd->add_option("--report", opt->report, "Write the generated-versus-asked report as JSON");
  cmd->callback([opt, &global] {
    refuse_overwriting_inputs({opt->input}, {opt->output, opt->vtk, opt->report});
    if (dl_input_dimension(opt->input) == 3) {
      run_dl_3d(*opt, global);
      return;
    }
    DlOutcome dl = run_dl(opt->input);
    write_lines_h5(opt->output, dl.lines);
    if (!opt->vtk.empty()) write_lines_vtu(opt->vtk, dl.lines);
    if (!opt->report.empty()) write_json(opt->report, dl.report);
    if (dl.report.contains("sets") || dl.report.contains("layers")) say(global.quiet, dl::format_report(dl.report));
    say(global.quiet, std::to_string(dl.lines.lines.size()) + " lines written to " + opt->output + "\n");
  });
}

}  // namespace dda::cli
