#include "dda/dl/statistical.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dda::dl {

namespace {

struct Frame {
  Vec2 u, n;                 // along the set's dip, and its normal
  double s_lo, s_hi, t_lo, t_hi;  // extent of the domain along u and n
};

Frame frame_of(const StatisticalSetSpec& spec, const Polygon2& domain) {
  const double th = deg2rad(spec.dip_deg);
  Frame f{Vec2(std::cos(th), std::sin(th)), Vec2(-std::sin(th), std::cos(th)), 0, 0, 0, 0};
  f.s_lo = f.t_lo = std::numeric_limits<double>::infinity();
  f.s_hi = f.t_hi = -f.s_lo;
  for (const Vec2& p : domain) {
    f.s_lo = std::min(f.s_lo, p.dot(f.u));
    f.s_hi = std::max(f.s_hi, p.dot(f.u));
    f.t_lo = std::min(f.t_lo, p.dot(f.n));
    f.t_hi = std::max(f.t_hi, p.dot(f.n));
  }
  return f;
}

}  // namespace

double estimate_statistical_traces(const StatisticalSetSpec& spec, const Polygon2& domain) {
  if (domain.empty()) return 0;
  const Frame f = frame_of(spec, domain);
  const double scan_lines = (f.t_hi - f.t_lo) / spec.mean_spacing + 1;
  const double per_line = (f.s_hi - f.s_lo) / (spec.mean_length + spec.mean_bridge) + 2;
  return scan_lines * per_line;
}

StatisticalSetOutput generate_statistical_set(const StatisticalSetSpec& spec, const Polygon2& domain, Stream& rng) {
  StatisticalSetOutput out;
  if (domain.empty()) return out;
  const Frame f = frame_of(spec, domain);
  const double cycle = spec.mean_length + spec.mean_bridge;
  // First scan line a random fraction of one spacing above the lowest corner.
  double t = f.t_lo + rng.uniform01() * rng.around(spec.mean_spacing, spec.spacing_randomness);
  while (t <= f.t_hi) {
    ++out.stats.scan_lines;
    // Random phase: start a random fraction of a mean joint+bridge cycle
    // before the region, with a joint.
    double s = f.s_lo - rng.uniform01() * cycle;
    while (s < f.s_hi) {
      const double len = rng.around(spec.mean_length, spec.length_randomness);
      const double dip = spec.dip_deg + spec.dip_spread_deg * rng.symmetric();
      ++out.stats.traces;
      out.stats.sum_length += len;
      out.stats.sum_dip_deg += dip;
      if (s + len > f.s_lo) {
        const Vec2 mid = (s + 0.5 * len) * f.u + t * f.n;
        const double a = deg2rad(dip);
        const Vec2 half = 0.5 * len * Vec2(std::cos(a), std::sin(a));
        out.traces.push_back({mid - half, mid + half});
      }
      s += len;
      if (s >= f.s_hi) break;
      const double bridge = rng.around(spec.mean_bridge, spec.bridge_randomness);
      ++out.stats.bridges;
      out.stats.sum_bridge += bridge;
      s += bridge;
    }
    const double spacing = rng.around(spec.mean_spacing, spec.spacing_randomness);
    ++out.stats.spacings;
    out.stats.sum_spacing += spacing;
    t += spacing;
  }
  return out;
}

}  // namespace dda::dl
