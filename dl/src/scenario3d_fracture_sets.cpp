// Section `fracture_sets`: statistical disc or polygon sets (Poisson centres,
// Fisher orientation, a radius law, a count or a P32 target).
#include <cmath>
#include <limits>

#include "builder.hpp"
#include "dda/dl/fractures3d.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl::detail {

namespace {

struct SizeRead {
  SizeLaw law = SizeLaw::constant(1);
  double mean_radius = 1;
  nlohmann::json asked;
};

SizeRead read_size(const YamlNode& n) {
  const std::string law = n.choice("law", {"constant", "lognormal", "exponential", "power_law"});
  if (law == "constant") {
    n.allow({"law", "radius"});
    const double r = n.number("radius", Range::positive());
    return {SizeLaw::constant(r), r, {{"law", law}, {"radius", r}}};
  }
  if (law == "lognormal") {
    n.allow({"law", "mean", "std"});
    const double mean = n.number("mean", Range::positive()), std = n.number("std", Range::non_negative());
    return {SizeLaw::lognormal(mean, std), mean, {{"law", law}, {"mean", mean}, {"std", std}}};
  }
  if (law == "exponential") {
    n.allow({"law", "mean"});
    const double mean = n.number("mean", Range::positive());
    return {SizeLaw::exponential(mean), mean, {{"law", law}, {"mean", mean}}};
  }
  n.allow({"law", "alpha", "rmin", "rmax"});
  const double alpha = n.number("alpha", Range{1, 1e300, true, false});
  const double rmin = n.number("rmin", Range::positive());
  const double rmax = n.number("rmax", Range::positive());
  if (!(rmax > rmin))
    n.fail_key("rmax", "must be greater than rmin (" + format_number(rmin) + "), got " + format_number(rmax));
  // The mean radius only serves a default margin, which rmax gives here.
  // (The factories' own checks cannot fail after the ones above.)
  return {
      SizeLaw::power_law(alpha, rmin, rmax), rmin, {{"law", law}, {"alpha", alpha}, {"rmin", rmin}, {"rmax", rmax}}};
}

}  // namespace

void read_fracture_sets3(const YamlNode& root, Builder3& b) {
  nlohmann::json rep = nlohmann::json::array();
  const auto items = root.list_or_empty("fracture_sets");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const YamlNode& n = items[i];
    n.allow({"name", "dip", "dip_direction", "kappa", "size", "shape", "sides", "count", "p32", "margin"});
    DiscSetSpec spec;
    spec.name = read_name(n, "F", i);
    spec.dip_deg = read_dip(n, "dip");
    spec.dip_direction_deg = read_dip_direction(n, "dip_direction");
    spec.kappa = n.number("kappa", std::numeric_limits<double>::infinity(), Range::non_negative());
    const SizeRead size = read_size(n.child("size"));
    spec.size = size.law;
    const std::string shape = n.choice("shape", {"disc", "polygon"}, "disc");
    if (shape == "disc" && n.has("sides")) n.fail_key("sides", "goes with shape: polygon only");
    if (shape == "polygon")
      spec.polygon_sides = static_cast<int>(n.integer("sides", 6, Range::closed(3, kMaxPolygonSides)));
    const std::string intensity = n.one_of({"count", "p32"});
    if (intensity == "count")
      spec.count = static_cast<std::size_t>(n.integer("count", Range::closed(1, static_cast<double>(kMaxDiscsPerSet))));
    else
      spec.p32 = n.number("p32", Range::positive());
    // Default margin: wide enough for every fracture that can reach the
    // domain when the law is bounded; else 3 mean radii, where the tail of
    // a log-normal or exponential law leaves little out.
    const double max_r = spec.size.max_radius();
    const double margin =
        n.number("margin", std::isfinite(max_r) ? max_r : 3 * size.mean_radius, Range::non_negative());

    const int set = b.add_new_set(spec.name, "dfn", n, "name");
    Stream rng(b.seed, "dfn3d.set", i);
    std::vector<Fracture3> made;
    try {
      made = generate_fracture_set(spec, set, b.model.domain, margin, rng);
    } catch (const InputError& e) {
      fail_from(n, intensity, "cannot be generated", e);
    }
    // Fractures wholly in the margin served the statistics; DC has no use for them.
    std::size_t kept = 0;
    for (Fracture3& f : made)
      if (fracture_area_in_box(f, b.model.domain) > 0) {
        b.model.fractures.push_back(std::move(f));
        ++kept;
      }
    const double grown_volume = b.model.domain.grown(margin).volume();
    const double expected =
        spec.p32 > 0 ? spec.p32 : static_cast<double>(spec.count) * spec.size.mean_area() / grown_volume;
    b.asked_p32[static_cast<std::size_t>(set)] = expected;

    nlohmann::json asked = {{"dip", spec.dip_deg},
                            {"dip_direction", spec.dip_direction_deg},
                            {"kappa", std::isfinite(spec.kappa) ? nlohmann::json(spec.kappa) : nlohmann::json(nullptr)},
                            {"size", size.asked},
                            {"shape", shape},
                            {"margin", margin}};
    if (spec.polygon_sides) asked["sides"] = spec.polygon_sides;
    if (spec.p32 > 0)
      asked["p32"] = spec.p32;
    else
      asked["count"] = spec.count;
    rep.push_back({{"name", spec.name},
                   {"set", set},
                   {"asked", asked},
                   {"expected_p32", expected},
                   {"generated", made.size()},
                   {"in_domain", kept}});
  }
  b.report["fracture_sets"] = rep;
}

}  // namespace dda::dl::detail
