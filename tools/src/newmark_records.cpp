// Newmark analyses of a series of records (newmark_records.hpp).
#include "newmark_records.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <sstream>
#include <thread>

#include "dda/analysis/coupled_sliding.hpp"
#include "dda/analysis/displacement_regressions.hpp"
#include "dda/analysis/response_spectrum.hpp"
#include "dda/analysis/rigid_sliding.hpp"
#include "dda/common/error.hpp"
#include "dda/common/record.hpp"

namespace dda::cli {

namespace {

constexpr double kG = kRecordGravity;

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) out.push_back(item);
  return out;
}

RecordResult analyse_one(const std::string& path, const RecordOptions& options, const RecordsAnalysis& an) {
  const AccelRecord rec = load_record(options, path, true);
  RecordResult r;
  r.path = path;
  r.samples = rec.size();
  r.dt = uniform_step(rec, "Newmark (" + path + ")");
  const analysis::Vec3 dir = parse_axis(options.axis, "--axis");
  std::vector<double> a(rec.size());
  for (std::size_t i = 0; i < rec.size(); ++i)
    a[i] = rec.a[0][i] * dir.x() + rec.a[1][i] * dir.y() + rec.a[2][i] * dir.z();
  r.im = analysis::intensity_measures(a, r.dt);
  r.beam = an.beam;
  if ((an.decoupled || an.coupled) && an.curve.reference_strain > 0.0) {
    const analysis::EquivalentLinearResult el = analysis::equivalent_linear(a, r.dt, an.beam, an.height, an.curve);
    if (!el.converged)
      throw InputError(path + ": the equivalent-linear properties did not converge in " +
                       std::to_string(el.iterations) + " iterations.");
    r.beam = el.beam;
    r.modulus_ratio = el.modulus_ratio;
    r.effective_strain = el.effective_strain;
  }
  // Bray and Travasarou's Sa(1.5 Ts), Ts the small-strain period; the PGA below 0.05 s.
  if (an.has_magnitude)
    r.sa_bt =
        an.beam.period < 0.05 ? r.im.pga : analysis::response_spectrum(a, r.dt, {1.5 * an.beam.period}).psa.front();
  const double ay = an.ky * kG;
  for (int sign : {1, -1}) {
    if ((sign > 0 && !an.normal) || (sign < 0 && !an.inverse)) continue;
    std::vector<double> signed_a = a;
    if (sign < 0)
      for (double& x : signed_a) x = -x;
    PolarityResult p;
    p.polarity = sign > 0 ? "normal" : "inverse";
    if (an.rigid) p.rigid = analysis::rigid_sliding(signed_a, r.dt, ay).displacement;
    if (an.decoupled) {
      const std::vector<double> hea = analysis::average_acceleration(signed_a, r.dt, r.beam);
      for (double x : hea) p.kmax = std::max(p.kmax, std::abs(x) / kG);
      p.decoupled = analysis::rigid_sliding(hea, r.dt, ay).displacement;
    }
    if (an.coupled) p.coupled = analysis::coupled_sliding(signed_a, r.dt, ay, r.beam).displacement;
    r.polarities.push_back(p);
  }
  return r;
}

void put(std::string& out, double v) {
  out += ',';
  if (std::isnan(v)) return;  // an empty field: the regression does not apply
  put_number(out, v);
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

void parse_methods(const std::string& text, RecordsAnalysis& a) {
  a.rigid = a.decoupled = a.coupled = false;
  for (const std::string& m : split_list(text)) {
    if (m == "rigid")
      a.rigid = true;
    else if (m == "decoupled")
      a.decoupled = true;
    else if (m == "coupled")
      a.coupled = true;
    else if (m == "all")
      a.rigid = a.decoupled = a.coupled = true;
    else
      throw InputError("--method: '" + m + "' is not rigid, decoupled, coupled or all.");
  }
  if (!a.rigid && !a.decoupled && !a.coupled) throw InputError("--method: give at least one method.");
}

void parse_polarity(const std::string& text, RecordsAnalysis& a) {
  a.normal = text == "normal" || text == "both";
  a.inverse = text == "inverse" || text == "both";
  if (!a.normal && !a.inverse) throw InputError("--polarity: '" + text + "' is not normal, inverse or both.");
}

std::vector<std::string> expand_record_paths(const std::vector<std::string>& args) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  for (const std::string& arg : args) {
    std::error_code ec;
    if (!fs::is_directory(arg, ec)) {
      if (!fs::exists(arg, ec)) throw InputError(arg + ": file not found.");
      out.push_back(arg);
      continue;
    }
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(arg, ec)) {
      const std::string name = e.path().filename().string();
      if (!name.empty() && name[0] != '.' && e.is_regular_file()) files.push_back(e.path().string());
    }
    if (ec) throw InputError(arg + ": cannot list the folder.");
    if (files.empty()) throw InputError(arg + ": no record files in the folder.");
    std::sort(files.begin(), files.end());
    out.insert(out.end(), files.begin(), files.end());
  }
  return out;
}

std::vector<RecordResult> analyse_records(const std::vector<std::string>& paths, const RecordOptions& record,
                                          const RecordsAnalysis& analysis) {
  std::vector<RecordResult> results(paths.size());
  std::vector<std::exception_ptr> errors(paths.size());
  const std::size_t workers =
      std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, std::max<std::size_t>(paths.size(), 1));
  // Record k goes to worker k mod workers: the records are alike in size.
  auto work = [&](std::size_t first) {
    for (std::size_t k = first; k < paths.size(); k += workers) {
      try {
        results[k] = analyse_one(paths[k], record, analysis);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t w = 1; w < workers; ++w) threads.emplace_back(work, w);
  work(0);
  for (auto& t : threads) t.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  return results;
}

std::string records_table_csv(const std::vector<RecordResult>& results, const RecordsAnalysis& an) {
  const bool flexible = an.decoupled || an.coupled;
  std::string csv = "record,polarity,ky,pga_g,pgv_cm_s,pgd_cm,arias_m_s,d5_95_s,mean_period_s,predominant_period_s";
  if (flexible) csv += ",ts_s,damping,modulus_ratio";
  if (an.decoupled) csv += ",kmax_g";
  if (an.rigid) csv += ",rigid_cm";
  if (an.decoupled) csv += ",decoupled_cm";
  if (an.coupled) csv += ",coupled_cm";
  csv += ",jibson2007_ratio_cm,jibson2007_arias_cm,jibson2007_arias_ratio_cm,saygili_rathje2008_cm";
  if (an.has_magnitude) csv += ",sa_1_5ts_g,bray_travasarou2007_cm,bray_travasarou2007_p_zero";
  csv += '\n';
  for (const RecordResult& r : results) {
    const double pga = r.im.pga / kG, pgv = 100.0 * r.im.pgv;
    for (const PolarityResult& p : r.polarities) {
      csv += csv_field(r.path) + ',' + p.polarity;
      for (double v : {an.ky, pga, pgv, 100.0 * r.im.pgd, r.im.arias, r.im.significant_duration, r.im.mean_period,
                       r.im.predominant_period})
        put(csv, v);
      if (flexible) {
        put(csv, r.beam.period);
        put(csv, r.beam.damping);
        put(csv, r.modulus_ratio);
      }
      if (an.decoupled) put(csv, p.kmax);
      if (an.rigid) put(csv, 100.0 * p.rigid);
      if (an.decoupled) put(csv, 100.0 * p.decoupled);
      if (an.coupled) put(csv, 100.0 * p.coupled);
      put(csv, analysis::jibson2007_ratio(an.ky, pga).median_cm);
      put(csv, analysis::jibson2007_arias(an.ky, r.im.arias).median_cm);
      put(csv, analysis::jibson2007_arias_ratio(an.ky, pga, r.im.arias).median_cm);
      put(csv, analysis::saygili_rathje2008(an.ky, pga, pgv).median_cm);
      if (an.has_magnitude) {
        const double ts = an.beam.period;
        put(csv, r.sa_bt / kG);
        put(csv, analysis::bray_travasarou2007(an.ky, r.sa_bt / kG, ts, an.magnitude).median_cm);
        put(csv, analysis::probability_zero_bt2007(an.ky, r.sa_bt / kG, ts));
      }
      csv += '\n';
    }
  }
  return csv;
}

}  // namespace dda::cli
