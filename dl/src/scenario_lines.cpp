// Sections `lines` (user lines), `traces` (CSV files) and `geometry` (a DDA
// for Windows .geo file).
#include <cmath>

#include "builder.hpp"
#include "dda/common/error.hpp"
#include "dda/common/scenario.hpp"
#include "dda/dl/generate.hpp"
#include "dda/dl/import.hpp"
#include "dda/common/sentence_tail.hpp"

namespace dda::dl::detail {

void read_user_lines(const YamlNode& root, Builder& b) {
  std::size_t given = 0, kept = 0;
  for (const YamlNode& n : root.list_or_empty("lines")) {
    n.allow({"set", "from", "to"});
    const std::string name = n.text("set", "user");
    if (name.empty()) n.fail_key("set", "must not be empty");
    const Segment s{b.local(n.point("from")), b.local(n.point("to"))};
    if (s.a == s.b) n.fail_key("to", "must differ from 'from' (the line has zero length)");
    const int set = b.find_or_add_set(name, "user");
    const int pieces = b.add_clipped(s, set);
    if (pieces == 0) n.fail("lies wholly outside the domain");
    ++given;
    kept += static_cast<std::size_t>(pieces);
  }
  b.report["user_lines"] = {{"given", given}, {"pieces_in_domain", kept}};
}

void read_traces(const YamlNode& root, Builder& b) {
  nlohmann::json rep = nlohmann::json::array();
  for (const YamlNode& n : root.list_or_empty("traces")) {
    n.allow({"file", "set"});
    const std::string file = n.text("file");
    const std::string default_set = n.text("set", "traces");
    if (default_set.empty()) n.fail_key("set", "must not be empty");
    const std::string path = resolve_scenario_path(n, file);
    std::vector<CsvTrace> traces;
    try {
      traces = read_traces_csv(path);
    } catch (const InputError& e) {
      // Name both the scenario key and the trace file's own line.
      n.fail_key("file", "names a trace file with an error: " + sentence_tail(e));
    }
    std::size_t kept = 0, outside = 0;
    for (const CsvTrace& t : traces) {
      const int set = b.find_or_add_set(t.set.empty() ? default_set : t.set, "csv");
      const int pieces = b.add_clipped({b.local(t.seg.a), b.local(t.seg.b)}, set);
      kept += static_cast<std::size_t>(pieces);
      outside += pieces == 0;
    }
    rep.push_back({{"file", file}, {"traces", traces.size()}, {"pieces_in_domain", kept}, {"outside_domain", outside}});
  }
  b.report["traces"] = rep;
}

void read_geometry(const YamlNode& root, Builder& b) {
  const auto node = root.optional_child("geometry");
  if (!node) {
    b.report["geometry"] = nullptr;
    return;
  }
  node->allow({"file"});
  const std::string file = node->text("file");
  LineModel geo;
  try {
    geo = import_geo(resolve_scenario_path(*node, file));
  } catch (const InputError& e) {
    node->fail_key("file", std::string("names a DDA geometry file with an error: ") + e.what());
  }
  std::size_t kept = 0;
  for (const JointLine& l : geo.lines) {
    const int set = b.find_or_add_set(geo.sets[static_cast<std::size_t>(l.set)].name, "geo");
    kept += static_cast<std::size_t>(b.add_clipped({b.local(l.a), b.local(l.b)}, set));
  }
  for (const ModelPoint& p : geo.points) {
    for (const ModelPoint& q : b.model.points)
      if (q.name == p.name) node->fail_key("file", "holds a second point named '" + p.name + "'");
    if (!b.model.domain.empty() && !point_in_polygon(b.model.domain, b.local(p.p)))
      node->fail_key("file", "holds the " + std::string(to_string(p.kind)) + " point '" + p.name + "' at (" +
                                 format_number(p.p.x()) + ", " + format_number(p.p.y()) + "), outside the domain");
    b.model.points.push_back({p.name, p.kind, b.local(p.p)});
  }
  b.report["geometry"] = {{"file", file}, {"lines", geo.lines.size()}, {"pieces_in_domain", kept},
                          {"points", geo.points.size()}};
}

}  // namespace dda::dl::detail
