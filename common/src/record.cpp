#include "dda/common/record.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/text_input.hpp"

namespace dda {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

// Fields separated by commas, semicolons, blanks or tabs.
std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool had_comma = false;
  for (char c : line) {
    if (c == ',' || c == ';') {
      out.push_back(trim(cur));
      cur.clear();
      had_comma = true;
    } else if ((c == ' ' || c == '\t') && !had_comma) {
      if (!trim(cur).empty()) out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (had_comma || !trim(cur).empty()) out.push_back(trim(cur));
  return out;
}

// Parses a whole field as a number; false if it is not one.
bool parse_number(const std::string& field, double& value) {
  if (field.empty()) return false;
  const char* b = field.data();
  const char* e = b + field.size();
  if (*b == '+') ++b;
  const auto r = std::from_chars(b, e, value);
  return r.ec == std::errc() && r.ptr == e;
}

std::string read_text(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": file not found.");
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a folder, not a file.");
  return read_text_file(path, "record");
}

double unit_factor(AccelUnits u) { return u == AccelUnits::g ? kRecordGravity : 1.0; }

Eigen::Vector3d unit_direction(const RecordReadOptions& options, const std::string& name) {
  const double n = options.direction.norm();
  if (!(n > 0.0) || !std::isfinite(n))
    throw InputError(name + ": the direction of the one-component record is zero or not finite.");
  return options.direction / n;
}

void check_times(const std::vector<double>& t, const std::vector<std::size_t>& lines, const std::string& name,
                 bool uniform) {
  for (std::size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      throw InputError(name + ", line " + std::to_string(lines[i]) + ": time " + num(t[i]) +
                       " s is not greater than the previous time " + num(t[i - 1]) + " s (times must increase).");
  if (!uniform) return;
  const double first = t[1] - t[0];
  for (std::size_t i = 2; i < t.size(); ++i)
    if (std::abs(t[i] - t[i - 1] - first) > 1e-6 * first)
      throw InputError(name + ", line " + std::to_string(lines[i]) + ": time step " + num(t[i] - t[i - 1]) +
                       " s where the first step is " + num(first) + " s (the record must be uniformly sampled).");
}

// At least two samples; `line` is the line of the only sample, if any.
void check_sample_count(std::size_t samples, std::size_t line, const std::string& name) {
  if (samples == 0) throw InputError(name + ": no samples (the record is empty).");
  if (samples < 2)
    throw InputError(name + ", line " + std::to_string(line) + ": only one sample; a record needs at least two.");
}

}  // namespace

AccelUnits parse_accel_units(const std::string& text, const std::string& what) {
  const std::string s = lower(trim(text));
  if (s == "g") return AccelUnits::g;
  if (s == "m/s2" || s == "m/s^2" || s == "m/s/s" || s == "mps2") return AccelUnits::m_per_s2;
  throw InputError(what + ": unknown acceleration units '" + text + "' (use g or m/s2).");
}

Eigen::Vector3d AccelRecord::at(double time) const {
  if (t.empty() || time < t.front() || time > t.back()) return Eigen::Vector3d::Zero();
  const auto it = std::upper_bound(t.begin(), t.end(), time);
  std::size_t j = static_cast<std::size_t>(it - t.begin());
  if (j >= t.size()) j = t.size() - 1;
  const std::size_t i = j - 1;
  const double w = (time - t[i]) / (t[j] - t[i]);
  Eigen::Vector3d out;
  for (int c = 0; c < 3; ++c) out[c] = (1.0 - w) * a[c][i] + w * a[c][j];
  return out;
}

double AccelRecord::peak_magnitude() const {
  double peak = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i)
    peak = std::max(peak, std::sqrt(a[0][i] * a[0][i] + a[1][i] * a[1][i] + a[2][i] * a[2][i]));
  return peak;
}

AccelRecord parse_record_csv(const std::string& text, const std::string& name, const RecordReadOptions& options) {
  if (options.units == AccelUnits::unspecified)
    throw InputError(name + ": the units of the acceleration values are not given (g or m/s2).");
  const double factor = unit_factor(options.units);
  AccelRecord rec;
  rec.source = name;
  std::vector<std::size_t> lines;
  std::size_t columns = 0;
  bool seen_content = false;
  std::istringstream in(text);
  std::string line;
  std::size_t line_no = 0;
  Eigen::Vector3d dir = Eigen::Vector3d::UnitX();
  while (read_text_line(in, line, name, line_no + 1)) {
    ++line_no;
    const std::string tl = trim(line);
    if (tl.empty() || tl[0] == '#') continue;
    const std::vector<std::string> fields = split_fields(tl);
    double first = 0.0;
    if (!seen_content && !parse_number(fields[0], first)) {
      seen_content = true;  // header line
      continue;
    }
    seen_content = true;
    if (columns == 0) {
      columns = fields.size();
      if (columns < 2 || columns > 4)
        throw InputError(name + ", line " + std::to_string(line_no) + ": " + std::to_string(columns) +
                         " columns; a record has t, a (one component) or t, ax, ay[, az].");
      if (columns == 2) dir = unit_direction(options, name);
    } else if (fields.size() != columns) {
      throw InputError(name + ", line " + std::to_string(line_no) + ": " + std::to_string(fields.size()) +
                       " columns where the first data line has " + std::to_string(columns) + ".");
    }
    double v[4] = {0, 0, 0, 0};
    for (std::size_t c = 0; c < columns; ++c) {
      if (!parse_number(fields[c], v[c]))
        throw InputError(name + ", line " + std::to_string(line_no) + ", column " + std::to_string(c + 1) + ": '" +
                         fields[c] + "' is not a number.");
      if (!std::isfinite(v[c]))
        throw InputError(name + ", line " + std::to_string(line_no) + ", column " + std::to_string(c + 1) + ": '" +
                         fields[c] + "' is not a finite number.");
    }
    rec.t.push_back(v[0]);
    lines.push_back(line_no);
    if (columns == 2) {
      for (int c = 0; c < 3; ++c) rec.a[c].push_back(factor * v[1] * dir[c]);
    } else {
      for (int c = 0; c < 3; ++c) rec.a[c].push_back(c + 1 < static_cast<int>(columns) ? factor * v[c + 1] : 0.0);
    }
  }
  check_sample_count(rec.t.size(), lines.empty() ? 0 : lines.front(), name);
  check_times(rec.t, lines, name, options.require_uniform_step);
  return rec;
}

AccelRecord parse_record_at2(const std::string& text, const std::string& name, const RecordReadOptions& options) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> header;
  for (int i = 0; i < 4; ++i) {
    if (!read_text_line(in, line, name, static_cast<std::size_t>(i) + 1))
      throw InputError(name + ": the AT2 header is cut short (four lines expected, then the values).");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    header.push_back(line);
  }
  // Units declared in the header (third line in the NGA format).
  bool declares_g = false;
  for (int i = 0; i < 3; ++i) {
    const std::string h = lower(header[static_cast<std::size_t>(i)]);
    const auto p = h.find("units of ");
    if (p != std::string::npos) {
      const std::string u = trim(h.substr(p + 9));
      if (u == "g" || u.rfind("g ", 0) == 0) declares_g = true;
    }
  }
  AccelUnits units = options.units;
  if (declares_g && units == AccelUnits::m_per_s2)
    throw InputError(name + ": the AT2 header declares units of g, but m/s2 was asked for.");
  if (units == AccelUnits::unspecified) {
    if (!declares_g)
      throw InputError(name + ": the AT2 header does not declare units of g; give the units (g or m/s2).");
    units = AccelUnits::g;
  }
  // NPTS and DT: "NPTS=  3929, DT=   .0100 SEC" or "3929   .0100   NPTS, DT".
  const std::string h4 = lower(header[3]);
  long npts = -1;
  double dt = -1.0;
  const auto pn = h4.find("npts");
  const auto pd = h4.find("dt");
  auto number_after = [&](std::size_t pos) -> std::string {
    std::size_t i = h4.find('=', pos);
    if (i == std::string::npos) return "";
    ++i;
    while (i < h4.size() && std::isspace(static_cast<unsigned char>(h4[i]))) ++i;
    std::size_t j = i;
    while (j < h4.size() && (std::isdigit(static_cast<unsigned char>(h4[j])) || h4[j] == '.' || h4[j] == 'e' ||
                             h4[j] == '-' || h4[j] == '+'))
      ++j;
    return h4.substr(i, j - i);
  };
  // A count beyond any file the reader takes (1 GiB) is no count: kept out
  // of the conversion to long, whose result would be undefined.
  auto count = [](double v) { return v >= 0.0 && v <= static_cast<double>(kMaxTextFileBytes) ? static_cast<long>(v) : -1L; };
  if (pn != std::string::npos && pd != std::string::npos && h4.find('=', pn) != std::string::npos) {
    double v = 0;
    if (parse_number(number_after(pn), v)) npts = count(v);
    if (parse_number(number_after(pd), v)) dt = v;
  } else {
    const std::vector<std::string> f = split_fields(header[3]);
    double v = 0;
    if (f.size() >= 2 && parse_number(f[0], v)) npts = count(v);
    if (f.size() >= 2 && parse_number(f[1], v)) dt = v;
  }
  if (npts <= 0 || !(dt > 0.0) || !std::isfinite(dt))
    throw InputError(name + ", line 4: no valid NPTS and DT (expected e.g. 'NPTS=  3929, DT=   .0100 SEC').");
  if (npts < 2) throw InputError(name + ", line 4: NPTS= 1; a record needs at least two samples.");
  const Eigen::Vector3d dir = unit_direction(options, name);
  const double factor = unit_factor(units);
  AccelRecord rec;
  rec.source = name;
  std::size_t line_no = 4;
  while (read_text_line(in, line, name, line_no + 1)) {
    ++line_no;
    std::istringstream ls(line);
    std::string field;
    while (ls >> field) {
      double v = 0;
      if (!parse_number(field, v))
        throw InputError(name + ", line " + std::to_string(line_no) + ": '" + field + "' is not a number.");
      if (!std::isfinite(v))
        throw InputError(name + ", line " + std::to_string(line_no) + ": '" + field + "' is not a finite number.");
      if (static_cast<long>(rec.t.size()) >= npts)
        throw InputError(name + ", line " + std::to_string(line_no) + ": more values than NPTS= " +
                         std::to_string(npts) + ".");
      rec.t.push_back(static_cast<double>(rec.t.size()) * dt);
      for (int c = 0; c < 3; ++c) rec.a[c].push_back(factor * v * dir[c]);
    }
  }
  if (rec.t.empty()) throw InputError(name + ": no samples (the record is empty).");
  if (static_cast<long>(rec.t.size()) != npts)
    throw InputError(name + ": " + std::to_string(rec.t.size()) + " values where the header says NPTS= " +
                     std::to_string(npts) + ".");
  return rec;
}

AccelRecord parse_record_values(const std::string& text, const std::string& name, const RecordReadOptions& options) {
  if (!(options.sample_step > 0.0) || !std::isfinite(options.sample_step))
    throw InputError(name + ": a file of values only needs a positive sample step.");
  if (options.units == AccelUnits::unspecified)
    throw InputError(name + ": the units of the acceleration values are not given (g or m/s2).");
  const double factor = unit_factor(options.units);
  const Eigen::Vector3d dir = unit_direction(options, name);
  AccelRecord rec;
  rec.source = name;
  std::istringstream in(text);
  std::string line;
  std::size_t line_no = 0, first_line = 0;
  while (read_text_line(in, line, name, line_no + 1)) {
    ++line_no;
    const std::string tl = trim(line);
    if (tl.empty() || tl[0] == '#') continue;
    double v = 0.0;
    if (!parse_number(tl, v))
      throw InputError(name + ", line " + std::to_string(line_no) + ": '" + tl +
                       "' is not a number (a file of values holds one acceleration per line).");
    if (!std::isfinite(v))
      throw InputError(name + ", line " + std::to_string(line_no) + ": '" + tl + "' is not a finite number.");
    if (first_line == 0) first_line = line_no;
    rec.t.push_back(static_cast<double>(rec.t.size()) * options.sample_step);
    for (int c = 0; c < 3; ++c) rec.a[c].push_back(factor * v * dir[c]);
  }
  check_sample_count(rec.t.size(), first_line, name);
  return rec;
}

AccelRecord read_record_csv(const std::string& path, const RecordReadOptions& options) {
  return parse_record_csv(read_text(path), path, options);
}

AccelRecord read_record_at2(const std::string& path, const RecordReadOptions& options) {
  return parse_record_at2(read_text(path), path, options);
}

AccelRecord read_record(const std::string& path, const RecordReadOptions& options) {
  if (options.sample_step > 0.0) return parse_record_values(read_text(path), path, options);
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  return ext == ".at2" ? read_record_at2(path, options) : read_record_csv(path, options);
}

void write_record_csv(const AccelRecord& record, const std::string& path) {
  std::ostringstream s;
  s.precision(12);
  s << "t,ax,ay,az\n";
  for (std::size_t i = 0; i < record.size(); ++i)
    s << record.t[i] << ',' << record.a[0][i] << ',' << record.a[1][i] << ',' << record.a[2][i] << '\n';
  write_text_atomically(path, s.str());
}

void scale_record(AccelRecord& record, double factor) {
  if (!std::isfinite(factor)) throw InputError("The scale factor of record " + record.source + " is not finite.");
  for (auto& comp : record.a)
    for (double& v : comp) v *= factor;
}

AccelRecord resample_record(const AccelRecord& record, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw InputError("Resampling record " + record.source + ": the step " + num(dt) + " s is not positive.");
  if (record.size() < 2) throw InputError("Resampling record " + record.source + ": fewer than two samples.");
  AccelRecord out;
  out.source = record.source;
  const double t0 = record.t.front();
  const std::size_t n = static_cast<std::size_t>(std::floor(record.duration() / dt * (1.0 + 1e-12))) + 1;
  std::size_t j = 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double time = std::min(t0 + static_cast<double>(i) * dt, record.t.back());
    while (j + 1 < record.size() && record.t[j] < time) ++j;
    const double w = (time - record.t[j - 1]) / (record.t[j] - record.t[j - 1]);
    out.t.push_back(t0 + static_cast<double>(i) * dt);
    for (int c = 0; c < 3; ++c) out.a[c].push_back((1.0 - w) * record.a[c][j - 1] + w * record.a[c][j]);
  }
  return out;
}

void ramp_record(AccelRecord& record, double ramp_seconds) {
  if (!(ramp_seconds >= 0.0) || !std::isfinite(ramp_seconds))
    throw InputError("The ramp-up time " + num(ramp_seconds) + " s of record " + record.source +
                     " must be zero or positive.");
  if (ramp_seconds == 0.0 || record.t.empty()) return;
  const double t0 = record.t.front();
  for (std::size_t i = 0; i < record.size(); ++i) {
    const double w = std::min(1.0, (record.t[i] - t0) / ramp_seconds);
    for (auto& comp : record.a) comp[i] *= w;
  }
}

double uniform_step(const AccelRecord& record, const std::string& what) {
  if (record.size() < 2) throw InputError(what + ": record " + record.source + " has fewer than two samples.");
  const double dt = record.duration() / static_cast<double>(record.size() - 1);
  for (std::size_t i = 1; i < record.size(); ++i)
    if (std::abs(record.t[i] - record.t[i - 1] - dt) > 1e-6 * dt)
      throw InputError(what + ": record " + record.source + " is not uniformly sampled near t = " +
                       num(record.t[i]) + " s (resample it first).");
  return dt;
}

void filter_record(AccelRecord& record, const ButterworthSpec& spec) {
  const double dt = uniform_step(record, "Filtering");
  for (auto& comp : record.a) comp = zero_phase_filter(comp, dt, spec);
}

IntegratedRecord integrate_record(const AccelRecord& record, int baseline_degree) {
  if (record.size() < 2) throw InputError("Integrating record " + record.source + ": fewer than two samples.");
  if (baseline_degree > 8)
    throw InputError("Baseline correction degree " + std::to_string(baseline_degree) + " is above the maximum of 8.");
  IntegratedRecord out;
  out.t = record.t;
  const std::size_t n = record.size();
  for (int c = 0; c < 3; ++c) {
    out.a[c] = record.a[c];
    out.v[c].assign(n, 0.0);
    out.d[c].assign(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) {
      const double h = record.t[i] - record.t[i - 1];
      out.v[c][i] = out.v[c][i - 1] + 0.5 * h * (out.a[c][i - 1] + out.a[c][i]);
      out.d[c][i] = out.d[c][i - 1] + 0.5 * h * (out.v[c][i - 1] + out.v[c][i]);
    }
  }
  if (baseline_degree < 2) return out;
  // Least squares on the scaled time x = tau / T for conditioning.
  const double t0 = record.t.front();
  const double T = record.duration();
  const int terms = baseline_degree - 1;  // powers 2..degree
  Eigen::MatrixXd A(static_cast<Eigen::Index>(n), terms);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = (record.t[i] - t0) / T;
    for (int k = 0; k < terms; ++k) A(static_cast<Eigen::Index>(i), k) = std::pow(x, k + 2);
  }
  const auto qr = A.colPivHouseholderQr();
  for (int c = 0; c < 3; ++c) {
    Eigen::VectorXd b = Eigen::Map<const Eigen::VectorXd>(out.d[c].data(), static_cast<Eigen::Index>(n));
    const Eigen::VectorXd coef = qr.solve(b);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = (record.t[i] - t0) / T;
      double p = 0, dp = 0, ddp = 0;
      for (int k = 0; k < terms; ++k) {
        const int e = k + 2;
        p += coef[k] * std::pow(x, e);
        dp += coef[k] * e * std::pow(x, e - 1) / T;
        ddp += coef[k] * e * (e - 1) * std::pow(x, e - 2) / (T * T);
      }
      out.d[c][i] -= p;
      out.v[c][i] -= dp;
      out.a[c][i] -= ddp;
    }
  }
  return out;
}

}  // namespace dda

namespace dda {

void process_record(AccelRecord& rec, const RecordProcessing& p) {
  for (std::size_t c = 0; c < 3; ++c)
    if (!p.use[c]) std::fill(rec.a[c].begin(), rec.a[c].end(), 0.0);
  scale_record(rec, p.scale);
  if (p.resample > 0) rec = resample_record(rec, p.resample);
  if (p.filter) filter_record(rec, *p.filter);
  ramp_record(rec, p.ramp);
  if (p.baseline >= 2) rec.a = integrate_record(rec, p.baseline).a;
}

}  // namespace dda
