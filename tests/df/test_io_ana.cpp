// DDA for Windows analysis files (df/io/import_ana.hpp).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "dda/common/error.hpp"
#include "dda/df/io/import_ana.hpp"
#include "df_test_models.hpp"

namespace dda::df {
namespace {

std::string pushblock_ana() {
  std::ifstream f(std::string(DDA_TEST_DATA_DIR) + "/df_pushblock.ana");
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// The blocks `dda dl df_pushblock.geo` + `dda dc` make: a base (sets type1)
// and a block on it (sides type2, bottom type1).
BlockModel pushblock_blocks() {
  BlockModel m;
  m.sets = {{"type1", "geo"}, {"type2", "geo"}};
  m.blocks.push_back(test::make_block(test::rectangle(0, 0, 4, 1), 0));
  Block b = test::make_block(test::rectangle(1.5, 1, 1, 1), 1);
  b.edge_set[0] = 0;
  m.blocks.push_back(b);
  m.points = {{{"fixed_1", PointKind::Fixed, {0.5, 0.5}}, 0},
              {{"fixed_2", PointKind::Fixed, {3.5, 0.5}}, 0},
              {{"load_1", PointKind::Load, {2, 1.5}}, 1},
              {{"measured_1", PointKind::Measurement, {2, 1.5}}, 1}};
  return m;
}

std::string error_of(const std::string& text) {
  try {
    import_ana(text, "m.ana", pushblock_blocks(), "b.h5");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(IoAna, MapsTheAnalysis) {
  const AnaImport a = import_ana(pushblock_ana(), "m.ana", pushblock_blocks(), "b.h5");
  const ModelInput& in = a.scenario.input;
  EXPECT_EQ(in.control.steps, 500);
  EXPECT_EQ(in.control.dt, 0.001);
  EXPECT_EQ(in.control.max_displacement_ratio, 0.01);
  EXPECT_EQ(in.control.max_open_close, 6);
  EXPECT_EQ(in.control.penalty_factor, 50);
  EXPECT_EQ(in.control.dynamic, 1);
  EXPECT_EQ(a.scenario.output.every, 50);
  ASSERT_EQ(in.materials.size(), 1u);
  EXPECT_EQ(in.materials[0].density, 2000);
  EXPECT_EQ(in.materials[0].young, 5e10);
  EXPECT_EQ(in.materials[0].plane, PlaneMode::Stress);
  EXPECT_NEAR(in.gravity.y(), -9.81, 1e-12);
  ASSERT_EQ(in.joint_sets.size(), 2u);
  EXPECT_EQ(in.joint_sets[0].friction_deg, 20);
  EXPECT_EQ(in.joint_sets[1].friction_deg, 30);
  EXPECT_EQ(in.default_joint.friction_deg, 20);
  ASSERT_EQ(in.loads.size(), 1u);
  ASSERT_TRUE(in.loads[0].history.has_value());
  EXPECT_EQ(in.loads[0].history->value.back(), Vec2(15000, 0));
  EXPECT_EQ(in.fixed_points.size(), 2u);
  EXPECT_EQ(in.measurements.size(), 1u);
  EXPECT_TRUE(a.warnings.empty());
}

TEST(IoAna, ErrorsNameFileAndLine) {
  const std::string ana = pushblock_ana();
  EXPECT_NE(error_of(replaced(ana, "maxtimestep=\"0.001\"", "maxtimestep=\"-1\"")).find("<Maxtimestep> needs maxtimestep > 0"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(ana, "<Jointproperties type=\"2\">", "<Jointproperties type=\"3\">"))
                .find("has no <Jointproperties type=\"2\"> for joint set type2 of b.h5"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(ana, "<Rotation type=\"exact\"/>", "<Frobnicate/>")).find("m.ana:"), std::string::npos);
  EXPECT_NE(error_of(replaced(ana, "<Unitmass> 2000 </Unitmass>", "<Unitmass> -2 </Unitmass>")).find("Unitmass"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(ana, "numpoints=\"2\"", "numpoints=\"3\"")).find("numpoints records"), std::string::npos);
  EXPECT_NE(error_of("<a/>").find("not a DDA for Windows file"), std::string::npos);
  EXPECT_NE(error_of("<a").find("m.ana:1: is not well-formed XML"), std::string::npos);
  const AnaImport g = import_ana(replaced(ana, "<Gravity flag=\"no\"/>", "<Gravity flag=\"yes\"/>"), "m.ana",
                                 pushblock_blocks(), "b.h5");
  EXPECT_EQ(g.warnings.size(), 1u);
  // The old program's gravity turn-on phase is our relaxation before t = 0.
  EXPECT_TRUE(g.scenario.input.control.initial_equilibrium);
  EXPECT_FALSE(import_ana(ana, "m.ana", pushblock_blocks(), "b.h5").scenario.input.control.initial_equilibrium);
}

// Found by fuzzing (docs/reliability.md, "Fuzzing"): whole numbers beyond
// an int were converted to one (undefined behaviour) before any check.
TEST(IoAna, HugeWholeNumbersAreRefused) {
  const std::string ana = pushblock_ana();
  EXPECT_NE(error_of(replaced(ana, "<Saveinterval step=\"50\"/>", "<Saveinterval step=\"6e68\"/>"))
                .find("<Saveinterval> needs step to be a whole number >= 1"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(ana, "<Blockmaterial type=\"1\">", "<Blockmaterial type=\"1e300\">"))
                .find("<Blockmaterial> needs a type attribute with a whole number >= 0"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(ana, "numpoints=\"2\"", "numpoints=\"1e300\"")).find("numpoints records"),
            std::string::npos);
}

}  // namespace
}  // namespace dda::df
