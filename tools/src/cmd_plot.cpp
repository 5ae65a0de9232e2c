// dda plot FILE.h5 [FILE.h5 ...] -o OUT.png
#include <optional>

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
    std::string output, kind = "auto", title, color;
    std::vector<double> view;
    std::optional<double> explode;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "plot", "Draw lines, blocks, fractures or 3D blocks (PNG/SVG), or block width and area histograms of blocks files");
  cmd->add_option("files", opt->inputs, "Lines, blocks, fractures or 3D blocks files (HDF5)")->required();
  cmd->add_option("-o,--output", opt->output, "Figure to write; .png or .svg")->required();
  cmd->add_option("--kind", opt->kind, "auto (from the file), lines, blocks or histograms")
      ->check(CLI::IsMember({"auto", "lines", "blocks", "histograms"}));
  cmd->add_option("--labels", opt->labels, "Legend labels, one per file (histograms)");
  cmd->add_option("--title", opt->title, "Figure title");
  cmd->add_option("--view", opt->view, "3D: camera elevation and azimuth, degrees (default 25 -60)")->expected(2);
  cmd->add_option("--explode", opt->explode, "3D blocks: move bodies apart by this factor of their offset from the centre")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--color", opt->color, "3D blocks: colour by removability (default), body or layer")
      ->check(CLI::IsMember({"removability", "body", "layer"}));
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
    run_plot_script(args);
    say(global.quiet, "figure written to " + opt->output + "\n");
  });
}

}  // namespace dda::cli
