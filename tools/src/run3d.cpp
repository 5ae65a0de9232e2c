// `dda run` on a scenario with dimension: 3. OUTDIR receives
// fractures.h5, blocks3d.h5, dl_report.json, dc_report.json, stats.json,
// sections/<name>.lines.h5 and <name>.blocks.h5 for every trace plane (the
// 2D section cut by the 2D cutter: the hybrid 3D network -> 2D DDA workflow),
// vtk/{fractures.vtu, blocks3d.vtu, model.pvd} and
// figures/{fractures, blocks3d, blocks3d_exploded}.png; a scenario with a
// `control` section is then run forward in 3D into results.h5 and
// vtk/{df.pvd, df_blocks_*.vtu, df_contacts_*.vtu} (cmd_df3d.cpp).
#include <filesystem>

#include "commands.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/model_io3d.hpp"
#include "dda/common/vtk.hpp"
#include "dda/common/vtk3d.hpp"
#include "dda/dc/cut.hpp"
#include "dda/dc/cut3d.hpp"
#include "dda/dc/stats3d.hpp"
#include "dda/dl/scenario3d.hpp"
#include "dda/dl/trace_plane.hpp"
#include "dda/df/io/scenario.hpp"
#include "pipeline.hpp"
#include "pipeline3d.hpp"
#include "plot_runner.hpp"

namespace dda::cli {

namespace fs = std::filesystem;

void run_pipeline_3d(const YamlNode& root, const fs::path& dir, const OutputOptions& out, bool quiet) {
  const dc::Cut3dOptions cut_options = dc::parse_cut3d_options(root.optional_child("cutting"));
  const dl::DlResult3 dl = dl::generate_3d_from_scenario(root);

  const std::string fractures_h5 = (dir / "fractures.h5").string();
  write_fractures_h5(fractures_h5, dl.model);
  write_json((dir / "dl_report.json").string(), dl.report);
  say(quiet, dl::format_report3(dl.report));
  say(quiet, "DL: " + std::to_string(dl.model.fractures.size()) + " fractures written to " + fractures_h5 + "\n");

  for (const dl::TracePlaneSpec& t : dl.trace_planes) {
    const fs::path sections = dir / "sections";
    fs::create_directories(sections);
    const LineModel lines = dl::trace_section(dl.model, dl::trace_frame(t.point, t.dip_deg, t.dip_direction_deg));
    const std::string lines_h5 = (sections / (t.name + ".lines.h5")).string();
    write_lines_h5(lines_h5, lines);
    const dc::CutResult cut2d =
        naming_input(root.file(), [&] { return dc::cut_blocks(lines, dc::parse_cut_options(std::nullopt)); });
    const std::string blocks_h5 = (sections / (t.name + ".blocks.h5")).string();
    write_blocks_h5(blocks_h5, cut2d.model);
    say(quiet, "trace plane " + t.name + ": " + std::to_string(lines.lines.size()) + " lines, " +
                   std::to_string(cut2d.model.blocks.size()) + " 2D blocks written to " + blocks_h5 + "\n");
  }

  const dc::Cut3dResult cut = naming_input(root.file(), [&] { return dc::cut_blocks_3d(dl.model, cut_options); });
  const std::string blocks_h5 = (dir / "blocks3d.h5").string();
  write_polyhedra_h5(blocks_h5, cut.model);
  write_json((dir / "dc_report.json").string(), cut.report);
  say(quiet, "DC: " + describe_cut3d(cut.model, blocks_h5));
  const nlohmann::json stats = dc::block_statistics_3d(cut.model, out.histogram_bins);
  write_json((dir / "stats.json").string(), stats);
  say(quiet, format_statistics_3d(stats));

  if (out.vtk) {
    fs::create_directories(dir / "vtk");
    write_fractures_vtu((dir / "vtk" / "fractures.vtu").string(), dl.model);
    write_polyhedra_vtu((dir / "vtk" / "blocks3d.vtu").string(), cut.model);
    write_pvd((dir / "vtk" / "model.pvd").string(),
              {{"fractures.vtu", 0.0, 0, "fractures"}, {"blocks3d.vtu", 0.0, 1, "blocks"}});
  }
  if (out.plots) {
    if (!plotting_available()) {
      say(quiet, "figures skipped: /usr/bin/python3 with matplotlib and h5py is not installed\n");
    } else {
      const fs::path figs = dir / "figures";
      fs::create_directories(figs);
      run_plot_script({fractures_h5, "-o", (figs / "fractures.png").string()});
      run_plot_script({blocks_h5, "-o", (figs / "blocks3d.png").string()});
      run_plot_script(
          {blocks_h5, "-o", (figs / "blocks3d_exploded.png").string(), "--explode", "0.4", "--color", "body"});
      say(quiet, "figures written to " + figs.string() + "\n");
    }
  }
  if (df::scenario_has_df(root)) {
    DfStage stage;
    stage.results_path = (dir / "results.h5").string();
    if (out.vtk) stage.vtk_dir = (dir / "vtk").string();
    stage.quiet = quiet;
    run_df3_scenario(root, cut.model, blocks_h5, stage);
    report_after_run(stage.results_path, dir, out, quiet);
  }
}

}  // namespace dda::cli
