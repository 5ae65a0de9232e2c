// The near list (Verlet list) of contact detection: contacts found from the
// kept near pairs must be exactly those of a fresh search, step after step,
// while the pairs are searched afresh only when some vertex has moved more
// than half the skin (near_list.hpp gives the argument).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <tuple>

#include "df_test_models.hpp"
#include "dda/df/core/broad_phase.hpp"
#include "dda/df/2d/contact_detection.hpp"
#include "dda/df/2d/near_list.hpp"

namespace dda::df {
namespace {

using test::rectangle;

std::vector<ContactCandidate> fresh_search(const std::vector<Polygon2>& blocks, double d0) {
  std::vector<Box2> boxes;
  for (const Polygon2& b : blocks) boxes.push_back(bounding_box(b));
  return find_contacts(blocks, broad_phase(boxes, 0.5 * d0), d0);
}

auto fields(const ContactCandidate& c) {
  return std::make_tuple(c.vblock, c.vertex, c.eblock, c.edge, c.dn, c.vertex_vertex);
}

void expect_same(const std::vector<ContactCandidate>& kept, const std::vector<ContactCandidate>& fresh, int step) {
  ASSERT_EQ(kept.size(), fresh.size()) << "step " << step;
  for (std::size_t k = 0; k < kept.size(); ++k) EXPECT_EQ(fields(kept[k]), fields(fresh[k])) << "step " << step;
}

// A brick wall of 1 m x 0.5 m blocks with joints open by 0 to 3 d0, every
// block then moved rigidly by a random walk: steps of up to 0.1 d0 in x and
// y and small rotations, so contacts open, close and pass to neighbouring
// edges, vertices beyond the reach come within the search distance, and the
// vertices drift past half the skin now and then. (Keeping the pairs until
// a vertex moved twice the skin makes this test fail.)
TEST(NearList, ContactsFromKeptPairsEqualAFreshSearchEveryStep) {
  const double d0 = 0.01;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> gap(0, 3 * d0);
  std::vector<Polygon2> blocks;
  double y = 0;
  for (int row = 0; row < 8; ++row, y += 0.5 + gap(rng)) {
    double x = 0.5 * (row % 2);
    for (int col = 0; col < 10; ++col, x += 1 + gap(rng)) blocks.push_back(rectangle(x, y + gap(rng), 1.0, 0.5));
  }
  std::uniform_real_distribution<double> shift(-0.1 * d0, 0.1 * d0), turn(-0.1 * d0, 0.1 * d0);
  NearList near_list;
  NearList bounded;  // told how far the vertices moved: must give the same pairs
  double moved = std::numeric_limits<double>::infinity();
  int compared = 0;
  for (int step = 0; step < 120; ++step) {
    const auto kept = find_contacts(blocks, near_list.update(blocks, d0), d0);
    const auto kept_bounded = find_contacts(blocks, bounded.update(blocks, d0, moved), d0);
    const auto fresh = fresh_search(blocks, d0);
    ASSERT_FALSE(fresh.empty());
    expect_same(kept, fresh, step);
    expect_same(kept_bounded, fresh, step);
    compared += static_cast<int>(fresh.size());
    moved = 0;
    for (Polygon2& b : blocks) {
      Vec2 c = Vec2::Zero();
      for (const Vec2& p : b) c += p;
      c /= static_cast<double>(b.size());
      const Vec2 move(shift(rng), shift(rng));
      const double angle = turn(rng);  // rad about the centre: up to 0.1 d0 at 1 m
      for (Vec2& p : b) {
        const Vec2 next = c + move + test::rotated(Vec2(p - c), angle);
        moved = std::max(moved, (next - p).norm());
        p = next;
      }
    }
  }
  // Both reuse and fresh searches happened, or the test proves nothing.
  EXPECT_GT(near_list.searches(), 1);
  EXPECT_LT(near_list.searches(), 60);  // 19 with this seed
  EXPECT_GT(compared, 120 * 100);  // 118 to 141 contacts a step
  // With the bounds: the same searches, and fewer reads of every vertex
  // (the unbounded list reads them on every update).
  EXPECT_EQ(bounded.searches(), near_list.searches());
  EXPECT_EQ(near_list.checks(), 120);
  EXPECT_LT(bounded.checks(), near_list.checks());
  EXPECT_GT(bounded.checks(), bounded.searches());  // some checks found the pairs still holding
}

// The bounds are trusted only while their sum stays under 0.99 of half the
// skin (0.495 d0 here); past that the vertices decide. A block moved 0.1 d0
// away and back, with bounds summing to 0.6 d0: then every vertex is read,
// found where it was, and the pairs are kept without a search. A move the
// bounds understate (2.5 d0 told as 0.3 d0) is caught once their sum passes
// the limit. (The caller promises true bounds; this only shows that the
// vertices, not the sum, decide once it is past the limit.)
TEST(NearList, BoundsAddUpAndTheVerticesDecideBeyondThem) {
  const double d0 = 0.01;
  std::vector<Polygon2> blocks{rectangle(0, 0, 1, 1), rectangle(0, 1 + 3 * d0, 1, 1)};
  NearList near_list;
  EXPECT_TRUE(find_contacts(blocks, near_list.update(blocks, d0), d0).empty());
  EXPECT_EQ(near_list.checks(), 1);
  for (Vec2& p : blocks[1]) p.y() += 0.1 * d0;
  near_list.update(blocks, d0, 0.1 * d0);  // within the bound: nothing read
  EXPECT_EQ(near_list.checks(), 1);
  for (Vec2& p : blocks[1]) p.y() -= 0.1 * d0;
  near_list.update(blocks, d0, 0.1 * d0);
  EXPECT_EQ(near_list.checks(), 1);
  near_list.update(blocks, d0, 0.4 * d0);  // summed 0.6 d0: read, and nothing moved
  EXPECT_EQ(near_list.checks(), 2);
  EXPECT_EQ(near_list.searches(), 1);
  // The check found a drift of 0, so the bounds start again from there.
  for (Vec2& p : blocks[1]) p.y() -= 2.5 * d0;  // now 0.5 d0 apart: a contact
  near_list.update(blocks, d0, 0.3 * d0);       // understated: 0.3 d0 summed, trusted
  EXPECT_EQ(near_list.searches(), 1);
  const auto found = find_contacts(blocks, near_list.update(blocks, d0, 0.3 * d0), d0);  // 0.6 d0: read
  EXPECT_EQ(near_list.searches(), 2);
  EXPECT_EQ(found.size(), 2u);
}

// Two blocks 3 d0 apart: no contact. One moves 2.5 d0 towards the other in
// one step, more than half the skin, so the kept pairs (none) must not be
// used: the fresh search finds the contact.
TEST(NearList, SearchesAfreshOnceAVertexMovesHalfTheSkin) {
  const double d0 = 0.01;
  std::vector<Polygon2> blocks{rectangle(0, 0, 1, 1), rectangle(0, 1 + 3 * d0, 1, 1)};
  NearList near_list;
  EXPECT_TRUE(find_contacts(blocks, near_list.update(blocks, d0), d0).empty());
  for (Vec2& p : blocks[1]) p.y() -= 0.4 * d0;  // within half the skin: kept
  EXPECT_TRUE(find_contacts(blocks, near_list.update(blocks, d0), d0).empty());
  EXPECT_EQ(near_list.searches(), 1);
  for (Vec2& p : blocks[1]) p.y() -= 2.1 * d0;  // now 0.5 d0 apart
  const auto found = find_contacts(blocks, near_list.update(blocks, d0), d0);
  EXPECT_EQ(near_list.searches(), 2);
  EXPECT_EQ(found.size(), 2u);  // the two lower corners of block 1 on the top edge of block 0
}

TEST(NearList, SearchesAfreshWhenTheSearchDistanceOrBlocksChange) {
  std::vector<Polygon2> blocks{rectangle(0, 0, 1, 1), rectangle(0, 1.005, 1, 1)};
  NearList near_list;
  EXPECT_TRUE(find_contacts(blocks, near_list.update(blocks, 0.001), 0.001).empty());
  EXPECT_EQ(find_contacts(blocks, near_list.update(blocks, 0.01), 0.01).size(), 2u);
  EXPECT_EQ(near_list.searches(), 2);
  blocks.push_back(rectangle(2, 0, 1, 1));
  near_list.update(blocks, 0.01);
  EXPECT_EQ(near_list.searches(), 3);
}

TEST(NearList, ASearchDistanceBeyondTheReachIsRefused) {
  const std::vector<Polygon2> blocks{rectangle(0, 0, 1, 1), rectangle(0, 1.005, 1, 1)};
  NearList near_list;
  const NearPairs& near = near_list.update(blocks, 0.001);
  EXPECT_THROW(find_contacts(blocks, near, 0.01), std::exception);
}

}  // namespace
}  // namespace dda::df
