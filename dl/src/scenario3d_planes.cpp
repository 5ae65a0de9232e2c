// Sections `persistent_sets` (spaced planes through the whole domain) and
// `planes` (deterministic planes or discs, one set each).
#include "builder.hpp"
#include "dda/dl/fractures3d.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl::detail {

void read_persistent_sets3(const YamlNode& root, Builder3& b) {
  nlohmann::json rep = nlohmann::json::array();
  const auto items = root.list_or_empty("persistent_sets");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const YamlNode& n = items[i];
    n.allow({"name", "dip", "dip_direction", "spacing", "point", "randomness"});
    PersistentSetSpec spec;
    spec.name = read_name(n, "S", i);
    spec.dip_deg = read_dip(n, "dip");
    spec.dip_direction_deg = read_dip_direction(n, "dip_direction");
    spec.spacing = n.number("spacing", Range::positive());
    if (n.has("point")) spec.point = b.local(point3(n, "point"));
    spec.randomness = n.number("randomness", 0.0, Range::half_open(0, 1));
    // Checked here too, to name the key: the generator's message names the set.
    if (spec.point && spacings_to_point(spec, b.model.domain) > kMaxSpacingsToPoint)
      n.fail_key("point", "lies " + format_number(spacings_to_point(spec, b.model.domain), 3) +
                              " spacings from the domain, more than the limit of " +
                              format_number(kMaxSpacingsToPoint) + "; give a point nearer the domain");
    const int set = b.add_new_set(spec.name, "persistent", n, "name");
    Stream rng(b.seed, "persistent3d.set", i);
    std::vector<Fracture3> planes;
    try {
      planes = generate_persistent_set(spec, set, b.model.domain, rng);
    } catch (const InputError& e) {
      fail_from(n, "spacing", "cannot be generated", e);
    }
    rep.push_back({{"name", spec.name},
                   {"set", set},
                   {"asked",
                    {{"dip", spec.dip_deg},
                     {"dip_direction", spec.dip_direction_deg},
                     {"spacing", spec.spacing},
                     {"randomness", spec.randomness}}},
                   {"planes", planes.size()}});
    for (Fracture3& f : planes) b.model.fractures.push_back(std::move(f));
  }
  b.report["persistent_sets"] = rep;
}

void read_planes3(const YamlNode& root, Builder3& b) {
  nlohmann::json rep = nlohmann::json::array();
  const auto items = root.list_or_empty("planes");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const YamlNode& n = items[i];
    n.allow({"name", "dip", "dip_direction", "point", "radius"});
    PlaneSpec spec;
    const std::string name = read_name(n, "P", i);
    spec.dip_deg = read_dip(n, "dip");
    spec.dip_direction_deg = read_dip_direction(n, "dip_direction");
    const Vec3 user_point = point3(n, "point");
    spec.point = b.local(user_point);
    if (n.has("radius")) spec.radius = n.number("radius", Range::positive());
    // One set per plane: a fault or a mapped joint usually has properties of
    // its own in DF, and a set is what carries them.
    const int set = b.add_new_set(name, "plane", n, "name");
    const Fracture3 f = make_plane(spec, set);  // the keys are checked above: it cannot throw
    if (!(fracture_area_in_box(f, b.model.domain) > 0))
      n.fail("misses the domain (a plane or disc must cut it to make a fracture)");
    b.model.fractures.push_back(f);
    rep.push_back({{"name", name},
                   {"set", set},
                   {"dip", spec.dip_deg},
                   {"dip_direction", spec.dip_direction_deg},
                   {"point", {user_point.x(), user_point.y(), user_point.z()}},
                   {"radius", spec.radius ? nlohmann::json(*spec.radius) : nlohmann::json(nullptr)}});
  }
  b.report["planes"] = rep;
}

}  // namespace dda::dl::detail
