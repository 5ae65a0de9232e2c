#pragma once
// Text inputs read with limits (docs/reliability.md, "Bounded reads").
//
// Every text file the project reads (scenarios, trace and polygon CSVs,
// FracMan .fab, STL and OBJ, records, .geo/.ana, analysis tables) is read
// through these, so that a file that is not what it claims to be ends in
// one sentence instead of an endless read: /dev/zero has no line ends and
// no end, and a binary file read as lines is one huge line.
#include <cstddef>
#include <istream>
#include <string>

namespace dda {

// A line longer than this is not a line of a text input (the longest real
// lines, a scenario's inline polygon or a CSV row, are a few kB).
inline constexpr std::size_t kMaxTextLineBytes = std::size_t{1} << 20;  // 1 MiB
// A text input larger than this is refused before it fills the memory (a
// million fracture traces as CSV take about 60 MB).
inline constexpr std::size_t kMaxTextFileBytes = std::size_t{1} << 30;  // 1 GiB

// The whole file. InputError "PATH: cannot open the WHAT file.", "PATH:LINE:
// is longer than 1 MiB, so this is not a WHAT file." (said as soon as the
// line passes the limit, so /dev/zero ends after 1 MiB) or "PATH: is larger
// than 1 GiB, too large for a WHAT file.".
std::string read_text_file(const std::string& path, const std::string& what);

// The whole file with the size limit only, for formats that may be binary
// (STL): "PATH: cannot open the WHAT file." or "PATH: is larger than 1 GiB,
// too large for a WHAT file.".
std::string read_input_file(const std::string& path, const std::string& what);

// The next line of `in` into `line`, without its end ("\n", "\r\n"): false
// at the end of the input, as std::getline. InputError "FILE:LINE: is longer
// than 1 MiB, so this is not a text file." for a longer line.
bool read_text_line(std::istream& in, std::string& line, const std::string& file, std::size_t line_number);

}  // namespace dda
