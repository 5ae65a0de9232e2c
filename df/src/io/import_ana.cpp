// DDA for Windows analysis files (.ana, XML). The format was learnt from the
// examples and documentation of DDA for Windows (doolin/ntdda); this is an
// independent reader. The mapping onto the scenario keys is in
// docs/formats.md ("DDA for Windows analysis files").
//
//   <Berkeley:DDA xmlns:Berkeley="...">
//     <Analysis type="dynamic">
//       <Analysistype type="dynamic"/>            static -> dynamic 0, dynamic -> 1
//       <Numtimesteps timesteps="500"/>           control.steps
//       <Maxtimestep maxtimestep="0.01"/>         control.dt
//       <Mintimestep mintimestep="0.0001"/>       control.min_dt_ratio = min / max
//       <Maxdisplacement maxdisplacement="0.025"/> control.max_displacement_ratio (g2)
//       <OCLimit maxopenclose="8"/>               control.max_open_close (also <Opencloselimit>)
//       <Autopenalty flag="no" pfactor="50"/>     control.penalty_factor
//       <Planestrain flag="no"/>                  plane strain / stress
//       <Saveinterval step="1"/>                  control.output_every
//       <Gravaccel value="9.81"/>                 gravity (else unit weight / unit mass)
//       <Gravity flag="yes"/>                     control.initial_equilibrium (the gravity turn-on phase)
//       <Blockmaterial type="1"> <Unitmass/> <Unitweight/> <Youngsmod/> <Poissonratio/>
//            <Damping/> <Istress/> <Ivelocity/> <Istrain/> </Blockmaterial>
//       <Jointproperties type="1"> <Friction/> <Cohesion/> <Tensile/> </Jointproperties>
//       <Loadpointlist> <Loadpoint numpoints="2"> t fx fy; t fx fy; </Loadpoint> </Loadpointlist>
//                                                 force history of the k-th load point
//     </Analysis>
//   </Berkeley:DDA>
#include "dda/df/io/import_ana.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "dda/common/error.hpp"

namespace dda::df {
namespace {

using tinyxml2::XMLElement;

std::string local_name(const XMLElement* e) {
  const std::string n = e->Name();
  const auto colon = n.rfind(':');
  return colon == std::string::npos ? n : n.substr(colon + 1);
}

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

struct AnaReader {
  std::string label;

  [[noreturn]] void fail(const XMLElement* e, const std::string& message) const {
    throw InputError(label + ":" + std::to_string(e->GetLineNum()) + ": <" + local_name(e) + "> " + message + ".");
  }

  double parse_number(const XMLElement* e, const std::string& word) const {
    char* end = nullptr;
    const double x = std::strtod(word.c_str(), &end);
    if (word.empty() || end != word.c_str() + word.size()) fail(e, "holds '" + word + "', which is not a number");
    if (!std::isfinite(x)) fail(e, "holds '" + word + "', which is not a finite number");
    return x;
  }

  std::vector<double> numbers(const XMLElement* e) const {
    const char* text = e->GetText();
    std::istringstream in(text ? text : "");
    std::vector<double> v;
    std::string word;
    while (in >> word) v.push_back(parse_number(e, word));
    return v;
  }

  double number(const XMLElement* e) const {
    const std::vector<double> v = numbers(e);
    if (v.size() != 1) fail(e, "must hold one number, got " + std::to_string(v.size()));
    return v[0];
  }

  std::vector<double> numbers(const XMLElement* e, std::size_t count) const {
    const std::vector<double> v = numbers(e);
    if (v.size() != count) fail(e, "must hold " + std::to_string(count) + " numbers, got " + std::to_string(v.size()));
    return v;
  }

  std::string attr(const XMLElement* e, const char* name) const {
    const char* v = e->Attribute(name);
    if (!v) fail(e, std::string("needs a ") + name + " attribute");
    return v;
  }

  double attr_number(const XMLElement* e, const char* name) const { return parse_number(e, attr(e, name)); }

  bool flag(const XMLElement* e) const {
    const std::string v = attr(e, "flag");
    if (v == "yes") return true;
    if (v == "no") return false;
    fail(e, "has flag=\"" + v + "\", expected \"yes\" or \"no\"");
  }

  int type_of(const XMLElement* e, int fallback) const {
    const char* t = e->Attribute("type");
    if (!t) return fallback;
    const double v = parse_number(e, t);
    // Bounded before the conversion: a double beyond int has no int value.
    if (v != std::floor(v) || v < 0 || v > 1e9)
      fail(e, "needs a type attribute with a whole number >= 0, e.g. type=\"1\"");
    return static_cast<int>(v);
  }
};

struct AnaMaterial {
  const XMLElement* element = nullptr;
  double mass = 0, weight = 0, young = 0, poisson = 0;
  bool has_mass = false, has_weight = false, has_young = false, has_poisson = false;
  Vector3d stress = Vector3d::Zero();
  Vector3d velocity = Vector3d::Zero();
};

}  // namespace

bool is_ana_path(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e == ".ana";
}

AnaImport import_ana(const std::string& text, const std::string& label, const BlockModel& blocks,
                     const std::string& blocks_path) {
  const AnaReader r{label};
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    throw InputError(label + ":" + std::to_string(doc.ErrorLineNum()) + ": is not well-formed XML (" +
                     tinyxml2::XMLDocument::ErrorIDToName(doc.ErrorID()) + ").");
  const XMLElement* root = doc.RootElement();
  if (!root || local_name(root) != "DDA")
    throw InputError(label + ": is not a DDA for Windows file (its root element must be <Berkeley:DDA>).");
  const XMLElement* analysis = nullptr;
  for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement())
    if (local_name(e) == "Analysis") analysis = e;
  if (!analysis) {
    for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement())
      if (local_name(e) == "Geometry") r.fail(e, "is a geometry; give it to `dda dl`, and the analysis (.ana) to `dda df`");
    r.fail(root, "has no <Analysis> element");
  }

  AnaImport out;
  DfScenario& sc = out.scenario;
  ModelInput& in = sc.input;
  Control& ctl = in.control;
  // The old program loads the model suddenly unless <Gravity flag="yes">.
  ctl.initial_equilibrium = false;
  in.geometry = blocks;
  std::map<int, AnaMaterial> materials;
  std::map<int, std::pair<const XMLElement*, JointProperties>> joints;
  std::vector<std::pair<const XMLElement*, std::vector<double>>> loads;  // t fx fy records
  std::optional<double> grav_accel, min_dt;
  const XMLElement* dt_element = nullptr;
  const XMLElement* steps_element = nullptr;
  bool plane_strain = false;
  if (const char* t = analysis->Attribute("type")) ctl.dynamic = std::string(t) == "static" ? 0.0 : 1.0;

  for (const XMLElement* e = analysis->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string name = local_name(e);
    if (name == "Analysistype") {
      const std::string t = r.attr(e, "type");
      if (t != "static" && t != "dynamic") r.fail(e, "has type=\"" + t + "\", expected \"static\" or \"dynamic\"");
      ctl.dynamic = t == "static" ? 0.0 : 1.0;
    } else if (name == "Numtimesteps") {
      const double n = r.attr_number(e, "timesteps");
      if (n < 1 || n != std::floor(n) || n > 1e9) r.fail(e, "needs timesteps to be a whole number >= 1");
      ctl.steps = static_cast<int>(n);
      steps_element = e;
    } else if (name == "Maxtimestep") {
      ctl.dt = r.attr_number(e, "maxtimestep");
      if (ctl.dt <= 0) r.fail(e, "needs maxtimestep > 0, got " + fmt(ctl.dt));
      dt_element = e;
    } else if (name == "Mintimestep") {
      min_dt = r.attr_number(e, "mintimestep");
      if (*min_dt <= 0) r.fail(e, "needs mintimestep > 0, got " + fmt(*min_dt));
    } else if (name == "Maxdisplacement") {
      ctl.max_displacement_ratio = r.attr_number(e, "maxdisplacement");
      if (ctl.max_displacement_ratio <= 0 || ctl.max_displacement_ratio >= 1)
        r.fail(e, "needs maxdisplacement (the ratio g2) in (0, 1), got " + fmt(ctl.max_displacement_ratio));
    } else if (name == "OCLimit" || name == "Opencloselimit") {
      const double n = r.attr_number(e, "maxopenclose");
      if (n < 1 || n != std::floor(n) || n > 1000) r.fail(e, "needs maxopenclose to be a whole number >= 1");
      ctl.max_open_close = static_cast<int>(n);
    } else if (name == "Autopenalty") {
      if (e->Attribute("pfactor")) {
        ctl.penalty_factor = r.attr_number(e, "pfactor");
        if (ctl.penalty_factor <= 0) r.fail(e, "needs pfactor > 0, got " + fmt(ctl.penalty_factor));
      }
    } else if (name == "Planestrain") {
      plane_strain = r.flag(e);
    } else if (name == "Saveinterval") {
      const double n = r.attr_number(e, "step");
      if (n < 1 || n != std::floor(n) || n > 1e9) r.fail(e, "needs step to be a whole number >= 1");
      sc.output.every = static_cast<int>(n);
    } else if (name == "Gravaccel") {
      grav_accel = r.attr_number(e, "value");
      if (*grav_accel < 0) r.fail(e, "needs value >= 0, got " + fmt(*grav_accel));
    } else if (name == "Gravity") {
      // The old program's gravity turn-on phase loads the model with every
      // contact held before its dynamics starts: what initial_equilibrium
      // does. Ignoring it gave a different problem, a wall switched on under
      // gravity, which bounces on its contact springs (and, on a 1,601-brick
      // wall, changed contact states in every iterate of every step).
      if (r.flag(e)) {
        ctl.initial_equilibrium = true;
        out.warnings.push_back(label + ":" + std::to_string(e->GetLineNum()) +
                               ": <Gravity flag=\"yes\"> (the old program's gravity turn-on phase) is run as "
                               "control.initial_equilibrium: the model is relaxed under gravity before t = 0, first "
                               "with every contact held, then with the joints' friction.");
      }
    } else if (name == "Rotation" || name == "Autotimestep" || name == "AConstants" || name == "Writevertices") {
      // Always exact rotation and automatic step control here; the constants are unused.
    } else if (name == "ContactDamping" || name == "Boltproperties") {
      out.warnings.push_back(label + ":" + std::to_string(e->GetLineNum()) + ": <" + name + "> is ignored.");
    } else if (name == "Blockmaterial") {
      const int type = r.type_of(e, static_cast<int>(materials.size()) + 1);
      if (materials.count(type)) r.fail(e, "repeats material type " + std::to_string(type));
      AnaMaterial m;
      m.element = e;
      for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        const std::string cn = local_name(c);
        if (cn == "Unitmass") m.mass = r.number(c), m.has_mass = true;
        else if (cn == "Unitweight") m.weight = r.number(c), m.has_weight = true;
        else if (cn == "Youngsmod") m.young = r.number(c), m.has_young = true;
        else if (cn == "Poissonratio") m.poisson = r.number(c), m.has_poisson = true;
        else if (cn == "Istress") {
          const auto v = r.numbers(c, 3);
          m.stress = Vector3d(v[0], v[1], v[2]);
        } else if (cn == "Ivelocity") {
          const auto v = r.numbers(c, 3);
          m.velocity = Vector3d(v[0], v[1], v[2]);
        } else if (cn == "Damping" || cn == "Istrain") {
          const auto v = r.numbers(c);
          if (std::any_of(v.begin(), v.end(), [](double x) { return x != 0; }))
            out.warnings.push_back(label + ":" + std::to_string(c->GetLineNum()) + ": <" + cn +
                                   "> is not supported and is ignored.");
        } else {
          r.fail(c, "is not a known element of <Blockmaterial> (expected Unitmass, Unitweight, Youngsmod, "
                    "Poissonratio, Damping, Istress, Ivelocity, Istrain)");
        }
      }
      if (!m.has_mass && !m.has_weight) r.fail(e, "needs <Unitmass> (density)");
      if (!m.has_young) r.fail(e, "needs <Youngsmod>");
      if (!m.has_poisson) r.fail(e, "needs <Poissonratio>");
      materials[type] = m;
    } else if (name == "Jointproperties") {
      const int type = r.type_of(e, static_cast<int>(joints.size()) + 1);
      if (joints.count(type)) r.fail(e, "repeats joint type " + std::to_string(type));
      JointProperties j;
      j.friction_deg = 0;
      bool has_friction = false;
      for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        const std::string cn = local_name(c);
        if (cn == "Friction") j.friction_deg = r.number(c), has_friction = true;
        else if (cn == "Cohesion") j.cohesion = r.number(c);
        else if (cn == "Tensile") j.tensile_strength = r.number(c);
        else r.fail(c, "is not a known element of <Jointproperties> (expected Friction, Cohesion, Tensile)");
        if (cn == "Friction" && (j.friction_deg < 0 || j.friction_deg >= 90))
          r.fail(c, "must be a friction angle in [0, 90) degrees, got " + fmt(j.friction_deg));
        if (cn == "Cohesion" && j.cohesion < 0) r.fail(c, "must be >= 0, got " + fmt(j.cohesion));
        if (cn == "Tensile" && j.tensile_strength < 0) r.fail(c, "must be >= 0, got " + fmt(j.tensile_strength));
      }
      if (!has_friction) r.fail(e, "needs <Friction> (degrees)");
      joints[type] = {e, j};
    } else if (name == "Loadpointlist") {
      for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (local_name(c) != "Loadpoint") r.fail(c, "is not allowed in <Loadpointlist> (only <Loadpoint>)");
        const double n = r.attr_number(c, "numpoints");
        const char* t = c->GetText();
        std::string body = t ? t : "";
        std::replace(body.begin(), body.end(), ';', ' ');
        std::istringstream words(body);
        std::vector<double> v;
        std::string w;
        while (words >> w) v.push_back(r.parse_number(c, w));
        if (v.size() % 3 != 0 || static_cast<double>(v.size() / 3) != n || n < 1)
          r.fail(c, "must hold numpoints records \"t fx fy;\", got " + std::to_string(v.size()) +
                        " numbers for numpoints=\"" + fmt(n) + "\"");
        loads.emplace_back(c, v);
      }
    } else if (name == "Timehistory") {
      r.fail(e, "(earthquake input) is not supported by this importer yet; give the record in a scenario instead");
    } else {
      r.fail(e, "is not a known element of a DDA analysis");
    }
  }
  if (!dt_element) r.fail(analysis, "needs <Maxtimestep maxtimestep=\"...\"/> (the time step)");
  if (!steps_element) r.fail(analysis, "needs <Numtimesteps timesteps=\"...\"/> (the number of steps)");
  if (materials.empty()) r.fail(analysis, "needs a <Blockmaterial>");
  if (joints.empty()) r.fail(analysis, "needs a <Jointproperties>");
  if (min_dt) {
    ctl.min_dt_ratio = std::min(1.0, *min_dt / ctl.dt);
  }

  // Materials: without material lines (which the .geo importer refuses)
  // every block is of the lowest type.
  const AnaMaterial& m = materials.begin()->second;
  if (materials.size() > 1)
    out.warnings.push_back(label + ": only <Blockmaterial type=\"" + std::to_string(materials.begin()->first) +
                           "\"> is used (the geometry assigns no other material to any block).");
  Material mat;
  mat.density = m.has_mass ? m.mass : 0;
  mat.young = m.young;
  mat.poisson = m.poisson;
  mat.plane = plane_strain ? PlaneMode::Strain : PlaneMode::Stress;
  double g = 9.81;
  if (grav_accel) {
    g = *grav_accel;
  } else if (m.has_weight && m.has_mass && m.mass > 0) {
    g = m.weight / m.mass;
  }
  if (!m.has_mass && g > 0) mat.density = m.weight / g;
  if (!(mat.density > 0)) r.fail(m.element, "needs a <Unitmass> (density) > 0, got " + fmt(mat.density));
  if (!(mat.young > 0)) r.fail(m.element, "needs a <Youngsmod> > 0, got " + fmt(mat.young));
  if (!(mat.poisson > -1 && mat.poisson < 0.5)) r.fail(m.element, "needs a <Poissonratio> in (-1, 0.5), got " + fmt(mat.poisson));
  in.materials = {mat};
  in.gravity = Vec2(0, -g);
  if (!m.stress.isZero() || !m.velocity.isZero()) {
    Vector6d v = Vector6d::Zero();
    v.head<3>() = m.velocity;
    in.initial_stress.assign(blocks.blocks.size(), m.stress);
    in.initial_velocity.assign(blocks.blocks.size(), v);
  }

  // Joints: set "typeN" takes <Jointproperties type="N">; everything else
  // the lowest type.
  in.default_joint = joints.begin()->second.second;
  in.joint_sets.assign(blocks.sets.size(), in.default_joint);
  for (std::size_t s = 0; s < blocks.sets.size(); ++s) {
    const std::string& n = blocks.sets[s].name;
    if (n.rfind("type", 0) != 0 || n.size() == 4 || !std::all_of(n.begin() + 4, n.end(), [](char ch) { return ch >= '0' && ch <= '9'; })) continue;
    const int type = std::stoi(n.substr(4));
    const auto it = joints.find(type);
    if (it == joints.end())
      r.fail(analysis, "has no <Jointproperties type=\"" + std::to_string(type) + "\"> for joint set " + n + " of " +
                           blocks_path);
    in.joint_sets[s] = it->second.second;
  }

  // Load points: the k-th <Loadpoint> is the force history (t, fx, fy;
  // piecewise linear) of the k-th load point.
  std::vector<const LocatedPoint*> load_points;
  for (const LocatedPoint& lp : blocks.points)
    if (lp.point.kind == PointKind::Load) load_points.push_back(&lp);
  if (loads.size() != load_points.size())
    r.fail(analysis, "gives " + std::to_string(loads.size()) + " <Loadpoint> histories for the " +
                         std::to_string(load_points.size()) + " load points of " + blocks_path);
  std::map<std::string, Vec2> forces;
  std::map<std::string, TimeHistory> histories;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const std::vector<double>& v = loads[k].second;
    TimeHistory h;
    for (std::size_t i = 0; i < v.size(); i += 3) {
      if (!h.t.empty() && v[i] <= h.t.back())
        r.fail(loads[k].first, "has times that do not increase (record " + std::to_string(i / 3 + 1) + ")");
      h.t.push_back(v[i]);
      h.value.emplace_back(v[i + 1], v[i + 2]);
    }
    forces[load_points[k]->point.name] = h.value.front();
    histories[load_points[k]->point.name] = h;
  }
  check_blocks_for_df(blocks, blocks_path);
  add_points_from_block_model(blocks, forces, in);
  for (PointLoad& l : in.loads) l.history = histories.at(l.name);
  try {
    build_model(in);
  } catch (const InputError& e) {
    throw InputError(label + ": " + e.what());
  }
  return out;
}

}  // namespace dda::df
