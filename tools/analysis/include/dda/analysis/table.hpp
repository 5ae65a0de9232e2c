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

}  // namespace dda::analysis
