#include "dda/study/key_path.hpp"

#include <cctype>

namespace dda::study {

std::optional<KeyPath> parse_key_path(const std::string& text, std::string* why) {
  KeyPath p;
  p.text = text;
  std::size_t i = 0;
  const auto fail = [&](const std::string& reason) -> std::optional<KeyPath> {
    if (why) *why = reason;
    return std::nullopt;
  };
  if (text.empty()) return fail("is empty");
  while (i < text.size()) {
    if (text[i] == '[') {
      const std::size_t close = text.find(']', i);
      if (close == std::string::npos || close == i + 1) return fail("has an unclosed or empty [index]");
      std::size_t index = 0;
      for (std::size_t k = i + 1; k < close; ++k) {
        if (!std::isdigit(static_cast<unsigned char>(text[k]))) return fail("has an index that is not a whole number");
        index = index * 10 + static_cast<std::size_t>(text[k] - '0');
      }
      p.steps.emplace_back(index);
      i = close + 1;
      if (i < text.size() && text[i] == '.') {
        ++i;
        if (i == text.size()) return fail("ends with a dot");
      } else if (i < text.size() && text[i] != '[') {
        return fail("needs a dot after ]");
      }
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && text[end] != '.' && text[end] != '[') ++end;
    if (end == i) return fail("has an empty key");
    p.steps.emplace_back(text.substr(i, end - i));
    i = end;
    if (i < text.size() && text[i] == '.') {
      ++i;
      if (i == text.size()) return fail("ends with a dot");
    }
  }
  if (!std::holds_alternative<std::string>(p.steps.front())) return fail("must start with a key");
  return p;
}

namespace {

// The path up to (not including) step `n`, for messages.
std::string prefix(const KeyPath& path, std::size_t n) {
  std::string out;
  for (std::size_t k = 0; k < n; ++k) {
    if (const auto* key = std::get_if<std::string>(&path.steps[k])) {
      if (!out.empty()) out += '.';
      out += *key;
    } else {
      // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "[" + to_string(i) + "]".
      out += '[';
      out += std::to_string(std::get<std::size_t>(path.steps[k]));
      out += ']';
    }
  }
  return out;
}

// yaml-cpp nodes are handles: assigning one Node to another writes through
// it, so the walk goes by recursion, one fresh handle per level.
std::string set_from(YAML::Node node, const KeyPath& path, std::size_t k, const YAML::Node& value) {
  const bool last = k + 1 == path.steps.size();
  if (const auto* key = std::get_if<std::string>(&path.steps[k])) {
    if (!node.IsMap()) return "the base has no mapping at " + (k == 0 ? std::string("the top") : prefix(path, k));
    if (last) {
      node[*key] = YAML::Clone(value);
      return "";
    }
    if (!node[*key]) return "the base has no " + prefix(path, k + 1);
    return set_from(node[*key], path, k + 1, value);
  }
  const std::size_t index = std::get<std::size_t>(path.steps[k]);
  if (!node.IsSequence() || index >= node.size()) return "the base has no " + prefix(path, k + 1);
  if (last) {
    node[index] = YAML::Clone(value);
    return "";
  }
  return set_from(node[index], path, k + 1, value);
}

std::optional<YAML::Node> get_from(const YAML::Node& node, const KeyPath& path, std::size_t k) {
  if (k == path.steps.size()) return node;
  if (const auto* key = std::get_if<std::string>(&path.steps[k])) {
    if (!node.IsMap() || !node[*key]) return std::nullopt;
    return get_from(node[*key], path, k + 1);
  }
  const std::size_t index = std::get<std::size_t>(path.steps[k]);
  if (!node.IsSequence() || index >= node.size()) return std::nullopt;
  return get_from(node[index], path, k + 1);
}

}  // namespace

std::string set_at(YAML::Node doc, const KeyPath& path, const YAML::Node& value) {
  return set_from(doc, path, 0, value);
}

std::optional<YAML::Node> get_at(const YAML::Node& doc, const KeyPath& path) { return get_from(doc, path, 0); }

}  // namespace dda::study
