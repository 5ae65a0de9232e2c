#include "dda/dc/removability.hpp"

#include <cmath>

namespace dda::dc {

namespace {

bool admissible(const Vec3& d, const std::vector<Vec3>& normals, double tol) {
  for (const Vec3& n : normals)
    if (d.dot(n) > tol) return false;  // moving into the neighbour across this face
  return true;
}

}  // namespace

RemovabilityResult classify_removability(const std::vector<Vec3>& normals, bool exposed, const Vec3& gravity,
                                         double tol) {
  RemovabilityResult r;
  if (!exposed) return r;
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
      r.sliding_faces = {static_cast<int>(i)};
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
        r.sliding_faces = {static_cast<int>(i), static_cast<int>(j)};
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
