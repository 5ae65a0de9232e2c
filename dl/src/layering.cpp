#include "dda/dl/layering.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dda/common/error.hpp"

namespace dda::dl {

namespace {

struct BedFrame {
  Vec2 along, normal;
  double q_lo, q_hi, w_lo, w_hi;  // extent of the domain along the beds and the normal
};

BedFrame bed_frame(double dip_deg, const Polygon2& domain) {
  const double b = deg2rad(dip_deg);
  BedFrame f{Vec2(std::cos(b), std::sin(b)), Vec2(-std::sin(b), std::cos(b)), 0, 0, 0, 0};
  f.q_lo = f.w_lo = std::numeric_limits<double>::infinity();
  f.q_hi = f.w_hi = -f.q_lo;
  for (const Vec2& p : domain) {
    f.q_lo = std::min(f.q_lo, p.dot(f.along));
    f.q_hi = std::max(f.q_hi, p.dot(f.along));
    f.w_lo = std::min(f.w_lo, p.dot(f.normal));
    f.w_hi = std::max(f.w_hi, p.dot(f.normal));
  }
  return f;
}

// Direction of a layered joint, oriented from bed bottom to bed top, and the
// sine of its angle to the beds (> 0).
void joint_direction(double dip_deg, const BedFrame& f, Vec2& d, double& sin_rel) {
  const double a = deg2rad(dip_deg);
  d = Vec2(std::cos(a), std::sin(a));
  sin_rel = d.dot(f.normal);
  if (sin_rel < 0) {
    d = -d;
    sin_rel = -sin_rel;
  }
}

}  // namespace

void lognormal_from_moments(double mean, double std, double& mu, double& sigma) {
  const double s2 = std::log1p((std * std) / (mean * mean));
  sigma = std::sqrt(s2);
  mu = std::log(mean) - 0.5 * s2;
}

double thickness_acceptance(const ThicknessSpec& spec) {
  if (spec.kind == ThicknessSpec::Kind::Constant || spec.minimum <= 0) return 1.0;
  if (spec.sigma == 0) return std::exp(spec.mu) >= spec.minimum ? 1.0 : 0.0;
  const double z = (std::log(spec.minimum) - spec.mu) / spec.sigma;
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

double draw_thickness(const ThicknessSpec& spec, Stream& rng) {
  if (spec.kind == ThicknessSpec::Kind::Constant) return spec.value;
  // Truncation by rejection: redraw until the thickness reaches the minimum.
  for (int attempt = 0; attempt < 1000000; ++attempt) {
    const double t = std::exp(spec.mu + spec.sigma * rng.normal());
    if (t >= spec.minimum) return t;
  }
  throw InternalError("bed thickness: no draw reached the minimum in 1e6 attempts");
}

double LayerSetInBed::median_spacing() const {
  if (spacings.empty()) return 0;
  std::vector<double> v = spacings;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double expected_bed_count(const LayeringSpec& spec, const Polygon2& domain) {
  if (domain.empty()) return 0;
  const BedFrame f = bed_frame(spec.dip_deg, domain);
  const ThicknessSpec& t = spec.thickness;
  const double mean = t.kind == ThicknessSpec::Kind::Constant
                          ? t.value
                          : std::max(t.minimum, std::exp(t.mu + 0.5 * t.sigma * t.sigma));
  return (f.w_hi - f.w_lo) / mean + 1;
}

std::vector<Layer> stack_beds(const LayeringSpec& spec, const Polygon2& domain, std::uint64_t seed,
                              std::vector<double>* drawn_thickness) {
  std::vector<Layer> beds;
  if (drawn_thickness) drawn_thickness->clear();
  if (domain.empty()) return beds;
  const BedFrame f = bed_frame(spec.dip_deg, domain);
  const double tiny = 1e-12 * std::max(1.0, f.w_hi - f.w_lo);
  Stream rng(seed, "layering.thickness");
  double w = f.w_lo;
  while (w < f.w_hi - tiny) {
    const double drawn = draw_thickness(spec.thickness, rng);
    const double top = std::min(w + drawn, f.w_hi);
    if (drawn_thickness) drawn_thickness->push_back(drawn);
    Layer layer;
    layer.bottom = w;
    layer.top = top;
    beds.push_back(layer);
    w = top;
  }
  if (!beds.empty()) beds.back().top = f.w_hi;
  return beds;
}

double expected_layered_joints(const LayeringSpec& spec, const Polygon2& domain, const std::vector<Layer>& beds) {
  if (domain.empty()) return 0;
  const BedFrame f = bed_frame(spec.dip_deg, domain);
  double total = 0;
  for (const LayerSetSpec& set : spec.sets) {
    Vec2 d;
    double sin_rel = 0;
    joint_direction(set.dip_deg, f, d, sin_rel);
    for (const Layer& bed : beds) {
      const double h = bed.thickness();
      const double shift = std::abs(h * d.dot(f.along) / sin_rel);
      const double median = h / set.fsi;
      total += (f.q_hi - f.q_lo + shift) * sin_rel / median + 2;
    }
  }
  return total;
}

LayeringOutput generate_layering(const LayeringSpec& spec, const Polygon2& domain, std::uint64_t seed) {
  LayeringOutput out;
  if (domain.empty()) return out;
  const BedFrame f = bed_frame(spec.dip_deg, domain);
  out.along = f.along;
  out.normal = f.normal;
  std::vector<double> drawn;
  out.layers = stack_beds(spec, domain, seed, &drawn);
  const double margin = 1e-6 * std::max(1.0, f.q_hi - f.q_lo);

  // Interior bed boundaries, as long as the domain is wide, clipped to it.
  for (std::size_t i = 0; i + 1 < out.layers.size(); ++i) {
    const double w = out.layers[i].top;
    const Segment s{(f.q_lo - margin) * f.along + w * f.normal, (f.q_hi + margin) * f.along + w * f.normal};
    for (const Segment& piece : clip_segment(domain, s)) out.bed_boundaries.push_back(piece);
  }

  out.per_set.assign(spec.sets.size(), std::vector<LayerSetInBed>(out.layers.size()));
  for (std::size_t k = 0; k < spec.sets.size(); ++k) {
    const LayerSetSpec& set = spec.sets[k];
    Vec2 d;
    double sin_rel = 0;
    joint_direction(set.dip_deg, f, d, sin_rel);
    const std::string tag = "layering.set." + std::to_string(k);
    for (std::size_t i = 0; i < out.layers.size(); ++i) {
      const Layer& bed = out.layers[i];
      LayerSetInBed& stats = out.per_set[k][i];
      Stream rng(seed, tag, i);
      const double h = bed.thickness();
      const double median = drawn[i] / set.fsi;  // the whole bed's FSI, also for the cut top bed
      const double length = h / sin_rel;           // joint length from bottom to top
      const double shift = length * d.dot(f.along);  // offset of the top end along the beds
      // Position of the bottom end along the beds; a random phase before the
      // first position whose joint can reach the domain.
      double q = f.q_lo - std::max(0.0, shift) - rng.uniform01() * rng.around(median, set.randomness) / sin_rel;
      bool previous_kept = false;
      double last_spacing = 0;
      while (q + std::min(0.0, shift) <= f.q_hi) {
        const Vec2 a = q * f.along + bed.bottom * f.normal;
        const Vec2 b = a + length * d;
        const auto pieces = clip_segment(domain, {a, b});
        for (const Segment& piece : pieces) {
          out.joints.push_back({piece, static_cast<int>(i), static_cast<int>(k)});
          ++stats.joints;
          stats.total_length += piece.length();
        }
        const bool kept = !pieces.empty();
        if (kept && previous_kept) stats.spacings.push_back(last_spacing);
        previous_kept = kept;
        last_spacing = rng.around(median, set.randomness);
        q += last_spacing / sin_rel;
      }
    }
  }
  for (std::size_t i = 0; i < out.layers.size(); ++i) {
    if (spec.sets.empty()) break;
    Layer& layer = out.layers[i];
    layer.target_fsi = spec.sets[0].fsi;
    const double m = out.per_set[0][i].median_spacing();
    layer.realised_fsi = m > 0 ? drawn[i] / m : 0;
  }
  return out;
}

}  // namespace dda::dl
