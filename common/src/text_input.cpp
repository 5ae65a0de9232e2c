// Text inputs read with limits (text_input.hpp).
#include "dda/common/text_input.hpp"

#include <algorithm>
#include <fstream>
#include <vector>

#include "dda/common/error.hpp"

namespace dda {

namespace {

// Reads `path` in chunks up to the size limit; `check` sees the text after
// each chunk (so a text file can be refused long before its end).
template <class Check>
std::string read_bounded(const std::string& path, const std::string& what, Check&& check) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the " + what + " file.");
  std::string text;
  std::vector<char> chunk(std::size_t{1} << 16);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxTextFileBytes)
      throw InputError(path + ": is larger than 1 GiB, too large for a " + what + " file.");
    check(text);
  }
  if (in.bad()) throw InputError(path + ": cannot be read to its end.");
  return text;
}

}  // namespace

std::string read_input_file(const std::string& path, const std::string& what) {
  return read_bounded(path, what, [](const std::string&) {});
}

std::string read_text_file(const std::string& path, const std::string& what) {
  // A line past the limit ends the read here, not a gigabyte later
  // (/dev/zero has no line ends). The search from the end stops at the
  // last line end, within the last chunk but for a line already too long.
  return read_bounded(path, what, [&](const std::string& text) {
    const std::size_t last_end = text.rfind('\n');
    const std::size_t line_start = last_end == std::string::npos ? 0 : last_end + 1;
    if (text.size() - line_start > kMaxTextLineBytes) {
      const auto line = std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(line_start), '\n') + 1;
      throw InputError(path + ":" + std::to_string(line) + ": is longer than 1 MiB, so this is not a " + what +
                       " file.");
    }
  });
}

bool read_text_line(std::istream& in, std::string& line, const std::string& file, std::size_t line_number) {
  line.clear();
  std::streambuf* buffer = in.rdbuf();
  if (buffer == nullptr) return false;
  for (;;) {
    const int c = buffer->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in.setstate(std::ios::eofbit);
      if (line.empty()) {
        in.setstate(std::ios::failbit);  // nothing read: the end, as std::getline says it
        return false;
      }
      break;
    }
    if (c == '\n') break;
    if (line.size() >= kMaxTextLineBytes)
      throw InputError(file + ":" + std::to_string(line_number) + ": is longer than 1 MiB, so this is not a text file.");
    line.push_back(static_cast<char>(c));
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

}  // namespace dda
