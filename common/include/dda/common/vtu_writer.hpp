#pragma once
// One writer for every ParaView .vtu file the project makes (lines, blocks,
// forward-run frames, contacts): a VTK XML UnstructuredGrid with ASCII data
// arrays, written atomically. Callers add points and cells, then named cell
// or point arrays; the grid knows nothing about rock.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "dda/common/geometry.hpp"

namespace dda {

// VTK cell type codes used by the project.
inline constexpr int kVtkVertex = 1;
inline constexpr int kVtkLine = 3;
inline constexpr int kVtkPolygon = 7;

class VtuGrid {
 public:
  void add_point(const Vec2& p) { points_.insert(points_.end(), {p.x(), p.y(), 0.0}); }
  // A cell over the last `n` points added.
  void add_cell(std::size_t n, int vtk_type);

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
  std::vector<double> points_;
  std::vector<std::int64_t> connectivity_, offsets_;
  std::vector<std::uint8_t> types_;
  std::vector<Array> cell_arrays_, point_arrays_;
};

}  // namespace dda
