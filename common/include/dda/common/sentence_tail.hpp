#pragma once
// A library message as the tail of a longer sentence: "the scenario key ...
// names a file with an error: <message>" (YamlNode::fail adds the full stop,
// so the message's own goes).
#include <exception>
#include <string>

namespace dda {

inline std::string sentence_tail(const std::exception& e) {
  std::string s = e.what();
  while (!s.empty() && (s.back() == '.' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace dda
