// Friction laws as a scenario gives them (joints.<set>.friction_law) and
// their per-contact state in checkpoints: a resumed run must repeat the
// uninterrupted one bit for bit, whatever memory the law keeps.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "dda/common/error.hpp"
#include "dda/df/core/friction_laws.hpp"
#include "dda/df/io/results.hpp"
#include "dda/df/io/scenario.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

using test::friction_joint;

namespace fs = std::filesystem;

// One block whose edges belong to set "fault" (0); enough for the joints section.
BlockModel one_block() {
  BlockModel m;
  m.sets = {{"fault", "user"}};
  m.blocks.push_back(test::make_block(test::rectangle(0, 0, 1, 1), 0));
  return m;
}

ModelInput read(const std::string& joints) {
  const std::string text = "name: t\n" + joints + "control: {dt: 0.001, steps: 1}\n";
  return read_df_scenario(YamlNode::load_string(text, "s.yaml"), one_block(), "b.h5").input;
}

std::string error_of(const std::string& joints) {
  try {
    read(joints);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(FrictionInput, ReadsALawWithItsParameters) {
  const ModelInput in = read(
      "joints:\n"
      "  default: {friction_deg: 35, cohesion: 2000}\n"
      "  fault:\n"
      "    friction_law: {name: rate_state, mu0: 0.6, a: 0.01, b: 0.015, dc: 1.0e-4, v0: 1.0e-6,\n"
      "                   evolution: slip}\n");
  ASSERT_EQ(in.joint_sets.size(), 1u);
  const JointProperties& j = in.joint_sets[0];
  EXPECT_EQ(j.friction_law, "rate_state");
  EXPECT_EQ(j.friction_parameters.at("b"), 0.015);
  EXPECT_EQ(j.friction_parameters.at("dc"), 1e-4);
  EXPECT_EQ(j.friction_options.at("evolution"), "slip");
  EXPECT_EQ(j.cohesion, 2000);  // cohesion stays per joint set
  EXPECT_EQ(in.default_joint.friction_law, "coulomb");
  EXPECT_EQ(make_friction_law(j)->name(), "rate_state");
}

TEST(FrictionInput, TheNameFormStillWorks) {
  const ModelInput in = read("joints:\n  default: {friction_deg: 35, friction_law: coulomb}\n  fault: {friction_deg: 20}\n");
  EXPECT_EQ(in.joint_sets[0].friction_law, "coulomb");
  EXPECT_EQ(in.joint_sets[0].friction_deg, 20);
  // A set inherits the default's law with its parameters.
  const ModelInput inherit = read(
      "joints:\n  default: {friction_law: {name: stribeck, mu_s: 0.6, mu_k: 0.5, v_s: 0.001}}\n"
      "  fault: {cohesion: 10}\n");
  EXPECT_EQ(inherit.joint_sets[0].friction_law, "stribeck");
  EXPECT_EQ(inherit.joint_sets[0].friction_parameters.at("mu_k"), 0.5);
}

TEST(FrictionInput, BadParametersNameTheFileKeyAndLine) {
  const std::string head = "joints:\n  fault:\n    friction_law:\n";
  EXPECT_EQ(error_of(head + "      {name: rate_state, mu0: 0.6, a: 0.01, b: 0.015, dc: -1.0e-4}\n"),
            "s.yaml:5: joints.fault.friction_law.dc must be > 0, got -0.0001.");
  EXPECT_EQ(error_of(head + "      name: rate_state\n      mu0: 0.6\n      a: 0.01\n      b: 0.015\n      dc: 1.0e-4\n"
                            "      evolution: healing\n"),
            "s.yaml:10: joints.fault.friction_law.evolution must be one of aging, slip, got 'healing'.");
  EXPECT_EQ(error_of(head + "      {name: rate_state, mu0: 0.6, b: 0.015, dc: 1.0e-4}\n"),
            "s.yaml:5: joints.fault.friction_law.a is required (1).");
  const std::string unknown = error_of(head + "      {name: stribeck, mu_s: 0.6, mu_k: 0.5, vs: 0.001}\n");
  EXPECT_NE(unknown.find("vs"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("s.yaml:5:"), std::string::npos) << unknown;
  EXPECT_NE(error_of(head + "      {name: mohr_coulomb}\n").find("must be a known friction law"), std::string::npos);
  EXPECT_NE(error_of(head + "      {name: slip_weakening, mu_s: 0.5, mu_d: 0.6, dc: 0.01}\n")
                .find("s.yaml:5: joints.fault.friction_law.mu_d must not exceed mu_s"),
            std::string::npos);
  EXPECT_NE(error_of("joints:\n  fault: {friction_law: mohr}\n").find("Unknown friction law 'mohr'"), std::string::npos);
}

// A 1 x 0.5 m slider (1000 kg) on a fixed base, pulled back and forth by a
// moving fixed point (a 1e6 N/m spring) with an amplitude of 5 cm at 2 Hz:
// it slides both ways, so each law's memory (theta, slip, cycle count)
// changes in every step.
ModelInput shaken_slider(const JointProperties& joint) {
  ModelInput in;
  in.geometry.blocks.push_back(test::make_block(test::rectangle(-1.5, -0.5, 4, 0.5)));
  in.geometry.blocks.push_back(test::make_block(test::rectangle(0, 0, 1, 0.5)));
  in.geometry.sets = {{"J", "user"}};
  in.materials = {test::rock(2000, 1e10)};
  in.joint_sets = {joint};
  in.control.dt = 2e-3;
  in.control.total_time = 0.5;  // one full cycle of the pull: it slides both ways
  for (const double x : {-1.0, 0.5, 2.0}) in.fixed_points.push_back({"base", {x, -0.25}, 0, {}});
  TimeHistory shake;
  for (int k = 0; k <= 8; ++k) {
    shake.t.push_back(0.125 * k);
    shake.value.emplace_back(k % 4 == 1 ? 0.05 : k % 4 == 3 ? -0.05 : 0.0, 0.0);
  }
  in.fixed_points.push_back({"pull", {0.5, 0.1}, 1, 1e6, shake});
  in.measurements.push_back({"slider", {0.5, 0.25}, 1});
  return in;
}

// The laws with memory, by name.
JointProperties law_with_memory(const std::string& name) {
  if (name == "rate_state")
    return friction_joint("rate_state", {{"mu0", 0.4}, {"a", 0.01}, {"b", 0.015}, {"dc", 1e-3}, {"v0", 1e-3}});
  return friction_joint("degradation", {{"phi_peak", 30}, {"phi_residual", 15}, {"nc", 2}}, {{"measure", "cycles"}});
}

class FrictionCheckpoint : public ::testing::TestWithParam<std::string> {};

TEST_P(FrictionCheckpoint, ResumedRunIsBitIdentical) {
  const ModelInput in = shaken_slider(law_with_memory(GetParam()));
  const fs::path dir = fs::temp_directory_path() / ("dda_friction_checkpoint_" + GetParam());
  fs::create_directories(dir);
  const std::string whole = (dir / "whole.h5").string(), part = (dir / "part.h5").string();
  auto fresh = [&]() {
    Results r;
    r.blocks = in.geometry;
    r.source.provenance.scenario_path = "test";
    r.output.every = 50;
    return r;
  };
  Simulation a(build_model(in));
  {
    Results r = fresh();
    ASSERT_EQ(run_recorded(a, r, whole, RunControl{}), RunEnd::Finished);
  }
  {
    Simulation s(build_model(in));
    Results r = fresh();
    RunControl rc;
    rc.stop_at_step = 120;
    ASSERT_EQ(run_recorded(s, r, part, rc), RunEnd::Stopped);
  }
  const Results saved = read_results_h5(part);
  ASSERT_TRUE(saved.checkpoint.has_value());
  Simulation b(build_model(in));
  b.restore(*saved.checkpoint);
  {
    Results r = fresh();
    r.frames = saved.frames;
    ASSERT_EQ(run_recorded(b, r, part, RunControl{}), RunEnd::Finished);
  }
  // The law's memory, contact by contact, and the motion, sample by sample.
  ASSERT_EQ(a.contacts().size(), b.contacts().size());
  bool memory = false;
  for (std::size_t k = 0; k < a.contacts().size(); ++k) {
    EXPECT_EQ(a.contacts()[k].friction.to_vector(), b.contacts()[k].friction.to_vector()) << "contact " << k;
    // rate_state: theta evolved; degradation: slip reversals counted.
    memory = memory || a.contacts()[k].friction.theta != 0 || DegradationFriction::reversals(a.contacts()[k].friction) > 0;
  }
  EXPECT_TRUE(memory) << "the law kept no state: the test checks nothing";
  const auto &ha = a.histories()[0], &hb = b.histories()[0];
  ASSERT_EQ(ha.size(), hb.size());
  for (std::size_t s = 0; s < ha.size(); ++s) {
    EXPECT_EQ(ha[s].displacement.x(), hb[s].displacement.x()) << "sample " << s;
    EXPECT_EQ(ha[s].velocity.x(), hb[s].velocity.x()) << "sample " << s;
  }
  // It slid both ways (the memory was exercised).
  double lo = 0, hi = 0;
  for (const MeasurementSample& m : ha) lo = std::min(lo, m.displacement.x()), hi = std::max(hi, m.displacement.x());
  EXPECT_LT(lo, -0.01);
  EXPECT_GT(hi, 0.01);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Laws, FrictionCheckpoint, ::testing::Values("rate_state", "degradation"));

}  // namespace
}  // namespace dda::df
