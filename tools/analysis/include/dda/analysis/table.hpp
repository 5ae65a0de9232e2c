#pragma once
// Numeric CSV tables (measured histories, friction tables): comma, semicolon,
// blank or tab separated; one optional header line; '#' comments.
#include <string>
#include <vector>

namespace dda::analysis {

struct NumericTable {
  std::vector<std::vector<double>> rows;
  std::size_t columns = 0;
};

// InputError naming the file and line for a non-number, NaN, a wrong column
// count (allowed counts in `allowed_columns`), a first column (time) that
// does not increase (repeats allowed with `allow_repeats`), or no rows.
NumericTable read_numeric_table(const std::string& path, const std::vector<std::size_t>& allowed_columns,
                                bool allow_repeats = false);

// A table whose first line names its columns, time `t` (s) first (an
// analytical solution for `dda compare`, a `dda history --csv` file, any
// series for `dda spectra`); the rows as read_numeric_table reads them, as
// many columns as names, time strictly increasing. InputError naming the
// file without a header line (`expected` describes the columns wanted, for
// the message) or with another first column than t.
struct NamedTable {
  std::vector<std::string> header;
  NumericTable table;
  int column(const std::string& name) const;  // index, -1 if absent
};
NamedTable read_named_table(const std::string& path, const std::string& expected);

}  // namespace dda::analysis
