// dda record FILE --units g|m/s2 [processing ...] [-o out.csv] [--integrate [--baseline N]] [--json]
//
// Inspect, process (scale, resample, filter, ramp) and integrate an
// acceleration record (docs/analytical.md).
#include <cmath>
#include <iostream>

#include "analysis_options.hpp"
#include "commands.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/output_guard.hpp"
#include "pipeline.hpp"

namespace dda::cli {

void add_record_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    RecordOptions record;
    std::string output;
    bool integrate = false;
    int baseline = 3;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "record",
      "Inspect and process an acceleration record: scale, resample, zero-phase Butterworth filter, ramp-up (in that "
      "order), and integrate to velocity and displacement with a baseline correction. Axes x east, y north, z up; "
      "output in m/s^2, m/s, m.");
  add_record_options(cmd, opt->record, true);
  cmd->add_option("-o,--output", opt->output,
                  "Write the processed record as CSV t, ax, ay, az (+ vx, vy, vz, dx, dy, dz with --integrate)");
  cmd->add_flag("--integrate", opt->integrate, "Integrate to velocity and displacement (trapezoidal, from rest)");
  cmd->add_option("--baseline", opt->baseline,
                  "Baseline correction: remove the least-squares polynomial c2 t^2 + ... + cN t^N from the "
                  "displacement (and its derivatives from v, a); N (default 3), below 2 for none");
  cmd->add_flag("--json", opt->json, "Print a JSON summary (samples, duration, step, peaks, final v and d)");
  cmd->callback([opt, &global] {
    refuse_overwriting_inputs({opt->record.path}, {opt->output});
    const AccelRecord rec = load_record(opt->record);
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
        << " s, peak |a| = " << rec.peak_magnitude() << " m/s^2\n";
      say(global.quiet, s.str());
    }
  });
}

}  // namespace dda::cli
