// Beds and layer-bound joint sets in a 3D box.
#include "dda/dl/layering3d.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "builder.hpp"  // detail::format_number
#include "dda/common/error.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/polygon3d.hpp"

namespace dda::dl {

using detail::format_number;

namespace {

// Limits against requests that could never be cut into blocks.
constexpr double kMaxBeds = 1e6;
constexpr double kMaxLayeredJoints = 1e7;
// Joints closer to the bedding than this cannot be bounded by it (the 2D rule).
constexpr double kMinAngleToBedsDeg = 5;

std::vector<Vec3> box_corners(const Box3& b) {
  std::vector<Vec3> c;
  for (int i = 0; i < 8; ++i)
    c.emplace_back(i & 1 ? b.hi.x() : b.lo.x(), i & 2 ? b.hi.y() : b.lo.y(), i & 4 ? b.hi.z() : b.lo.z());
  return c;
}

std::pair<double, double> range_along(const Vec3& dir, const std::vector<Vec3>& points) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec3& p : points) {
    lo = std::min(lo, dir.dot(p));
    hi = std::max(hi, dir.dot(p));
  }
  return {lo, hi};
}

// The vertices of the part of the box between the two bed planes: the box
// corners inside the slab and the two sections of the box by the planes.
std::vector<Vec3> slab_vertices(const Box3& box, const Vec3& nb, double bottom, double top) {
  std::vector<Vec3> v;
  for (const Vec3& c : box_corners(box))
    if (nb.dot(c) >= bottom && nb.dot(c) <= top) v.push_back(c);
  for (const double w : {bottom, top})
    for (const Vec3& p : plane_in_box(nb, w, box)) v.push_back(p);
  return v;
}

// A Plane fracture whose centre is the centroid of its section of the box.
Fracture3 plane_through_box(const Vec3& n, double offset, const Box3& box) {
  Fracture3 f;
  f.shape = FractureShape::Plane;
  f.normal = n;
  f.centre = polygon_centroid(plane_in_box(n, offset, box));
  f.centre -= (n.dot(f.centre) - offset) * n;
  return f;
}

void validate(const LayeringSpec3& spec, const Vec3& nb) {
  const ThicknessSpec& t = spec.thickness;
  if (t.kind == ThicknessSpec::Kind::Constant) {
    if (!(t.value > 0) || !std::isfinite(t.value))
      throw InputError("The bed thickness must be a finite number > 0, got " + format_number(t.value) + ".");
  } else {
    if (!std::isfinite(t.mu) || !(t.sigma >= 0) || !std::isfinite(t.sigma))
      throw InputError("The log-normal bed thickness needs a finite mu and a finite sigma >= 0.");
    if (!(t.minimum >= 0) || !std::isfinite(t.minimum))
      throw InputError("The minimum bed thickness must be a finite number >= 0, got " + format_number(t.minimum) + ".");
    if (thickness_acceptance(t) < 1e-6)
      throw InputError("The minimum bed thickness " + format_number(t.minimum) +
                       " m is beyond almost every draw of the log-normal thickness; lower it.");
  }
  for (const LayerSetSpec3& s : spec.sets) {
    const std::string where = "Layered joint set '" + s.name + "'";
    if (!(s.dip_deg >= 0 && s.dip_deg <= 90) || !std::isfinite(s.dip_direction_deg))
      throw InputError(where + " needs a dip between 0 and 90 degrees and a finite dip direction.");
    if (!(s.fsi > 0) || !std::isfinite(s.fsi))
      throw InputError(where + " has FSI " + format_number(s.fsi) + "; it must be a finite number > 0.");
    if (!(s.randomness >= 0 && s.randomness < 1))
      throw InputError(where + " has spacing randomness " + format_number(s.randomness) +
                       "; it must be at least 0 and less than 1.");
    const Vec3 m = normal_from_dip(s.dip_deg, s.dip_direction_deg);
    if (m.cross(nb).norm() < std::sin(deg2rad(kMinAngleToBedsDeg)))
      throw InputError(where + " must differ from the bedding by at least " + format_number(kMinAngleToBedsDeg) +
                       " degrees (the joints would run along the beds).");
  }
}

double mean_thickness(const ThicknessSpec& t) {
  // The untruncated mean is a lower bound of the truncated one.
  return t.kind == ThicknessSpec::Kind::Constant ? t.value
                                                 : std::max(t.minimum, std::exp(t.mu + 0.5 * t.sigma * t.sigma));
}

}  // namespace

double BedSetStats::median_spacing() const {
  if (spacings.empty()) return 0;
  std::vector<double> v = spacings;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double expected_bed_count3(const LayeringSpec3& spec, const Box3& domain) {
  const auto [lo, hi] = range_along(normal_from_dip(spec.dip_deg, spec.dip_direction_deg), box_corners(domain));
  return (hi - lo) / mean_thickness(spec.thickness) + 1;
}

LayeringOutput3 generate_layering3d(const LayeringSpec3& spec, const Box3& domain, std::uint64_t seed) {
  validate_box(domain, "The layered domain");
  LayeringOutput3 out;
  const Vec3 nb = normal_from_dip(spec.dip_deg, spec.dip_direction_deg);
  validate(spec, nb);
  out.bed_normal = nb;
  const double beds_expected = expected_bed_count3(spec, domain);
  if (beds_expected > kMaxBeds)
    throw InputError("The layering would make about " + format_number(beds_expected, 3) +
                     " beds, more than the limit of " + format_number(kMaxBeds) + "; raise the bed thickness.");

  // Beds, as in 2D (stack_beds): drawn thicknesses from the lowest corner up,
  // the last bed cut at the highest corner.
  const auto [w_lo, w_hi] = range_along(nb, box_corners(domain));
  const double diag = (domain.hi - domain.lo).norm(), tiny = 1e-12 * std::max(1.0, w_hi - w_lo);
  Stream thickness_rng(seed, "layering3d.thickness");
  for (double w = w_lo; w < w_hi - tiny;) {
    const double drawn = draw_thickness(spec.thickness, thickness_rng);
    Layer bed;
    bed.bottom = w;
    bed.top = std::min(w + drawn, w_hi);
    out.layers.push_back(bed);
    out.drawn_thickness.push_back(drawn);
    w = bed.top;
  }
  if (!out.layers.empty()) out.layers.back().top = w_hi;

  for (std::size_t i = 0; i + 1 < out.layers.size(); ++i) {
    Fracture3 f = plane_through_box(nb, out.layers[i].top, domain);
    f.kind = LineKind::Bedding;
    f.set = static_cast<int>(spec.sets.size());
    f.layer = static_cast<int>(i);
    out.bed_boundaries.push_back(f);
  }

  // The extent of each bed's slab along each set's normal, once, for the
  // budget and the joints.
  const std::size_t nbeds = out.layers.size();
  std::vector<std::vector<std::pair<double, double>>> extent(spec.sets.size());
  double joints_expected = 0;
  for (std::size_t k = 0; k < spec.sets.size(); ++k) {
    const Vec3 m = normal_from_dip(spec.sets[k].dip_deg, spec.sets[k].dip_direction_deg);
    for (std::size_t i = 0; i < nbeds; ++i) {
      extent[k].push_back(range_along(m, slab_vertices(domain, nb, out.layers[i].bottom, out.layers[i].top)));
      const double median = out.drawn_thickness[i] / spec.sets[k].fsi;
      joints_expected += (extent[k][i].second - extent[k][i].first) / (median * (1 - spec.sets[k].randomness)) + 2;
    }
  }
  if (joints_expected > kMaxLayeredJoints)
    throw InputError("The layered joint sets would make up to about " + format_number(joints_expected, 3) +
                     " joints, more than the limit of " + format_number(kMaxLayeredJoints) + "; lower their FSI.");

  out.per_set.assign(spec.sets.size(), std::vector<BedSetStats>(nbeds));
  for (std::size_t k = 0; k < spec.sets.size(); ++k) {
    const LayerSetSpec3& set = spec.sets[k];
    const Vec3 m = normal_from_dip(set.dip_deg, set.dip_direction_deg);
    const std::string tag = "layering3d.set." + std::to_string(k);
    for (std::size_t i = 0; i < nbeds; ++i) {
      const Layer& bed = out.layers[i];
      BedSetStats& stats = out.per_set[k][i];
      Stream rng(seed, tag, i);
      const double median = out.drawn_thickness[i] / set.fsi;  // the whole bed's FSI, also for the cut top bed
      stats.target_median = median;
      const auto [s_lo, s_hi] = extent[k][i];
      const double phase = rng.uniform01();  // two statements: the order of the draws is fixed
      double s = s_lo - phase * rng.around(median, set.randomness);
      const ConvexRegion slab{{HalfSpace{nb, bed.top}, HalfSpace{-nb, -bed.bottom}}};
      bool previous_kept = false;
      double last_spacing = 0;
      while (s <= s_hi) {
        Polygon3 poly = clip_polygon(plane_in_box(m, s, domain), slab);
        remove_duplicate_vertices(poly, 1e-12 * diag);
        const double area = polygon_area(poly);
        const bool kept = poly.size() >= 3 && area > 1e-12 * diag * diag;
        if (kept) {
          Fracture3 f;
          f.shape = FractureShape::Polygon;
          f.normal = m;
          f.centre = polygon_centroid(poly);
          f.vertices = std::move(poly);
          f.set = static_cast<int>(k);
          f.layer = static_cast<int>(i);
          out.joints.push_back(std::move(f));
          ++stats.joints;
          stats.area += area;
          if (previous_kept) stats.spacings.push_back(last_spacing);
        }
        previous_kept = kept;
        last_spacing = rng.around(median, set.randomness);
        s += last_spacing;
      }
      const double realised = stats.median_spacing();
      stats.realised_fsi = realised > 0 ? out.drawn_thickness[i] / realised : 0;
    }
  }
  for (std::size_t i = 0; i < nbeds && !spec.sets.empty(); ++i) {
    out.layers[i].target_fsi = spec.sets[0].fsi;
    out.layers[i].realised_fsi = out.per_set[0][i].realised_fsi;
  }
  return out;
}

void add_layering(FractureModel& model, const LayeringSpec3& spec, const LayeringOutput3& out) {
  const int base = static_cast<int>(model.sets.size());
  for (const LayerSetSpec3& s : spec.sets) model.sets.push_back({s.name, "layered"});
  model.sets.push_back({spec.bedding_set, "bedding"});
  for (const auto* list : {&out.bed_boundaries, &out.joints})
    for (Fracture3 f : *list) {
      f.set += base;
      model.fractures.push_back(std::move(f));
    }
  model.layers = out.layers;
  model.bed_normal = out.bed_normal;
}

}  // namespace dda::dl
