// DDA for Windows geometry files (.geo): an XML document
//
//   <Berkeley:DDA xmlns:Berkeley="...">
//     <Berkeley:Geometry>
//       <Berkeley:Edgenodedist distance="0.01"/>        (ignored: a solver setting)
//       <Jointlist> <Joint type="1"> x1 y1 x2 y2 </Joint> ... </Jointlist>
//       <Fixedpointlist> <Point> x y </Point> <Line> x1 y1 x2 y2 </Line> </Fixedpointlist>
//       <Loadpointlist> / <Measuredpointlist> / <Holepointlist> <Point> x y </Point>
//     </Berkeley:Geometry>
//   </Berkeley:DDA>
//
// Format learnt from the examples of DDA for Windows (doolin/ntdda); this is
// an independent reader.
#include <tinyxml2.h>

#include <cmath>
#include <cstdlib>
#include <locale>
#include <map>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/dl/clip.hpp"
#include "dda/dl/generate.hpp"
#include "dda/common/text_input.hpp"

namespace dda::dl {

namespace {

// Element name without a namespace prefix ("Berkeley:Geometry" -> "Geometry").
std::string local_name(const tinyxml2::XMLElement* e) {
  const std::string n = e->Name();
  const auto colon = n.rfind(':');
  return colon == std::string::npos ? n : n.substr(colon + 1);
}

struct GeoReader {
  std::string path;

  [[noreturn]] void fail(const tinyxml2::XMLElement* e, const std::string& message) const {
    throw InputError(path + ":" + std::to_string(e->GetLineNum()) + ": <" + e->Name() + "> " + message + ".");
  }

  std::vector<double> numbers(const tinyxml2::XMLElement* e, std::size_t count) const {
    const char* text = e->GetText();
    std::istringstream in(text ? text : "");
    in.imbue(std::locale::classic());
    std::vector<double> v;
    std::string word;
    while (in >> word) {
      char* end = nullptr;
      const double x = std::strtod(word.c_str(), &end);
      if (end != word.c_str() + word.size()) fail(e, "holds '" + word + "', which is not a number");
      if (!std::isfinite(x)) fail(e, "holds '" + word + "', which is not a finite number");
      v.push_back(x);
    }
    if (v.size() != count)
      fail(e, "must hold " + std::to_string(count) + " numbers (" + (count == 2 ? "x y" : "x1 y1 x2 y2") + "), got " +
                  std::to_string(v.size()));
    return v;
  }
};

}  // namespace

LineModel import_geo(const std::string& path) {
  tinyxml2::XMLDocument doc;
  // Read with the project's limits (tinyxml2's LoadFile asks the file its
  // size, which /dev/zero does not have).
  const std::string text = read_text_file(path, "DDA geometry");
  const tinyxml2::XMLError err = doc.Parse(text.c_str(), text.size());
  if (err != tinyxml2::XML_SUCCESS)
    throw InputError(path + ":" + std::to_string(doc.ErrorLineNum()) + ": is not valid XML (" +
                     tinyxml2::XMLDocument::ErrorIDToName(err) + ").");
  GeoReader r{path};
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root || local_name(root) != "DDA")
    throw InputError(path + ":" + std::to_string(root ? root->GetLineNum() : 1) +
                     ": is not a DDA geometry file (the root element must be <Berkeley:DDA>).");
  const tinyxml2::XMLElement* geometry = nullptr;
  for (auto* e = root->FirstChildElement(); e; e = e->NextSiblingElement())
    if (local_name(e) == "Geometry") geometry = e;
  if (!geometry) r.fail(root, "has no <Berkeley:Geometry> element");

  LineModel model;
  std::map<int, std::vector<Segment>> joints_by_type;
  std::vector<Segment> fixed_lines;
  std::vector<ModelPoint> points;
  std::map<PointKind, int> counts;
  auto add_point = [&](PointKind kind, const Vec2& p) {
    static const std::map<PointKind, std::string> prefix = {
        {PointKind::Fixed, "fixed"}, {PointKind::Load, "load"}, {PointKind::Measurement, "measured"},
        {PointKind::Hole, "hole"}};
    points.push_back({prefix.at(kind) + "_" + std::to_string(++counts[kind]), kind, p});
  };

  for (auto* list = geometry->FirstChildElement(); list; list = list->NextSiblingElement()) {
    const std::string name = local_name(list);
    if (name == "Edgenodedist") continue;  // a solver setting, not geometry
    if (name == "Jointlist") {
      for (auto* j = list->FirstChildElement(); j; j = j->NextSiblingElement()) {
        if (local_name(j) != "Joint") r.fail(j, "is not allowed in <Jointlist> (only <Joint>)");
        int type = 0;
        if (j->QueryIntAttribute("type", &type) != tinyxml2::XML_SUCCESS || type < 0)
          r.fail(j, "needs a type attribute with a whole number >= 0, e.g. type=\"1\"");
        const auto v = r.numbers(j, 4);
        const Segment s{Vec2(v[0], v[1]), Vec2(v[2], v[3])};
        if (s.a == s.b) r.fail(j, "has zero length (both ends are the same point)");
        joints_by_type[type].push_back(s);
      }
    } else if (name == "Fixedpointlist") {
      for (auto* p = list->FirstChildElement(); p; p = p->NextSiblingElement()) {
        if (local_name(p) == "Point") {
          const auto v = r.numbers(p, 2);
          add_point(PointKind::Fixed, Vec2(v[0], v[1]));
        } else if (local_name(p) == "Line") {
          const auto v = r.numbers(p, 4);
          const Segment s{Vec2(v[0], v[1]), Vec2(v[2], v[3])};
          if (s.a == s.b) {
            add_point(PointKind::Fixed, s.a);  // a degenerate line is a point
            continue;
          }
          fixed_lines.push_back(s);
          add_point(PointKind::Fixed, s.a);
          add_point(PointKind::Fixed, 0.5 * (s.a + s.b));
          add_point(PointKind::Fixed, s.b);
        } else {
          r.fail(p, "is not allowed in <Fixedpointlist> (only <Point> and <Line>)");
        }
      }
    } else if (name == "Loadpointlist" || name == "Measuredpointlist" || name == "Holepointlist") {
      const PointKind kind = name == "Loadpointlist"       ? PointKind::Load
                             : name == "Measuredpointlist" ? PointKind::Measurement
                                                           : PointKind::Hole;
      for (auto* p = list->FirstChildElement(); p; p = p->NextSiblingElement()) {
        if (local_name(p) != "Point") r.fail(p, "is not allowed in <" + name + "> (only <Point>)");
        const auto v = r.numbers(p, 2);
        add_point(kind, Vec2(v[0], v[1]));
      }
    } else if (name == "Boltlist" || name == "Matlinelist" || name == "Seismicpointlist" || name == "Boundlist") {
      if (list->FirstChildElement()) r.fail(list, "is not supported by this importer yet (remove it or leave it empty)");
    } else {
      r.fail(list, "is not a known element of a DDA geometry (expected Jointlist, Fixedpointlist, Loadpointlist, "
                   "Measuredpointlist or Holepointlist)");
    }
  }

  for (const auto& [type, segs] : joints_by_type) {
    const int set = static_cast<int>(model.sets.size());
    model.sets.push_back({"type" + std::to_string(type), "geo"});
    for (const Segment& s : segs) model.lines.push_back({s.a, s.b, set, LineKind::Joint, -1});
  }
  if (!fixed_lines.empty()) {
    const int set = static_cast<int>(model.sets.size());
    model.sets.push_back({"fixed", "geo"});
    for (const Segment& s : fixed_lines) model.lines.push_back({s.a, s.b, set, LineKind::Joint, -1});
  }
  model.points = std::move(points);
  return model;  // domain left empty: the lines themselves make the outline
}

}  // namespace dda::dl
