// Poisson (Baecher) disc sets in a box with a margin.
#include <cmath>
#include <string>

#include "builder.hpp"  // detail::format_number
#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"
#include "dda/dl/dfn3d.hpp"

namespace dda::dl {

using detail::format_number;

void validate_box(const Box3& box, const std::string& what) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(box.lo[k]) || !std::isfinite(box.hi[k]) || !(box.lo[k] < box.hi[k]))
      throw InputError(what + " must have finite bounds with min < max on " + std::string(1, "xyz"[k]) + ", got [" +
                       format_number(box.lo[k]) + ", " + format_number(box.hi[k]) + "].");
}

std::vector<Disc> generate_disc_set(const DiscSetSpec& spec, int set, const Box3& domain, double margin,
                                    Stream& rng, std::vector<double>* rotations) {
  const std::string where = "Fracture set '" + spec.name + "'";
  validate_box(domain, "The fracture network's domain");
  if (!(margin >= 0) || !std::isfinite(margin))
    throw InputError("The fracture network's margin must be a finite number >= 0, got " + format_number(margin) + ".");
  const bool by_count = spec.count > 0, by_p32 = spec.p32 != 0;
  if (by_count == by_p32)
    throw InputError(where + " needs exactly one intensity, a disc count or a P32 target.");
  if (by_p32 && (!(spec.p32 > 0) || !std::isfinite(spec.p32)))
    throw InputError(where + " has P32 target " + format_number(spec.p32) + "; it must be a finite number > 0.");
  if (spec.count > kMaxDiscsPerSet)
    throw InputError(where + " asks for " + std::to_string(spec.count) + " discs, more than the limit of " +
                     std::to_string(kMaxDiscsPerSet) + ".");
  if (spec.polygon_sides != 0 && (spec.polygon_sides < 3 || spec.polygon_sides > kMaxPolygonSides))
    throw InputError(where + " has " + std::to_string(spec.polygon_sides) +
                     " polygon sides; it must be 0 (discs) or from 3 to " + std::to_string(kMaxPolygonSides) + ".");
  const bool polygons = spec.polygon_sides != 0;
  if (rotations) rotations->clear();
  const Eigen::Vector3d mean = normal_from_dip(spec.dip_deg, spec.dip_direction_deg);
  if (!(spec.kappa >= 0))
    throw InputError(where + " has Fisher kappa " + format_number(spec.kappa) + "; it must be >= 0 (or infinity).");

  const Box3 grown = domain.grown(margin);
  const Eigen::Vector3d size = grown.hi - grown.lo;
  const double target_area = spec.p32 * grown.volume();
  // Refuse before drawing when even the expected count is beyond the limit.
  if (by_p32 && target_area / spec.size.mean_area() > static_cast<double>(kMaxDiscsPerSet))
    throw InputError(where + " would need about " + format_number(target_area / spec.size.mean_area(), 3) +
                     " discs to reach P32 " + format_number(spec.p32) + ", more than the limit of " +
                     std::to_string(kMaxDiscsPerSet) + "; lower it or raise the radii.");
  std::vector<Disc> discs;
  if (by_count) discs.reserve(spec.count);
  double area = 0;
  while (by_count ? discs.size() < spec.count : area < target_area) {
    if (discs.size() == kMaxDiscsPerSet)
      throw InputError(where + " would need more than " + std::to_string(kMaxDiscsPerSet) +
                       " discs to reach P32 " + format_number(spec.p32) + "; lower it or raise the radii.");
    Disc d;
    for (int k = 0; k < 3; ++k) d.centre[k] = grown.lo[k] + rng.uniform01() * size[k];
    d.normal = upper_hemisphere(sample_fisher(mean, spec.kappa, rng));
    d.radius = spec.size.sample(rng);
    d.set = set;
    if (polygons) {
      const double turn = 2 * kPi * rng.uniform01();
      if (rotations) rotations->push_back(turn);
    }
    area += kPi * d.radius * d.radius;
    discs.push_back(d);
  }
  return discs;
}

std::vector<Disc> generate_dfn(const std::vector<DiscSetSpec>& sets, const Box3& domain, double margin,
                               std::uint64_t seed) {
  std::vector<Disc> all;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    Stream rng(seed, "dfn3d.set", i);
    const auto discs = generate_disc_set(sets[i], static_cast<int>(i), domain, margin, rng);
    all.insert(all.end(), discs.begin(), discs.end());
  }
  return all;
}

}  // namespace dda::dl
