#pragma once
// Limit equilibrium of a tetrahedral wedge on two planes (and, as a special
// case, of a block on one plane), Goodman & Shi's vector method.
//
// Forces per unit weight W: the resultant is r = (0, 0, -1) + k u, with u the
// unit direction of the pseudo-static inertial (body) force k W (opposite to
// the ground acceleration). Normals n1, n2 are the upward plane normals; the
// block rests on the upper side of both planes.
// Mode (first that applies):
//   lifting        r.n1 >= 0 and r.n2 >= 0;
//   double-face    N1 = -((r x n2).I)/|I|^2 >= 0 and N2 = ((r x n1).I)/|I|^2 >= 0,
//                  I = n1 x n2; driving D = |r.e|, e = I/|I|;
//   single face i  N_i = -r.n_i > 0 and the sliding direction s_i (r projected
//                  on plane i) leaves the other plane (s_i.n_j >= 0); D = |s_i|;
//   otherwise lifting.
// Factor of safety FS = (N1 tan phi1 + N2 tan phi2 + (c1 A1 + c2 A2)/W) / D
// (only the planes in contact count); infinite when D = 0, zero when lifting.
// Water on the planes (forces U1, U2 per unit weight, along the upward
// normals: they push the wedge off its planes) adds U1 n1 + U2 n2 to r for
// the mode and the normal reactions, which become the effective ones; being
// normal to both planes it leaves the driving along the line unchanged.
// Yield acceleration: the smallest k >= 0 with FS <= 1 (0 if FS < 1 already).
#include <optional>
#include <string>

#include "dda/analysis/orientation.hpp"

namespace dda::analysis {

struct WedgeSpec {
  Plane plane1, plane2;
  double phi1_deg = 30.0, phi2_deg = 30.0;
  // Optional cohesion: c (kPa) times area (m^2) over weight (kN).
  double cohesion1_kpa = 0.0, cohesion2_kpa = 0.0;
  double area1_m2 = 0.0, area2_m2 = 0.0;
  double weight_kn = 0.0;  // needed only with cohesion
  // Water forces on plane 1 and 2 per unit weight (e.g. Hoek & Bray's
  // saturated wedge, wedge_body.hpp); 0: dry.
  double water1 = 0.0, water2 = 0.0;
};

struct WedgeEquilibrium {
  std::string mode;        // "double-face", "single-face-1", "single-face-2", "lifting"
  double fs = 0.0;         // factor of safety (infinity if nothing drives)
  double n1 = 0.0, n2 = 0.0;  // normal reactions per unit weight
  double driving = 0.0;    // driving force per unit weight
  Vec3 sliding_direction = Vec3::Zero();  // unit, zero when lifting
};

struct WedgeGeometry {
  Vec3 line = Vec3::Zero();   // unit, pointing down the line of intersection
  TrendPlunge line_orientation;
  double wedge_factor = 0.0;  // K = (N1 + N2) / cos(plunge) under gravity alone
};

// InputError if the planes are parallel (no line of intersection).
WedgeGeometry wedge_geometry(const WedgeSpec& spec);
WedgeEquilibrium wedge_equilibrium(const WedgeSpec& spec, const Vec3& r_per_unit_weight);

struct YieldResult {
  double k = 0.0;          // yield acceleration in g (body acceleration along u)
  bool found = false;      // false if FS stays above 1 up to k_max
  std::string mode;        // mode at yield
};
YieldResult wedge_yield(const WedgeSpec& spec, const Vec3& u, double k_max = 10.0);

// Friction angle (same on both planes) at which FS = 1 under gravity alone,
// cohesion included; nullopt if none in (0, 89.9) degrees.
std::optional<double> wedge_critical_friction(const WedgeSpec& spec);

}  // namespace dda::analysis
