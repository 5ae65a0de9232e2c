#include "dda/analysis/table.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/common/text_input.hpp"

namespace dda::analysis {

namespace {

std::string trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> out;
  const bool commas = line.find_first_of(",;") != std::string::npos;
  std::string cur;
  for (char c : line) {
    const bool sep = commas ? (c == ',' || c == ';') : (c == ' ' || c == '\t');
    if (sep) {
      if (commas || !trim(cur).empty()) out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (commas || !trim(cur).empty()) out.push_back(trim(cur));
  return out;
}

bool number(const std::string& f, double& v) {
  if (f.empty()) return false;
  const char* b = f.data();
  if (*b == '+') ++b;
  const auto r = std::from_chars(b, f.data() + f.size(), v);
  return r.ec == std::errc() && r.ptr == f.data() + f.size();
}

}  // namespace

NumericTable read_numeric_table(const std::string& path, const std::vector<std::size_t>& allowed_columns,
                                bool allow_repeats) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": file not found.");
  std::istringstream f(read_text_file(path, "table"));
  NumericTable table;
  std::string line;
  std::size_t line_no = 0;
  bool seen = false;
  while (read_text_line(f, line, path, line_no + 1)) {
    ++line_no;
    const std::string tl = trim(line);
    if (tl.empty() || tl[0] == '#') continue;
    const auto fields = fields_of(tl);
    double first = 0;
    if (!seen && !number(fields[0], first)) {
      seen = true;
      continue;
    }
    seen = true;
    if (table.columns == 0) {
      bool ok = false;
      for (std::size_t c : allowed_columns) ok = ok || c == fields.size();
      if (!ok) {
        std::string list;
        for (std::size_t i = 0; i < allowed_columns.size(); ++i)
          list += (i ? (i + 1 == allowed_columns.size() ? " or " : ", ") : "") + std::to_string(allowed_columns[i]);
        throw InputError(path + ", line " + std::to_string(line_no) + ": " + std::to_string(fields.size()) +
                         " columns, expected " + list + ".");
      }
      table.columns = fields.size();
    } else if (fields.size() != table.columns) {
      throw InputError(path + ", line " + std::to_string(line_no) + ": " + std::to_string(fields.size()) +
                       " columns where the first data line has " + std::to_string(table.columns) + ".");
    }
    std::vector<double> row(fields.size());
    for (std::size_t c = 0; c < fields.size(); ++c)
      if (!number(fields[c], row[c]) || !std::isfinite(row[c]))
        throw InputError(path + ", line " + std::to_string(line_no) + ", column " + std::to_string(c + 1) + ": '" +
                         fields[c] + "' is not a finite number.");
    if (!table.rows.empty() && (allow_repeats ? row[0] < table.rows.back()[0] : !(row[0] > table.rows.back()[0])))
      throw InputError(path + ", line " + std::to_string(line_no) + ": the first column (time) does not increase.");
    table.rows.push_back(std::move(row));
  }
  if (table.rows.empty()) throw InputError(path + ": no data rows (the table is empty).");
  return table;
}

int NamedTable::column(const std::string& name) const {
  for (std::size_t k = 0; k < header.size(); ++k)
    if (header[k] == name) return static_cast<int>(k);
  return -1;
}

NamedTable read_named_table(const std::string& path, const std::string& expected) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": file not found.");
  std::istringstream f(read_text_file(path, "table"));
  NamedTable t;
  std::string line;
  std::size_t line_no = 0;
  while (read_text_line(f, line, path, line_no + 1)) {
    ++line_no;
    const std::string tl = trim(line);
    if (tl.empty() || tl[0] == '#') continue;
    t.header = fields_of(tl);
    break;
  }
  double probe = 0;
  if (t.header.empty() || number(t.header[0], probe))
    throw InputError(path + ": needs a header line naming its columns (" + expected + ").");
  if (t.header[0] != "t")
    throw InputError(path + ", line " + std::to_string(line_no) + ": the first column must be t (time in s), got '" +
                     t.header[0] + "'.");
  t.table = read_numeric_table(path, {t.header.size()});
  return t;
}

}  // namespace dda::analysis
