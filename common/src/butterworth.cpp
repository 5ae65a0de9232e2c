#include "dda/common/butterworth.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "dda/common/error.hpp"

namespace dda {

namespace {

constexpr double kPiB = 3.14159265358979323846;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void check_cutoff(double fc, double fs, const char* which) {
  if (!(fc > 0.0) || !(fc < 0.5 * fs))
    throw InputError(std::string("Butterworth ") + which + " cutoff " + num(fc) +
                     " Hz must lie strictly between 0 and the Nyquist frequency " + num(0.5 * fs) +
                     " Hz of the signal.");
}

// Sections of one low- or high-pass Butterworth filter (bilinear, prewarped).
void append_sections(std::vector<Biquad>& out, bool highpass, int order, double fc, double fs) {
  const double k = std::tan(kPiB * fc / fs);
  for (int m = 0; m < order / 2; ++m) {
    const double c = 2.0 * std::sin(kPiB * (2.0 * m + 1.0) / (2.0 * order));
    const double a0 = 1.0 + c * k + k * k;
    Biquad q;
    if (highpass) {
      q.b0 = 1.0 / a0;
      q.b1 = -2.0 / a0;
      q.b2 = 1.0 / a0;
    } else {
      q.b0 = k * k / a0;
      q.b1 = 2.0 * k * k / a0;
      q.b2 = k * k / a0;
    }
    q.a1 = (2.0 * k * k - 2.0) / a0;
    q.a2 = (1.0 - c * k + k * k) / a0;
    out.push_back(q);
  }
  if (order % 2 == 1) {
    Biquad q;
    const double a0 = 1.0 + k;
    if (highpass) {
      q.b0 = 1.0 / a0;
      q.b1 = -1.0 / a0;
    } else {
      q.b0 = k / a0;
      q.b1 = k / a0;
    }
    q.a1 = (k - 1.0) / a0;
    out.push_back(q);
  }
}

}  // namespace

FilterKind parse_filter_kind(const std::string& text, const std::string& what) {
  const std::string s = lower(text);
  if (s == "lowpass" || s == "low") return FilterKind::lowpass;
  if (s == "highpass" || s == "high") return FilterKind::highpass;
  if (s == "bandpass" || s == "band") return FilterKind::bandpass;
  throw InputError(what + ": unknown filter type '" + text + "' (use lowpass, highpass or bandpass).");
}

std::vector<Biquad> butterworth_sections(const ButterworthSpec& spec, double fs) {
  if (spec.order < 1 || spec.order > 12)
    throw InputError("Butterworth filter order " + std::to_string(spec.order) + " must be between 1 and 12.");
  if (!(fs > 0.0) || !std::isfinite(fs))
    throw InputError("Butterworth filter: the sampling frequency " + num(fs) + " Hz is not positive.");
  std::vector<Biquad> out;
  switch (spec.kind) {
    case FilterKind::lowpass:
      check_cutoff(spec.f_high, fs, "low-pass");
      append_sections(out, false, spec.order, spec.f_high, fs);
      break;
    case FilterKind::highpass:
      check_cutoff(spec.f_low, fs, "high-pass");
      append_sections(out, true, spec.order, spec.f_low, fs);
      break;
    case FilterKind::bandpass:
      check_cutoff(spec.f_low, fs, "band-pass lower");
      check_cutoff(spec.f_high, fs, "band-pass upper");
      if (!(spec.f_low < spec.f_high))
        throw InputError("Butterworth band-pass: the lower cutoff " + num(spec.f_low) +
                         " Hz must be below the upper cutoff " + num(spec.f_high) + " Hz.");
      append_sections(out, true, spec.order, spec.f_low, fs);
      append_sections(out, false, spec.order, spec.f_high, fs);
      break;
  }
  return out;
}

std::vector<double> filter_forward(const std::vector<Biquad>& sections, const std::vector<double>& x) {
  std::vector<double> y = x;
  for (const Biquad& q : sections) {
    // Direct form II transposed.
    double z1 = 0.0, z2 = 0.0;
    for (double& v : y) {
      const double in = v;
      const double out = q.b0 * in + z1;
      z1 = q.b1 * in - q.a1 * out + z2;
      z2 = q.b2 * in - q.a2 * out;
      v = out;
    }
  }
  return y;
}

std::vector<double> zero_phase_filter(const std::vector<double>& x, double dt, const ButterworthSpec& spec) {
  if (!(dt > 0.0)) throw InputError("Butterworth filter: the sampling step " + num(dt) + " s is not positive.");
  const double fs = 1.0 / dt;
  const std::vector<Biquad> sections = butterworth_sections(spec, fs);
  const std::size_t n = x.size();
  if (n < 2) return x;
  const double fc_min = spec.kind == FilterKind::lowpass ? spec.f_high : spec.f_low;
  const std::size_t want = static_cast<std::size_t>(
      std::max(6.0 * spec.order, std::ceil(3.0 * fs / fc_min)));
  const std::size_t pad = std::min(n - 1, want);
  std::vector<double> ext;
  ext.reserve(n + 2 * pad);
  for (std::size_t k = pad; k >= 1; --k) ext.push_back(2.0 * x.front() - x[k]);
  ext.insert(ext.end(), x.begin(), x.end());
  for (std::size_t k = 1; k <= pad; ++k) ext.push_back(2.0 * x.back() - x[n - 1 - k]);
  std::vector<double> y = filter_forward(sections, ext);
  std::reverse(y.begin(), y.end());
  y = filter_forward(sections, y);
  std::reverse(y.begin(), y.end());
  return std::vector<double>(y.begin() + static_cast<std::ptrdiff_t>(pad),
                             y.begin() + static_cast<std::ptrdiff_t>(pad + n));
}

double zero_phase_gain(const ButterworthSpec& spec, double f, double fs) {
  const double w = std::tan(kPiB * f / fs);
  auto lp = [&](double fc) {
    const double r = w / std::tan(kPiB * fc / fs);
    return 1.0 / (1.0 + std::pow(r, 2.0 * spec.order));
  };
  auto hp = [&](double fc) {
    if (w == 0.0) return 0.0;
    const double r = std::tan(kPiB * fc / fs) / w;
    return 1.0 / (1.0 + std::pow(r, 2.0 * spec.order));
  };
  // |H|^2 of the one-way cascade is the amplitude gain of the forward-backward pass.
  double gain = 1.0;
  if (spec.kind != FilterKind::highpass) gain *= lp(spec.f_high);
  if (spec.kind != FilterKind::lowpass) gain *= hp(spec.f_low);
  return gain;
}

}  // namespace dda
