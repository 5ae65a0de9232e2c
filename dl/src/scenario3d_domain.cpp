// Section `domain` in 3D: {box: [x0, y0, z0, x1, y1, z1]}.
#include "builder.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl::detail {

void read_domain3(const YamlNode& root, Builder3& b) {
  const auto node = root.optional_child("domain");
  if (!node) root.fail_key("domain", "is required (a box [x0, y0, z0, x1, y1, z1])");
  node->allow({"box"});
  const YamlNode box = node->child("box");
  if (!box.is_sequence()) box.fail("must be [x0, y0, z0, x1, y1, z1]");
  const auto v = box.as_numbers();
  if (v.size() != 6) box.fail("must be [x0, y0, z0, x1, y1, z1], got " + std::to_string(v.size()) + " numbers");
  if (!(v[3] > v[0] && v[4] > v[1] && v[5] > v[2])) box.fail("must have x1 > x0, y1 > y0 and z1 > z0");
  b.model.domain = {Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5])};
  b.report["domain"] = {{"box", v}, {"volume", b.model.domain.volume()}};
}

}  // namespace dda::dl::detail
