// Section `trace_planes`: sections of the network that `dda dl` writes as 2D
// lines files next to the fractures file.
#include <cctype>

#include "builder.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/polygon3d.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl::detail {

namespace {

// The name becomes part of a file name (<stem>.<name>.lines.h5): keep it to
// characters every file system takes.
bool file_safe(const std::string& name) {
  for (const char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return !name.empty();
}

}  // namespace

void read_trace_planes3(const YamlNode& root, Builder3& b) {
  nlohmann::json rep = nlohmann::json::array();
  const auto items = root.list_or_empty("trace_planes");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const YamlNode& n = items[i];
    n.allow({"name", "point", "dip", "dip_direction"});
    TracePlaneSpec t;
    t.name = read_name(n, "T", i);
    if (!file_safe(t.name))
      n.fail_key("name",
                 "must hold only letters, digits, '_' and '-' (it becomes part of a file name), got '" + t.name + "'");
    for (const TracePlaneSpec& other : b.trace_planes)
      if (other.name == t.name) n.fail_key("name", "'" + t.name + "' is already the name of another trace plane");
    const Vec3 user_point = point3(n, "point");
    t.point = b.local(user_point);
    t.dip_deg = read_dip(n, "dip");
    t.dip_direction_deg = read_dip_direction(n, "dip_direction");
    const Vec3 normal = normal_from_dip(t.dip_deg, t.dip_direction_deg);
    const Polygon3 section = plane_in_box(normal, normal.dot(t.point), b.model.domain);
    if (section.empty()) n.fail("misses the domain (the plane through " + point_text(user_point) + " must cut it)");
    rep.push_back({{"name", t.name},
                   {"point", {user_point.x(), user_point.y(), user_point.z()}},
                   {"dip", t.dip_deg},
                   {"dip_direction", t.dip_direction_deg},
                   {"section_area", polygon_area(section)}});
    b.trace_planes.push_back(t);
  }
  b.report["trace_planes"] = rep;
}

}  // namespace dda::dl::detail
