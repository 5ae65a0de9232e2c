// STL (ASCII and binary) and Wavefront OBJ readers for TriangleMesh.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/common/triangle_mesh.hpp"
#include "dda/common/text_input.hpp"

namespace dda {

namespace {

// STL repeats each corner in every triangle that has it; the copies are
// written from one value, so bit-identical coordinates are one vertex.
class VertexMerger {
 public:
  explicit VertexMerger(TriangleMesh& m) : m_(m) {}
  int id(const Vec3& p) {
    const auto [it, added] = ids_.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(m_.vertices.size()));
    if (added) m_.vertices.push_back(p);
    return it->second;
  }

 private:
  TriangleMesh& m_;
  std::map<std::array<double, 3>, int> ids_;
};

bool parse_double(const std::string& word, double& out) {
  const char* s = word.c_str();
  char* end = nullptr;
  out = std::strtod(s, &end);
  return end != s && *end == '\0' && std::isfinite(out);
}

// Binary STL: an 80-byte header, a little-endian uint32 count, then 50
// bytes a triangle (normal, three corners as float32, a 16-bit attribute).
bool looks_binary(const std::string& data) {
  if (data.size() < 84) return false;
  std::uint32_t n = 0;
  std::memcpy(&n, data.data() + 80, 4);
  if constexpr (std::endian::native == std::endian::big) n = __builtin_bswap32(n);
  return data.size() == 84 + 50 * static_cast<std::uint64_t>(n);
}

TriangleMesh read_binary_stl(const std::string& path, const std::string& data) {
  TriangleMesh m;
  VertexMerger merge(m);
  const std::size_t n = (data.size() - 84) / 50;
  for (std::size_t t = 0; t < n; ++t) {
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      Vec3 p;
      for (int c = 0; c < 3; ++c) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, data.data() + 84 + 50 * t + 12 * (k + 1) + 4 * c, 4);
        if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap32(bits);
        p[c] = static_cast<double>(std::bit_cast<float>(bits));
      }
      if (!p.allFinite())
        throw InputError(path + ": triangle " + std::to_string(t + 1) + " has a corner that is not finite.");
      tri[static_cast<std::size_t>(k)] = merge.id(p);
    }
    m.triangles.push_back(tri);
  }
  return m;
}

TriangleMesh read_ascii_stl(const std::string& path, const std::string& data) {
  TriangleMesh m;
  VertexMerger merge(m);
  std::istringstream in(data);
  std::string line;
  int number = 0;
  bool in_solid = false, in_loop = false;
  std::vector<int> corners;
  while (read_text_line(in, line, path, static_cast<std::size_t>(number) + 1)) {
    ++number;
    std::istringstream words(line);
    std::string key;
    if (!(words >> key)) continue;
    const std::string at = path + ":" + std::to_string(number) + ": ";
    if (key == "solid") {
      in_solid = true;
    } else if (!in_solid) {
      throw InputError(at + "expected 'solid' (an ASCII STL file), got '" + key + "'.");
    } else if (key == "vertex") {
      if (!in_loop) throw InputError(at + "'vertex' outside 'outer loop' ... 'endloop'.");
      std::string w[3], extra;
      Vec3 p;
      for (int c = 0; c < 3; ++c)
        if (!(words >> w[c]) || !parse_double(w[c], p[c]))
          throw InputError(at + "expected 'vertex x y z' with three finite numbers.");
      if (words >> extra) throw InputError(at + "expected 'vertex x y z', got more after it.");
      corners.push_back(merge.id(p));
    } else if (key == "outer") {
      in_loop = true;
      corners.clear();
    } else if (key == "endloop") {
      if (corners.size() != 3)
        throw InputError(at + "the facet has " + std::to_string(corners.size()) + " vertices; STL facets have 3.");
      m.triangles.push_back({corners[0], corners[1], corners[2]});
      in_loop = false;
    } else if (key == "endsolid") {
      in_solid = false;  // another solid may follow
    } else if (key != "facet" && key != "endfacet") {
      throw InputError(at + "expected facet, outer loop, vertex, endloop, endfacet or endsolid, got '" + key + "'.");
    }
  }
  if (in_loop) throw InputError(path + ": ends inside a facet (no 'endloop').");
  return m;
}

// One corner of an OBJ face: "v", "v/vt", "v/vt/vn" or "v//vn"; only v matters.
bool obj_corner(const std::string& word, long long& v) {
  const std::string head = word.substr(0, word.find('/'));
  const char* s = head.c_str();
  char* end = nullptr;
  v = std::strtoll(s, &end, 10);
  return end != s && *end == '\0' && v != 0;
}

}  // namespace

TriangleMesh read_stl(const std::string& path) {
  // Binary STL has no lines: the size limit only (its ASCII lines are
  // bounded one by one as they are read).
  const std::string data = read_input_file(path, "STL surface");
  // Some binary files start with "solid" too: the size decides first.
  if (looks_binary(data)) return read_binary_stl(path, data);
  const std::size_t first = data.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && data.compare(first, 5, "solid") == 0) return read_ascii_stl(path, data);
  throw InputError(path + ": is neither an ASCII STL file (starting with 'solid') nor a binary one "
                          "(84 bytes and 50 per triangle).");
}

TriangleMesh read_obj(const std::string& path) {
  const std::string data = read_text_file(path, "OBJ surface");
  TriangleMesh m;
  std::vector<int> triangle_line;  // for messages about ids read before their vertices
  std::istringstream in(data);
  std::string line;
  int number = 0;
  while (read_text_line(in, line, path, static_cast<std::size_t>(number) + 1)) {
    ++number;
    std::istringstream words(line);
    std::string key;
    if (!(words >> key)) continue;
    const std::string at = path + ":" + std::to_string(number) + ": ";
    if (key == "v") {
      std::string w;
      Vec3 p;
      for (int c = 0; c < 3; ++c)
        if (!(words >> w) || !parse_double(w, p[c]))
          throw InputError(at + "expected 'v x y z' with three finite numbers.");
      m.vertices.push_back(p);
    } else if (key == "f") {
      std::vector<int> ids;
      std::string w;
      while (words >> w) {
        long long v = 0;
        if (!obj_corner(w, v)) throw InputError(at + "'" + w + "' is not a vertex id (1, 2, ... or -1, -2, ...).");
        // Negative ids count back from the last vertex read so far.
        const long long id = v > 0 ? v - 1 : static_cast<long long>(m.vertices.size()) + v;
        if (id < 0 || id > std::numeric_limits<int>::max())
          throw InputError(at + "vertex id " + w + " does not exist (" + std::to_string(m.vertices.size()) +
                           " vertices so far).");
        ids.push_back(static_cast<int>(id));
      }
      if (ids.size() < 3) throw InputError(at + "a face needs at least 3 vertices, got " + std::to_string(ids.size()) + ".");
      for (std::size_t k = 1; k + 1 < ids.size(); ++k) {
        m.triangles.push_back({ids[0], ids[k], ids[k + 1]});
        triangle_line.push_back(number);
      }
    }
  }
  // Positive ids may point forward; check them once every vertex is known.
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int id : m.triangles[t])
      if (id >= static_cast<int>(m.vertices.size()))
        throw InputError(path + ":" + std::to_string(triangle_line[t]) + ": vertex id " + std::to_string(id + 1) +
                         " does not exist (the file has " + std::to_string(m.vertices.size()) + " vertices).");
  return m;
}

}  // namespace dda
