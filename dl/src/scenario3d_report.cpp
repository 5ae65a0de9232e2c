// The 3D DL report as text for the terminal (the JSON is the record; this is
// for reading at a glance).
#include <algorithm>
#include <sstream>

#include "builder.hpp"  // detail::format_number
#include "report_table.hpp"
#include "dda/dl/scenario3d.hpp"

namespace dda::dl {

namespace {

using nlohmann::json;

using detail::num;
using detail::Table;

std::string three(const json& v, const char* a, const char* b, const char* c) {
  return num(v[a], 3) + " / " + num(v[b], 3) + " / " + num(v[c], 3);
}

std::string dip_dd(const json& dip, const json& dd) { return dip.is_null() ? "-" : num(dip, 3) + "/" + num(dd, 4); }

std::string size_text(const json& s) {
  const std::string law = s["law"].get<std::string>();
  if (law == "constant") return "r = " + num(s["radius"]);
  if (law == "lognormal") return "lognormal " + num(s["mean"]) + " +- " + num(s["std"]);
  if (law == "exponential") return "exponential " + num(s["mean"]);
  return "power " + num(s["alpha"]) + " [" + num(s["rmin"]) + ", " + num(s["rmax"]) + "]";
}

void sets_section(std::ostringstream& out, const json& r) {
  if (r.contains("fracture_sets") && !r["fracture_sets"].empty()) {
    out << "\nFracture sets (asked; sizes are radii in m; generated counts include the margin)\n";
    Table t({"set", "shape", "dip/dd deg", "kappa", "size m", "intensity", "margin m", "generated", "in domain"});
    for (const auto& s : r["fracture_sets"]) {
      const json& a = s["asked"];
      const std::string shape = a["shape"] == "polygon" ? "polygon " + num(a["sides"]) : "disc";
      const std::string intensity = a.contains("p32") ? "P32 " + num(a["p32"]) : "count " + num(a["count"]);
      t.add({num(s["name"]), shape, dip_dd(a["dip"], a["dip_direction"]),
             a["kappa"].is_null() ? "inf" : num(a["kappa"]), size_text(a["size"]), intensity, num(a["margin"]),
             num(s["generated"]), num(s["in_domain"])});
    }
    out << t.str();
  }
  if (r.contains("sets") && !r["sets"].empty()) {
    out << "\nAll sets in the domain (P32 asked / realised, 1/m; P10 on the x / y / z lines through the centre, 1/m;\n"
           "P21 on the yz / xz / xy mid-planes, 1/m; mean radius, m; mean orientation and Fisher kappa estimate)\n";
    Table t({"set", "origin", "fractures", "P32", "P10 x/y/z", "P21 yz/xz/xy", "mean r", "dip/dd deg", "kappa"});
    for (const auto& s : r["sets"]) {
      const json& o = s["orientation"];
      t.add({num(s["name"]), num(s["origin"]), num(s["fractures"]), num(s["asked_p32"]) + " / " + num(s["p32"]),
             three(s["p10"], "x", "y", "z"), three(s["p21"], "yz", "xz", "xy"), num(s["mean_radius"]),
             o.is_null() ? "-" : dip_dd(o["dip"], o["dip_direction"]),
             // kappa: null means infinite (parallel fractures) unless there is only one
             o.is_null() || s["fractures"].get<std::size_t>() < 2 ? "-"
                                                                  : (o["kappa"].is_null() ? "inf" : num(o["kappa"]))});
    }
    out << t.str();
  }
}

void layering_section(std::ostringstream& out, const json& r) {
  if (!r.contains("layering") || r["layering"].is_null()) return;
  const json& l = r["layering"];
  const json& th = l["thickness"];
  out << "\nLayering: " << num(l["beds"]) << " beds, bedding " << dip_dd(l["dip"], l["dip_direction"])
      << " deg; thickness of the " << num(th["full_beds"]) << " full beds: mean " << num(th["mean"]) << " m, std "
      << num(th["std"]) << " m, min " << num(th["min"]) << " m, max " << num(th["max"]) << " m (minimum "
      << num(th["minimum"]) << " m)\n";
  for (const auto& s : l["sets"]) {
    out << "Layered set " << num(s["name"]) << " (" << dip_dd(s["dip"], s["dip_direction"]) << " deg, FSI "
        << num(s["fsi"]) << ", randomness " << num(s["randomness"]) << "): " << num(s["joints"]) << " joints\n";
    Table t(
        {"bed", "drawn thickness m", "asked spacing m", "realised spacing m", "target FSI", "realised FSI", "joints"});
    for (const auto& b : s["per_bed"])
      t.add({num(b["bed"]), num(l["layers"][b["bed"].get<std::size_t>()]["drawn_thickness"]),
             num(b["asked_median_spacing"]), num(b["realised_median_spacing"]), num(b["target_fsi"]),
             num(b["realised_fsi"]), num(b["joints"])});
    out << t.str();
  }
}

}  // namespace

std::string format_report3(const json& r) {
  std::ostringstream out;
  out << "DL report, 3D";
  if (r.contains("seed")) out << " (seed " << num(r["seed"]) << ")";
  out << "\n";
  if (r.contains("domain")) {
    const json& b = r["domain"]["box"];
    out << "Domain: box (" << num(b[0]) << ", " << num(b[1]) << ", " << num(b[2]) << ") to (" << num(b[3]) << ", "
        << num(b[4]) << ", " << num(b[5]) << "), volume " << num(r["domain"]["volume"]) << " m^3\n";
  }
  sets_section(out, r);
  layering_section(out, r);
  if (r.contains("excavations") && !r["excavations"].empty()) {
    out << "\nExcavations\n";
    Table t({"name", "shape", "half-spaces", "volume in domain m^3"});
    for (const auto& e : r["excavations"])
      t.add({num(e["name"]), num(e["shape"]), num(e["half_spaces"]), num(e["volume_in_domain"])});
    out << t.str();
  }
  if (r.contains("trace_planes") && !r["trace_planes"].empty()) {
    out << "\nTrace planes\n";
    Table t({"name", "dip/dd deg", "point", "section m^2"});
    for (const auto& p : r["trace_planes"]) {
      std::string point = "(";  // appended, not "(" + ...: GCC 12 -Wrestrict false positive
      point += num(p["point"][0]) + ", " + num(p["point"][1]) + ", " + num(p["point"][2]) + ")";
      t.add({num(p["name"]), dip_dd(p["dip"], p["dip_direction"]), point, num(p["section_area"])});
    }
    out << t.str();
  }
  if (r.contains("totals")) {
    const json& t = r["totals"];
    out << "\nTotals: " << num(t["fractures"]) << " fractures in " << num(t["sets"]) << " sets, P32 " << num(t["p32"])
        << " 1/m, P10 x/y/z " << three(t["p10"], "x", "y", "z") << " 1/m, P21 yz/xz/xy "
        << three(t["p21"], "yz", "xz", "xy") << " 1/m, " << num(t["excavations"]) << " excavations, "
        << num(t["points"]) << " points\n";
  }
  return out.str();
}

}  // namespace dda::dl
