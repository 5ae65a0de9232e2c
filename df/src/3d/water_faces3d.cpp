// Joint water loads of the 3D solver (water_faces3d.hpp).
#include "3d/facing_patches3d.hpp"
#include "3d/water_faces3d.hpp"

namespace dda::df {

std::vector<WaterLoad<3>> water_loads_3d(const WaterTable<3>& water, const std::vector<double>& saturation,
                                         const std::vector<Polyhedron>& blocks,
                                         const std::vector<df3::Contact3>& contacts, double reach) {
  auto wet = [&](const df3::Contact3& c) { return saturation[static_cast<std::size_t>(c.joint)] > 0; };
  std::vector<WaterLoad<3>> loads;
  for (const FacingPatch3& p : facing_patches3(blocks, contacts, reach, wet)) {
    const df3::Contact3& c = contacts[p.contact];
    const PressureResultant<3> r = pressure_on_polygon(water, p.polygon);
    if (r.force <= 0) continue;
    const Eigen::Vector3d f = saturation[static_cast<std::size_t>(c.joint)] * r.force * p.normal;  // pushes block i off face j
    loads.push_back({c.i, r.centre, f});
    loads.push_back({c.j, r.centre, -f});
  }
  return loads;
}

}  // namespace dda::df
