#pragma once
// Mechanically layered rock in 3D, the 2D scheme of layering.hpp on planes:
// beds of log-normal thickness (with a minimum) stacked along the bedding
// normal, and joint sets bounded by each bed, whose median spacing is the
// bed's drawn thickness / FSI (fracture spacing index).
//
// Coordinates along the bedding normal n_b (Layer::bottom/top) are n_b . x.
// A layered joint is the joint plane clipped to its bed's slab and to the
// domain box: a convex polygon spanning exactly the bed's thickness.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/fracture_model.hpp"
#include "dda/dl/layering.hpp"  // ThicknessSpec, draw_thickness, lognormal_from_moments

namespace dda::dl {

struct LayerSetSpec3 {
  std::string name;
  double dip_deg = 90;           // the joints' plane, [0, 90]
  double dip_direction_deg = 0;
  double fsi = 1;                // > 0: bed thickness / median spacing
  double randomness = 0;         // [0, 1): spacing = median * (1 + r X), X uniform on [-1, 1)
};

struct LayeringSpec3 {
  double dip_deg = 0;            // bedding; default horizontal
  double dip_direction_deg = 0;
  ThicknessSpec thickness;
  std::string bedding_set = "bedding";
  std::vector<LayerSetSpec3> sets;
};

// What one set made in one bed.
struct BedSetStats {
  std::size_t joints = 0;        // polygons in the domain
  double area = 0;               // m^2, their total area
  std::vector<double> spacings;  // normal spacings between consecutive joints in the domain
  double target_median = 0;      // drawn bed thickness / FSI
  double median_spacing() const;
  double realised_fsi = 0;       // drawn bed thickness / median_spacing() (0 if fewer than two joints)
};

struct LayeringOutput3 {
  Vec3 bed_normal{0, 0, 1};           // unit, upper hemisphere
  std::vector<Layer> layers;          // bottom to top along bed_normal; FSIs of the first set
  std::vector<double> drawn_thickness;  // per bed; the top bed is cut by the domain
  // Interior bed boundaries: Plane fractures of kind Bedding, centre inside
  // the domain, set = spec.sets.size() (the bedding set follows the joint
  // sets), layer = the bed below.
  std::vector<Fracture3> bed_boundaries;
  // Polygon joints, set = index into spec.sets, layer = their bed.
  std::vector<Fracture3> joints;
  std::vector<std::vector<BedSetStats>> per_set;  // [set][bed]
};

// Upper bound of the expected number of beds, to refuse absurd requests.
double expected_bed_count3(const LayeringSpec3& spec, const Box3& domain);

// Beds from the lowest corner of the box along the bedding normal to the
// highest, thicknesses from Stream(seed, "layering3d.thickness"); the last bed
// is cut by the box and may be thinner than the minimum. Joints of set k in
// bed i draw from Stream(seed, "layering3d.set.<k>", i): a random phase (the
// first joint a random fraction of one spacing before the box), then one
// spacing draw per joint. InputError for bad parameters (naming the set) or
// a joint set parallel to the beds (less than 5 degrees apart, as in 2D).
LayeringOutput3 generate_layering3d(const LayeringSpec3& spec, const Box3& domain, std::uint64_t seed);

// Appends the output to a model: one set per joint set (origin "layered") and
// the bedding set (origin "bedding", named spec.bedding_set), the fractures
// with their set indices shifted accordingly, the layers and the bed normal.
void add_layering(FractureModel& model, const LayeringSpec3& spec, const LayeringOutput3& out);

}  // namespace dda::dl
