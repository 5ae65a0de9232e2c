#pragma once
// Importers of lines made by other programs.
#include <string>
#include <vector>

#include "dda/dl/clip.hpp"

namespace dda::dl {

struct CsvTrace {
  Segment seg;
  std::string set;  // from the optional fifth column, "" if absent or empty
  int line = 0;     // line of the file, 1-based
};

// CSV of x1,y1,x2,y2[,set], one trace a line; an optional header line (its
// first field is not a number); blank lines and lines starting with '#' are
// skipped; fields may be separated by commas, semicolons or blanks. Errors
// (wrong column count, a field that is not a finite number, a zero-length
// trace) are InputErrors "file:line: ...".
std::vector<CsvTrace> read_traces_csv(const std::string& path);

}  // namespace dda::dl
