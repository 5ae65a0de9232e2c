#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "dda/common/error.hpp"
#include "dda/dl/import.hpp"
#include "dda/common/text_input.hpp"
#include "text_fields.hpp"

namespace dda::dl {

using detail::split_fields;
using detail::trim;

namespace {

// The whole field as a double (strtod is locale-independent for "C").
bool parse_number(const std::string& field, double& v) {
  if (field.empty()) return false;
  char* end = nullptr;
  errno = 0;
  v = std::strtod(field.c_str(), &end);
  return end == field.c_str() + field.size();
}

}  // namespace

std::vector<CsvTrace> read_traces_csv(const std::string& path) {
  std::istringstream in(read_text_file(path, "trace"));
  std::vector<CsvTrace> out;
  std::string raw;
  int line_no = 0;
  bool first_content = true;
  const char* columns = "x1,y1,x2,y2[,set]";
  while (read_text_line(in, raw, path, static_cast<std::size_t>(line_no) + 1)) {
    ++line_no;
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const auto fields = split_fields(line);
    const std::string where = path + ":" + std::to_string(line_no) + ": ";
    double first = 0;
    if (first_content && !parse_number(fields[0], first)) {
      first_content = false;  // a header line
      if (fields.size() != 4 && fields.size() != 5)
        throw InputError(where + "the header has " + std::to_string(fields.size()) + " columns, expected 4 or 5 (" +
                         columns + ").");
      continue;
    }
    first_content = false;
    if (fields.size() != 4 && fields.size() != 5)
      throw InputError(where + "has " + std::to_string(fields.size()) + " columns, expected 4 or 5 (" + columns + ").");
    double v[4];
    static const char* names[4] = {"x1", "y1", "x2", "y2"};
    for (int k = 0; k < 4; ++k) {
      if (!parse_number(fields[k], v[k]))
        throw InputError(where + "column " + std::to_string(k + 1) + " (" + names[k] + ") must be a number, got '" +
                         fields[k] + "'.");
      if (!std::isfinite(v[k]))
        throw InputError(where + "column " + std::to_string(k + 1) + " (" + names[k] + ") must be finite, got '" +
                         fields[k] + "'.");
    }
    CsvTrace t;
    t.seg = {Vec2(v[0], v[1]), Vec2(v[2], v[3])};
    t.line = line_no;
    if (fields.size() == 5) t.set = fields[4];  // empty: the set given in the scenario
    if (t.seg.a == t.seg.b) throw InputError(where + "the trace has zero length (both ends are the same point).");
    out.push_back(t);
  }
  return out;
}

}  // namespace dda::dl
