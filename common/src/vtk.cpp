// ParaView output: VTK XML UnstructuredGrid (.vtu, ASCII data arrays) and
// the Collection (.pvd) that strings them into a time series. See
// docs/formats.md.
#include "dda/common/vtk.hpp"

#include <charconv>
#include <cstdint>
#include <type_traits>
#include <string>
#include <vector>

#include "dda/common/atomic_file.hpp"

namespace dda {
namespace {

constexpr int kVtkLine = 3;
constexpr int kVtkPolygon = 7;
// Line kinds in the .vtu beyond LineKind (0 joint, 1 bedding): the outlines.
constexpr int kKindDomainOutline = 2;
constexpr int kKindExcavationOutline = 3;

std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// Shortest text that reads back to the same double.
void put(std::string& out, double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}
void put(std::string& out, long long v) {
  char buf[24];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

// Writes values, a fixed number per text line so the file stays readable.
template <class T>
void data_array(std::string& out, const char* type, const char* name, int components,
                const std::vector<T>& values) {
  out += "        <DataArray type=\"";
  out += type;
  out += "\"";
  if (name) {
    out += " Name=\"";
    out += name;
    out += "\"";
  }
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

struct Grid {
  std::vector<double> points;             // x y z per point
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;      // end of each cell in connectivity
  std::vector<std::uint8_t> types;
  std::size_t num_points() const { return points.size() / 3; }
  void add_point(const Vec2& p) { points.insert(points.end(), {p.x(), p.y(), 0.0}); }
  // A cell over the last `n` points added.
  void add_cell(std::size_t n, int type) {
    const std::int64_t first = static_cast<std::int64_t>(num_points() - n);
    for (std::size_t k = 0; k < n; ++k) connectivity.push_back(first + static_cast<std::int64_t>(k));
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    types.push_back(static_cast<std::uint8_t>(type));
  }
};

std::string begin_file(const Grid& g) {
  std::string out;
  out.reserve(64 * g.points.size() + 256);
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n";
  out += "  <UnstructuredGrid>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(g.num_points()) + "\" NumberOfCells=\"" +
         std::to_string(g.types.size()) + "\">\n";
  out += "      <Points>\n";
  data_array(out, "Float64", "Points", 3, g.points);
  out += "      </Points>\n";
  out += "      <Cells>\n";
  data_array(out, "Int64", "connectivity", 1, g.connectivity);
  data_array(out, "Int64", "offsets", 1, g.offsets);
  data_array(out, "UInt8", "types", 1, g.types);
  out += "      </Cells>\n";
  return out;
}

void end_file(std::string& out) {
  out += "    </Piece>\n";
  out += "  </UnstructuredGrid>\n";
  out += "</VTKFile>\n";
}

}  // namespace

void write_lines_vtu(const std::string& path, const LineModel& model) {
  Grid g;
  std::vector<std::int32_t> set, kind, layer;
  for (const JointLine& l : model.lines) {
    g.add_point(l.a);
    g.add_point(l.b);
    g.add_cell(2, kVtkLine);
    set.push_back(l.set);
    kind.push_back(static_cast<std::int32_t>(l.kind));
    layer.push_back(l.layer);
  }
  // The outlines, one line cell per edge, so the picture is complete in
  // ParaView without the blocks.
  auto outline = [&](const Polygon2& poly, int set_id, int kind_id) {
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
      g.add_point(poly[i]);
      g.add_point(poly[(i + 1) % n]);
      g.add_cell(2, kVtkLine);
      set.push_back(set_id);
      kind.push_back(kind_id);
      layer.push_back(-1);
    }
  };
  if (model.domain.size() >= 2) outline(model.domain, kBoundarySet, kKindDomainOutline);
  for (const Polygon2& e : model.excavations) outline(e, kExcavationSet, kKindExcavationOutline);

  std::string out = begin_file(g);
  out += "      <CellData Scalars=\"set\">\n";
  data_array(out, "Int32", "set", 1, set);
  data_array(out, "Int32", "kind", 1, kind);
  data_array(out, "Int32", "layer", 1, layer);
  out += "      </CellData>\n";
  end_file(out);
  write_text_atomically(path, out);
}

void write_blocks_vtu(const std::string& path, const BlockModel& model) {
  Grid g;
  std::vector<std::int64_t> id;
  std::vector<double> area;
  std::vector<std::int32_t> layer;
  for (std::size_t i = 0; i < model.blocks.size(); ++i) {
    const Block& b = model.blocks[i];
    for (const Vec2& v : b.vertices) g.add_point(v);
    g.add_cell(b.vertices.size(), kVtkPolygon);
    id.push_back(static_cast<std::int64_t>(i));
    area.push_back(b.area);
    layer.push_back(b.layer);
  }
  std::string out = begin_file(g);
  out += "      <CellData Scalars=\"block_id\">\n";
  data_array(out, "Int64", "block_id", 1, id);
  data_array(out, "Float64", "area", 1, area);
  data_array(out, "Int32", "layer", 1, layer);
  out += "      </CellData>\n";
  end_file(out);
  write_text_atomically(path, out);
}

void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries) {
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += "  <Collection>\n";
  for (const PvdEntry& e : entries) {
    out += "    <DataSet timestep=\"";
    put(out, e.time);
    out += "\" group=\"\" part=\"" + std::to_string(e.part) + "\" file=\"" + xml_escape(e.file) + "\"";
    if (!e.name.empty()) out += " name=\"" + xml_escape(e.name) + "\"";
    out += "/>\n";
  }
  out += "  </Collection>\n";
  out += "</VTKFile>\n";
  write_text_atomically(path, out);
}

}  // namespace dda
