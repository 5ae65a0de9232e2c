#pragma once
// 3D discrete fracture networks: sets of discs with Poisson (Baecher)
// centres, Fisher orientations and a radius law.
//
// Conventions: x east, y north, z up; metres. A plane is given by its dip d
// and dip direction a in degrees; its normal is
//   (sin d sin a, sin d cos a, cos d),
// the upper-hemisphere normal (z >= 0). Discs store that normal.
//
// Each set draws from its own stream (derive_seed(seed, "dfn3d.set", i)), so
// the same seed gives the same discs and adding a set does not change another.
// Measures of the result (P10, P21, P32) are in dfn3d_measures.hpp.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "dda/common/geometry3d.hpp"
#include "dda/dl/random.hpp"

namespace dda::dl {

struct Disc {
  Eigen::Vector3d centre{0, 0, 0};
  Eigen::Vector3d normal{0, 0, 1};  // unit, z >= 0
  double radius = 0;
  int set = 0;
};

// The domain box is the common dda::Box3 (geometry3d.hpp).
using dda::Box3;

// InputError unless every lo < hi and all are finite; `what` names the box.
void validate_box(const Box3& box, const std::string& what);

// ---- orientation -------------------------------------------------------

struct DipDirection {
  double dip_deg = 0;            // [0, 90]
  double dip_direction_deg = 0;  // [0, 360); 0 for a horizontal plane
};

// Upper-hemisphere unit normal of a plane; InputError unless dip is in
// [0, 90] and the dip direction is finite.
Eigen::Vector3d normal_from_dip(double dip_deg, double dip_direction_deg);
// Dip and dip direction of the plane with normal n (either sign, any length
// > 0); InputError for a zero or non-finite vector.
DipDirection dip_from_normal(const Eigen::Vector3d& n);
// n or -n, whichever has z >= 0 (for z == 0, the one with y > 0, or x > 0),
// so that a plane has one stored normal.
Eigen::Vector3d upper_hemisphere(const Eigen::Vector3d& n);
// Unit vectors e1, e2 with (e1, e2, n) a right-handed orthonormal frame, for a
// unit n: coordinates in a plane with normal n.
std::pair<Eigen::Vector3d, Eigen::Vector3d> plane_basis(const Eigen::Vector3d& n);

// A unit vector from the Fisher distribution about the unit vector `mean`
// with concentration kappa >= 0: the angle theta from the mean is drawn by the
// exact inverse CDF
//   cos theta = 1 + ln(1 - U (1 - e^{-2 kappa})) / kappa
// (the limit cos theta = 1 - 2U, uniform on the sphere, for kappa -> 0) and
// the azimuth about the mean is uniform. kappa = infinity returns the mean.
// The sample is on the mean's side (not folded to the upper hemisphere), so
// the resultant of many samples estimates the mean; two draws per sample.
Eigen::Vector3d sample_fisher(const Eigen::Vector3d& mean, double kappa, Stream& rng);

// ---- radius laws -------------------------------------------------------

// Law of the disc radius. Made only through the factories, which check the
// parameters (InputError naming the law and the parameter).
class SizeLaw {
 public:
  enum class Kind { constant, lognormal, exponential, power_law };

  static SizeLaw constant(double radius);
  // Mean and standard deviation of the radius itself (not of its logarithm).
  static SizeLaw lognormal(double mean, double std);
  static SizeLaw exponential(double mean);
  // Density p(r) ~ r^-alpha on [rmin, rmax], alpha > 1, 0 < rmin < rmax < inf.
  static SizeLaw power_law(double alpha, double rmin, double rmax);

  Kind kind() const { return kind_; }
  const char* name() const;
  double sample(Stream& rng) const;
  // Largest radius the law can give (infinity for log-normal and exponential):
  // a margin at least this wide removes the edge effect entirely.
  double max_radius() const;
  // E[pi r^2], the mean disc area: with a P32 target the expected number of
  // discs is P32 * volume / mean_area().
  double mean_area() const;

 private:
  SizeLaw(Kind kind, double a, double b, double c) : kind_(kind), a_(a), b_(b), c_(c) {}
  Kind kind_;
  double a_, b_, c_;  // meaning depends on kind_; see dfn3d_size.cpp
};

// ---- sets --------------------------------------------------------------

struct DiscSetSpec {
  std::string name;
  double dip_deg = 0;
  double dip_direction_deg = 0;
  double kappa = std::numeric_limits<double>::infinity();  // Fisher; infinity = all at the mean
  SizeLaw size = SizeLaw::constant(1);
  // Intensity: exactly one of the two. p32 is fracture area per unit volume.
  std::size_t count = 0;
  double p32 = 0;
  // 0: discs. n >= 3: convex regular n-gons of the same area pi r^2 as the
  // disc they replace (so count and P32 keep their meaning), each turned about
  // its normal by a random angle (fractures3d.hpp makes them).
  int polygon_sides = 0;
};

// Most sides a polygon set may ask for.
inline constexpr int kMaxPolygonSides = 1000;

// Most discs one set may have, so that a tiny radius with a large P32 target
// is an error rather than an exhausted memory.
inline constexpr std::size_t kMaxDiscsPerSet = 10'000'000;

// One set in `domain` grown by `margin` (>= 0) on every side: centres uniform
// (Poisson) in the grown box, normal Fisher about the set's mean, radius from
// the size law; draws per disc: 3 for the centre, 2 for the normal, then the
// radius. With a count, that many discs. With a P32 target, discs are added
// until the sum of their full areas pi r^2 divided by the grown box's volume
// reaches the target: for Poisson centres that sum over the volume is an
// unbiased estimator of the P32 of the process (Campbell's theorem: P32 =
// centre density * E[pi r^2]), and it overshoots by less than one disc. The
// P32 realised inside the domain matches it when the margin is at least the
// largest radius (SizeLaw::max_radius); a narrower margin misses discs centred
// farther out that would reach into the domain.
// A polygon set (polygon_sides >= 3) draws one more number per disc after the
// radius, the polygon's turn about its normal, 2 pi U radians, stored in
// `rotations` if given (drawn either way, so a set's discs do not depend on
// whether the caller keeps the turns). Disc sets draw no turn.
std::vector<Disc> generate_disc_set(const DiscSetSpec& spec, int set, const Box3& domain, double margin,
                                    Stream& rng, std::vector<double>* rotations = nullptr);

// All sets, set i from Stream(seed, "dfn3d.set", i), discs in set order.
std::vector<Disc> generate_dfn(const std::vector<DiscSetSpec>& sets, const Box3& domain, double margin,
                               std::uint64_t seed);

}  // namespace dda::dl
