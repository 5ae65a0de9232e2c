// Laws of the disc radius.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "builder.hpp"  // detail::format_number
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/dl/dfn3d.hpp"

namespace dda::dl {

using detail::format_number;

namespace {

// Parameters as stored: constant (radius, -, -); log-normal (mu, sigma, -) of
// ln r; exponential (mean, -, -); power law (alpha, rmin, rmax).

[[noreturn]] void fail(const char* law, const char* parameter, const std::string& rule, double got) {
  throw InputError(std::string("The ") + law + " size law's " + parameter + " must be " + rule + ", got " +
                   format_number(got) + ".");
}

void require_positive(const char* law, const char* parameter, double v) {
  if (!(v > 0) || !std::isfinite(v)) fail(law, parameter, "a finite number > 0", v);
}

}  // namespace

SizeLaw SizeLaw::constant(double radius) {
  require_positive("constant", "radius", radius);
  return {Kind::constant, radius, 0, 0};
}

SizeLaw SizeLaw::lognormal(double mean, double std) {
  require_positive("log-normal", "mean", mean);
  if (!(std >= 0) || !std::isfinite(std)) fail("log-normal", "std", "a finite number >= 0", std);
  // ln r ~ N(mu, sigma^2) with E[r] = exp(mu + sigma^2/2) = mean and
  // Var[r] = (exp(sigma^2) - 1) mean^2 = std^2.
  const double s2 = std::log1p((std / mean) * (std / mean));
  return {Kind::lognormal, std::log(mean) - 0.5 * s2, std::sqrt(s2), 0};
}

SizeLaw SizeLaw::exponential(double mean) {
  require_positive("exponential", "mean", mean);
  return {Kind::exponential, mean, 0, 0};
}

SizeLaw SizeLaw::power_law(double alpha, double rmin, double rmax) {
  if (!(alpha > 1) || !std::isfinite(alpha)) fail("power-law", "exponent alpha", "a finite number > 1", alpha);
  require_positive("power-law", "rmin", rmin);
  if (!(rmax > rmin) || !std::isfinite(rmax))
    fail("power-law", "rmax", "finite and greater than rmin (" + format_number(rmin) + ")", rmax);
  return {Kind::power_law, alpha, rmin, rmax};
}

const char* SizeLaw::name() const {
  switch (kind_) {
    case Kind::constant: return "constant";
    case Kind::lognormal: return "log-normal";
    case Kind::exponential: return "exponential";
    case Kind::power_law: return "power-law";
  }
  return "?";
}

double SizeLaw::sample(Stream& rng) const {
  switch (kind_) {
    case Kind::constant: return a_;
    case Kind::lognormal: return std::exp(a_ + b_ * rng.normal());
    case Kind::exponential: return -a_ * std::log(rng.uniform_open01());
    case Kind::power_law: {
      // Inverse of F(r) = (rmin^(1-alpha) - r^(1-alpha)) / (rmin^(1-alpha) - rmax^(1-alpha)).
      const double e = 1 - a_, lo = std::pow(b_, e), hi = std::pow(c_, e);
      const double r = std::pow(lo - rng.uniform01() * (lo - hi), 1 / e);
      return std::clamp(r, b_, c_);  // rounding must not leave [rmin, rmax]
    }
  }
  return a_;
}

double SizeLaw::max_radius() const {
  switch (kind_) {
    case Kind::constant: return a_;
    case Kind::power_law: return c_;
    case Kind::lognormal: return b_ == 0 ? std::exp(a_) : std::numeric_limits<double>::infinity();
    case Kind::exponential: return std::numeric_limits<double>::infinity();
  }
  return a_;
}

double SizeLaw::mean_area() const {
  switch (kind_) {
    case Kind::constant: return kPi * a_ * a_;
    case Kind::lognormal: return kPi * std::exp(2 * a_ + 2 * b_ * b_);  // E[r^2] = exp(2 mu + 2 sigma^2)
    case Kind::exponential: return 2 * kPi * a_ * a_;                   // E[r^2] = 2 mean^2
    case Kind::power_law: {
      // E[r^2] = (alpha-1)/(alpha-3) (rmin^(3-alpha) - rmax^(3-alpha)) / (rmin^(1-alpha) - rmax^(1-alpha)),
      // and 2 ln(rmax/rmin) / (rmin^-2 - rmax^-2) at alpha = 3.
      const double norm = std::pow(b_, 1 - a_) - std::pow(c_, 1 - a_);
      if (a_ == 3) return kPi * 2 * std::log(c_ / b_) / norm;
      return kPi * (a_ - 1) / (a_ - 3) * (std::pow(b_, 3 - a_) - std::pow(c_, 3 - a_)) / norm;
    }
  }
  return 0;
}

}  // namespace dda::dl
