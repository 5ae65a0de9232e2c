// dda spectra INPUT [--point NAME | --column NAME] [--component C] [--quantity Q]
//             [--reference NAME | --hv | --response [--periods P] [--damping Z] [--at T,...]]
//             [--dt S] [--smooth B] [--points N] [--taper T] [--detrend] [--amplitude fourier|sine]
//             [--fmin F] [--fmax F] [-o out.csv] [--csv] [--plot FIG] [--json]
//
// Seismic spectra of receiver histories (docs/analytical.md, "Spectra"):
// Fourier amplitude spectra with Konno-Ohmachi smoothing, spectral ratios
// against a reference receiver, H/V ratios, response spectra. The numerics
// are in tools/analysis; reading the signals in spectra_input.cpp.
#include <charconv>
#include <cmath>
#include <iostream>
#include <sstream>

#include "analysis_options.hpp"
#include "commands.hpp"
#include "dda/analysis/fourier_spectrum.hpp"
#include "dda/analysis/response_spectrum.hpp"
#include "dda/analysis/spectral_ratio.hpp"
#include "dda/common/atomic_file.hpp"
#include "dda/common/error.hpp"
#include "dda/common/output_guard.hpp"
#include "pipeline.hpp"
#include "plot_runner.hpp"
#include "spectra_input.hpp"

namespace dda::cli {
namespace {

constexpr const char* kFooter =
    "Input: a results file (.h5) of `dda df`/`dda run`, whose measurement points are the receivers (--point; "
    "model axes x horizontal, y up); a CSV with a header line and t first (--column NAME, or --point NAME for the "
    "NAME.ux/uy/vx/vy columns of `dda history --csv`); or an acceleration record, PEER .AT2 or a CSV read as by "
    "`dda record` when --units is given (t, ax, ay[, az] or t, a; --component x|y|z; m/s^2). Results store "
    "displacement, velocity and acceleration per step (the acceleration is constant within a DDA step); from a "
    "file without accelerations (an older results file, a `dda history --csv` without --acceleration) "
    "--quantity acceleration is the central difference of the velocity (after resampling; it scales a frequency "
    "f by sin(2 pi f dt)/(2 pi f dt)). Uneven times (adaptive steps) "
    "are resampled by linear interpolation to --dt, by default the median step. "
    "Spectrum: mean removed (--detrend: the least-squares line), --taper (default tukey:0.1, cosine flanks over "
    "10 % of the record), A(f) = dt |sum x_n w_n exp(-2 pi i f n dt)| (--amplitude fourier: units of the signal "
    "times s) or 2 |X| / sum w_n (--amplitude sine: a sinusoid's amplitude) at f = k/(N dt) from 0 to Nyquist; "
    "Konno-Ohmachi smoothing W = [sin(b log10(f/fc)) / (b log10(f/fc))]^4, normalised at each fc (--smooth b, "
    "default 40, 0 none), reported at --points centres evenly spaced in log f over [--fmin, --fmax] (default "
    "1/(N dt) to Nyquist; --points 0: every transform frequency, slow for long records). --reference: the "
    "classical spectral ratio S(point) / S(reference), each smoothed first. --hv: S(x) / S(y) of the point (one "
    "horizontal in 2D); with two horizontals (--horizontal H1,H2, or a record's ax, ay over az) H is "
    "sqrt((S_H1^2 + S_H2^2) / 2). --response: response spectra of the acceleration (damping --damping, default "
    "0.05): SD = max|u|, SV = max|u'|, PSV = w SD, PSA = w^2 SD, SA = max|u'' + a_g| over the record, exact for "
    "a record linear between samples (Nigam & Jennings); T = 0 gives the PGA. "
    "CSV columns: spectrum f (Hz), amplitude; --reference f, amplitude, reference, ratio; --hv f, horizontal, "
    "vertical, hv; --response T (s), SD (units of a times s^2), SV (a times s), PSV (a times s), PSA, SA (a). "
    "--json: input, mode, signals, samples, dt, resampled, df, nyquist, smoothing, taper, peak_frequency and "
    "peak_value of the output (a ratio's peak; the largest sample, not interpolated); --response: pga, "
    "peak_psa, peak_psa_period and, for --at periods, sd, sv, psv, psa, sa.";

enum class Mode { spectrum, ratio, hv, response };

const char* mode_name(Mode m) {
  switch (m) {
    case Mode::spectrum: return "spectrum";
    case Mode::ratio: return "ratio";
    case Mode::hv: return "hv";
    case Mode::response: break;
  }
  return "response";
}

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

double parse_number(const std::string& text, const std::string& flag) {
  double v = 0;
  const char* b = text.data();
  const char* e = text.data() + text.size();
  const auto r = std::from_chars(b, e, v);
  if (text.empty() || r.ec != std::errc() || r.ptr != e || !std::isfinite(v))
    throw InputError(flag + ": '" + text + "' is not a number.");
  return v;
}

// "A:B:N" (N periods from A to B evenly spaced in log T, A > 0) or a list "T1,T2,...".
std::vector<double> parse_periods(const std::string& text, const std::string& flag) {
  std::vector<double> out;
  if (text.find(':') != std::string::npos) {
    std::vector<std::string> parts;
    std::stringstream ss(text);
    for (std::string p; std::getline(ss, p, ':');) parts.push_back(p);
    if (parts.size() != 3) throw InputError(flag + ": '" + text + "' is not FIRST:LAST:COUNT or a list T1,T2,....");
    const double a = parse_number(parts[0], flag), b = parse_number(parts[1], flag);
    const double n = parse_number(parts[2], flag);
    if (!(a > 0.0) || !(b > a) || n < 2 || n != std::floor(n) || n > 1e5)
      throw InputError(flag + ": '" + text + "' needs 0 < FIRST < LAST and a whole COUNT of 2 or more.");
    return analysis::log_spaced(a, b, static_cast<std::size_t>(n));
  }
  std::stringstream ss(text);
  for (std::string p; std::getline(ss, p, ',');) {
    const double t = parse_number(p, flag);
    if (t < 0.0) throw InputError(flag + ": the period " + p + " s is negative.");
    out.push_back(t);
  }
  if (out.empty()) throw InputError(flag + ": give FIRST:LAST:COUNT or a list of periods.");
  return out;
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string p; std::getline(ss, p, ',');)
    if (!p.empty()) out.push_back(p);
  return out;
}

void add_row(std::string& csv, std::initializer_list<double> values) {
  bool first = true;
  for (const double v : values) {
    if (!first) csv += ',';
    first = false;
    put_number(csv, v);
  }
  csv += '\n';
}

nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

struct Options {
  std::string input, point, column, component = "x", quantity = "velocity", units, reference;
  std::string horizontal, vertical, periods = "0.01:10:91", at, taper = "tukey:0.1", amplitude = "fourier";
  std::string output, plot;
  bool hv = false, response = false, detrend = false, csv = false, json = false;
  double dt = 0.0, smooth = analysis::kKonnoOhmachiBandwidth, damping = analysis::kResponseDamping;
  double fmin = 0.0, fmax = 0.0;
  int points = 500;
};

// What a mode produces: the CSV text, the curve labels of the figure, the summary line; the JSON is filled in place.
struct Product {
  std::string csv;
  std::vector<std::string> labels;
  std::ostringstream summary;
};

// The histories a mode needs, in order: the signal (and the reference) or,
// for --hv, the horizontal(s) then the vertical (`horizontals` of them).
std::vector<RawSignal> select_signals(const Options& o, const SignalSource& src, Mode mode, Quantity quantity,
                                      std::size_t& horizontals) {
  if (src.is_results() && o.point.empty())
    throw InputError("--point: give the measurement point to analyse in " + o.input + ".");
  if (src.is_record() && (!o.point.empty() || !o.column.empty()))
    throw InputError(o.input + ": is a record (one series per axis): choose it with --component, not --point or "
                     "--column.");
  const bool hv_columns = mode == Mode::hv && (!o.vertical.empty() || !o.horizontal.empty());
  if (src.is_table() && o.point.empty() && o.column.empty() && !hv_columns)
    throw InputError(o.input + ": give the series to analyse with --column NAME (or --point NAME for a "
                     "`dda history --csv` file).");
  horizontals = 1;
  if (mode == Mode::hv) {
    if (src.is_record()) {  // ax and ay over az
      std::vector<RawSignal> raw{src.record_component('x'), src.record_component('y'), src.record_component('z')};
      bool any = false;
      for (const double v : raw[2].x) any = any || v != 0.0;
      if (!any) throw InputError(o.input + ": has no vertical (z) component for --hv.");
      horizontals = 2;
      return raw;
    }
    if (hv_columns) {
      const std::vector<std::string> hs = split_list(o.horizontal);
      if (!src.is_table() || hs.empty() || hs.size() > 2 || o.vertical.empty())
        throw InputError("--hv on a CSV table: give --horizontal H1[,H2] and --vertical V.");
      std::vector<RawSignal> raw;
      for (const std::string& h : hs) raw.push_back(src.column(h));
      raw.push_back(src.column(o.vertical));
      horizontals = hs.size();
      return raw;
    }
    if (o.point.empty()) throw InputError("--hv: give --point NAME (or --horizontal and --vertical columns).");
    return {src.point(o.point, 'x', quantity), src.point(o.point, 'y', quantity)};
  }
  const char c = o.component[0];
  const auto one = [&](const std::string& name) {
    if (src.is_record()) return src.record_component(c);
    if (!o.point.empty()) return src.point(name, c, quantity);
    return src.column(name);
  };
  std::vector<RawSignal> raw{one(o.point.empty() ? o.column : o.point)};
  if (mode == Mode::ratio) {
    if (src.is_record())
      throw InputError("--reference: a record has one series per axis; use a results file or a CSV table.");
    raw.push_back(one(o.reference));
  }
  return raw;
}

// --response: the spectra at the periods, and at the --at periods for the JSON and summary.
void response_output(const UniformSignal& s, const std::vector<double>& periods, const std::vector<double>& at,
                     double damping, nlohmann::json& j, Product& out) {
  const double dt = s.series.dt;
  const analysis::ResponseSpectrum r = analysis::response_spectrum(s.series.x, dt, periods, damping);
  out.csv = "T,SD,SV,PSV,PSA,SA\n";
  std::size_t best = 0;
  for (std::size_t i = 0; i < r.period.size(); ++i) {
    add_row(out.csv, {r.period[i], r.sd[i], r.sv[i], r.psv[i], r.psa[i], r.sa[i]});
    if (r.psa[i] > r.psa[best]) best = i;
  }
  j["damping"] = damping;
  j["pga"] = r.pga;
  j["peak_psa"] = r.psa[best];
  j["peak_psa_period"] = r.period[best];
  out.summary << "response spectra of " << s.label << " (" << 100 * damping << " % damping, " << r.period.size()
              << " periods): PGA " << r.pga << ", peak PSA " << r.psa[best] << " at T = " << r.period[best] << " s";
  if (!at.empty()) {
    const analysis::ResponseSpectrum ra = analysis::response_spectrum(s.series.x, dt, at, damping);
    nlohmann::json list = nlohmann::json::array();
    for (std::size_t i = 0; i < at.size(); ++i) {
      list.push_back({{"period", at[i]}, {"sd", ra.sd[i]}, {"sv", ra.sv[i]}, {"psv", ra.psv[i]}, {"psa", ra.psa[i]},
                      {"sa", ra.sa[i]}});
      out.summary << "; PSA(" << at[i] << " s) " << ra.psa[i];
    }
    j["at"] = list;
  }
  out.summary << " (" << (s.units.empty() ? "units of the input" : s.units) << ")";
  out.labels = {s.label};
}

// The spectrum, the spectral ratio or H/V of the signals (select_signals' order).
void spectra_output(const std::vector<UniformSignal>& sig, Mode mode, std::size_t horizontals,
                    const analysis::SpectrumOptions& so, const analysis::SpectrumGrid& grid, nlohmann::json& j,
                    Product& out) {
  const double dt = sig.front().series.dt;
  std::vector<analysis::SampledSpectrum> spectra;
  analysis::AmplitudeSpectrum first;
  for (const UniformSignal& s : sig) {
    analysis::AmplitudeSpectrum a = analysis::amplitude_spectrum(s.series.x, dt, so);
    spectra.push_back(analysis::report_spectrum(a, grid));
    if (spectra.size() == 1) first = std::move(a);
  }
  const std::vector<double>& f = spectra[0].f;
  std::vector<double> value;  // what the peak is of
  if (mode == Mode::spectrum) {
    out.csv = "f,amplitude\n";
    value = spectra[0].amplitude;
    for (std::size_t i = 0; i < f.size(); ++i) add_row(out.csv, {f[i], value[i]});
    out.labels = {sig[0].label};
    out.summary << sig[0].label << " amplitude spectrum";
  } else if (mode == Mode::ratio) {
    out.csv = "f,amplitude,reference,ratio\n";
    value = analysis::spectral_ratio(spectra[0].amplitude, spectra[1].amplitude);
    for (std::size_t i = 0; i < f.size(); ++i)
      add_row(out.csv, {f[i], spectra[0].amplitude[i], spectra[1].amplitude[i], value[i]});
    out.labels = {sig[0].label, sig[1].label};
    out.summary << "spectral ratio " << sig[0].label << " / " << sig[1].label;
  } else {
    const std::vector<double> h = horizontals == 2
                                      ? analysis::quadratic_mean(spectra[0].amplitude, spectra[1].amplitude)
                                      : spectra[0].amplitude;
    const std::vector<double>& v = spectra[horizontals].amplitude;
    out.csv = "f,horizontal,vertical,hv\n";
    value = analysis::spectral_ratio(h, v);
    for (std::size_t i = 0; i < f.size(); ++i) add_row(out.csv, {f[i], h[i], v[i], value[i]});
    const std::string hname = sig[0].label + (horizontals == 2 ? "+" + sig[1].label : "");
    out.labels = {"H (" + hname + ")", "V (" + sig[horizontals].label + ")"};
    out.summary << "H/V " << hname << " / " << sig[horizontals].label;
  }
  const analysis::SpectralPeak peak = analysis::find_peak(f, value);
  j["df"] = first.df;
  j["nyquist"] = first.f.back();
  j["fmin"] = f.front();
  j["fmax"] = f.back();
  j["frequencies"] = f.size();
  j["smoothing"] = grid.smoothing;
  j["taper"] = analysis::taper_name(so.taper);
  j["detrend"] = so.detrend;
  j["amplitude"] = so.scale == analysis::AmplitudeScale::fourier ? "fourier" : "sine";
  j["peak_frequency"] = finite_or_null(peak.frequency);
  j["peak_value"] = finite_or_null(peak.value);
  out.summary << ": peak " << peak.value << " at " << peak.frequency << " Hz";
  if (grid.smoothing > 0) out.summary << " (Konno-Ohmachi b = " << grid.smoothing << ")";
}

}  // namespace

void add_spectra_command(CLI::App& app, const GlobalOptions& global) {
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "spectra",
      "Seismic spectra of receiver histories: Fourier amplitude spectra with windowing and Konno-Ohmachi "
      "smoothing, spectral ratios against a reference receiver, H/V ratios, response spectra of an acceleration "
      "record; CSV, JSON summary and figures.");
  cmd->footer(kFooter);
  cmd->add_option("input", opt->input,
                  "results.h5, a CSV with a header line (t first), or a record (.AT2, or CSV with --units)")
      ->required();
  cmd->add_option("--point", opt->point, "Measurement point (results file or `dda history --csv` file)");
  cmd->add_option("--column", opt->column, "Column of a CSV table (instead of --point)");
  cmd->add_option("--component", opt->component, "x (horizontal, default) or y (up) of a point; x, y or z of a record");
  cmd->add_option("--quantity", opt->quantity,
                  "velocity (default), displacement or acceleration of a point");
  cmd->add_option("--units", opt->units, "Read a CSV as an acceleration record in these units: g or m/s2");
  auto* ref = cmd->add_option("--reference", opt->reference,
                              "Spectral ratio against this reference point (or column): S / S_reference");
  auto* hv = cmd->add_flag("--hv", opt->hv, "H/V ratio of the point: S(x) / S(y)");
  cmd->add_option("--horizontal", opt->horizontal, "--hv on a CSV table: the horizontal column(s) H1[,H2]");
  cmd->add_option("--vertical", opt->vertical, "--hv on a CSV table: the vertical column");
  auto* resp = cmd->add_flag("--response", opt->response, "Response spectra of the acceleration instead");
  ref->excludes(hv)->excludes(resp);
  hv->excludes(resp);
  cmd->add_option("--periods", opt->periods,
                  "--response periods (s): FIRST:LAST:COUNT evenly spaced in log T (default 0.01:10:91) or a list");
  cmd->add_option("--damping", opt->damping, "--response damping ratio, 0 <= zeta < 1 (default 0.05)");
  cmd->add_option("--at", opt->at, "--response: report these periods (s) in the JSON and summary, e.g. 0.2,1");
  cmd->add_option("--dt", opt->dt, "Resample to this step (s); default: the median step where the steps are uneven");
  cmd->add_option("--smooth", opt->smooth, "Konno-Ohmachi bandwidth b (default 40; 0: no smoothing)");
  cmd->add_option("--points", opt->points,
                  "Smoothed spectra at this many frequencies evenly spaced in log f (default 500; 0: every "
                  "transform frequency)");
  cmd->add_option("--taper", opt->taper, "none, hann, tukey or tukey:FRACTION (default tukey:0.1)");
  cmd->add_flag("--detrend", opt->detrend, "Remove the least-squares line (default: the mean only)");
  cmd->add_option("--amplitude", opt->amplitude, "fourier (dt |X|, default) or sine (2 |X| / sum w)");
  cmd->add_option("--fmin", opt->fmin, "Lowest frequency reported (Hz; default 1/(N dt))");
  cmd->add_option("--fmax", opt->fmax, "Highest frequency reported (Hz; default Nyquist)");
  cmd->add_option("-o,--output", opt->output, "Write the spectra as CSV (columns below)");
  cmd->add_flag("--csv", opt->csv, "Print the CSV on the standard output");
  cmd->add_option("--plot", opt->plot, "Draw the spectra (.png, .svg or .pdf)");
  cmd->add_flag("--json", opt->json, "Print a JSON summary");
  cmd->callback([opt, cmd, &global] {
    refuse_overwriting_inputs({opt->input}, {opt->output, opt->plot});
    const Mode mode = opt->response ? Mode::response
                      : opt->hv     ? Mode::hv
                      : !opt->reference.empty() ? Mode::ratio
                                                : Mode::spectrum;
    // Options first, before reading anything.
    if (opt->dt < 0.0 || !std::isfinite(opt->dt)) throw InputError("--dt: the step must be positive.");
    if (!(opt->smooth >= 0.0) || !std::isfinite(opt->smooth))
      throw InputError("--smooth: the Konno-Ohmachi bandwidth must be zero (none) or positive.");
    if (opt->points < 0) throw InputError("--points: must be zero or positive.");
    if (opt->fmin < 0.0 || opt->fmax < 0.0) throw InputError("--fmin/--fmax: frequencies must not be negative.");
    if (opt->fmax > 0.0 && !(opt->fmin < opt->fmax))
      throw InputError("--fmin (" + num(opt->fmin) + " Hz) must be below --fmax (" + num(opt->fmax) + " Hz).");
    if (!(opt->damping >= 0.0 && opt->damping < 1.0))
      throw InputError("--damping: the damping ratio " + num(opt->damping) + " is outside [0, 1).");
    if (opt->component.size() != 1)
      throw InputError("--component: '" + opt->component + "' is not x, y or z.");
    analysis::SpectrumOptions so;
    so.detrend = opt->detrend;
    so.taper = analysis::parse_taper(opt->taper, "--taper");
    so.scale = analysis::parse_amplitude_scale(opt->amplitude, "--amplitude");
    Quantity quantity = parse_quantity(opt->quantity, "--quantity");
    if (mode == Mode::response) {
      if (cmd->count("--quantity") > 0 && quantity != Quantity::acceleration)
        throw InputError("--response: response spectra are of an acceleration, not of the " + opt->quantity + ".");
      quantity = Quantity::acceleration;
    }
    const std::vector<double> periods =
        mode == Mode::response ? parse_periods(opt->periods, "--periods") : std::vector<double>{};
    const std::vector<double> at = opt->at.empty() ? std::vector<double>{} : parse_periods(opt->at, "--at");
    if (!opt->point.empty() && !opt->column.empty()) throw InputError("--point or --column: give one, not both.");
    if ((!opt->horizontal.empty() || !opt->vertical.empty()) && mode != Mode::hv)
      throw InputError("--horizontal/--vertical: apply to --hv only.");

    // The signals, on a uniform step.
    const SignalSource src(opt->input, opt->units);
    std::size_t horizontals = 1;
    const std::vector<RawSignal> raw = select_signals(*opt, src, mode, quantity, horizontals);
    bool resampled = false;
    const std::vector<UniformSignal> sig = make_uniform(raw, opt->dt, opt->input, resampled);
    const std::size_t n = sig.front().series.x.size();

    nlohmann::json j;
    j["input"] = opt->input;
    j["mode"] = mode_name(mode);
    j["signals"] = nlohmann::json::array();
    for (const UniformSignal& s : sig) j["signals"].push_back(s.label);
    j["units"] = sig.front().units;
    j["quantity"] = src.is_record()                           ? "acceleration"
                    : src.is_results() || !opt->point.empty() ? quantity_name(quantity)
                                                              : "as given";  // a CSV column
    j["samples"] = n;
    j["dt"] = sig.front().series.dt;
    j["duration"] = sig.front().series.dt * static_cast<double>(n - 1);
    j["resampled"] = resampled;
    Product out;
    out.summary << "spectra: ";
    if (mode == Mode::response) {
      response_output(sig[0], periods, at, opt->damping, j, out);
    } else {
      analysis::SpectrumGrid grid;
      grid.fmin = opt->fmin;
      grid.fmax = opt->fmax;
      grid.smoothing = opt->smooth;
      grid.points = static_cast<std::size_t>(opt->points);
      spectra_output(sig, mode, horizontals, so, grid, j, out);
    }
    out.summary << "; " << n << " samples at dt = " << sig.front().series.dt << " s"
                << (resampled ? " (resampled)" : "") << "\n";

    if (!opt->output.empty()) write_text_atomically(opt->output, out.csv);
    if (!opt->plot.empty()) {
      // The amplitude's unit: the signal's, times s for a Fourier amplitude.
      const std::string& unit = sig.front().units;
      std::string amplitude_unit = unit;
      if (so.scale == analysis::AmplitudeScale::fourier)
        amplitude_unit = unit == "m/s" ? "m" : unit == "m/s^2" ? "m/s" : unit.empty() ? "" : unit + "·s";
      std::vector<std::string> args{"-o", opt->plot, "--kind", "spectra", "--labels"};
      if (!amplitude_unit.empty()) args.insert(args.begin(), {"--amplitude-unit", amplitude_unit});
      args.insert(args.end(), out.labels.begin(), out.labels.end());
      plot_csv(out.csv, opt->output, args);
    }
    if (opt->csv)
      std::cout << out.csv << std::flush;
    else if (opt->json)
      std::cout << j.dump(2) << "\n";
    else
      say(global.quiet, out.summary.str());
  });
}

}  // namespace dda::cli
