#include "dda/dc/removability.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace dda::dc {

namespace {

bool admissible(const Vec3& d, const std::vector<Vec3>& normals, double tol) {
  for (const Vec3& n : normals)
    if (d.dot(n) > tol) return false;  // moving into the neighbour across this face
  return true;
}

// The distinct normals (to 1e-9): a body of many parts has many faces on the
// same few planes, and the tests below are cubic in the number of normals.
std::vector<Vec3> distinct(const std::vector<Vec3>& normals, std::vector<int>& first_index) {
  std::vector<std::pair<std::array<long long, 3>, int>> keyed;
  keyed.reserve(normals.size());
  for (std::size_t i = 0; i < normals.size(); ++i)
    keyed.push_back({{std::llround(normals[i].x() * 1e9), std::llround(normals[i].y() * 1e9),
                      std::llround(normals[i].z() * 1e9)},
                     static_cast<int>(i)});
  std::sort(keyed.begin(), keyed.end());
  std::vector<Vec3> out;
  first_index.clear();
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    if (i > 0 && keyed[i].first == keyed[i - 1].first) continue;
    out.push_back(normals[static_cast<std::size_t>(keyed[i].second)]);
    first_index.push_back(keyed[i].second);
  }
  return out;
}

}  // namespace

RemovabilityResult classify_removability(const std::vector<Vec3>& all_normals, bool exposed, const Vec3& gravity,
                                         double tol) {
  RemovabilityResult r;
  if (!exposed) return r;
  std::vector<int> index;
  const std::vector<Vec3> normals = distinct(all_normals, index);
  const Vec3 g = gravity.normalized();

  // Lifting: gravity opens every contact.
  if (admissible(g, normals, tol)) {
    r.mode = Removability::Falls;
    r.direction = g;
    return r;
  }
  // Sliding on one face: the steepest admissible one.
  double best = 0;
  for (std::size_t i = 0; i < normals.size(); ++i) {
    if (g.dot(normals[i]) <= tol) continue;  // gravity does not press on this face
    Vec3 s = g - g.dot(normals[i]) * normals[i];
    const double drive = s.norm();
    if (drive <= tol) continue;  // a horizontal face: no sliding
    s /= drive;
    if (drive > best && admissible(s, normals, tol)) {
      best = drive;
      r.mode = Removability::SlidesOne;
      r.direction = s;
      r.sliding_faces = {index[i]};
    }
  }
  if (r.mode == Removability::SlidesOne) return r;
  // Sliding on two faces, along their line, downwards.
  best = 0;
  for (std::size_t i = 0; i < normals.size(); ++i)
    for (std::size_t j = i + 1; j < normals.size(); ++j) {
      Vec3 s = normals[i].cross(normals[j]);
      const double len = s.norm();
      if (len <= tol) continue;
      s /= len;
      if (s.dot(g) < 0) s = -s;
      if (s.dot(g) > best + tol && g.dot(normals[i]) > 0 && g.dot(normals[j]) > 0 && admissible(s, normals, tol)) {
        best = s.dot(g);
        r.mode = Removability::SlidesTwo;
        r.direction = s;
        r.sliding_faces = {index[i], index[j]};
      }
    }
  if (r.mode == Removability::SlidesTwo) return r;
  // Removable at all? The cone's extreme rays are among the normals and the
  // lines of pairs of faces; a cone that is a whole line or plane contains
  // such a candidate too.
  bool removable = normals.empty();
  for (std::size_t i = 0; i < normals.size() && !removable; ++i) {
    // A direction perpendicular to n_i settles the case of normals that all
    // lie on one line (faces on both sides of a slab).
    const Vec3 any = std::abs(normals[i].x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 perp = normals[i].cross(any).normalized();
    removable = admissible(normals[i], normals, tol) || admissible(perp, normals, tol);
    for (std::size_t j = i + 1; j < normals.size() && !removable; ++j) {
      Vec3 s = normals[i].cross(normals[j]);
      if (s.norm() <= tol) continue;
      s.normalize();
      removable = admissible(s, normals, tol) || admissible(-s, normals, tol);
    }
  }
  r.mode = removable ? Removability::Removable : Removability::Tapered;
  return r;
}

}  // namespace dda::dc
