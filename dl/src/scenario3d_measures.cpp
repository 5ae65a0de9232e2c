// The 3D report's measures of every set: what was made, against what was asked.
#include <Eigen/Eigenvalues>
#include <cmath>

#include "dda/dl/dfn3d.hpp"
#include "dda/dl/fracture_measures3d.hpp"
#include "dda/dl/fractures3d.hpp"
#include "dda/dl/polygon3d.hpp"
#include "scenario3d_builder.hpp"

namespace dda::dl::detail {

namespace {

// Running sums of one set (or of all).
struct Tally {
  std::size_t fractures = 0, sized = 0;
  double area_in_domain = 0, radius_sum = 0;
  double crossings[3] = {0, 0, 0};  // scan lines along x, y, z
  double traces[3] = {0, 0, 0};     // trace length on the planes x, y, z = centre
  std::vector<Vec3> normals;
};

// The mean orientation and Fisher's kappa estimate. Stored normals are folded
// to the upper hemisphere, which splits a steep set in two; unfolding each
// onto the side of the set's principal axis (largest eigenvector of the sum
// of n n^T) first gives the resultant the Fisher estimate assumes.
nlohmann::json orientation(const std::vector<Vec3>& normals) {
  if (normals.empty()) return nullptr;
  Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
  for (const Vec3& n : normals) t += n * n.transpose();
  const Vec3 axis = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(t).eigenvectors().col(2);
  Vec3 r = Vec3::Zero();
  for (const Vec3& n : normals) r += n.dot(axis) < 0 ? Vec3(-n) : n;
  const double count = static_cast<double>(normals.size()), length = r.norm();
  const DipDirection dd = dip_from_normal(r);
  // (n - 1) / (n - |R|); null when it is infinite (all parallel) or undefined (one fracture).
  const double spread = count - length;
  const bool finite = count > 1 && spread > 1e-12 * count;
  return {{"dip", dd.dip_deg + 0.0},  // + 0.0: no "-0" in the report
          {"dip_direction", dd.dip_direction_deg + 0.0},
          {"mean_resultant_length", length / count},
          {"kappa", finite ? nlohmann::json((count - 1) / spread) : nlohmann::json(nullptr)}};
}

nlohmann::json measures(const Tally& t, const Box3& box) {
  const Vec3 size = box.hi - box.lo;
  return {
      {"p32", t.area_in_domain / box.volume()},
      {"p10", {{"x", t.crossings[0] / size.x()}, {"y", t.crossings[1] / size.y()}, {"z", t.crossings[2] / size.z()}}},
      {"p21",
       {{"yz", t.traces[0] / (size.y() * size.z())},
        {"xz", t.traces[1] / (size.x() * size.z())},
        {"xy", t.traces[2] / (size.x() * size.y())}}}};
}

}  // namespace

void add_measures_to_report3(Builder3& b) {
  const Box3& box = b.model.domain;
  const Vec3 c = 0.5 * (box.lo + box.hi), size = box.hi - box.lo;
  // The axis-parallel scan lines through the centre and the mid-planes.
  Vec3 line_a[3], line_b[3];
  Rectangle3 mid[3];
  for (int k = 0; k < 3; ++k) {
    line_a[k] = c;
    line_b[k] = c;
    line_a[k][k] = box.lo[k];
    line_b[k][k] = box.hi[k];
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    mid[k].origin = box.lo;
    mid[k].origin[k] = c[k];
    mid[k].e1 = Vec3::Zero();
    mid[k].e2 = Vec3::Zero();
    mid[k].e1[std::min(i, j)] = size[std::min(i, j)];
    mid[k].e2[std::max(i, j)] = size[std::max(i, j)];
  }

  std::vector<Tally> per(b.model.sets.size());
  Tally all;
  for (const Fracture3& f : b.model.fractures) {
    Tally& t = per[static_cast<std::size_t>(f.set)];
    const double area = fracture_area_in_box(f, box);
    double radius = -1;  // planes have none
    if (f.shape == FractureShape::Disc) radius = f.radius;
    if (f.shape == FractureShape::Polygon) radius = std::sqrt(polygon_area(f.vertices) / kPi);  // equivalent
    for (Tally* s : {&t, &all}) {
      ++s->fractures;
      s->area_in_domain += area;
      if (radius >= 0) {
        ++s->sized;
        s->radius_sum += radius;
      }
      for (int k = 0; k < 3; ++k) {
        s->crossings[k] += segment_meets(f, line_a[k], line_b[k]) ? 1 : 0;
        s->traces[k] += trace_length_on(f, mid[k]);
      }
    }
    t.normals.push_back(f.normal);
  }

  nlohmann::json sets = nlohmann::json::array();
  for (std::size_t i = 0; i < per.size(); ++i) {
    const Tally& t = per[i];
    nlohmann::json s = {
        {"index", i}, {"name", b.model.sets[i].name}, {"origin", b.model.sets[i].origin}, {"fractures", t.fractures}};
    s.update(measures(t, box));
    const auto& asked = i < b.asked_p32.size() ? b.asked_p32[i] : std::nullopt;
    s["asked_p32"] = asked ? nlohmann::json(*asked) : nlohmann::json(nullptr);
    s["mean_radius"] = t.sized ? nlohmann::json(t.radius_sum / static_cast<double>(t.sized)) : nlohmann::json(nullptr);
    s["orientation"] = orientation(t.normals);
    sets.push_back(s);
  }
  b.report["sets"] = sets;
  nlohmann::json totals = {{"sets", b.model.sets.size()},
                           {"fractures", all.fractures},
                           {"excavations", b.model.excavations.size()},
                           {"points", b.model.points.size()},
                           {"trace_planes", b.trace_planes.size()}};
  totals.update(measures(all, box));
  b.report["totals"] = totals;
}

}  // namespace dda::dl::detail
