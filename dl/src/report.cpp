// The DL report: per-set totals (from the finished model) and the text table.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "builder.hpp"
#include "report_table.hpp"
#include "dda/dl/generate.hpp"

namespace dda::dl {

namespace detail {

void add_totals_to_report(Builder& b) {
  const double area = b.domain_area();
  std::vector<std::size_t> count(b.model.sets.size(), 0);
  std::vector<double> length(b.model.sets.size(), 0.0);
  std::size_t joints = 0, bedding = 0;
  double total = 0;
  for (const JointLine& l : b.model.lines) {
    const double len = (l.b - l.a).norm();
    ++count[static_cast<std::size_t>(l.set)];
    length[static_cast<std::size_t>(l.set)] += len;
    total += len;
    (l.kind == LineKind::Bedding ? bedding : joints) += 1;
  }
  nlohmann::json sets = nlohmann::json::array();
  for (std::size_t i = 0; i < b.model.sets.size(); ++i)
    sets.push_back({{"index", i},
                    {"name", b.model.sets[i].name},
                    {"origin", b.model.sets[i].origin},
                    {"lines", count[i]},
                    {"total_length", length[i]},
                    {"p21", area > 0 ? length[i] / area : 0.0}});
  b.report["sets"] = sets;
  b.report["totals"] = {{"sets", b.model.sets.size()},
                        {"lines", b.model.lines.size()},
                        {"joint_lines", joints},
                        {"bedding_lines", bedding},
                        {"total_length", total},
                        {"p21", area > 0 ? total / area : 0.0},
                        {"excavations", b.model.excavations.size()},
                        {"points", b.model.points.size()}};
}

}  // namespace detail

namespace {

using detail::num;
using detail::Table;

std::string pair(const nlohmann::json& asked, const nlohmann::json& real) { return num(asked) + " / " + num(real); }

}  // namespace

std::string format_report(const nlohmann::json& r) {
  std::ostringstream out;
  out << "DL report";
  if (r.contains("seed")) out << " (seed " << num(r["seed"]) << ")";
  out << "\n";
  if (r.contains("domain") && !r["domain"].is_null())
    out << "Domain: " << num(r["domain"]["kind"]) << ", area " << num(r["domain"]["area"]) << " m^2\n";
  else
    out << "Domain: none (outline made by the imported lines)\n";

  if (r.contains("statistical_sets") && !r["statistical_sets"].empty()) {
    out << "\nStatistical sets (asked / realised; realised over all generated traces, before clipping)\n";
    Table t({"set", "dip deg", "length m", "bridge m", "spacing m", "generated", "in domain", "length m", "P21 1/m"});
    for (const auto& s : r["statistical_sets"])
      t.add({num(s["name"]), pair(s["asked"]["dip"], s["realised"]["dip"]),
             pair(s["asked"]["mean_length"], s["realised"]["mean_length"]),
             pair(s["asked"]["mean_bridge"], s["realised"]["mean_bridge"]),
             pair(s["asked"]["mean_spacing"], s["realised"]["mean_spacing"]), num(s["realised"]["generated_traces"]),
             num(s["in_domain"]["traces"]), num(s["in_domain"]["total_length"]), num(s["in_domain"]["p21"])});
    out << t.str();
  }

  if (r.contains("layering") && !r["layering"].is_null()) {
    const auto& l = r["layering"];
    const auto& th = l["thickness"];
    out << "\nLayering: " << num(l["beds"]) << " beds, bedding dip " << num(l["bedding_dip"])
        << " deg; thickness of the " << num(th["full_beds"]) << " full beds: mean " << num(th["mean"]) << " m, std "
        << num(th["std"]) << " m, min " << num(th["min"]) << " m, max " << num(th["max"]) << " m (minimum "
        << num(th["minimum"]) << " m)\n";
    Table t({"bed", "bottom m", "top m", "thickness m", "target FSI", "realised FSI", "joints"});
    for (const auto& b : l["layers"])
      t.add({num(b["index"]), num(b["bottom"]), num(b["top"]), num(b["thickness"]), num(b["target_fsi"]),
             num(b["realised_fsi"]), num(b["joints"])});
    out << t.str();
    if (!l["sets"].empty()) {
      out << "\nLayered sets\n";
      Table s({"set", "dip deg", "FSI", "randomness", "joints", "length m", "median FSI of beds"});
      for (const auto& set : l["sets"]) {
        std::vector<double> f;
        for (const auto& pl : set["per_layer"])
          if (pl["realised_fsi"].get<double>() > 0) f.push_back(pl["realised_fsi"].get<double>());
        std::sort(f.begin(), f.end());
        const double med = f.empty() ? 0 : (f.size() % 2 ? f[f.size() / 2] : 0.5 * (f[f.size() / 2 - 1] + f[f.size() / 2]));
        s.add({num(set["name"]), num(set["dip"]), num(set["fsi"]), num(set["randomness"]), num(set["joints"]),
               num(set["total_length"]), f.empty() ? "-" : detail::format_number(med)});
      }
      out << s.str();
    }
  }

  if (r.contains("excavations") && !r["excavations"].empty()) {
    out << "\nExcavations\n";
    Table t({"#", "shape", "vertices", "area m^2"});
    std::size_t i = 0;
    for (const auto& e : r["excavations"]) t.add({std::to_string(i++), num(e["shape"]), num(e["vertices"]), num(e["area"])});
    out << t.str();
  }

  if (r.contains("sets") && !r["sets"].empty()) {
    out << "\nAll sets in the model\n";
    Table t({"set", "origin", "lines", "length m", "P21 1/m"});
    for (const auto& s : r["sets"])
      t.add({num(s["name"]), num(s["origin"]), num(s["lines"]), num(s["total_length"]), num(s["p21"])});
    out << t.str();
  }

  if (r.contains("totals")) {
    const auto& t = r["totals"];
    out << "\nTotals: " << num(t["lines"]) << " lines (" << num(t["joint_lines"]) << " joints, "
        << num(t["bedding_lines"]) << " bed boundaries) in " << num(t["sets"]) << " sets, length "
        << num(t["total_length"]) << " m, P21 " << num(t["p21"]) << " 1/m, " << num(t["excavations"])
        << " excavations, " << num(t["points"]) << " points\n";
  }
  return out.str();
}

}  // namespace dda::dl
