// dda record FILE --units g|m/s2 [processing ...] [-o out.csv] [--integrate [--baseline N]] [--husid H.csv] [--json]
//
// Inspect, process (scale, resample, filter, ramp) and integrate an
// acceleration record, and give its intensity measures (docs/analytical.md).
#include <cmath>
#include <iostream>

#include "analysis_options.hpp"
#include "commands.hpp"
#include "dda/analysis/intensity_measures.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/output_guard.hpp"
#include "pipeline.hpp"

namespace dda::cli {

namespace {

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

bool all_zero(const std::vector<double>& v) {
  for (double x : v)
    if (x != 0.0) return false;
  return true;
}

nlohmann::json intensity_json(const analysis::IntensityMeasures& m) {
  return {{"pga", m.pga},
          {"pga_g", m.pga / kRecordGravity},
          {"pgv", m.pgv},
          {"pgd", m.pgd},
          {"arias_intensity", m.arias},
          {"t5", m.t5},
          {"t95", m.t95},
          {"significant_duration_5_95", m.significant_duration},
          {"mean_period", m.mean_period},
          {"predominant_period", m.predominant_period}};
}

}  // namespace

void add_record_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    RecordOptions record;
    std::string output, husid;
    bool integrate = false;
    int baseline = 3;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "record",
      "Inspect and process an acceleration record: scale, resample, zero-phase Butterworth filter, ramp-up (in that "
      "order), and integrate to velocity and displacement with a baseline correction. Axes x east, y north, z up; "
      "output in m/s^2, m/s, m. Intensity measures of each non-zero component: PGA, PGV, PGD, Arias intensity, "
      "5-95 % significant duration, mean period (Rathje et al.) and predominant period (peak of the 5 %-damped "
      "PSA); the record must be uniformly sampled (or resampled).");
  add_record_options(cmd, opt->record, true);
  cmd->add_option("-o,--output", opt->output,
                  "Write the processed record as CSV t, ax, ay, az (+ vx, vy, vz, dx, dy, dz with --integrate)");
  cmd->add_flag("--integrate", opt->integrate, "Integrate to velocity and displacement (trapezoidal, from rest)");
  cmd->add_option("--baseline", opt->baseline,
                  "Baseline correction: remove the least-squares polynomial c2 t^2 + ... + cN t^N from the "
                  "displacement (and its derivatives from v, a); N (default 3), below 2 for none");
  cmd->add_option("--husid", opt->husid,
                  "Write the Husid plot (normalised cumulative Arias intensity) as CSV t, husid_x, husid_y, husid_z");
  cmd->add_flag("--json", opt->json,
                "Print a JSON summary (samples, duration, step, peaks, intensity measures, final v and d)");
  cmd->callback([opt, &global] {
    refuse_overwriting_inputs({opt->record.path}, {opt->output, opt->husid});
    const AccelRecord rec = load_record(opt->record, true);
    const double dt = uniform_step(rec, "Intensity measures");
    nlohmann::json j;
    j["source"] = rec.source;
    j["samples"] = rec.size();
    j["start"] = rec.t.front();
    j["duration"] = rec.duration();
    j["mean_step"] = rec.duration() / static_cast<double>(rec.size() - 1);
    nlohmann::json peaks = nlohmann::json::array();
    for (int c = 0; c < 3; ++c) {
      double p = 0;
      for (double v : rec.a[static_cast<std::size_t>(c)]) p = std::max(p, std::abs(v));
      peaks.push_back(p);
    }
    j["peak_acceleration"] = peaks;
    j["peak_acceleration_magnitude"] = rec.peak_magnitude();
    nlohmann::json ims = nlohmann::json::object();
    std::ostringstream im_text;
    for (std::size_t c = 0; c < 3; ++c) {
      if (all_zero(rec.a[c])) continue;
      const analysis::IntensityMeasures m = analysis::intensity_measures(rec.a[c], dt);
      ims[kAxisNames[c]] = intensity_json(m);
      im_text << "  " << kAxisNames[c] << ": PGA " << m.pga / kRecordGravity << " g, PGV " << m.pgv << " m/s, PGD "
              << m.pgd << " m, Arias " << m.arias << " m/s, D5-95 " << m.significant_duration << " s, Tm "
              << m.mean_period << " s, Tp " << m.predominant_period << " s\n";
    }
    j["intensity_measures"] = ims;
    if (!opt->husid.empty()) {
      std::array<std::vector<double>, 3> h;
      for (std::size_t c = 0; c < 3; ++c) h[c] = analysis::husid(rec.a[c], dt);
      std::string out = "t,husid_x,husid_y,husid_z\n";
      for (std::size_t i = 0; i < rec.size(); ++i) {
        put_number(out, rec.t[i]);
        for (std::size_t c = 0; c < 3; ++c) {
          out += ',';
          put_number(out, h[c][i]);
        }
        out += '\n';
      }
      write_text_atomically(opt->husid, out);
    }
    std::string csv;
    if (opt->integrate) {
      const IntegratedRecord m = integrate_record(rec, opt->baseline);
      j["final_velocity"] = {m.v[0].back(), m.v[1].back(), m.v[2].back()};
      j["final_displacement"] = {m.d[0].back(), m.d[1].back(), m.d[2].back()};
      j["baseline_degree"] = opt->baseline;
      if (!opt->output.empty()) {
        csv = "t,ax,ay,az,vx,vy,vz,dx,dy,dz\n";
        for (std::size_t i = 0; i < m.t.size(); ++i) {
          put_number(csv, m.t[i]);
          for (const auto* series : {&m.a, &m.v, &m.d})
            for (int c = 0; c < 3; ++c) {
              csv += ',';
              put_number(csv, (*series)[static_cast<std::size_t>(c)][i]);
            }
          csv += '\n';
        }
      }
    } else if (!opt->output.empty()) {
      csv = "t,ax,ay,az\n";
      for (std::size_t i = 0; i < rec.size(); ++i) {
        put_number(csv, rec.t[i]);
        for (int c = 0; c < 3; ++c) {
          csv += ',';
          put_number(csv, rec.a[static_cast<std::size_t>(c)][i]);
        }
        csv += '\n';
      }
    }
    if (!opt->output.empty()) write_text_atomically(opt->output, csv);
    if (opt->json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::ostringstream s;
      s << "record " << rec.source << ": " << rec.size() << " samples over " << rec.duration()
        << " s, peak |a| = " << rec.peak_magnitude() << " m/s^2\n"
        << im_text.str();
      say(global.quiet, s.str());
    }
  });
}

}  // namespace dda::cli
