// dda sliding3d --plane D/B [--plane D/B] --phi F ... [-o out.csv] [--json]
//
// The seed report's 3D analytical solution of dynamic single- and double-face
// sliding (docs/analytical.md).
#include <cmath>
#include <iostream>

#include "analysis_options.hpp"
#include "commands.hpp"
#include "dda/analysis/sliding3d.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/output_guard.hpp"
#include "pipeline.hpp"

namespace dda::cli {

void add_sliding3d_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::vector<std::string> planes;
    std::vector<double> water;
    FrictionOptions friction;
    InputOptions input;
    double dt = 1e-4, duration = 0.0;
    int every = 1;
    std::string output;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "sliding3d",
      "3D dynamic sliding of a rigid block on one plane or a wedge on two (seed report ch. 2). Resultant "
      "r = (0,0,-9.81) + b(t); b = -a_g for --input ground (default), the input itself for --input body. Axes x "
      "east, y north, z up; planes as dip/dip-direction. CSV: t, ux, uy, uz (m), vx, vy, vz (m/s), N1, N2 (normal "
      "reactions per unit weight).");
  cmd->add_option("--plane", opt->planes, "Plane as dip/dip-direction in degrees, e.g. 20/090; once or twice (wedge)")
      ->required();
  add_friction_options(cmd, opt->friction);
  cmd->add_option("--water", opt->water,
                  "Water force on each plane as a fraction of the weight, U1[,U2] (pore pressure on the sliding "
                  "planes, constant, normal to each; e.g. dda wedge --water's forces over the weight)")
      ->delimiter(',');
  add_input_options(cmd, opt->input);
  cmd->add_option("--dt", opt->dt, "Time step (s, default 1e-4)");
  cmd->add_option("--duration", opt->duration, "Duration (s; default: the record's end)");
  cmd->add_option("--every", opt->every, "Write every n-th step to the CSV (default 1)");
  cmd->add_option("-o,--output", opt->output, "Write the time history CSV here");
  cmd->add_flag("--json", opt->json,
                "Print a JSON summary (final_displacement [x,y,z], final_displacement_magnitude, events, ...)");
  cmd->callback([opt, &global] {
    refuse_overwriting_inputs({opt->input.record.path, opt->friction.table}, {opt->output});
    analysis::SlidingModel model;
    if (opt->planes.empty() || opt->planes.size() > 2) throw InputError("--plane: give one or two planes.");
    for (const auto& p : opt->planes) model.planes.push_back(analysis::parse_plane(p, "--plane"));
    model.friction = build_friction(opt->friction, model.planes.size());
    if (!opt->water.empty()) {
      if (opt->water.size() != model.planes.size())
        throw InputError("--water: give one water force per plane (" + std::to_string(model.planes.size()) + ").");
      for (const double u : opt->water)
        if (!(u >= 0.0 && std::isfinite(u))) throw InputError("--water: each force must be >= 0 (a fraction of W).");
      model.water = opt->water;
    }
    model.input = build_excitation(opt->input);
    double duration = opt->duration > 0.0 ? opt->duration : model.input.duration;
    if (!(duration > 0.0)) throw InputError("--duration: give a positive duration (needed without a record).");
    if (!(opt->dt > 0.0)) throw InputError("--dt: the time step must be positive.");
    if (opt->every < 1) throw InputError("--every: must be 1 or more.");
    const analysis::SlidingRun run = analysis::run_sliding(model, opt->dt, duration, opt->every);
    if (!opt->output.empty()) {
      std::string csv = "t,ux,uy,uz,vx,vy,vz,N1,N2\n";
      for (const auto& s : run.samples) {
        const double vals[9] = {s.t,   s.u.x(), s.u.y(), s.u.z(), s.v.x(), s.v.y(), s.v.z(), s.n1 / model.gravity,
                                s.n2 / model.gravity};
        for (int k = 0; k < 9; ++k) {
          if (k) csv += ',';
          put_number(csv, vals[k]);
        }
        csv += '\n';
      }
      write_text_atomically(opt->output, csv);
    }
    const auto& end = run.samples.back();
    double vmax = 0;
    for (const auto& s : run.samples) vmax = std::max(vmax, s.v.norm());
    nlohmann::json j;
    j["final_time"] = end.t;
    j["final_displacement"] = {end.u.x(), end.u.y(), end.u.z()};
    j["final_displacement_magnitude"] = end.u.norm();
    j["final_displacement_along_reference"] = end.u.dot(run.reference);
    j["reference_direction"] = {run.reference.x(), run.reference.y(), run.reference.z()};
    const auto tp = analysis::trend_plunge(run.reference);
    j["reference_trend"] = tp.trend_deg;
    j["reference_plunge"] = tp.plunge_deg;
    j["max_speed"] = vmax;
    j["final_mode"] = analysis::mode_name(end.mode);
    j["lift_off"] = end.mode == analysis::ContactMode::lifted;
    j["events"] = nlohmann::json::array();
    for (const auto& e : run.events) j["events"].push_back({{"t", e.t}, {"what", e.what}});
    j["input"] = model.input.description;
    if (opt->json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::ostringstream s;
      s << "sliding3d: |D| = " << end.u.norm() << " m, D = (" << end.u.x() << ", " << end.u.y() << ", " << end.u.z()
        << ") m at t = " << end.t << " s (" << analysis::mode_name(end.mode) << ")\n";
      for (const auto& e : run.events) s << "  " << e.what << "\n";
      say(global.quiet, s.str());
    }
  });
}

}  // namespace dda::cli
