#include "dda/study/wedge_case.hpp"

#include <cmath>
#include <limits>

namespace dda::study {

namespace {

analysis::Plane read_plane(const YamlNode& node) {
  node.allow({"dip", "dip_direction"});
  analysis::Plane p;
  p.dip_deg = node.number("dip", Range::closed(0, 90));
  p.dip_direction_deg = std::fmod(node.number("dip_direction", Range::closed(-360, 720)) + 360.0, 360.0);
  return p;
}

}  // namespace

WedgeCase read_wedge_case(const YamlNode& node) {
  node.allow({"plane1", "plane2", "phi", "phi1", "phi2", "azimuth"});
  WedgeCase c;
  c.spec.plane1 = read_plane(node.child("plane1"));
  c.spec.plane2 = read_plane(node.child("plane2"));
  const Range friction = Range::half_open(0, 90);
  if (node.has("phi")) {
    if (node.has("phi1") || node.has("phi2")) node.fail("takes phi, or phi1 and phi2, not both");
    c.spec.phi1_deg = c.spec.phi2_deg = node.number("phi", friction);
  } else {
    c.spec.phi1_deg = node.number("phi1", friction);
    c.spec.phi2_deg = node.number("phi2", friction);
  }
  if (node.has("azimuth")) c.azimuth_deg = node.number("azimuth", Range::closed(-360, 720));
  // Parallel planes have no line of intersection: refused here, by name.
  try {
    analysis::wedge_geometry(c.spec);
  } catch (const std::exception& e) {
    node.fail(std::string("has planes that make no wedge: ") + e.what());
  }
  return c;
}

std::vector<double> wedge_measures(const WedgeCase& c, const std::vector<MeasureSpec>& measures) {
  using namespace analysis;
  const double none = std::numeric_limits<double>::quiet_NaN();
  const WedgeGeometry g = wedge_geometry(c.spec);
  // Computed once each, and only when a measure asks (the yield search is
  // most of a case's cost).
  std::optional<WedgeEquilibrium> equilibrium;
  std::optional<YieldResult> yield;
  std::vector<double> out;
  for (const MeasureSpec& m : measures) {
    if (m.kind == "fs") {
      if (!equilibrium) equilibrium = wedge_equilibrium(c.spec, Vec3(0, 0, -1));
      out.push_back(equilibrium->fs);
    } else if (m.kind == "yield_acceleration") {
      if (!yield) {
        const Vec3 dir = horizontal(c.azimuth_deg ? *c.azimuth_deg : g.line_orientation.trend_deg).normalized();
        yield = wedge_yield(c.spec, dir);
      }
      out.push_back(yield->found ? yield->k : none);
    } else if (m.kind == "wedge_factor") {
      out.push_back(g.wedge_factor);
    } else if (m.kind == "critical_friction") {
      const auto crit = wedge_critical_friction(c.spec);
      out.push_back(crit ? *crit : none);
    } else if (m.kind == "trend") {
      out.push_back(g.line_orientation.trend_deg);
    } else if (m.kind == "plunge") {
      out.push_back(g.line_orientation.plunge_deg);
    } else {
      out.push_back(none);  // read_measure admits no other kind for a wedge
    }
  }
  return out;
}

}  // namespace dda::study
