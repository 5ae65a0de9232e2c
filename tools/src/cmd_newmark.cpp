// dda newmark --dip D [--dip-direction B] --phi F (--record FILE | --sine A --freq F) [-o out.csv] [--json]
//
// Newmark rigid block on a plane (docs/analytical.md).
#include <cmath>
#include <iostream>

#include "analysis_options.hpp"
#include "commands.hpp"
#include "dda/analysis/newmark.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/output_guard.hpp"
#include "pipeline.hpp"

namespace dda::cli {

void add_newmark_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    analysis::NewmarkInput in;
    InputOptions input;
    std::string output;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "newmark",
      "Newmark rigid block on a plane (2D section along the dip direction). Input: --record or --sine, read as "
      "ground acceleration (the block feels -a_g) unless --input body; axes x east, y north, z up; gravity 9.81 "
      "m/s^2 included. Yield (horizontal body acceleration along the dip direction) = g tan(phi - dip). CSV: t, s "
      "(m, along the plane, downslope positive), v (m/s), a (m/s^2).");
  cmd->add_option("--dip", opt->in.dip_deg, "Dip of the plane (deg)")->required();
  cmd->add_option("--dip-direction", opt->in.dip_direction_deg, "Dip direction (deg from north, default 90 = east)");
  cmd->add_option("--phi", opt->in.phi_deg, "Friction angle (deg)")->required();
  cmd->add_flag("--two-way", opt->in.two_way, "Allow upslope sliding too (default: downslope only)");
  cmd->add_option("--dt", opt->in.dt, "Time step (s, default 1e-4)");
  cmd->add_option("--duration", opt->in.duration, "Duration (s; default: the record's end)");
  add_input_options(cmd, opt->input);
  cmd->add_option("-o,--output", opt->output, "Write the time history CSV here");
  cmd->add_flag("--json", opt->json,
                "Print a JSON summary (yield_acceleration_g, yield_acceleration_up_g, final_displacement, ...)");
  cmd->callback([opt, &global] {
    refuse_overwriting_inputs({opt->input.record.path}, {opt->output});
    const analysis::Excitation ex = build_excitation(opt->input);
    analysis::NewmarkInput in = opt->in;
    if (in.duration <= 0.0) in.duration = ex.duration;
    if (!(in.duration > 0.0)) throw InputError("--duration: give a positive duration (needed without a record).");
    if (!(in.dt > 0.0)) throw InputError("--dt: the time step must be positive.");
    const analysis::NewmarkResult r = analysis::run_newmark(in, ex);
    if (!opt->output.empty()) {
      std::string csv = "t,s,v,a\n";
      for (std::size_t i = 0; i < r.t.size(); ++i) {
        put_number(csv, r.t[i]);
        csv += ',';
        put_number(csv, r.s[i]);
        csv += ',';
        put_number(csv, r.v[i]);
        csv += ',';
        put_number(csv, r.a[i]);
        csv += '\n';
      }
      write_text_atomically(opt->output, csv);
    }
    double vmax = 0;
    for (double v : r.v) vmax = std::max(vmax, std::abs(v));
    nlohmann::json j;
    j["yield_acceleration_g"] = r.yield_down / in.gravity;
    j["yield_acceleration_up_g"] = r.yield_up / in.gravity;
    j["final_displacement"] = r.s.back();
    j["max_velocity"] = vmax;
    j["slip_episodes"] = r.slip_episodes;
    j["lift_off"] = r.lift_off;
    if (r.lift_off) j["lift_off_time"] = r.lift_off_time;
    j["duration"] = r.t.back();
    j["dt"] = in.dt;
    j["input"] = ex.description;
    if (opt->json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::ostringstream s;
      s << "newmark: yield acceleration " << r.yield_down / in.gravity << " g (downslope), final displacement "
        << r.s.back() << " m after " << r.t.back() << " s, " << r.slip_episodes << " slip episodes";
      if (r.lift_off) s << "; the block lifted off at t = " << r.lift_off_time << " s";
      say(global.quiet, s.str() + "\n");
    }
  });
}

}  // namespace dda::cli
