// Key paths as the scenario reader writes them, and setting values at them.
#include <gtest/gtest.h>

#include "dda/study/key_path.hpp"

namespace dda::study {
namespace {

TEST(KeyPath, ParsesKeysAndIndices) {
  const auto p = parse_key_path("joint_sets[1].mean_length", nullptr);
  ASSERT_TRUE(p);
  ASSERT_EQ(p->steps.size(), 3u);
  EXPECT_EQ(std::get<std::string>(p->steps[0]), "joint_sets");
  EXPECT_EQ(std::get<std::size_t>(p->steps[1]), 1u);
  EXPECT_EQ(std::get<std::string>(p->steps[2]), "mean_length");
  const auto q = parse_key_path("lines[0][1]", nullptr);
  ASSERT_TRUE(q);
  EXPECT_EQ(q->steps.size(), 3u);
}

TEST(KeyPath, RefusesWhatIsNoPath) {
  for (const char* bad : {"", "a..b", "a.", "[0].a", "a[x]", "a[]", "a[0]b", "a[0"}) {
    std::string why;
    EXPECT_FALSE(parse_key_path(bad, &why)) << bad;
    EXPECT_FALSE(why.empty()) << bad;
  }
}

TEST(KeyPath, SetsExistingAndNewLastKeysOnly) {
  YAML::Node doc = YAML::Load("control: {dt: 0.001}\njoint_sets: [{dip: 30}, {dip: 60}]\n");
  EXPECT_EQ(set_at(doc, *parse_key_path("joint_sets[1].dip", nullptr), YAML::Node(75)), "");
  EXPECT_EQ(doc["joint_sets"][1]["dip"].as<int>(), 75);
  EXPECT_EQ(doc["joint_sets"][0]["dip"].as<int>(), 30);  // the other set is left alone
  // A last key the base leaves at its default is added...
  EXPECT_EQ(set_at(doc, *parse_key_path("control.total_time", nullptr), YAML::Node(2)), "");
  EXPECT_EQ(doc["control"]["total_time"].as<int>(), 2);
  // ... but no step before it, and no list item beyond the list.
  EXPECT_EQ(set_at(doc, *parse_key_path("loading.gravity", nullptr), YAML::Node(1)), "the base has no loading");
  EXPECT_EQ(set_at(doc, *parse_key_path("joint_sets[2].dip", nullptr), YAML::Node(1)),
            "the base has no joint_sets[2]");
  EXPECT_EQ(set_at(doc, *parse_key_path("control.dt.x", nullptr), YAML::Node(1)),
            "the base has no mapping at control.dt");
  EXPECT_FALSE(doc["loading"]);  // a refused setting leaves nothing behind
}

}  // namespace
}  // namespace dda::study
