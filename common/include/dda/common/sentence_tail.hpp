#pragma once
// A library message as the tail of a longer sentence: "the scenario key ...
// names a file with an error: <message>" (YamlNode::fail adds the full stop,
// so the message's own goes).
#include <cctype>
#include <exception>
#include <string>

namespace dda {

inline std::string sentence_tail(const std::exception& e) {
  std::string s = e.what();
  while (!s.empty() && (s.back() == '.' || s.back() == ' ')) s.pop_back();
  return s;
}

// A library sentence continued after a name ("l.h5: the domain ...",
// "fracture_sets[0]: a dip must ..."): its capital goes, unless the word is
// an acronym (P32, STL) whose second letter is not lower case.
inline std::string with_lowered_start(std::string s) {
  if (s.size() > 1 && std::isupper(static_cast<unsigned char>(s[0])) && std::islower(static_cast<unsigned char>(s[1])))
    s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
  return s;
}

}  // namespace dda
