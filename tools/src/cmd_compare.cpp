// dda compare RESULTS.h5 --point NAME [--relative-to NAME] (--dip D | --direction DX,DY)
//             --reference FILE.csv [--column NAME | --reference-direction X,Y,Z] [--floor U]
//             [--csv] [-o FILE.csv] [--plot FIG.png] [--json]
//
// A DDA measurement-point history against an analytical solution
// (docs/analytical.md, "dda compare"); the numerics are in
// tools/analysis (compare.hpp).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "analysis_options.hpp"
#include "commands.hpp"
#include "dda/analysis/compare.hpp"
#include "dda/analysis/table.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/output_guard.hpp"
#include "dda/df/results.hpp"
#include "pipeline.hpp"
#include "plot_runner.hpp"
#include "results_points.hpp"

namespace dda::cli {
namespace {

constexpr const char* kFooter =
    "Sign conventions. Model axes: x to the right (east), y up. The DDA component is "
    "u(t) = (u_point(t) - u_relative_to(t)) . e, displacements from the start of the run, e the unit --direction; "
    "--dip D means down a plane dipping D degrees towards +x, e = (cos D, -sin D), which is the downslope-positive "
    "s of `dda newmark --dip D` with its default dip direction 090 (east). In loading mode the foundation stands "
    "still, so the point's own displacement is the relative sliding; in displacement mode the foundation moves "
    "with the ground: give --relative-to a measurement point on it. The reference CSV (header line required) "
    "gives the analytical displacement: --column NAME, by default `s` (dda newmark: along the plane, downslope "
    "positive); a dda sliding3d CSV (ux, uy, uz; x east, y north, z up) is projected on --reference-direction, by "
    "default (e_x, 0, e_y): the 2D model is the vertical section through x (east) and z (up). The reference is "
    "interpolated linearly at the DDA sample times inside its time span. Relative error e(t) = (u - u_ref) / "
    "max(|u_ref|, floor), floor = --floor or 1 % of max |u_ref|; the final error is (u - u_ref) / |u_ref| at the "
    "last compared time. CSV columns: t (s), dda, reference, difference (m), relative_error (fraction).";

std::string csv_text(const analysis::SeriesComparison& c) {
  std::string out = "t,dda,reference,difference,relative_error\n";
  for (std::size_t i = 0; i < c.t.size(); ++i) {
    for (const double v : {c.t[i], c.model[i], c.reference[i], c.difference[i]}) {
      put_number(out, v);
      out += ',';
    }
    put_number(out, c.relative[i]);
    out += '\n';
  }
  return out;
}

}  // namespace

void add_compare_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string results, point, relative_to, reference, column, output, plot, label;
    std::vector<double> direction, reference_direction;
    double dip = NAN, floor = 0;
    bool csv = false, json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Compare a DDA measurement-point history (results.h5) with an analytical solution CSV (dda newmark, dda "
      "sliding3d): relative error over time and at the end; --plot draws both curves and the error.");
  cmd->footer(kFooter);
  cmd->add_option("results", opt->results, "Results file written by `dda df` or `dda run`")->required();
  cmd->add_option("--point", opt->point, "Measurement point to compare")->required();
  cmd->add_option("--relative-to", opt->relative_to,
                  "Subtract this measurement point's displacement (a point on the moving foundation)");
  cmd->add_option("--dip", opt->dip, "Component down a plane dipping this many degrees towards +x: (cos, -sin)");
  cmd->add_option("--direction", opt->direction, "Component along this model direction dx,dy (instead of --dip)")
      ->delimiter(',');
  cmd->add_option("--reference", opt->reference, "Analytical solution CSV with a header line")->required();
  cmd->add_option("--column", opt->column, "Reference column to use (default s, or ux,uy,uz projected)");
  cmd->add_option("--reference-direction", opt->reference_direction,
                  "Project the reference's ux,uy,uz on this 3D direction x,y,z (default (e_x, 0, e_y))")
      ->delimiter(',');
  cmd->add_option("--floor", opt->floor, "Floor of |u_ref| in the relative error (m; default 1 % of max |u_ref|)");
  cmd->add_flag("--csv", opt->csv, "Print the error history as CSV on the standard output");
  cmd->add_option("-o,--output", opt->output, "Write the error history CSV here");
  cmd->add_option("--plot", opt->plot, "Draw both curves and the relative error (.png, .svg or .pdf)");
  cmd->add_option("--label", opt->label, "Legend label of the reference (default: its file name)");
  cmd->add_flag("--json", opt->json,
                "Print a JSON summary (final_time, final_dda, final_reference, final_relative_error, ...)");
  cmd->callback([opt, &global] {
    refuse_overwriting_inputs({opt->results, opt->reference}, {opt->output, opt->plot});
    // The DDA component.
    const bool has_dip = !std::isnan(opt->dip);
    if (has_dip == !opt->direction.empty())
      throw InputError("--dip or --direction: give exactly one (the direction of the compared component).");
    Vec2 e;
    if (has_dip) {
      const double a = opt->dip * M_PI / 180.0;
      e = Vec2(std::cos(a), -std::sin(a));
    } else {
      if (opt->direction.size() != 2) throw InputError("--direction: give two numbers dx,dy.");
      e = Vec2(opt->direction[0], opt->direction[1]);
    }
    if (!(e.norm() > 0) || !std::isfinite(e.norm())) throw InputError("--direction: the direction must not be zero.");
    e.normalize();
    if (opt->floor < 0) throw InputError("--floor: must not be negative.");

    const df::Results r = df::read_results_h5(opt->results, false);
    const std::size_t p = measurement_point_index(r, opt->point, opt->results);
    std::vector<double> mt, mu;
    for (std::size_t s = 0; s < r.histories[p].size(); ++s) {
      Vec2 u = r.histories[p][s].displacement;
      if (!opt->relative_to.empty())
        u -= r.histories[measurement_point_index(r, opt->relative_to, opt->results)][s].displacement;
      mt.push_back(r.histories[p][s].time);
      mu.push_back(u.dot(e));
    }

    // The reference component.
    const analysis::NamedTable ref = analysis::read_named_table(opt->reference, "t, s or t, ux, uy, uz");
    std::vector<double> rt, ru;
    const std::string col = opt->column.empty() ? "s" : opt->column;
    const int c = ref.column(col);
    const int ux = ref.column("ux"), uy = ref.column("uy"), uz = ref.column("uz");
    const bool project = c < 0 && opt->column.empty() && ux >= 0 && uy >= 0 && uz >= 0;
    if (c < 0 && !project)
      throw InputError(opt->reference + ": has no column '" + col + "'" +
                       (opt->column.empty() ? " and no ux, uy, uz to project" : "") + " (give --column).");
    if (!opt->reference_direction.empty() && !project)
      throw InputError("--reference-direction: applies to a reference with ux, uy, uz columns only.");
    Eigen::Vector3d d3(e.x(), 0.0, e.y());
    if (!opt->reference_direction.empty()) {
      if (opt->reference_direction.size() != 3) throw InputError("--reference-direction: give three numbers x,y,z.");
      d3 = Eigen::Vector3d(opt->reference_direction[0], opt->reference_direction[1], opt->reference_direction[2]);
      if (!(d3.norm() > 0) || !std::isfinite(d3.norm()))
        throw InputError("--reference-direction: the direction must not be zero.");
      d3.normalize();
    }
    for (const auto& row : ref.table.rows) {
      rt.push_back(row[0]);
      ru.push_back(project ? d3.dot(Eigen::Vector3d(row[ux], row[uy], row[uz])) : row[c]);
    }
    const analysis::SeriesComparison cmp = analysis::compare_series(mt, mu, rt, ru, opt->floor);

    const std::string csv = csv_text(cmp);
    if (!opt->output.empty()) write_text_atomically(opt->output, csv);
    if (!opt->plot.empty()) {
      const std::string label =
          opt->label.empty() ? std::filesystem::path(opt->reference).filename().string() : opt->label;
      const std::string dda_label = "DDA, " + opt->point + (opt->relative_to.empty() ? "" : " - " + opt->relative_to);
      plot_csv(csv, opt->output, {"-o", opt->plot, "--kind", "compare", "--labels", dda_label, label});
    }

    nlohmann::json j;
    j["point"] = opt->point;
    j["relative_to"] = opt->relative_to.empty() ? nlohmann::json() : nlohmann::json(opt->relative_to);
    j["direction"] = {e.x(), e.y()};
    j["samples"] = cmp.t.size();
    j["final_time"] = cmp.t.back();
    j["final_dda"] = cmp.model.back();
    j["final_reference"] = cmp.reference.back();
    j["final_relative_error"] = cmp.final_relative;
    j["max_abs_difference"] = cmp.max_abs_difference;
    j["rms_difference"] = cmp.rms_difference;
    j["floor"] = cmp.floor;
    if (opt->csv) {
      std::cout << csv << std::flush;
    } else if (opt->json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::ostringstream s;
      s << "compare: " << opt->point << (opt->relative_to.empty() ? "" : " - " + opt->relative_to) << " along ("
        << e.x() << ", " << e.y() << ") at t = " << cmp.t.back() << " s: DDA " << cmp.model.back()
        << " m, reference " << cmp.reference.back() << " m, relative error " << 100 * cmp.final_relative
        << " %; max |difference| " << cmp.max_abs_difference << " m over " << cmp.t.size() << " samples\n";
      say(global.quiet, s.str());
    }
  });
}

}  // namespace dda::cli
