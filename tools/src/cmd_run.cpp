// dda run SCENARIO.yaml -o OUTDIR: every stage the scenario asks for.
//
// OUTDIR receives lines.h5, blocks.h5, dl_report.json, dc_report.json,
// stats.json, vtk/{lines.vtu, blocks.vtu, model.pvd} and
// figures/{lines, blocks, histograms}.png; a scenario with a `control`
// section is then run forward (DF) into results.h5 and
// vtk/{df.pvd, df_blocks_*.vtu, df_contacts_*.vtu}, and report.html. The whole scenario is
// checked before the first stage runs, so a typo in a late section fails at
// once. A scenario with dimension: 3 runs the 3D pipeline (run3d.cpp).
#include <filesystem>

#include "commands.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/output_guard.hpp"
#include "dda/common/scenario.hpp"
#include "dda/common/vtk.hpp"
#include "dda/dc/stats.hpp"
#include "dda/df/io/scenario.hpp"
#include "dda/df/io/scenario3d.hpp"
#include "dda/dc/cut3d.hpp"
#include "dda/dl/generate.hpp"
#include "dda/dl/scenario3d.hpp"
#include "pipeline.hpp"
#include "plot_runner.hpp"

namespace dda::cli {

namespace fs = std::filesystem;

OutputOptions parse_output_options(const YamlNode& root) {
  OutputOptions o;
  if (auto out = root.optional_child("output")) {
    out->allow(
        {"vtk", "plots", "report", "histogram_bins", "checkpoint_seconds", "checkpoint_steps", "vtk_contacts"});
    o.vtk = out->flag("vtk", true);
    o.plots = out->flag("plots", true);
    o.report = out->flag("report", true);
    o.histogram_bins = static_cast<int>(out->integer("histogram_bins", 20, Range::closed(1, 10000)));
    o.checkpoint_seconds = out->number("checkpoint_seconds", 60, Range::non_negative());
    o.checkpoint_steps = static_cast<int>(out->integer("checkpoint_steps", 0, Range::closed(0, 1e9)));
    o.vtk_contacts = out->flag("vtk_contacts", true);
  }
  return o;
}

namespace {

// Everything `dda run` may write into its folder, 2D (here) and 3D
// (run3d.cpp), checked against the scenario before any stage runs: a
// scenario kept as out/stats.json would be replaced by the statistics.
void guard_run_outputs(const std::string& scenario, const std::string& outdir) {
  const fs::path dir(outdir);
  std::vector<std::string> files{outdir};
  for (const char* name : {"lines.h5", "fractures.h5", "blocks.h5", "blocks3d.h5", "results.h5", "dl_report.json",
                           "dc_report.json", "stats.json", "report.html"})
    files.push_back((dir / name).string());
  std::vector<std::string> folders;
  for (const char* name : {"vtk", "figures", "sections"}) folders.push_back((dir / name).string());
  refuse_overwriting_inputs({scenario}, files, folders);
}

}  // namespace

void add_run_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string scenario, outdir;
    bool no_plots = false, no_vtk = false, no_report = false;
    SliverOverrides slivers;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "run", "Run the whole pipeline of a scenario (DL -> DC, then DF if it has a control section) into a folder");
  cmd->add_option("scenario", opt->scenario, "Scenario file (.yaml)")->required();
  cmd->add_option("-o,--output", opt->outdir, "Output folder (created if missing)")->required();
  cmd->add_flag("--no-plots", opt->no_plots, "Do not draw the figures");
  cmd->add_flag("--no-vtk", opt->no_vtk, "Do not write ParaView files");
  cmd->add_flag("--no-report", opt->no_report, "Do not write report.html after a forward run");
  add_sliver_options(cmd, opt->slivers);
  cmd->callback([opt, &global] {
    guard_run_outputs(opt->scenario, opt->outdir);
    if (!fs::exists(opt->scenario)) throw InputError(opt->scenario + ": no such file.");
    const YamlNode root = load_scenario(opt->scenario);
    OutputOptions out = parse_output_options(root);
    if (dl::scenario_dimension(root) == 3) {
      if (opt->slivers.min_area || opt->slivers.max_aspect || opt->slivers.action)
        throw InputError("--min-area, --max-aspect and --slivers apply to 2D cuts; " + opt->scenario +
                         " is a 3D scenario.");
      dc::parse_cut3d_options(root.optional_child("cutting"));  // check before any stage runs
      df3::check_df3_scenario(root);
      if (opt->no_plots) out.plots = false;
      if (opt->no_vtk) out.vtk = false;
      if (opt->no_report) out.report = false;
      make_dir(fs::path(opt->outdir));
      run_pipeline_3d(root, fs::path(opt->outdir), out, global.quiet);
      return;
    }
    dc::CutOptions cut_options = dc::parse_cut_options(root.optional_child("cutting"));
    apply(opt->slivers, cut_options);
    df::check_df_scenario(root);
    if (opt->no_plots) out.plots = false;
    if (opt->no_vtk) out.vtk = false;
    if (opt->no_report) out.report = false;

    const fs::path dir(opt->outdir);
    make_dir(dir);

    dl::DlResult dl = dl::generate_from_scenario(root);
    const std::string lines_h5 = (dir / "lines.h5").string();
    write_lines_h5(lines_h5, dl.model);
    write_json((dir / "dl_report.json").string(), dl.report);
    say(global.quiet, dl::format_report(dl.report));
    say(global.quiet, "DL: " + std::to_string(dl.model.lines.size()) + " lines written to " + lines_h5 + "\n");

    const dc::CutResult cut = naming_input(opt->scenario, [&] { return dc::cut_blocks(dl.model, cut_options); });
    const std::string blocks_h5 = (dir / "blocks.h5").string();
    write_blocks_h5(blocks_h5, cut.model);
    write_json((dir / "dc_report.json").string(), cut.report);
    say(global.quiet, "DC: " + describe_cut(cut.model, blocks_h5));
    warn_of_lost_area(cut.model);

    write_json((dir / "stats.json").string(), dc::block_statistics(cut.model, out.histogram_bins));

    if (out.vtk) {
      make_dir(dir / "vtk");
      write_lines_vtu((dir / "vtk" / "lines.vtu").string(), dl.model);
      write_blocks_vtu((dir / "vtk" / "blocks.vtu").string(), cut.model);
      write_pvd((dir / "vtk" / "model.pvd").string(),
                {{"lines.vtu", 0.0, 0, "lines"}, {"blocks.vtu", 0.0, 1, "blocks"}});
    }
    if (out.plots) {
      if (!plotting_available()) {
        say(global.quiet, "figures skipped: /usr/bin/python3 with matplotlib and h5py is not installed\n");
      } else {
        const fs::path figs = dir / "figures";
        make_dir(figs);
        run_plot_script({lines_h5, "-o", (figs / "lines.png").string(), "--kind", "lines"});
        run_plot_script({blocks_h5, "-o", (figs / "blocks.png").string(), "--kind", "blocks"});
        run_plot_script({blocks_h5, "-o", (figs / "histograms.png").string(), "--kind", "histograms"});
        say(global.quiet, "figures written to " + figs.string() + "\n");
      }
    }
    if (df::scenario_has_df(root)) {
      DfStage stage;
      stage.results_path = (dir / "results.h5").string();
      if (out.vtk) stage.vtk_dir = (dir / "vtk").string();
      stage.quiet = global.quiet;
      run_df_scenario(root, cut.model, blocks_h5, stage);
      report_after_run(stage.results_path, dir, out, global.quiet);
    }
  });
}

}  // namespace dda::cli
