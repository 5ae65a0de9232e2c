#pragma once
// One writer for every ParaView .vtu file the project makes (lines, blocks,
// forward-run frames, contacts): a VTK XML UnstructuredGrid with ASCII data
// arrays, written atomically. Callers add points and cells, then named cell
// or point arrays; the grid knows nothing about rock. Points are 3D (2D
// points get z = 0); polyhedron cells carry their faces in the `faces` and
// `faceoffsets` arrays of the VTK XML format.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "dda/common/geometry.hpp"
#include "dda/common/geometry3d.hpp"

namespace dda {

// VTK cell type codes used by the project.
inline constexpr int kVtkVertex = 1;
inline constexpr int kVtkLine = 3;
inline constexpr int kVtkPolygon = 7;
inline constexpr int kVtkPolyhedron = 42;

class VtuGrid {
 public:
  VtuGrid() = default;
  // Points given about a model's local origin (coordinate_range.hpp) are
  // written at point + origin: ParaView shows the user's coordinates.
  explicit VtuGrid(const Vec2& origin) : origin_(origin.x(), origin.y(), 0.0) {}
  explicit VtuGrid(const Vec3& origin) : origin_(origin) {}
  void add_point(const Vec2& p) { add_point(Vec3(p.x(), p.y(), 0.0)); }
  void add_point(const Vec3& p);
  // A cell over the last `n` points added (not for polyhedra).
  void add_cell(std::size_t n, int vtk_type);
  // A VTK_POLYHEDRON cell over the last `n` points added; each face lists
  // point numbers 0 .. n-1 among those, counter-clockwise seen from outside.
  // InternalError for a number out of range.
  void add_polyhedron(std::size_t n, const std::vector<std::vector<int>>& faces);

  std::size_t num_points() const { return points_.size() / 3; }
  std::size_t num_cells() const { return types_.size(); }

  // Per-cell (or per-point) arrays, `components` values per cell (point).
  // The first array added of each kind is the one ParaView shows by default.
  void cell_data(std::string name, int components, std::vector<double> values);
  void cell_data(std::string name, int components, std::vector<std::int32_t> values);
  void cell_data(std::string name, int components, std::vector<std::int64_t> values);
  void point_data(std::string name, int components, std::vector<double> values);

  // The whole file as text, and the same written atomically to `path`.
  std::string to_xml() const;
  void write(const std::string& path) const;

 private:
  struct Array {
    std::string name;
    int components = 1;
    std::variant<std::vector<double>, std::vector<std::int32_t>, std::vector<std::int64_t>> values;
  };
  Vec3 origin_{0, 0, 0};
  std::vector<double> points_;
  std::vector<std::int64_t> connectivity_, offsets_;
  // Per cell, the end of its stream in faces_, -1 for cells without faces;
  // both stay empty (and are not written) until a polyhedron is added.
  std::vector<std::int64_t> faces_, face_offsets_;
  std::vector<std::uint8_t> types_;
  std::vector<Array> cell_arrays_, point_arrays_;
};

}  // namespace dda
