// dda plot FILE.h5 [FILE.h5 ...] -o OUT.png
// dda plot RESULTS.h5 -o FOLDER | -o FIG.png --kind KIND (docs/plots.md)
#include <filesystem>
#include <iomanip>
#include <optional>
#include <sstream>

#include "commands.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/output_guard.hpp"
#include "pipeline.hpp"
#include "plot_runner.hpp"

namespace dda::cli {

void add_plot_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::vector<std::string> inputs, labels;
    std::string output, kind = "auto", title, color, color_by, component;
    std::vector<double> view, times;
    std::vector<std::string> looks, sections, axes;
    bool vectors = false;
    std::optional<double> explode;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "plot",
      "Draw lines, blocks, fractures or 3D blocks (PNG/SVG), block width and area histograms of blocks files, "
      "or the figures of a results file (2D or 3D): deformed blocks, sections, contacts, histories, energy, steps");
  cmd->add_option("files", opt->inputs, "Lines, blocks, fractures, 3D blocks or results files (HDF5)")->required();
  cmd->add_option("-o,--output", opt->output,
                  "Figure to write (.png, .svg or .pdf); for a results file also a folder, which gets every figure")
      ->required();
  cmd->add_option("--kind", opt->kind,
                  "auto (from the file), lines, blocks or histograms; results: blocks, sections (3D), contacts, "
                  "histories, energy (2D), steps or all")
      ->check(CLI::IsMember(
          {"auto", "lines", "blocks", "histograms", "sections", "contacts", "histories", "energy", "steps", "all"}));
  cmd->add_option("--labels", opt->labels, "Legend labels, one per file (histograms)");
  cmd->add_option("--title", opt->title, "Figure title");
  cmd->add_option("--axes", opt->axes, "2D lines or blocks: the axis labels (default 'x (m)' 'y (m)'), e.g. a section's")
      ->expected(2);
  cmd->add_option("--view", opt->view, "3D: camera elevation and azimuth, degrees (default 25 -60)")->expected(2);
  cmd->add_option("--explode", opt->explode, "3D blocks: move bodies apart by this factor of their offset from the centre")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--color", opt->color, "3D blocks: colour by removability (default), body or layer")
      ->check(CLI::IsMember({"removability", "body", "layer"}));
  cmd->add_option("--times", opt->times, "Results: draw the blocks at the frames nearest these times (s; default the last)");
  cmd->add_option("--color-by", opt->color_by, "Results: colour blocks by displacement (default), velocity or stress")
      ->check(CLI::IsMember({"displacement", "velocity", "stress"}));
  cmd->add_option("--component", opt->component,
                  "Results, --color-by stress: mean (default), sxx, syy, sxy (2D) or szz, syz, szx (3D too)")
      ->check(CLI::IsMember({"mean", "sxx", "syy", "szz", "syz", "szx", "sxy"}));
  cmd->add_flag("--vectors", opt->vectors, "Results: draw the blocks' displacement vectors");
  cmd->add_option("--look", opt->looks,
                  "3D results: lines of sight TREND/PLUNGE (degrees) or north, south, east, west, plan (default "
                  "north west plan)");
  cmd->add_option("--section", opt->sections, "3D results: section planes x=V, y=V or z=V (m; default through the middle)");
  cmd->callback([opt, &global] {
    refuse_overwriting_inputs(opt->inputs, {opt->output});
    for (const auto& f : opt->inputs)
      if (h5_format_of(f).empty()) throw InputError(f + ": is not a file written by dda (lines, blocks, fractures or 3D blocks).");
    if (!opt->labels.empty() && opt->labels.size() != opt->inputs.size())
      throw InputError("--labels: give one label per file (" + std::to_string(opt->inputs.size()) + "), got " +
                       std::to_string(opt->labels.size()) + ".");
    std::vector<std::string> args = opt->inputs;
    args.insert(args.end(), {"-o", opt->output, "--kind", opt->kind});
    if (!opt->labels.empty()) {
      args.push_back("--labels");
      args.insert(args.end(), opt->labels.begin(), opt->labels.end());
    }
    if (!opt->title.empty()) args.insert(args.end(), {"--title", opt->title});
    if (opt->view.size() == 2) args.insert(args.end(), {"--view", std::to_string(opt->view[0]), std::to_string(opt->view[1])});
    if (opt->explode) args.insert(args.end(), {"--explode", std::to_string(*opt->explode)});
    if (!opt->color.empty()) args.insert(args.end(), {"--color", opt->color});
    if (!opt->times.empty()) {
      args.push_back("--times");
      for (const double t : opt->times) {
        std::ostringstream text;  // every digit: a frame time must reach the script unrounded
        text << std::setprecision(17) << t;
        args.push_back(text.str());
      }
    }
    if (!opt->color_by.empty()) args.insert(args.end(), {"--color-by", opt->color_by});
    if (!opt->component.empty()) args.insert(args.end(), {"--component", opt->component});
    if (opt->vectors) args.push_back("--vectors");
    for (const auto& [flag, values] : {std::pair{"--look", &opt->looks}, std::pair{"--section", &opt->sections},
                                        std::pair{"--axes", &opt->axes}})
      if (!values->empty()) {
        args.push_back(flag);
        args.insert(args.end(), values->begin(), values->end());
      }
    run_plot_script(args);
    const bool folder = !std::filesystem::path(opt->output).has_extension() || std::filesystem::is_directory(opt->output);
    say(global.quiet, (folder ? "figures written to " : "figure written to ") + opt->output + "\n");
  });
}

}  // namespace dda::cli
