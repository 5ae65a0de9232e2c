// dda newmark --dip D [--dip-direction B] --phi F (--record FILE | --sine A --freq F) [-o out.csv] [--json]
// dda newmark --ky K --records FILE|FOLDER... [--method rigid,decoupled,coupled] [--polarity both] [-o table.csv]
//
// Newmark rigid block on a plane, or Newmark analyses of a series of records
// at SLAMMER's level (docs/analytical.md).
#include <cmath>
#include <iostream>

#include "analysis_options.hpp"
#include "commands.hpp"
#include "dda/analysis/newmark.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/short_number.hpp"
#include "dda/common/output_guard.hpp"
#include "newmark_records.hpp"
#include "pipeline.hpp"

namespace dda::cli {

namespace {

struct Options {
  analysis::NewmarkInput in;
  InputOptions input;
  std::string output;
  bool json = false;
  bool has_plane = false;  // --dip and --phi given
  // --ky: records at SLAMMER's level
  RecordsAnalysis records;
  std::vector<std::string> record_paths;
  std::string methods = "rigid", polarity = "both";
  double vs = 0.0;
  bool has_ts = false, has_height = false, has_vs = false;
};

// The sliding mass's period from --ts, or --height and --vs (Ts = 4 H / Vs),
// and its height when the equivalent-linear strain needs it.
void resolve_sliding_mass(Options& o) {
  RecordsAnalysis& ra = o.records;
  const bool flexible = ra.decoupled || ra.coupled;
  if (!flexible) return;
  if (o.has_height && o.has_vs) {
    if (!(ra.height > 0.0) || !(o.vs > 0.0)) throw InputError("--height and --vs must be positive.");
    ra.beam.period = 4.0 * ra.height / o.vs;
  } else if (o.has_ts && o.has_height) {
    if (!(ra.height > 0.0)) throw InputError("--height must be positive.");
  } else if (!o.has_ts) {
    throw InputError("--method decoupled/coupled: give the sliding mass's period --ts, or --height and --vs.");
  }
  if (!(ra.beam.period >= 0.0) || !std::isfinite(ra.beam.period)) throw InputError("--ts must be zero or positive.");
  if (!(ra.beam.damping >= 0.0 && ra.beam.damping < 1.0)) throw InputError("--damping must lie in 0..1.");
  if (ra.curve.reference_strain < 0.0) throw InputError("--reference-strain must be positive.");
  if (ra.curve.reference_strain > 0.0 && !(ra.beam.period > 0.0))
    throw InputError("--reference-strain: the equivalent-linear analysis needs a positive Ts.");
}

void run_records(Options& o, const GlobalOptions& global) {
  RecordsAnalysis& ra = o.records;
  if (!(ra.ky > 0.0) || !std::isfinite(ra.ky)) throw InputError("--ky: the yield coefficient must be positive.");
  parse_methods(o.methods, ra);
  parse_polarity(o.polarity, ra);
  resolve_sliding_mass(o);
  if (o.input.sine_g != 0.0) throw InputError("--sine: with --ky give records (--record or --records).");
  std::vector<std::string> args = o.record_paths;
  if (!o.input.record.path.empty()) args.insert(args.begin(), o.input.record.path);
  if (args.empty()) throw InputError("--ky: give the records with --records (files or folders) or --record.");
  const std::vector<std::string> paths = expand_record_paths(args);
  refuse_overwriting_inputs(paths, {o.output});
  const std::vector<RecordResult> results = analyse_records(paths, o.input.record, ra);
  const std::string csv = records_table_csv(results, ra);
  if (!o.output.empty()) write_text_atomically(o.output, csv);
  if (o.json) {
    nlohmann::json j;
    j["ky"] = ra.ky;
    j["records"] = results.size();
    j["rows"] = nlohmann::json::array();
    for (const RecordResult& r : results)
      for (const PolarityResult& p : r.polarities) {
        nlohmann::json row{{"record", r.path},
                           {"polarity", p.polarity},
                           {"dt", r.dt},
                           {"samples", r.samples},
                           {"pga_g", r.im.pga / kRecordGravity},
                           {"pgv_m_s", r.im.pgv},
                           {"pgd_m", r.im.pgd},
                           {"arias_m_s", r.im.arias},
                           {"d5_95_s", r.im.significant_duration},
                           {"mean_period_s", r.im.mean_period},
                           {"predominant_period_s", r.im.predominant_period}};
        if (ra.rigid) row["rigid_m"] = p.rigid;
        if (ra.decoupled) {
          row["decoupled_m"] = p.decoupled;
          row["kmax_g"] = p.kmax;
        }
        if (ra.coupled) row["coupled_m"] = p.coupled;
        if (ra.decoupled || ra.coupled) {
          row["ts_s"] = r.beam.period;
          row["damping"] = r.beam.damping;
          row["modulus_ratio"] = r.modulus_ratio;
          row["effective_strain"] = r.effective_strain;
        }
        j["rows"].push_back(row);
      }
    std::cout << j.dump(2) << "\n";
  } else if (o.output.empty()) {
    std::cout << csv;
  } else {
    std::ostringstream s;
    s << "newmark: " << results.size() << " records, k_y = " << ra.ky << " g; table written to " << o.output << "\n";
    say(global.quiet, s.str());
  }
}

}  // namespace

void add_newmark_command(CLI::App& app, const GlobalOptions& global) {
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "newmark",
      "Newmark rigid block on a plane (2D section along the dip direction). Input: --record or --sine, read as "
      "ground acceleration (the block feels -a_g) unless --input body; axes x east, y north, z up; gravity 9.81 "
      "m/s^2 included. Yield (horizontal body acceleration along the dip direction) = g tan(phi - dip). CSV: t, s "
      "(m, along the plane, downslope positive), v (m/s), a (m/s^2). With --ky instead of --dip/--phi: SLAMMER-style "
      "analyses of records (rigid, decoupled, coupled; both polarities), a table with one row per record and "
      "polarity: the intensity measures, the displacements (cm) and the empirical regressions.");
  CLI::Option* dip = cmd->add_option("--dip", opt->in.dip_deg, "Dip of the plane (deg)");
  CLI::Option* dip_dir = cmd->add_option("--dip-direction", opt->in.dip_direction_deg,
                                         "Dip direction (deg from north, default 90 = east)");
  CLI::Option* phi = cmd->add_option("--phi", opt->in.phi_deg, "Friction angle (deg)");
  CLI::Option* two_way =
      cmd->add_flag("--two-way", opt->in.two_way, "Allow upslope sliding too (default: downslope only)");
  CLI::Option* ru = cmd->add_option("--ru", opt->in.ru,
                                    "Pore-pressure ratio on the plane, [0, 1) (Bishop's: u = ru x the vertical "
                                    "overburden; water force ru W / cos(dip) normal to the plane, constant)");
  CLI::Option* dt = cmd->add_option("--dt", opt->in.dt, "Time step (s, default 1e-4)");
  CLI::Option* duration = cmd->add_option("--duration", opt->in.duration, "Duration (s; default: the record's end)");
  add_input_options(cmd, opt->input);
  cmd->add_option("-o,--output", opt->output, "Write the time history CSV (with --ky: the table) here");
  cmd->add_flag("--json", opt->json,
                "Print a JSON summary (yield_acceleration_g, yield_acceleration_up_g, final_displacement, ...)");
  RecordsAnalysis& ra = opt->records;
  CLI::Option* ky = cmd->add_option(
      "--ky", ra.ky, "Yield coefficient k_y (g): analyse records as SLAMMER does (sliding while a > k_y g)");
  ky->excludes(dip)->excludes(dip_dir)->excludes(phi)->excludes(two_way)->excludes(dt)->excludes(duration);
  ky->excludes(ru);
  cmd->add_option("--records", opt->record_paths, "With --ky: record files and folders (every file in a folder)")
      ->needs(ky);
  cmd->add_option("--method", opt->methods,
                  "With --ky: rigid, decoupled, coupled or all, comma-separated (default rigid)")
      ->needs(ky);
  cmd->add_option("--polarity", opt->polarity, "With --ky: normal, inverse (the record times -1) or both (default)")
      ->needs(ky);
  CLI::Option* ts =
      cmd->add_option("--ts", ra.beam.period, "Site period of the sliding mass Ts = 4 H / Vs (s)")->needs(ky);
  CLI::Option* height = cmd->add_option("--height", ra.height, "Height H of the sliding mass (m)")->needs(ky);
  CLI::Option* vs = cmd->add_option("--vs", opt->vs, "Shear-wave speed Vs of the sliding mass (m/s)")->needs(ky);
  ts->excludes(vs);
  cmd->add_option("--damping", ra.beam.damping, "Damping ratio of the sliding mass (default 0.05)")->needs(ky);
  cmd->add_option("--reference-strain", ra.curve.reference_strain,
                  "Equivalent-linear: reference strain of G/Gmax = 1 / (1 + gamma / gamma_ref) (e.g. 5e-4)")
      ->needs(height);
  cmd->add_option(
      "--damping-max", ra.curve.damping_max,
      "Equivalent-linear: damping at G/Gmax = 0 (default 0.25), xi = xi_min + (xi_max - xi_min)(1 - G/Gmax)");
  CLI::Option* magnitude =
      cmd->add_option("--magnitude", ra.magnitude, "Earthquake magnitude, for Bray and Travasarou (2007)")->needs(ky);
  cmd->callback([opt, &global, ky, dip, phi, ts, height, vs, magnitude] {
    if (*ky) {
      opt->records.has_magnitude = magnitude->count() > 0;
      opt->has_ts = ts->count() > 0;
      opt->has_height = height->count() > 0;
      opt->has_vs = vs->count() > 0;
      run_records(*opt, global);
      return;
    }
    opt->has_plane = dip->count() > 0 && phi->count() > 0;
    if (!opt->has_plane) throw InputError("newmark: give --dip and --phi (a plane), or --ky (records).");
    if (!(opt->in.ru >= 0.0 && opt->in.ru < 1.0))
      throw InputError("--ru must lie in [0, 1) (a pore-pressure ratio), got " + short_number(opt->in.ru) + ".");
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
