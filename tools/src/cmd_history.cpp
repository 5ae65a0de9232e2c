// dda history results.h5 [--csv] [--point NAME ...] [--steps] [--bolts] [-o FILE]
//
// The measurement-point time series of a results file, 2D or 3D, as a
// summary or as CSV (one row per sample, sample 0 being the start of the run).
#include <charconv>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/common/coordinate_range.hpp"
#include "dda/common/error.hpp"
#include "dda/common/model_io.hpp"
#include "dda/common/output_guard.hpp"
#include "dda/df/io/results.hpp"
#include "dda/df/io/results3d.hpp"
#include "bolt_history.hpp"
#include "results_points.hpp"

namespace dda::cli {

namespace {

constexpr const char* kColumnsHelp =
    "CSV columns: t (s), then for each point NAME: NAME.x NAME.y (current position, m), NAME.ux NAME.uy "
    "(displacement from the start of the run, m), NAME.vx NAME.vy (velocity, m/s), NAME.sxx NAME.syy NAME.sxy "
    "(stress of the block the point lies in, Pa, tension positive); with --acceleration also NAME.ax NAME.ay "
    "after each point's columns (acceleration during the step that ended at the sample, m/s^2). With --steps: step, t, dt, iterations, "
    "dt_cuts, converged, open, sliding, locked, max_displacement, kinetic_energy, elastic_energy. "
    "A 3D results file: t, then NAME.x NAME.y NAME.z NAME.ux NAME.uy NAME.uz NAME.vx NAME.vy NAME.vz NAME.sxx "
    "NAME.syy NAME.szz NAME.syz NAME.szx NAME.sxy; with --steps: step, t, dt, iterations, dt_cuts, converged, open, "
    "sliding, locked, max_displacement. With --bolts (2D or 3D): t, then NAME.force (N, tension positive; 2D per unit "
    "thickness), NAME.length (m), NAME.broken (0 or 1) of every rock bolt.";

void put(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

std::string points_csv(const df::Results& r, const std::vector<std::size_t>& which, bool acceleration) {
  std::string out = "t";
  for (std::size_t p : which) {
    for (const char* c : {"x", "y", "ux", "uy", "vx", "vy", "sxx", "syy", "sxy"}) out += "," + r.point_names[p] + "." + c;
    if (acceleration)
      for (const char* c : {"ax", "ay"}) out += "," + r.point_names[p] + "." + c;
  }
  out += "\n";
  if (r.histories.empty()) {  // no measurement points: just the times
    put(out, r.log.empty() ? 0.0 : r.log.front().time - r.log.front().dt);
    out += "\n";
    for (const df::StepRecord& st : r.log) {
      put(out, st.time);
      out += "\n";
    }
    return out;
  }
  const std::size_t ns = r.histories[0].size();
  for (std::size_t s = 0; s < ns; ++s) {
    put(out, r.histories[0][s].time);
    for (std::size_t p : which) {
      const df::MeasurementSample& m = r.histories[p][s];
      // The file holds positions about the model's local origin; the user reads their own coordinates.
      const Vec2 x = user_position(m.position, r.blocks.origin);
      for (double v : {x.x(), x.y(), m.displacement.x(), m.displacement.y(), m.velocity.x(),
                       m.velocity.y(), m.stress[0], m.stress[1], m.stress[2]}) {
        out += ',';
        put(out, v);
      }
      if (acceleration)
        for (double v : {m.acceleration.x(), m.acceleration.y()}) {
          out += ',';
          put(out, v);
        }
    }
    out += "\n";
  }
  return out;
}

std::string steps_csv(const df::Results& r) {
  std::string out =
      "step,t,dt,iterations,dt_cuts,converged,open,sliding,locked,max_displacement,kinetic_energy,elastic_energy\n";
  for (const df::StepRecord& s : r.log) {
    out += std::to_string(s.step) + ",";
    put(out, s.time);
    out += ",";
    put(out, s.dt);
    out += "," + std::to_string(s.open_close_iterations) + "," + std::to_string(s.dt_cuts) + "," +
           std::to_string(s.converged ? 1 : 0) + "," + std::to_string(s.open) + "," + std::to_string(s.sliding) +
           "," + std::to_string(s.locked) + ",";
    put(out, s.max_displacement);
    out += ",";
    put(out, s.kinetic_energy);
    out += ",";
    put(out, s.elastic_energy);
    out += "\n";
  }
  return out;
}

std::string summary(const df::Results& r, const std::string& path, const std::vector<std::size_t>& which) {
  std::ostringstream s;
  const double t = r.log.empty() ? 0 : r.log.back().time;
  s << path << ": " << r.log.size() << " steps to t = " << t << " s" << (r.complete ? "" : " (not complete)") << ", "
    << r.point_names.size() << " measurement points\n";
  if (which.empty()) return s.str();
  s << "point            block        ux (m)        uy (m)     |u|max (m)\n";
  for (std::size_t p : which) {
    const auto& h = r.histories[p];
    double umax = 0;
    for (const df::MeasurementSample& m : h) umax = std::max(umax, m.displacement.norm());
    char line[160];
    std::snprintf(line, sizeof line, "%-14s %7d %13.6g %13.6g %13.6g\n", r.point_names[p].c_str(), r.point_blocks[p],
                  h.back().displacement.x(), h.back().displacement.y(), umax);
    s << line;
  }
  return s.str();
}

// ----------------------------------------------------------------- 3D

void put_all(std::string& out, std::initializer_list<double> values) {
  for (const double v : values) {
    out += ',';
    put(out, v);
  }
}

std::string points_csv3(const df3::Results3& r, const std::vector<std::size_t>& which) {
  std::string out = "t";
  for (std::size_t p : which)
    for (const char* c : {"x", "y", "z", "ux", "uy", "uz", "vx", "vy", "vz", "sxx", "syy", "szz", "syz", "szx", "sxy"})
      out += "," + r.point_names[p] + "." + c;
  out += "\n";
  if (r.histories.empty()) {  // no measurement points: just the times
    put(out, r.log.empty() ? 0.0 : r.log.front().time - r.log.front().dt);
    out += "\n";
    for (const df3::StepRecord3& st : r.log) {
      put(out, st.time);
      out += "\n";
    }
    return out;
  }
  for (std::size_t s = 0; s < r.histories[0].size(); ++s) {
    put(out, r.histories[0][s].time);
    for (std::size_t p : which) {
      const df3::MeasurementSample3& m = r.histories[p][s];
      const Vec3 x = user_position(m.position, r.blocks.origin);  // the user's coordinates, as in 2D
      const Vec3 &u = m.displacement, &v = m.velocity;
      put_all(out, {x.x(), x.y(), x.z(), u.x(), u.y(), u.z(), v.x(), v.y(), v.z()});
      put_all(out, {m.stress[0], m.stress[1], m.stress[2], m.stress[3], m.stress[4], m.stress[5]});
    }
    out += "\n";
  }
  return out;
}

std::string steps_csv3(const df3::Results3& r) {
  std::string out = "step,t,dt,iterations,dt_cuts,converged,open,sliding,locked,max_displacement\n";
  for (const df3::StepRecord3& s : r.log) {
    out += std::to_string(s.step);
    put_all(out, {s.time, s.dt});
    out += "," + std::to_string(s.iterations) + "," + std::to_string(s.dt_cuts) + "," +
           std::to_string(s.converged ? 1 : 0) + "," + std::to_string(s.open) + "," + std::to_string(s.sliding) + "," +
           std::to_string(s.locked);
    put_all(out, {s.max_displacement});
    out += "\n";
  }
  return out;
}

std::string summary3(const df3::Results3& r, const std::string& path, const std::vector<std::size_t>& which) {
  std::ostringstream s;
  const double t = r.log.empty() ? 0 : r.log.back().time;
  s << path << ": " << r.log.size() << " steps to t = " << t << " s" << (r.complete ? "" : " (not complete)") << ", "
    << r.point_names.size() << " measurement points (3D)\n";
  if (which.empty()) return s.str();
  s << "point            block        ux (m)        uy (m)        uz (m)     |u|max (m)\n";
  for (std::size_t p : which) {
    const auto& h = r.histories[p];
    double umax = 0;
    for (const df3::MeasurementSample3& m : h) umax = std::max(umax, m.displacement.norm());
    char line[200];
    const Vec3& u = h.back().displacement;
    std::snprintf(line, sizeof line, "%-14s %7d %13.6g %13.6g %13.6g %13.6g\n", r.point_names[p].c_str(),
                  r.point_blocks[p], u.x(), u.y(), u.z(), umax);
    s << line;
  }
  return s.str();
}

}  // namespace

void add_history_command(CLI::App& app, const GlobalOptions&) {
  struct Options {
    std::string input, output;
    std::vector<std::string> points;
    bool csv = false, steps = false, acceleration = false, bolts = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("history", "Time series of the measurement points of a results file");
  cmd->footer(kColumnsHelp);
  cmd->add_option("results", opt->input, "Results file written by `dda df` or `dda run`")->required();
  cmd->add_flag("--csv", opt->csv, "Print the series as CSV (one row per sample; see the columns below)");
  cmd->add_option("--point", opt->points, "Only these measurement points (repeat or list several)");
  cmd->add_flag("--acceleration", opt->acceleration,
                "With --csv: add NAME.ax NAME.ay (the acceleration of each point during each step)");
  cmd->add_flag("--steps", opt->steps, "Print the per-step statistics as CSV instead");
  cmd->add_flag("--bolts", opt->bolts, "Print the rock bolts' forces, lengths and breakage as CSV instead");
  cmd->add_option("-o,--output", opt->output, "Write to this file instead of the standard output");
  cmd->callback([opt] {
    refuse_overwriting_inputs({opt->input}, {opt->output});
    auto emit = [&opt](const std::string& text) {
      if (opt->output.empty())
        std::cout << text << std::flush;
      else
        write_text_atomically(opt->output, text);
    };
    if (h5_format_of(opt->input) == df3::kResults3dFormat) {
      const df3::Results3 r = df3::read_results3_h5(opt->input, df::ResultsParts::records());
      if (opt->acceleration)
        throw InputError(opt->input + ": a 3D results file holds no accelerations (--acceleration is for 2D runs).");
      std::vector<std::size_t> which;
      for (const std::string& name : opt->points) which.push_back(measurement_point_index(r.point_names, name, opt->input));
      if (opt->points.empty())
        for (std::size_t k = 0; k < r.point_names.size(); ++k) which.push_back(k);
      emit(opt->bolts   ? bolts_csv(r.bolt_names, r.bolt_histories)
           : opt->steps ? steps_csv3(r)
           : opt->csv   ? points_csv3(r, which)
                        : summary3(r, opt->input, which) + bolt_summary(r.bolt_names, r.bolt_histories));
      return;
    }
    const df::Results r = df::read_results_h5(opt->input, df::ResultsParts::records());
    if (opt->acceleration && !r.has_acceleration)
      throw InputError(opt->input + ": holds no accelerations (it was written by an older dda); run it again.");
    std::vector<std::size_t> which;
    for (const std::string& name : opt->points) which.push_back(measurement_point_index(r, name, opt->input));
    if (opt->points.empty())
      for (std::size_t k = 0; k < r.point_names.size(); ++k) which.push_back(k);
    std::string text;
    if (opt->bolts)
      text = bolts_csv(r.bolt_names, r.bolt_histories);
    else if (opt->steps)
      text = steps_csv(r);
    else if (opt->csv)
      text = points_csv(r, which, opt->acceleration);
    else
      text = summary(r, opt->input, which) + bolt_summary(r.bolt_names, r.bolt_histories);
    emit(text);
  });
}

}  // namespace dda::cli
