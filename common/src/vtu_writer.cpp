// VTK XML UnstructuredGrid text: the layout ParaView reads (Points, Cells,
// CellData, PointData), ASCII arrays with the shortest round-trip decimals.
#include "dda/common/vtu_writer.hpp"

#include <charconv>
#include <type_traits>

#include "dda/common/atomic_file.hpp"
#include "dda/common/coordinate_range.hpp"
#include "dda/common/error.hpp"

namespace dda {
namespace {

void put(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}
void put(std::string& out, long long v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

template <class T>
const char* vtk_type_name() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  else if constexpr (std::is_same_v<T, std::int32_t>) return "Int32";
  else if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
  else return "UInt8";
}

// Values a fixed number per text line so the file stays readable.
template <class T>
void data_array(std::string& out, const std::string& name, int components, const std::vector<T>& values) {
  out += "        <DataArray type=\"";
  out += vtk_type_name<T>();
  out += "\" Name=\"" + name + "\"";
  if (components > 1) out += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  out += " format=\"ascii\">\n";
  const std::size_t per_line = components > 1 ? static_cast<std::size_t>(components) * 4 : 12;
  for (std::size_t i = 0; i < values.size(); ++i) {
    out += (i % per_line == 0) ? "          " : " ";
    if constexpr (std::is_floating_point_v<T>)
      put(out, static_cast<double>(values[i]));
    else
      put(out, static_cast<long long>(values[i]));
    if (i % per_line == per_line - 1 || i + 1 == values.size()) out += '\n';
  }
  out += "        </DataArray>\n";
}

template <class ArrayList>
void data_section(std::string& out, const char* tag, const ArrayList& arrays) {
  if (arrays.empty()) return;
  // ParaView colours by the first scalar and draws glyphs of the first vector.
  std::string scalars, vectors;
  for (const auto& a : arrays) {
    if (a.components == 1 && scalars.empty()) scalars = a.name;
    if (a.components == 3 && vectors.empty()) vectors = a.name;
  }
  out += std::string("      <") + tag;
  if (!scalars.empty()) out += " Scalars=\"" + scalars + "\"";
  if (!vectors.empty()) out += " Vectors=\"" + vectors + "\"";
  out += ">\n";
  for (const auto& a : arrays)
    std::visit([&](const auto& v) { data_array(out, a.name, a.components, v); }, a.values);
  out += std::string("      </") + tag + ">\n";
}

}  // namespace

void VtuGrid::add_point(const Vec3& p) {
  const Vec3 q = user_position(p, origin_);
  points_.push_back(q.x());
  points_.push_back(q.y());
  points_.push_back(q.z());
}

void VtuGrid::add_cell(std::size_t n, int vtk_type) {
  const auto first = static_cast<std::int64_t>(num_points() - n);
  for (std::size_t k = 0; k < n; ++k) connectivity_.push_back(first + static_cast<std::int64_t>(k));
  offsets_.push_back(static_cast<std::int64_t>(connectivity_.size()));
  types_.push_back(static_cast<std::uint8_t>(vtk_type));
  if (!face_offsets_.empty()) face_offsets_.push_back(-1);
}

void VtuGrid::add_polyhedron(std::size_t n, const std::vector<std::vector<int>>& faces) {
  const auto first = static_cast<std::int64_t>(num_points() - n);
  for (const auto& f : faces)
    for (int k : f)
      if (k < 0 || static_cast<std::size_t>(k) >= n)
        throw InternalError("VtuGrid::add_polyhedron: face point " + std::to_string(k) +
                            " of a cell of " + std::to_string(n) + " points");
  // The cells before the first polyhedron have no faces.
  if (face_offsets_.empty()) face_offsets_.assign(types_.size(), -1);
  add_cell(n, kVtkPolyhedron);
  face_offsets_.resize(types_.size() - 1);  // drop the -1 add_cell gave it, if any
  faces_.push_back(static_cast<std::int64_t>(faces.size()));
  for (const auto& f : faces) {
    faces_.push_back(static_cast<std::int64_t>(f.size()));
    for (int k : f) faces_.push_back(first + k);
  }
  face_offsets_.push_back(static_cast<std::int64_t>(faces_.size()));
}

void VtuGrid::cell_data(std::string name, int components, std::vector<double> values) {
  cell_arrays_.push_back({std::move(name), components, std::move(values)});
}
void VtuGrid::cell_data(std::string name, int components, std::vector<std::int32_t> values) {
  cell_arrays_.push_back({std::move(name), components, std::move(values)});
}
void VtuGrid::cell_data(std::string name, int components, std::vector<std::int64_t> values) {
  cell_arrays_.push_back({std::move(name), components, std::move(values)});
}
void VtuGrid::point_data(std::string name, int components, std::vector<double> values) {
  point_arrays_.push_back({std::move(name), components, std::move(values)});
}

std::string VtuGrid::to_xml() const {
  std::string out;
  out.reserve(96 * points_.size() + 512);
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n";
  out += "  <UnstructuredGrid>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(num_points()) + "\" NumberOfCells=\"" +
         std::to_string(num_cells()) + "\">\n";
  out += "      <Points>\n";
  data_array(out, "Points", 3, points_);
  out += "      </Points>\n";
  out += "      <Cells>\n";
  data_array(out, "connectivity", 1, connectivity_);
  data_array(out, "offsets", 1, offsets_);
  data_array(out, "types", 1, types_);
  if (!face_offsets_.empty()) {
    data_array(out, "faces", 1, faces_);
    data_array(out, "faceoffsets", 1, face_offsets_);
  }
  out += "      </Cells>\n";
  data_section(out, "PointData", point_arrays_);
  data_section(out, "CellData", cell_arrays_);
  out += "    </Piece>\n";
  out += "  </UnstructuredGrid>\n";
  out += "</VTKFile>\n";
  return out;
}

void VtuGrid::write(const std::string& path) const { write_text_atomically(path, to_xml()); }

}  // namespace dda
