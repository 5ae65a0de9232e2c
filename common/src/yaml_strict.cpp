#include "yaml_strict.hpp"

#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <vector>

#include <yaml-cpp/eventhandler.h>

#include "dda/common/error.hpp"

namespace dda::yaml_strict {

namespace {

int line_of(const YAML::Node& n) { return n.Mark().line + 1; }  // yaml-cpp counts from 0

std::string child_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

// Walks the tree once, checking every mapping for keys given twice.
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(const std::string& file) : file_(file) {}

  void walk(const YAML::Node& n, const std::string& path) {
    if (!n.IsMap() && !n.IsSequence()) return;
    // An alias shares its anchor's node: each container is checked once,
    // so a document of nested aliases cannot make the walk exponential.
    // A container is known by where it starts and its kind.
    const auto id = std::make_tuple(n.Mark().line, n.Mark().column, n.IsMap());
    if (!visited_.insert(id).second) return;
    if (n.IsSequence()) {
      for (std::size_t i = 0; i < n.size(); ++i) walk(n[i], path + "[" + std::to_string(i) + "]");
      return;
    }
    std::map<std::string, int> first_line;
    for (auto it = n.begin(); it != n.end(); ++it) {
      if (!it->first.IsScalar()) continue;  // a complex key cannot be looked up by name anyway
      const std::string key = it->first.Scalar();
      const int line = line_of(it->first);
      const auto [where, fresh] = first_line.emplace(key, line);
      if (!fresh) {
        const std::string lines = where->second == line
                                      ? "both on line " + std::to_string(line)
                                      : "lines " + std::to_string(where->second) + " and " + std::to_string(line);
        throw InputError(file_ + ": key '" + child_path(path, key) + "' is given twice (" + lines + ").");
      }
      walk(it->second, child_path(path, key));
    }
  }

 private:
  const std::string& file_;
  std::set<std::tuple<int, int, bool>> visited_;
};

// The line of the `---` that opens the document whose first node is on
// `node_line` (1-based), or `node_line` itself if no marker is found.
int separator_line(const std::string& text, int node_line) {
  int line = 1, found = 0;
  for (std::size_t pos = 0; pos < text.size() && line <= node_line; ++line) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string_view l(text.data() + pos, end - pos);
    if (l.substr(0, 3) == "---" && (l.size() == 3 || l[3] == ' ' || l[3] == '\t' || l[3] == '\r')) found = line;
    pos = end + 1;
  }
  return found ? found : node_line;
}

// Where the first node of each document of a stream is, for the first two
// documents at most. Not YAML::LoadAll: yaml-cpp 0.7 (Debian 12) never ends
// it on a stray ',' where a node should start (yaml-cpp issue 1040, fixed in
// 0.8) — its parser hands out the same empty document again and again
// without reading on, and LoadAll keeps every one of them until the memory
// is gone. Found by fuzzing (docs/reliability.md, "Fuzzing").
class DocumentStarts : public YAML::EventHandler {
 public:
  std::vector<YAML::Mark> first_nodes;

  void OnDocumentStart(const YAML::Mark&) override { in_new_document_ = true; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& m, YAML::anchor_t) override { node_at(m); }
  void OnAlias(const YAML::Mark& m, YAML::anchor_t) override { node_at(m); }
  void OnScalar(const YAML::Mark& m, const std::string&, YAML::anchor_t, const std::string&) override { node_at(m); }
  void OnSequenceStart(const YAML::Mark& m, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    node_at(m);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& m, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    node_at(m);
  }
  void OnMapEnd() override {}

 private:
  void node_at(const YAML::Mark& m) {
    if (in_new_document_) first_nodes.push_back(m);
    in_new_document_ = false;
  }
  bool in_new_document_ = false;
};

}  // namespace

YAML::Node parse_document(const std::string& text, const std::string& file_label) {
  YAML::Node doc;
  DocumentStarts starts;
  try {
    std::istringstream in(text);
    YAML::Parser parser(in);
    while (starts.first_nodes.size() < 2 && parser.HandleNextDocument(starts)) {
    }
    doc = YAML::Load(text);  // the first document only (YAML::Load reads no further)
  } catch (const YAML::Exception& e) {
    throw InputError(file_label + ":" + std::to_string(e.mark.line + 1) + ": is not valid YAML (" + e.msg + ").");
  }
  if (starts.first_nodes.size() > 1) {
    const YAML::Mark& second = starts.first_nodes[1];
    if (second.pos == starts.first_nodes[0].pos)  // the parser read nothing: yaml-cpp 0.7's endless loop
      throw InputError(file_label + ":" + std::to_string(second.line + 1) +
                       ": is not valid YAML (no node can start at column " + std::to_string(second.column + 1) + ").");
    throw InputError(file_label + ":" + std::to_string(separator_line(text, second.line + 1)) +
                     ": a second YAML document starts here ('---'); the file must hold exactly one.");
  }
  if (starts.first_nodes.empty()) return YAML::Node();  // an empty file: the caller says what it should hold
  DuplicateKeyCheck(file_label).walk(doc, "");
  return doc;
}

}  // namespace dda::yaml_strict
