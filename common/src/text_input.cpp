// Text inputs read with limits (text_input.hpp).
#include "dda/common/text_input.hpp"

#include <fstream>
#include <vector>

#include "dda/common/error.hpp"

namespace dda {

std::string read_text_file(const std::string& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the " + what + " file.");
  std::string text;
  std::vector<char> chunk(std::size_t{1} << 16);
  std::size_t line_start = 0, line_number = 1;  // of the line being read
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const std::size_t from = text.size();
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxTextFileBytes)
      throw InputError(path + ": is larger than 1 GiB, too large for a " + what + " file.");
    // A line past the limit ends the read here, not a gigabyte later
    // (/dev/zero has no line ends).
    for (std::size_t k = from; k < text.size(); ++k)
      if (text[k] == '\n') line_start = k + 1, ++line_number;
    if (text.size() - line_start > kMaxTextLineBytes)
      throw InputError(path + ":" + std::to_string(line_number) + ": is longer than 1 MiB, so this is not a " + what +
                       " file.");
  }
  if (in.bad()) throw InputError(path + ": cannot be read to its end.");
  return text;
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
