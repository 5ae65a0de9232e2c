// dda wedge --plane D/B --plane D/B --phi F[,F2] [--azimuth A | --direction x,y,z]
//           [--face D/B --upper D/B --height H [--unit-weight G] [--water [--water-unit-weight GW]]] [--json]
//
// Limit equilibrium of a tetrahedral wedge (docs/analytical.md).
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>

#include "analysis_options.hpp"
#include "commands.hpp"
#include "dda/analysis/wedge.hpp"
#include "dda/analysis/wedge_body.hpp"
#include "dda/common/error.hpp"
#include "dda/common/short_number.hpp"
#include "pipeline.hpp"

namespace dda::cli {

namespace {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

void add_wedge_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::vector<std::string> planes;
    std::vector<double> phi, cohesion, area, direction;
    double weight = 0.0;
    std::string face, upper;
    double height = 0.0, unit_weight = 26.0, water_unit_weight = 9.81;
    bool water = false;
    double azimuth = std::numeric_limits<double>::quiet_NaN();
    double k = 0.0;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "wedge",
      "Limit equilibrium of a tetrahedral wedge on two planes (dip/dip-direction; axes x east, y north, z up): "
      "factor of safety under gravity, line of intersection, normal reactions per unit weight, mode, and the "
      "yield acceleration (g) of a pseudo-static body force k W along --azimuth or --direction (the opposite of "
      "the ground acceleration).");
  cmd->add_option("--plane", opt->planes, "Plane as dip/dip-direction in degrees; exactly twice")->required();
  cmd->add_option("--phi", opt->phi, "Friction angle (deg): one for both planes, or phi1,phi2")
      ->required()
      ->delimiter(',');
  cmd->add_option("--azimuth", opt->azimuth, "Horizontal direction of shaking for the yield acceleration (deg)");
  cmd->add_option("--direction", opt->direction, "Direction of shaking as a vector x,y,z (instead of --azimuth)")
      ->delimiter(',');
  cmd->add_option("--k", opt->k, "Also report FS with a pseudo-static coefficient k (g) along the shaking direction");
  cmd->add_option("--cohesion", opt->cohesion, "Cohesion per plane c1,c2 (kPa); needs --area and --weight")
      ->delimiter(',');
  cmd->add_option("--area", opt->area, "Areas of the two faces A1,A2 (m^2)")->delimiter(',');
  cmd->add_option("--weight", opt->weight, "Weight of the wedge (kN)");
  cmd->add_option("--face", opt->face, "Slope face (dip/dip-direction): with --upper and --height the wedge's "
                                       "weight and face areas come from its geometry");
  cmd->add_option("--upper", opt->upper, "Upper slope surface (dip/dip-direction)");
  cmd->add_option("--height", opt->height, "Total height H of the wedge (m): the rise of the line of intersection "
                                           "from the toe to the upper surface");
  cmd->add_option("--unit-weight", opt->unit_weight, "Unit weight of the rock (kN/m^3), default 26");
  cmd->add_flag("--water", opt->water,
                "Hoek & Bray's saturated wedge: water pressure gamma_w H / 2 at mid-height of the line of "
                "intersection, zero where the planes meet the free surfaces (needs --face, --upper, --height)");
  cmd->add_option("--water-unit-weight", opt->water_unit_weight, "Unit weight of water (kN/m^3), default 9.81");
  cmd->add_flag("--json", opt->json,
                "Print JSON: fs, yield_acceleration_g, trend, plunge, n1, n2, mode, wedge_factor, ...");
  cmd->callback([opt, &global] {
    using namespace analysis;
    if (opt->planes.size() != 2) throw InputError("--plane: a wedge needs exactly two planes.");
    WedgeSpec spec;
    spec.plane1 = parse_plane(opt->planes[0], "--plane");
    spec.plane2 = parse_plane(opt->planes[1], "--plane");
    if (opt->phi.size() != 1 && opt->phi.size() != 2) throw InputError("--phi: give one angle or two (phi1,phi2).");
    spec.phi1_deg = opt->phi[0];
    spec.phi2_deg = opt->phi[opt->phi.size() == 2 ? 1 : 0];
    const bool geometry_given = !opt->face.empty() && !opt->upper.empty() && opt->height > 0.0;
    if (!opt->cohesion.empty()) {
      if (opt->cohesion.size() != 2)
        throw InputError("--cohesion: give c1,c2 (kPa), one for each plane.");
      if (!geometry_given && (opt->area.size() != 2 || !(opt->weight > 0.0)))
        throw InputError("--cohesion: give c1,c2 with --area A1,A2 and a positive --weight, or the wedge's "
                         "geometry (--face, --upper, --height).");
      spec.cohesion1_kpa = opt->cohesion[0];
      spec.cohesion2_kpa = opt->cohesion[1];
      if (!geometry_given) {
        spec.area1_m2 = opt->area[0];
        spec.area2_m2 = opt->area[1];
        spec.weight_kn = opt->weight;
      }
    }
    std::optional<WedgeBody> body;
    const bool has_slope = !opt->face.empty() || !opt->upper.empty() || opt->height != 0.0;
    if (has_slope) {
      if (opt->face.empty() || opt->upper.empty() || opt->height == 0.0)
        throw InputError("--face, --upper, --height: give all three to build the wedge's geometry.");
      if (!(opt->height > 0.0)) throw InputError("--height must be > 0 m, got " + std::to_string(opt->height) + ".");
      if (!(opt->unit_weight > 0.0))
        throw InputError("--unit-weight must be > 0 kN/m^3, got " + short_number(opt->unit_weight) + ".");
      if (!opt->area.empty() || opt->weight != 0.0)
        throw InputError("--area and --weight come from --face, --upper and --height; give one or the other.");
      body = wedge_body(spec.plane1, spec.plane2,
                        SlopeFaces{parse_plane(opt->face, "--face"), parse_plane(opt->upper, "--upper"), opt->height});
      spec.weight_kn = opt->unit_weight * body->volume_m3;
      spec.area1_m2 = body->area1_m2;
      spec.area2_m2 = body->area2_m2;
    }
    if (opt->water) {
      if (!body) throw InputError("--water needs the wedge's geometry: give --face, --upper and --height.");
      if (!(opt->water_unit_weight > 0.0))
        throw InputError("--water-unit-weight must be > 0 kN/m^3, got " + short_number(opt->water_unit_weight) + ".");
      const WedgeWaterForces u = hoek_bray_water(*body, opt->water_unit_weight);
      spec.water1 = u.u1 / spec.weight_kn;
      spec.water2 = u.u2 / spec.weight_kn;
    }
    Vec3 dir;
    const bool has_az = std::isfinite(opt->azimuth);
    if (has_az && !opt->direction.empty()) throw InputError("--azimuth and --direction: give one of them.");
    if (!opt->direction.empty()) {
      if (opt->direction.size() != 3) throw InputError("--direction: give three numbers x,y,z.");
      dir = Vec3(opt->direction[0], opt->direction[1], opt->direction[2]);
      if (!(dir.norm() > 0.0)) throw InputError("--direction: the vector is zero.");
    } else {
      // Default: horizontal, towards the trend of the line of intersection.
      dir = horizontal(has_az ? opt->azimuth : wedge_geometry(spec).line_orientation.trend_deg);
    }
    dir.normalize();
    const WedgeGeometry g = wedge_geometry(spec);
    const WedgeEquilibrium e = wedge_equilibrium(spec, Vec3(0, 0, -1));
    const YieldResult y = wedge_yield(spec, dir);
    const auto crit = wedge_critical_friction(spec);
    nlohmann::json j;
    j["fs"] = number_or_null(e.fs);
    j["mode"] = e.mode;
    j["n1"] = e.n1;
    j["n2"] = e.n2;
    j["trend"] = g.line_orientation.trend_deg;
    j["plunge"] = g.line_orientation.plunge_deg;
    j["wedge_factor"] = g.wedge_factor;
    j["shaking_direction"] = {dir.x(), dir.y(), dir.z()};
    j["yield_acceleration_g"] = y.found ? nlohmann::json(y.k) : nlohmann::json(nullptr);
    j["yield_mode"] = y.mode;
    j["critical_friction_deg"] = crit ? nlohmann::json(*crit) : nlohmann::json(nullptr);
    if (body) {
      j["volume_m3"] = body->volume_m3;
      j["weight_kn"] = spec.weight_kn;
      j["area1_m2"] = body->area1_m2;
      j["area2_m2"] = body->area2_m2;
      j["water_force1_kn"] = spec.water1 * spec.weight_kn;
      j["water_force2_kn"] = spec.water2 * spec.weight_kn;
    }
    if (opt->k != 0.0) {
      const WedgeEquilibrium ek = wedge_equilibrium(spec, Vec3(0, 0, -1) + opt->k * dir);
      j["pseudo_static"] = {{"k", opt->k}, {"fs", number_or_null(ek.fs)}, {"mode", ek.mode},
                            {"n1", ek.n1}, {"n2", ek.n2}};
    }
    if (opt->json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::ostringstream s;
      s << "wedge: FS = " << e.fs << " (" << e.mode << "), line of intersection " << g.line_orientation.trend_deg
        << "/" << g.line_orientation.plunge_deg << " (trend/plunge), N1/W = " << e.n1 << ", N2/W = " << e.n2
        << "\n";
      if (body)
        s << "  wedge: volume " << body->volume_m3 << " m^3, weight " << spec.weight_kn << " kN, faces "
          << body->area1_m2 << " and " << body->area2_m2 << " m^2"
          << (opt->water ? ", water forces " + short_number(spec.water1 * spec.weight_kn) + " and " +
                               short_number(spec.water2 * spec.weight_kn) + " kN"
                         : std::string())
          << "\n";
      s << "  yield acceleration along (" << dir.x() << ", " << dir.y() << ", " << dir.z() << "): ";
      if (y.found)
        s << y.k << " g (" << y.mode << ")\n";
      else
        s << "none up to 10 g\n";
      say(global.quiet, s.str());
    }
  });
}

}  // namespace dda::cli
