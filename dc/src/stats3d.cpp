// Sizes and shapes of 3D blocks, per rock body. The shape measure comes from
// the body's second moment of volume, so it needs no choice of axes: for a
// box a x b x c (a >= b >= c) the moments are V a^2/12, V b^2/12, V c^2/12
// and the aspect sqrt(max/min) is a / c.
#include "dda/dc/stats3d.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <map>

#include "dda/common/coordinate_range.hpp"
#include "dda/common/geometry.hpp"
#include "distribution.hpp"

namespace dda::dc {

namespace {

const char* const kDefinitions[][2] = {
    {"bodies", "number of rock bodies: convex blocks, and non-convex bodies made of convex parts glued together"},
    {"blocks", "number of convex parts"},
    {"volume", "body volume, m^3"},
    {"equivalent_diameter", "diameter of the sphere of the body's volume, (6 V / pi)^(1/3), m"},
    {"aspect", "sqrt(largest / smallest eigenvalue) of the body's second moment of volume about its centroid: "
               "a / c for an a x b x c box, 1 for a cube or sphere"},
    {"faces", "faces per convex part"},
    {"removability", "bodies per block-theory mode (Goodman & Shi): not_exposed, tapered, removable (held by "
                     "gravity), falls, slides_one_face, slides_two_faces"},
    {"removable_volume", "volume of the bodies gravity moves (falls, slides_one_face, slides_two_faces), m^3"},
    {"per_layer", "bodies whose centroid lies in each bed, and their mean volume"},
};

}  // namespace

nlohmann::json block_statistics_3d(const PolyhedronModel& model, int bins) {
  using nlohmann::json;
  bins = std::max(bins, 1);
  std::vector<double> volume, diameter, aspect, faces;
  std::map<std::string, int> modes;
  for (int m = 0; m <= static_cast<int>(Removability::SlidesTwo); ++m) modes[to_string(static_cast<Removability>(m))] = 0;
  std::vector<int> layer_bodies(model.layers.size(), 0);
  std::vector<double> layer_volume(model.layers.size(), 0);
  double total = 0, removable_volume = 0;
  for (const Polyhedron& p : model.blocks) faces.push_back(static_cast<double>(p.faces.size()));
  for (const Body3& body : model.bodies) {
    double v = 0;
    Vec3 first = Vec3::Zero();
    for (int i : body.parts) {
      const Polyhedron& p = model.blocks[static_cast<std::size_t>(i)];
      v += p.volume;
      first += p.volume * p.centroid;
    }
    if (v <= 0) continue;
    const Vec3 c = first / v;
    // Parallel-axis sum of the parts' second moments about the body centroid.
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    for (int i : body.parts) {
      const Polyhedron& p = model.blocks[static_cast<std::size_t>(i)];
      const Vec3 d = p.centroid - c;
      second += p.second_moment + p.volume * d * d.transpose();
    }
    const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(second, Eigen::EigenvaluesOnly).eigenvalues();
    volume.push_back(v);
    total += v;
    diameter.push_back(std::cbrt(6 * v / kPi));
    if (ev[0] > 0) aspect.push_back(std::sqrt(ev[2] / ev[0]));
    ++modes[to_string(body.removability)];
    if (body.removability == Removability::Falls || body.removability == Removability::SlidesOne ||
        body.removability == Removability::SlidesTwo)
      removable_volume += v;
    const double level = c.dot(model.bed_normal.normalized());
    for (std::size_t l = 0; l < model.layers.size(); ++l)
      if (level >= model.layers[l].bottom && level <= model.layers[l].top) {
        ++layer_bodies[l];
        layer_volume[l] += v;
        break;
      }
  }
  json j;
  j["dimension"] = 3;
  j["bodies"] = model.bodies.size();
  j["blocks"] = model.blocks.size();
  j["total_volume"] = total;
  j["domain_volume"] = model.domain_volume;
  j["excavated_volume"] = model.excavated_volume;
  j["unfinished_cuts"] = model.unfinished_cuts;
  j["volume"] = detail::distribution(volume, bins);
  j["equivalent_diameter"] = detail::distribution(diameter, bins);
  j["aspect"] = detail::distribution(aspect, bins);
  j["faces"] = detail::distribution(faces, bins);
  j["removability"] = modes;
  j["removable_volume"] = removable_volume;
  json layers = json::array();
  const double level0 = model.bed_normal.dot(model.origin);  // the user's levels
  for (std::size_t l = 0; l < model.layers.size(); ++l)
    layers.push_back({{"layer", l},
                      {"bottom", user_level(model.layers[l].bottom, level0)},
                      {"top", user_level(model.layers[l].top, level0)},
                      {"bodies", layer_bodies[l]},
                      {"mean_volume", layer_bodies[l] ? json(layer_volume[l] / layer_bodies[l]) : json(nullptr)}});
  j["per_layer"] = layers;
  json defs;
  for (const auto& d : kDefinitions) defs[d[0]] = d[1];
  j["definitions"] = defs;
  return j;
}

}  // namespace dda::dc
