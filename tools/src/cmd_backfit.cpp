// dda backfit --measured FILE --plane ... [--plane ...] --segments t1,t2 (--record ... | --sine ...) [--fit-lnv]
//
// Friction back-analysis from a measured displacement history
// (docs/analytical.md).
#include <cmath>
#include <iostream>

#include "analysis_options.hpp"
#include "commands.hpp"
#include "dda/analysis/backfit.hpp"
#include "dda/analysis/table.hpp"
#include "dda/common/error.hpp"
#include "dda/common/output_guard.hpp"
#include "pipeline.hpp"

namespace dda::cli {

void add_backfit_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string measured;
    std::vector<std::string> planes;
    std::vector<double> segments, range;
    InputOptions input;
    analysis::BackfitOptions fit;
    std::string output;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "backfit",
      "Back-analysis of friction from a measured displacement history with the 3D analytical solution: one friction "
      "angle per time segment (same on every plane; golden-section fit of each segment in turn, continuing from the "
      "previous segment's end state), then mu = a + b ln(v / v_ref) by regression over the segments (with R^2) and, "
      "with --fit-lnv, by a direct fit to the whole history. Input conventions as in `dda sliding3d`.");
  cmd->add_option("--measured", opt->measured,
                  "CSV t, s (displacement along the line of intersection / down the dip, m) or t, ux, uy, uz")
      ->required();
  cmd->add_option("--plane", opt->planes, "Plane as dip/dip-direction (deg); once or twice (wedge)")->required();
  cmd->add_option("--segments", opt->segments, "Times (s) where one friction segment ends and the next begins")
      ->delimiter(',');
  cmd->add_option("--phi-range", opt->range, "Search range of the friction angle lo,hi (deg, default 5,60)")
      ->delimiter(',');
  add_input_options(cmd, opt->input);
  cmd->add_option("--dt", opt->fit.dt, "Time step of the solution (s, default 1e-3)");
  cmd->add_flag("--fit-lnv", opt->fit.fit_log_velocity, "Also fit a, b of mu = a + b ln(v / v_ref) directly");
  cmd->add_option("--v-ref", opt->fit.v_ref, "Reference speed (m/s, default 1; 0.001 for v in mm/s)");
  cmd->add_option("--v-min", opt->fit.v_min, "Speed floor of the log law (m/s, default 1e-6)");
  cmd->add_option("-o,--output", opt->output, "Write the JSON result here");
  cmd->add_flag("--json", opt->json, "Print the JSON result (segments, rms, regression, direct)");
  cmd->callback([opt, &global] {
    refuse_overwriting_inputs({opt->measured, opt->input.record.path}, {opt->output});
    using namespace analysis;
    SlidingModel model;
    if (opt->planes.empty() || opt->planes.size() > 2) throw InputError("--plane: give one or two planes.");
    for (const auto& p : opt->planes) model.planes.push_back(parse_plane(p, "--plane"));
    model.friction.assign(model.planes.size(), FrictionLaw::constant_angle(30));
    model.input = build_excitation(opt->input);
    const NumericTable table = read_numeric_table(opt->measured, {2, 4});
    MeasuredHistory m;
    m.vector_form = table.columns == 4;
    for (const auto& row : table.rows) {
      m.t.push_back(row[0]);
      if (m.vector_form)
        m.u.emplace_back(row[1], row[2], row[3]);
      else
        m.s.push_back(row[1]);
    }
    if (m.t.size() < 2) throw InputError(opt->measured + ": at least two samples are needed.");
    if (m.t.front() < 0.0) throw InputError(opt->measured + ": times must not be negative (the input starts at 0).");
    BackfitOptions fit = opt->fit;
    fit.breaks = opt->segments;
    if (!opt->range.empty()) {
      if (opt->range.size() != 2) throw InputError("--phi-range: give two angles lo,hi.");
      fit.phi_min = opt->range[0];
      fit.phi_max = opt->range[1];
    }
    if (!(fit.dt > 0.0)) throw InputError("--dt: the time step must be positive.");
    if (!(fit.v_ref > 0.0) || !(fit.v_min > 0.0)) throw InputError("--v-ref and --v-min must be positive.");
    const BackfitResult r = backfit(model, m, fit);
    nlohmann::json j;
    j["segments"] = nlohmann::json::array();
    for (const auto& s : r.segments)
      j["segments"].push_back({{"t0", s.t0},
                               {"t1", s.t1},
                               {"phi_deg", s.phi_deg},
                               {"mu", s.mu},
                               {"rms", s.rms},
                               {"mean_speed", s.mean_speed},
                               {"samples", s.samples}});
    j["rms"] = r.rms;
    j["v_ref"] = fit.v_ref;
    if (r.regression.valid)
      j["regression"] = {{"a", r.regression.a}, {"b", r.regression.b}, {"r2", r.regression.r2}};
    else
      j["regression"] = nullptr;
    if (r.direct.valid)
      j["direct"] = {{"a", r.direct.a}, {"b", r.direct.b}, {"rms", r.direct.rms}, {"stalled", r.direct.stalled}};
    j["measured_form"] = m.vector_form ? "vector" : "along reference direction";
    if (!opt->output.empty()) write_json(opt->output, j);
    if (opt->json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::ostringstream s;
      s << "backfit: " << r.segments.size() << " segments, rms " << r.rms << " m\n";
      for (const auto& sg : r.segments)
        s << "  " << sg.t0 << " .. " << sg.t1 << " s: phi = " << sg.phi_deg << " deg (mu " << sg.mu
          << "), mean speed " << sg.mean_speed << " m/s\n";
      // mu = a + b ln(v/v_ref), written with the sign of b.
      auto law = [&](double a, double b) {
        std::ostringstream l;
        l << "mu = " << a << (b < 0 ? " - " : " + ") << std::abs(b) << " ln(v/" << fit.v_ref << ")";
        return l.str();
      };
      if (r.regression.valid)
        s << "  regression: " << law(r.regression.a, r.regression.b) << ", R^2 = " << r.regression.r2 << "\n";
      if (r.direct.valid) s << "  direct fit: " << law(r.direct.a, r.direct.b) << ", rms " << r.direct.rms << " m\n";
      say(global.quiet, s.str());
    }
    if (r.direct.stalled)
      std::cerr << "dda backfit: warning: the direct fit found nothing better than its start (the regression): "
                   "either that is already the best, or the misfit is flat there (a velocity-weakening law whose "
                   "friction at --v-min holds the block never lets it slide).\n";
  });
}

}  // namespace dda::cli
