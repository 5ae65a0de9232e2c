// CSV polygons: one row per vertex, the rows of a fracture consecutive.
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "dda/common/error.hpp"
#include "dda/dl/fractures3d.hpp"
#include "dda/dl/import3d.hpp"
#include "dda/common/text_input.hpp"
#include "text_fields.hpp"

namespace dda::dl {

namespace {

struct Pending {
  std::string name, set;
  int line = 0;
  std::vector<Vec3> vertices;
};

int set_index(ImportedFractures& out, const std::string& name) {
  for (std::size_t i = 0; i < out.set_names.size(); ++i)
    if (out.set_names[i] == name) return static_cast<int>(i);
  out.set_names.push_back(name);
  return static_cast<int>(out.set_names.size()) - 1;
}

}  // namespace

ImportedFractures read_fracture_csv(const std::string& path) {
  std::istringstream in(read_text_file(path, "fracture polygon"));
  static const char* kColumns[5] = {"fracture", "set", "x", "y", "z"};
  ImportedFractures out;
  int column[5] = {-1, -1, -1, -1, -1};
  std::size_t width = 0;
  bool have_header = false;
  Pending cur;
  std::map<std::string, int> started;  // fracture name -> line of its first row

  auto finish = [&] {
    if (cur.vertices.empty()) return;
    const std::string where = path + ":" + std::to_string(cur.line) + ": fracture '" + cur.name + "'";
    out.fractures.push_back(polygon_fracture(cur.vertices, set_index(out, cur.set), where));
    out.lines.push_back(cur.line);
    cur = Pending{};
  };

  std::string raw;
  int line_no = 0;
  while (read_text_line(in, raw, path, static_cast<std::size_t>(line_no) + 1)) {
    ++line_no;
    const std::string line = detail::trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const auto fields = detail::split_fields(line);
    const std::string where = path + ":" + std::to_string(line_no) + ": ";
    if (!have_header) {
      // Columns by name, so that a file may order them (or add others) freely.
      for (std::size_t i = 0; i < fields.size(); ++i)
        for (int k = 0; k < 5; ++k)
          if (detail::upper(fields[i]) == detail::upper(kColumns[k])) {
            if (column[k] >= 0) throw InputError(where + "the header names column '" + kColumns[k] + "' twice.");
            column[k] = static_cast<int>(i);
          }
      for (int k = 0; k < 5; ++k)
        if (column[k] < 0)
          throw InputError(where + "the header has no column '" + kColumns[k] + "' (expected fracture,set,x,y,z).");
      width = fields.size();
      have_header = true;
      continue;
    }
    if (fields.size() != width)
      throw InputError(where + "has " + std::to_string(fields.size()) + " columns, the header " +
                       std::to_string(width) + ".");
    const std::string& name = fields[static_cast<std::size_t>(column[0])];
    const std::string& set = fields[static_cast<std::size_t>(column[1])];
    if (name.empty()) throw InputError(where + "the fracture name is empty.");
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      const std::string& field = fields[static_cast<std::size_t>(column[2 + k])];
      if (!detail::parse_finite(field, p[k]))
        throw InputError(where + "column " + kColumns[2 + k] + " must be a finite number, got '" + field + "'.");
    }
    if (name != cur.name || cur.vertices.empty()) {
      finish();
      const auto [it, fresh] = started.emplace(name, line_no);
      if (!fresh)
        throw InputError(where + "the rows of fracture '" + name + "' are not consecutive (it started at line " +
                         std::to_string(it->second) + ").");
      cur.name = name;
      cur.set = set;
      cur.line = line_no;
    } else if (set != cur.set) {
      throw InputError(where + "fracture '" + name + "' changes set from '" + cur.set + "' to '" + set + "'.");
    }
    cur.vertices.push_back(p);
  }
  if (!have_header) throw InputError(path + ": has no header line (expected fracture,set,x,y,z).");
  finish();
  return out;
}

}  // namespace dda::dl
