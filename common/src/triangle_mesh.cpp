// Closed-surface checks and the inside test of TriangleMesh (the readers
// are in triangle_mesh_read.cpp).
#include "dda/common/triangle_mesh.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "dda/common/error.hpp"

namespace dda {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string corner_text(const TriangleMesh& m, int v) {
  std::ostringstream s;
  s.precision(10);
  const Vec3& p = m.vertices[static_cast<std::size_t>(v)];
  s << "vertex " << v + 1 << " (" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

}  // namespace

void check_closed_surface(const TriangleMesh& m, const std::string& what) {
  const auto nv = static_cast<long long>(m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    if (!m.vertices[i].allFinite())
      throw InputError(what + ": vertex " + std::to_string(i + 1) + " has a coordinate that is not a finite number.");
  if (m.triangles.size() < 4)
    throw InputError(what + ": has " + std::to_string(m.triangles.size()) +
                     " triangles; a closed surface needs at least 4.");
  // Directed edge a -> b, as a * nv + b: each must occur once and its
  // reverse once, or the surface has a hole, a flap or flipped triangles.
  std::unordered_map<long long, int> uses;
  uses.reserve(3 * m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    for (int k = 0; k < 3; ++k) {
      if (tri[k] < 0 || tri[k] >= nv)
        throw InputError(what + ": triangle " + std::to_string(t + 1) + " names vertex " + std::to_string(tri[k] + 1) +
                         ", which does not exist (there are " + std::to_string(nv) + ").");
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
      throw InputError(what + ": triangle " + std::to_string(t + 1) + " uses one vertex twice.");
    for (int k = 0; k < 3; ++k) ++uses[tri[k] * nv + tri[(k + 1) % 3]];
  }
  // In triangle order, so that the first bad triangle of the file is named.
  for (const auto& tri : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      auto edge = [&] { return "the edge from " + corner_text(m, a) + " to " + corner_text(m, b); };
      const int count = uses[a * nv + b];
      if (count > 1)
        throw InputError(what + ": the surface is not closed and oriented: " + edge() + " is run in the same direction by " +
                         std::to_string(count) + " triangles (flipped triangles, or more than two meet there).");
      if (uses.find(b * nv + a) == uses.end())
        throw InputError(what + ": the surface is not closed: " + edge() +
                         " belongs to one triangle only (a hole or a free border there).");
    }
  const double v = enclosed_volume(m);
  const Box3 box = mesh_bounds(m);
  if (!(std::abs(v) > 1e-12 * box.volume()) || !(box.volume() > 0))
    throw InputError(what + ": the surface encloses no volume.");
}

double enclosed_volume(const TriangleMesh& m) {
  if (m.vertices.empty()) return 0;
  // Tetrahedra from a vertex of the mesh, not the origin, so that far
  // coordinates do not cancel.
  const Vec3 ref = m.vertices.front();
  double v = 0;
  for (const auto& t : m.triangles) {
    const Vec3 a = m.vertices[static_cast<std::size_t>(t[0])] - ref;
    const Vec3 b = m.vertices[static_cast<std::size_t>(t[1])] - ref;
    const Vec3 c = m.vertices[static_cast<std::size_t>(t[2])] - ref;
    v += a.dot(b.cross(c));
  }
  return v / 6.0;
}

void orient_outward(TriangleMesh& m) {
  if (enclosed_volume(m) >= 0) return;
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
}

Box3 mesh_bounds(const TriangleMesh& m) {
  Box3 b{Vec3::Constant(std::numeric_limits<double>::infinity()), Vec3::Constant(-std::numeric_limits<double>::infinity())};
  for (const Vec3& v : m.vertices) {
    b.lo = b.lo.cwiseMin(v);
    b.hi = b.hi.cwiseMax(v);
  }
  if (m.vertices.empty()) b = Box3{};
  return b;
}

double winding_number(const TriangleMesh& m, const Vec3& p) {
  // Solid angle of each triangle (van Oosterom and Strackee): the atan2
  // form keeps the sign and stays accurate for triangles seen edge-on.
  double sum = 0;
  for (const auto& t : m.triangles) {
    const Vec3 a = m.vertices[static_cast<std::size_t>(t[0])] - p;
    const Vec3 b = m.vertices[static_cast<std::size_t>(t[1])] - p;
    const Vec3 c = m.vertices[static_cast<std::size_t>(t[2])] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    sum += 2 * std::atan2(num, den);
  }
  return sum / (4 * kPi);
}

TriangleMesh read_triangle_mesh(const std::string& path) {
  const std::string ext = lower_extension(path);
  TriangleMesh m;
  if (ext == ".stl") m = read_stl(path);
  else if (ext == ".obj") m = read_obj(path);
  else throw InputError(path + ": is not a surface file this program reads (.stl or .obj).");
  check_closed_surface(m, path);
  orient_outward(m);
  return m;
}

}  // namespace dda
