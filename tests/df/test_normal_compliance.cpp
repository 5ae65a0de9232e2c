// Oden-Martins normal compliance (joints.<set>.normal_law: oden_martins):
// the contact's normal force is c_n g^m_n for a penetration g. Checked
// against the closed-form load-penetration curve of a block pressed onto a
// base, the law's own numbers, and its bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "dda/common/error.hpp"
#include "dda/df/core/normal_law.hpp"
#include "dda/df/io/scenario.hpp"
#include "dda/df/2d/simulation.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

JointProperties oden_martins(double c_n, double m_n) {
  JointProperties j;
  j.friction_deg = 30;
  j.normal_law = "oden_martins";
  j.normal_parameters = {{"c_n", c_n}, {"m_n", m_n}};
  return j;
}

TEST(NormalCompliance, LawNumbers) {
  // N = c_n g^m: at g = 1e-3 m, c_n = 5e10, m = 2: N = 5e4 N, dN/dg =
  // 2 c_n g = 1e8 N/m, energy c_n g^3 / 3 = 16.667 J (hand-computed).
  const OdenMartinsNormal law(5e10, 2);
  EXPECT_DOUBLE_EQ(law.force(1e-3), 5e4);
  EXPECT_DOUBLE_EQ(law.stiffness(1e-3), 1e8);
  EXPECT_NEAR(law.penetration_at_force(5e4), 1e-3, 1e-15);
  EXPECT_NEAR(law.energy_at_force(5e4), 5e10 * 1e-9 / 3, 1e-9);
  EXPECT_EQ(law.force(-1e-3), 0.0);  // an open contact carries nothing
  EXPECT_EQ(law.stiffness(0), 0.0);  // m > 1: soft at first touch
  // m = 1 is the linear penalty spring c_n.
  const OdenMartinsNormal linear(1e9, 1);
  EXPECT_DOUBLE_EQ(linear.stiffness(0), 1e9);
  EXPECT_DOUBLE_EQ(linear.force(2e-4), 2e5);
}

// A block [0, 1] x [0, 0.5] (rho 2000: W = 9810 N) on a fixed base, its two
// bottom corners the contacts, pressed by a point load on its centre that
// rises from 0 to p_max over t_ramp; quasi-static (dynamic 0).
struct Press {
  double c_n, m_n, p_max, t_ramp, dt;
};

struct PressRun {
  std::vector<double> load, sink;  // total load W + P (N) and the block's settlement (m), per step
};

PressRun press(const Press& p) {
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rectangle(-1, -0.5, 3, 0.5)));
  in.geometry.blocks.push_back(test::make_block(test::rectangle(0, 0, 1, 0.5)));
  // E = 1e12 Pa: the block's own compression under 1e5 N (~5e-8 m) is 5e-5
  // of the contacts' penetration (1e-3 m), the base's fixed springs (10 x
  // 50 E) give way by 2e-9 m.
  in.materials = {test::rock(2000, 1e12)};
  in.joint_sets = {oden_martins(p.c_n, p.m_n)};
  in.default_joint = in.joint_sets[0];
  in.control.dt = p.dt;
  in.control.dynamic = 0;
  in.control.initial_equilibrium = false;  // the curve from first touch on
  for (const double x : {-0.5, 0.5, 1.5}) in.fixed_points.push_back({"base", {x, -0.25}, 0, {}});
  TimeHistory ramp{{0, p.t_ramp}, {Vec2(0, 0), Vec2(0, -p.p_max)}};
  in.loads.push_back({"press", {0.5, 0.25}, {0, 0}, 1, ramp});
  in.measurements.push_back({"bottom", {0.5, 0.001}, 1});
  Simulation sim(build_model(in));
  PressRun r;
  while (sim.time() < p.t_ramp - 1e-9) {
    sim.run_until(sim.time() + p.dt);
    // The load the step applied is the ramp's mean over the step.
    const double t_mid = sim.time() - 0.5 * p.dt;
    r.load.push_back(9810 + p.p_max * t_mid / p.t_ramp);
    r.sink.push_back(-sim.histories()[0].back().displacement.y());
  }
  return r;
}

TEST(NormalCompliance, BlockPressedOnABaseFollowsTheClosedFormCurve) {
  // Closed form: the two corners carry half the load each, so the block
  // sinks g = ((W + P) / (2 c_n))^(1/m) (Oden & Martins' power law solved
  // for g). c_n = 5e10 N/m^3, m = 2: g = 1 mm at 1e5 N. The solver
  // linearises the law once per step; with 200 load steps its force at the
  // end of a step is off the curve by (m-1)/2 (dg/g)^2, below 1e-4 once the
  // load has doubled, so 0.5 % is asked for along the whole curve.
  const double c_n = 5e10, m = 2.0;
  const PressRun r = press({c_n, m, 1e5 - 9810, 2.0, 0.01});
  ASSERT_GT(r.load.size(), 150u);
  double worst = 0;
  for (std::size_t i = r.load.size() / 10; i < r.load.size(); ++i) {
    const double expected = std::pow(r.load[i] / (2 * c_n), 1 / m);
    worst = std::max(worst, std::abs(r.sink[i] - expected) / expected);
  }
  const double g_end = std::pow(r.load.back() / (2 * c_n), 1 / m);
  std::printf("Oden-Martins m = 2: sink at %.0f N %.6e m (closed form %.6e), worst relative error %.2e\n",
              r.load.back(), r.sink.back(), g_end, worst);
  EXPECT_LT(worst, 5e-3);
  // Not the linear spring: doubling the load sinks the block by sqrt(2).
  const std::size_t half = r.load.size() / 2 - 1;
  EXPECT_NEAR(r.sink.back() / r.sink[half], std::sqrt(r.load.back() / r.load[half]), 0.005);
}

TEST(NormalCompliance, ExponentThreeHalvesAsHertz) {
  // m = 1.5 (the Hertzian exponent), c_n = 3.16e9 N/m^2.5: g = (F/(2 c_n))^(2/3)
  // = 1.000 mm at F = 2 c_n 1e-4.5 = 2e5 N; same closed form.
  const double c_n = 3.16e9, m = 1.5;
  const PressRun r = press({c_n, m, 2e5 - 9810, 2.0, 0.01});
  const double expected = std::pow(r.load.back() / (2 * c_n), 1 / m);
  std::printf("Oden-Martins m = 1.5: sink %.6e m (closed form %.6e)\n", r.sink.back(), expected);
  EXPECT_NEAR(r.sink.back(), expected, 5e-3 * expected);
}

std::string error_of(const JointProperties& j) {
  try {
    make_normal_law(j, 1e9);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(NormalCompliance, BadParametersAreOneSentence) {
  JointProperties j = oden_martins(5e10, 0.5);
  EXPECT_EQ(error_of(j), "Normal law oden_martins: parameter m_n must be in [1, 10], got 0.5.");
  j.normal_parameters.erase("c_n");
  j.normal_parameters["m_n"] = 2;
  EXPECT_EQ(error_of(j), "Normal law oden_martins: parameter c_n is required (N/m^(1+m_n)).");
  j.normal_parameters["c"] = 1;
  EXPECT_NE(error_of(j).find("parameter c is not a number the law reads"), std::string::npos);
  j.normal_law = "hertz";
  EXPECT_EQ(error_of(j), "Unknown normal law 'hertz' (known: penalty, oden_martins).");
}


// The joints section as a scenario gives it, on one block whose edges are
// set "fault".
ModelInput read(const std::string& joints) {
  BlockModel blocks;
  blocks.sets = {{"fault", "user"}};
  blocks.blocks.push_back(test::make_block(test::rectangle(0, 0, 1, 1), 0));
  const std::string text = "name: t\n" + joints + "control: {dt: 0.001, steps: 1}\n";
  return read_df_scenario(YamlNode::load_string(text, "s.yaml"), blocks, "b.h5").input;
}

std::string scenario_error(const std::string& joints) {
  try {
    read(joints);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(NormalCompliance, ScenarioKey) {
  const ModelInput in = read(
      "joints:\n  default: {normal_law: {name: oden_martins, c_n: 5.0e10, m_n: 2.5}}\n  fault: {friction_deg: 20}\n");
  EXPECT_EQ(in.joint_sets[0].normal_law, "oden_martins");  // inherited with its numbers
  EXPECT_EQ(in.joint_sets[0].normal_parameters.at("m_n"), 2.5);
  EXPECT_EQ(read("joints:\n  fault: {normal_law: penalty}\n").joint_sets[0].normal_law, "penalty");
  const std::string head = "joints:\n  fault:\n    normal_law: ";
  EXPECT_EQ(scenario_error(head + "{name: oden_martins, c_n: 5.0e10, m_n: 0.5}\n"),
            "s.yaml:4: joints.fault.normal_law.m_n must be in [1, 10], got 0.5.");
  EXPECT_EQ(scenario_error(head + "{name: oden_martins, m_n: 2}\n"),
            "s.yaml:4: required key 'joints.fault.normal_law.c_n' is missing.");
  EXPECT_NE(scenario_error(head + "{name: oden_martins, c_n: 1, m_n: 2, b_n: 1}\n").find("b_n"), std::string::npos);
  EXPECT_EQ(scenario_error(head + "hertz\n"),
            "s.yaml:4: joints.fault.normal_law must be a known normal law (penalty, oden_martins), got 'hertz'.");
}

// 3D takes the normal laws too: test_normal_law3d.cpp.

}  // namespace
}  // namespace dda::df
