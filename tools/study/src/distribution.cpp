#include "dda/study/distribution.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dda/common/short_number.hpp"

namespace dda::study {

namespace {

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }

double log_sigma(const Distribution& d) { return std::sqrt(std::log1p(d.std * d.std / (d.mean * d.mean))); }
double log_mu(const Distribution& d) {
  const double s = log_sigma(d);
  return std::log(d.mean) - 0.5 * s * s;
}

double untruncated(const Distribution& d, dl::Stream& stream) {
  switch (d.law) {
    case Distribution::Law::normal:
      return d.mean + d.std * stream.normal();
    case Distribution::Law::lognormal:
      return std::exp(log_mu(d) + log_sigma(d) * stream.normal());
    case Distribution::Law::uniform:
      return d.from + (d.to - d.from) * stream.uniform01();
  }
  return 0;
}

}  // namespace

double Distribution::draw(dl::Stream& stream) const {
  for (;;) {
    const double v = untruncated(*this, stream);
    if (v >= lo && v <= hi) return v;
  }
}

double Distribution::kept() const {
  switch (law) {
    case Law::normal:
      return normal_cdf((hi - mean) / std) - normal_cdf((lo - mean) / std);
    case Law::lognormal: {
      const double upper = hi > 0 ? normal_cdf((std::log(hi) - log_mu(*this)) / log_sigma(*this)) : 0.0;
      const double lower = lo > 0 ? normal_cdf((std::log(lo) - log_mu(*this)) / log_sigma(*this)) : 0.0;
      return upper - lower;
    }
    case Law::uniform: {
      const double a = std::max(lo, from), b = std::min(hi, to);
      return b > a ? (b - a) / (to - from) : 0.0;
    }
  }
  return 0;
}

double Distribution::typical() const {
  const double centre = law == Law::uniform ? 0.5 * (from + to) : mean;
  return std::min(std::max(centre, lo), hi);
}

Distribution read_distribution(const YamlNode& node) {
  node.allow({"distribution", "mean", "std", "min", "max"});
  const std::string law =
      node.choice("distribution", {"normal", "lognormal", "uniform", "truncated_normal"});
  Distribution d;
  if (law == "uniform") {
    d.law = Distribution::Law::uniform;
    d.from = node.number("min");
    d.to = node.number("max");
    if (!(d.to > d.from))
      node.fail_key("max", "must be above min (" + short_number(d.from) + "), got " + short_number(d.to));
    if (node.has("mean") || node.has("std")) node.fail("takes min and max for a uniform law, not mean or std");
    return d;
  }
  d.law = law == "lognormal" ? Distribution::Law::lognormal : Distribution::Law::normal;
  d.mean = node.number("mean", d.law == Distribution::Law::lognormal ? Range::positive() : Range::any());
  d.std = node.number("std", Range::positive());
  if (law == "truncated_normal" && !(node.has("min") || node.has("max")))
    node.fail("needs min or max (a truncated normal law without bounds is a normal law)");
  if (node.has("min")) d.lo = node.number("min");
  if (node.has("max")) d.hi = node.number("max");
  if (!(d.hi > d.lo)) node.fail_key("max", "must be above min (" + short_number(d.lo) + "), got " + short_number(d.hi));
  if (d.kept() < kMinKept)
    node.fail("keeps " + short_number(100 * d.kept()) + " % of its law between min and max; at least " +
              short_number(100 * kMinKept) + " % is needed to draw from it");
  return d;
}

analysis::Plane fisher_draw(const analysis::Plane& mean, double kappa, dl::Stream& stream) {
  using analysis::Vec3;
  const Vec3 pole = mean.normal();
  // cos(theta) by inversion of the Fisher law's cumulative distribution,
  // written with exp(-2 kappa) so that a large kappa does not overflow.
  const double u = stream.uniform_open01();
  const double c = std::clamp(1.0 + std::log(u + (1.0 - u) * std::exp(-2.0 * kappa)) / kappa, -1.0, 1.0);
  const double s = std::sqrt(1.0 - c * c);
  const double azimuth = 2.0 * std::numbers::pi * stream.uniform01();
  Vec3 e1 = pole.cross(Vec3::UnitZ());
  e1 = e1.norm() > 1e-12 ? e1.normalized() : Vec3::UnitX();
  const Vec3 e2 = pole.cross(e1);
  Vec3 n = c * pole + s * (std::cos(azimuth) * e1 + std::sin(azimuth) * e2);
  if (n.z() < 0) n = -n;
  analysis::Plane p;
  p.dip_deg = std::acos(std::clamp(n.z(), -1.0, 1.0)) * 180.0 / std::numbers::pi;
  double dd = std::atan2(n.x(), n.y()) * 180.0 / std::numbers::pi;
  if (dd < 0) dd += 360.0;
  p.dip_direction_deg = dd;
  return p;
}

}  // namespace dda::study
