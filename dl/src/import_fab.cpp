// FracMan ASCII .fab files: the FORMAT, SETS and FRACTURE sections.
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "dda/common/error.hpp"
#include "dda/dl/fractures3d.hpp"
#include "dda/dl/import3d.hpp"
#include "dda/common/text_input.hpp"
#include "text_fields.hpp"

namespace dda::dl {

namespace {

struct Line {
  int number;
  std::string text;  // trimmed
};

// The file's non-blank lines and a cursor over them.
class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path) {
    std::istringstream in(read_text_file(path, "FracMan fracture"));
    std::string raw;
    int n = 0;
    while (read_text_line(in, raw, path, static_cast<std::size_t>(n) + 1)) {
      ++n;
      std::string t = detail::trim(raw);
      if (!t.empty()) lines_.push_back({n, std::move(t)});
    }
  }
  bool done() const { return pos_ == lines_.size(); }
  const Line& next() { return lines_[pos_++]; }
  const Line& peek() const { return lines_[pos_]; }
  std::string at(const Line& l) const { return path_ + ":" + std::to_string(l.number) + ": "; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<Line> lines_;
  std::size_t pos_ = 0;
};

// "BEGIN X" / "END X" with any spacing and case; the section name, or "".
std::string keyword(const std::string& text, const char* word) {
  const auto f = detail::split_fields(detail::upper(text));
  if (f.empty() || f[0] != word) return "";
  std::string name;
  for (std::size_t i = 1; i < f.size(); ++i) name += (i > 1 ? " " : "") + f[i];
  return name.empty() ? "-" : name;  // a bare END closes any section
}

bool ends(const Line& l, const std::string& section) {
  const std::string e = keyword(l.text, "END");
  return e == section || e == "-";
}

// "key = value" with the value's quotes removed; false without '='.
bool key_value(const std::string& text, std::string& key, std::string& value) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) return false;
  key = detail::upper(detail::trim(text.substr(0, eq)));
  value = detail::trim(text.substr(eq + 1));
  if (value.size() >= 2 && value.front() == '"' && value.back() == '"') value = value.substr(1, value.size() - 2);
  return true;
}

bool parse_integer(const std::string& field, long& v) {
  double d = 0;
  if (!detail::parse_finite(field, d) || d != std::floor(d) || std::abs(d) > 1e15) return false;
  v = static_cast<long>(d);
  return true;
}

// Numbers of a line; InputError naming `what` unless there are `count` (at least).
std::vector<double> numbers(const Reader& r, const Line& l, std::size_t count, const std::string& what) {
  const auto f = detail::split_fields(l.text);
  std::vector<double> v(f.size());
  bool ok = f.size() >= count;
  for (std::size_t i = 0; ok && i < count; ++i) ok = detail::parse_finite(f[i], v[i]);
  if (!ok) throw InputError(r.at(l) + "expected " + what + ", got '" + l.text + "'.");
  return v;
}

double length_unit(const Reader& r, const Line& l, const std::string& value) {
  const std::string u = detail::upper(value);
  if (u == "M" || u == "METER" || u == "METERS" || u == "METRE" || u == "METRES") return 1.0;
  if (u == "FT" || u == "FEET" || u == "FOOT") return 0.3048;
  throw InputError(r.at(l) + "the length unit '" + value + "' is not known (M or Ft).");
}

struct RawFracture {
  std::string id;
  long set = 0;
  int line = 0;
  std::vector<Vec3> vertices;
};

RawFracture read_one_fracture(Reader& r, const Line& head, double unit) {
  const auto f = detail::split_fields(head.text);
  long nodes = 0, set = 0;
  if (f.size() < 3 || !parse_integer(f[1], nodes) || nodes < 0 || !parse_integer(f[2], set))
    throw InputError(r.at(head) + "expected a fracture line 'id nnodes set [properties...]', got '" + head.text + "'.");
  RawFracture out{f[0], set, head.number, {}};
  const std::string which = "fracture " + out.id + " (line " + std::to_string(head.number) + ")";
  for (long i = 0; i <= nodes; ++i) {
    if (r.done() || ends(r.peek(), "FRACTURE"))
      throw InputError((r.done() ? r.path() + ": " : r.at(r.peek())) + which + " ends after " + std::to_string(i) +
                       (i == nodes ? " vertices, before its normal line '0 nx ny nz'." : " of its " +
                                     std::to_string(nodes) + " vertices."));
    const Line& l = r.next();
    if (i == nodes) {
      const auto v = numbers(r, l, 4, "the normal line '0 nx ny nz' of " + which);
      if (v[0] != 0)
        throw InputError(r.at(l) + "expected the normal line '0 nx ny nz' of " + which + ", got '" + l.text + "'.");
    } else {
      const auto v = numbers(r, l, 4, "a vertex line 'i x y z' of " + which);
      out.vertices.emplace_back(unit * v[1], unit * v[2], unit * v[3]);
    }
  }
  return out;
}

}  // namespace

ImportedFractures read_fab(const std::string& path) {
  Reader r(path);
  double unit = 1;
  std::vector<std::pair<long, std::string>> listed;  // SETS entries, in file order
  std::vector<RawFracture> raw;
  while (!r.done()) {
    const Line& begin = r.next();
    const std::string section = keyword(begin.text, "BEGIN");
    if (section.empty() || section == "-")
      throw InputError(r.at(begin) + "expected 'BEGIN <section>', got '" + begin.text + "'.");
    bool closed = false;
    while (!r.done() && !closed) {
      if (ends(r.peek(), section)) {
        r.next();
        closed = true;
      } else if (section == "FORMAT") {
        const Line& l = r.next();
        std::string key, value;
        if (key_value(l.text, key, value) && key == "LENGTH_UNIT") unit = length_unit(r, l, value);
      } else if (section == "SETS") {
        const Line& l = r.next();
        std::string key, value;
        long k = 0;
        if (!key_value(l.text, key, value) || key.rfind("SET", 0) != 0 || !parse_integer(key.substr(3), k))
          throw InputError(r.at(l) + "expected a set line 'SetK = \"name\"', got '" + l.text + "'.");
        listed.emplace_back(k, value);
      } else if (section == "FRACTURE") {
        const Line& head = r.next();
        raw.push_back(read_one_fracture(r, head, unit));
      } else {
        r.next();  // PROPERTIES, TESSFRACTURE, ROCKBLOCK, ...: not needed here
      }
    }
    if (!closed)
      throw InputError(r.at(begin) + "'" + begin.text + "' has no matching 'END " + section +
                       "' before the end of the file.");
  }

  // Sets: the listed ones in file order, then numbers used without an entry.
  ImportedFractures out;
  std::map<long, int> index;
  for (const auto& [k, name] : listed)
    if (index.emplace(k, static_cast<int>(out.set_names.size())).second) out.set_names.push_back(name);
  for (const RawFracture& f : raw) {
    if (index.emplace(f.set, static_cast<int>(out.set_names.size())).second)
      out.set_names.push_back("set " + std::to_string(f.set));
    const std::string where = path + ":" + std::to_string(f.line) + ": fracture " + f.id;
    out.fractures.push_back(polygon_fracture(f.vertices, index.at(f.set), where));
    out.lines.push_back(f.line);
  }
  return out;
}

}  // namespace dda::dl
