// dda compare RESULTS.h5 --point NAME [--relative-to NAME] (--dip D | --direction DX,DY)    (2D)
//             (--direction X,Y,Z | --trend-plunge T/P | --intersection D/B D/B)             (3D)
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
#include "compare_direction.hpp"
#include "dda/analysis/compare.hpp"
#include "dda/analysis/table.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/output_guard.hpp"
#include "dda/df/io/results.hpp"
#include "dda/df/io/results3d.hpp"
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
    "last compared time. CSV columns: t (s), dda, reference, difference (m), relative_error (fraction). "
    "3D results (dda-results3d; x east, y north, z up): u(t) = (u_point(t) - u_relative_to(t)) . e with e given as "
    "--direction x,y,z, --trend-plunge T/P (degrees, plunge positive down) or --intersection D/B D/B (the line "
    "where two planes, dip/dip-direction, meet, pointing down: a wedge's sliding direction); a ux, uy, uz "
    "reference is projected on the same e unless --reference-direction says otherwise.";

struct PointSeries {
  std::vector<double> t, u;  // time (s) and the displacement component along the direction (m)
};

// The DDA component of a 2D or a 3D results file.
PointSeries dda_series(const std::string& path, const std::string& point, const std::string& relative_to,
                       const Eigen::Vector3d& e, bool three_d) {
  PointSeries out;
  auto fill = [&](const auto& names, const auto& histories, auto displacement) {
    const std::size_t p = measurement_point_index(names, point, path);
    const std::size_t q = relative_to.empty() ? p : measurement_point_index(names, relative_to, path);
    for (std::size_t s = 0; s < histories[p].size(); ++s) {
      Eigen::Vector3d u = displacement(histories[p][s]);
      if (!relative_to.empty()) u -= displacement(histories[q][s]);
      out.t.push_back(histories[p][s].time);
      out.u.push_back(u.dot(e));
    }
  };
  if (three_d) {
    const df3::Results3 r = df3::read_results3_h5(path, df::ResultsParts::records());
    fill(r.point_names, r.histories, [](const auto& h) { return Eigen::Vector3d(h.displacement); });
  } else {
    const df::Results r = df::read_results_h5(path, df::ResultsParts::records());
    fill(r.point_names, r.histories,
         [](const auto& h) { return Eigen::Vector3d(h.displacement.x(), h.displacement.y(), 0.0); });
  }
  return out;
}

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
    CompareDirectionOptions along;
    std::vector<double> reference_direction;
    double floor = 0;
    bool csv = false, json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Compare a DDA measurement-point history (results.h5, 2D or 3D) with an analytical solution CSV (dda "
      "newmark, dda sliding3d): relative error over time and at the end; --plot draws both curves and the error.");
  cmd->footer(kFooter);
  cmd->add_option("results", opt->results, "Results file written by `dda df` or `dda run`")->required();
  cmd->add_option("--point", opt->point, "Measurement point to compare")->required();
  cmd->add_option("--relative-to", opt->relative_to,
                  "Subtract this measurement point's displacement (a point on the moving foundation)");
  cmd->add_option("--dip", opt->along.dip,
                  "2D: component down a plane dipping this many degrees towards +x: (cos, -sin)");
  cmd->add_option("--direction", opt->along.direction,
                  "Component along this model direction: dx,dy (2D) or x,y,z (3D; x east, y north, z up)")
      ->delimiter(',');
  cmd->add_option("--trend-plunge", opt->along.trend_plunge,
                  "3D: component along this trend/plunge (degrees, plunge positive down), e.g. 090/20");
  cmd->add_option("--intersection", opt->along.intersection,
                  "3D: component along the line where two planes D/B (dip/dip-direction) meet, pointing down")
      ->expected(2);
  cmd->add_option("--reference", opt->reference, "Analytical solution CSV with a header line")->required();
  cmd->add_option("--column", opt->column, "Reference column to use (default s, or ux,uy,uz projected)");
  cmd->add_option("--reference-direction", opt->reference_direction,
                  "Project the reference's ux,uy,uz on this 3D direction x,y,z (default: 2D (e_x, 0, e_y), 3D e)")
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
    const std::string format = h5_format_of(opt->results);
    const bool three_d = format == df3::kResults3dFormat;
    if (!three_d && format != "dda-results")
      throw InputError(opt->results + ": is not a results file (" + (format.empty() ? "no dda format" : format) +
                       "); dda compare reads the results.h5 of dda df or dda run.");
    const CompareDirection along = compare_direction(opt->along, three_d);
    const Eigen::Vector3d& e = along.unit;
    if (opt->floor < 0) throw InputError("--floor: must not be negative.");
    const PointSeries model = dda_series(opt->results, opt->point, opt->relative_to, e, three_d);
    const std::vector<double>&mt = model.t, &mu = model.u;

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
    // A 2D model is the vertical section through x (east) and z (up).
    Eigen::Vector3d d3 = three_d ? e : Eigen::Vector3d(e.x(), 0.0, e.y());
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
    j["direction"] = three_d ? nlohmann::json{e.x(), e.y(), e.z()} : nlohmann::json{e.x(), e.y()};
    j["reference_direction"] = project ? nlohmann::json{d3.x(), d3.y(), d3.z()} : nlohmann::json();
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
      s << "compare: " << opt->point << (opt->relative_to.empty() ? "" : " - " + opt->relative_to) << " along "
        << along.how << " at t = " << cmp.t.back() << " s: DDA " << cmp.model.back()
        << " m, reference " << cmp.reference.back() << " m, relative error " << 100 * cmp.final_relative
        << " %; max |difference| " << cmp.max_abs_difference << " m over " << cmp.t.size() << " samples\n";
      say(global.quiet, s.str());
    }
  });
}

}  // namespace dda::cli
