// ParaView output: VTK XML UnstructuredGrid (.vtu, ASCII data arrays) and
// the Collection (.pvd) that strings them into a time series. See
// docs/formats.md.
#include "dda/common/vtk.hpp"

#include <charconv>
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/atomic_file.hpp"
#include "dda/common/vtu_writer.hpp"

namespace dda {
namespace {

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

// Shortest text that reads back to the same double (the .pvd time stamps).
void put(std::string& out, double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

}  // namespace

void write_lines_vtu(const std::string& path, const LineModel& model) {
  VtuGrid g(model.origin);
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

  g.cell_data("set", 1, std::move(set));
  g.cell_data("kind", 1, std::move(kind));
  g.cell_data("layer", 1, std::move(layer));
  g.write(path);
}

void write_blocks_vtu(const std::string& path, const BlockModel& model) {
  VtuGrid g(model.origin);
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
  g.cell_data("block_id", 1, std::move(id));
  g.cell_data("area", 1, std::move(area));
  g.cell_data("layer", 1, std::move(layer));
  g.write(path);
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
