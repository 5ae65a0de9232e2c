// dda wedge --plane D/B --plane D/B --phi F[,F2] [--azimuth A | --direction x,y,z] [--json]
//
// Limit equilibrium of a tetrahedral wedge (docs/analytical.md).
#include <cmath>
#include <iostream>
#include <limits>

#include "analysis_options.hpp"
#include "commands.hpp"
#include "dda/analysis/wedge.hpp"
#include "dda/common/error.hpp"
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
    if (!opt->cohesion.empty()) {
      if (opt->cohesion.size() != 2 || opt->area.size() != 2 || !(opt->weight > 0.0))
        throw InputError("--cohesion: give c1,c2 with --area A1,A2 and a positive --weight.");
      spec.cohesion1_kpa = opt->cohesion[0];
      spec.cohesion2_kpa = opt->cohesion[1];
      spec.area1_m2 = opt->area[0];
      spec.area2_m2 = opt->area[1];
      spec.weight_kn = opt->weight;
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
        << "\n  yield acceleration along (" << dir.x() << ", " << dir.y() << ", " << dir.z() << "): ";
      if (y.found)
        s << y.k << " g (" << y.mode << ")\n";
      else
        s << "none up to 10 g\n";
      say(global.quiet, s.str());
    }
  });
}

}  // namespace dda::cli
