// Joint water loads of the 2D solver (water_faces.hpp).
#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "2d/water_faces.hpp"

namespace dda::df {

std::vector<WaterLoad<2>> water_loads_2d(const WaterTable<2>& water, const std::vector<double>& saturation,
                                         const std::vector<const Polygon2*>& blocks,
                                         const std::vector<Contact>& contacts, double reach) {
  constexpr double kSinTol = 0.173648;  // sin(10 degrees), as tributary_length
  std::vector<WaterLoad<2>> loads;
  std::set<std::tuple<int, int, int, int>> seen;  // (edge block, edge, other block, its edge), lower block first
  for (const Contact& c : contacts) {
    const double sat = saturation[c.joint];
    // A glued contact is across one of DC's artificial cuts, inside one
    // piece of rock: no joint, no water.
    if (sat <= 0 || c.glued) continue;
    const Polygon2& pe = *blocks[c.eblock];
    const Polygon2& pv = *blocks[c.vblock];
    const int ne = static_cast<int>(pe.size()), nv = static_cast<int>(pv.size());
    const Vec2 a = pe[c.edge], b = pe[(c.edge + 1) % ne];
    const double len = (b - a).norm();
    if (len <= 0) continue;
    const Vec2 t = (b - a) / len;
    const Vec2 n(t.y(), -t.x());  // outward normal of the edge (blocks are counter-clockwise)
    for (const int k : {(c.vertex + nv - 1) % nv, c.vertex}) {  // the two edges of the vertex block at the vertex
      const Vec2 q0 = pv[k], q1 = pv[(k + 1) % nv];
      const double lq = (q1 - q0).norm();
      if (lq <= 0) continue;
      const Vec2 tq = (q1 - q0) / lq;
      if (tq.dot(t) >= 0 || std::abs(cross(tq, t)) > kSinTol) continue;  // not facing
      if (std::abs((q0 - a).dot(n)) > reach || std::abs((q1 - a).dot(n)) > reach) continue;
      const auto key = c.eblock < c.vblock ? std::make_tuple(c.eblock, c.edge, c.vblock, k)
                                           : std::make_tuple(c.vblock, k, c.eblock, c.edge);
      if (!seen.insert(key).second) continue;
      // The stretch of the edge both faces cover.
      const double s0 = std::max(0.0, std::min((q0 - a).dot(t), (q1 - a).dot(t)));
      const double s1 = std::min(len, std::max((q0 - a).dot(t), (q1 - a).dot(t)));
      if (s1 <= s0) continue;
      const PressureResultant<2> r = pressure_on_segment(water, a + s0 * t, a + s1 * t);
      if (r.force <= 0) continue;
      const Vec2 f = sat * r.force * n;  // pushes the vertex block off the edge
      loads.push_back({c.vblock, r.centre, f});
      loads.push_back({c.eblock, r.centre, -f});
    }
  }
  return loads;
}

}  // namespace dda::df
