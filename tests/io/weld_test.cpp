// The internal welding of per-corner positions into shared vertices (STL, glTF).

#include "io/weld.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace subdiv::detail {
namespace {

TEST(Weld, EqualPointsMergeExactly) {
  std::vector<Vec3> vertices;
  const std::vector<Index> v = weld({{1, 2, 3}, {4, 5, 6}, {1, 2, 3}, {4, 5, 6.000000000000001}}, 0.0, vertices);
  EXPECT_EQ(v, (std::vector<Index>{0, 1, 0, 2}));
  EXPECT_EQ(vertices, (std::vector<Vec3>{{1, 2, 3}, {4, 5, 6}, {4, 5, 6.000000000000001}}));
}

TEST(Weld, PlusAndMinusZeroMerge) {
  std::vector<Vec3> vertices;
  const std::vector<Index> v = weld({{-0.0, 0.0, 1}, {0.0, -0.0, 1}}, 0.0, vertices);
  EXPECT_EQ(v, (std::vector<Index>{0, 0}));
  ASSERT_EQ(vertices.size(), 1u);
  EXPECT_TRUE(std::signbit(vertices[0].x));  // the first point's zero is kept
}

TEST(Weld, ToleranceMergesWithinAndNotBeyondInEveryCoordinate) {
  std::vector<Vec3> vertices;
  // Each coordinate within 0.1 of the first point merges, even when all three
  // differ (L-infinity, not Euclidean distance); 0.15 off in one coordinate does not.
  const std::vector<Index> v =
      weld({{0, 0, 0}, {0.1, 0.1, -0.1}, {0.0, 0.15, 0.0}, {0.05, 0, 0}, {-0.15, 0, 0}}, 0.1, vertices);
  EXPECT_EQ(v, (std::vector<Index>{0, 0, 1, 0, 2}));
  EXPECT_EQ(vertices.size(), 3u);
}

TEST(Weld, EarliestVertexWinsAndKeepsItsPosition) {
  std::vector<Vec3> vertices;
  // The third point lies within the tolerance of both earlier vertices: it
  // joins the earlier one, and no vertex moves; the fourth is near the second only.
  const std::vector<Index> v = weld({{0, 0, 0}, {0.3, 0, 0}, {0.2, 0, 0}, {0.29, 0, 0}}, 0.25, vertices);
  EXPECT_EQ(v, (std::vector<Index>{0, 1, 0, 1}));
  EXPECT_EQ(vertices, (std::vector<Vec3>{{0, 0, 0}, {0.3, 0, 0}}));
}

TEST(Weld, PointsStraddlingGridCellBoundariesMerge) {
  std::vector<Vec3> vertices;
  // With tolerance 1 the cells have boundaries at the integers: each pair
  // lies on either side of one, in one coordinate or in all three.
  const std::vector<Index> v = weld({{0.999, 5.5, 5.5},
                                     {1.001, 5.5, 5.5},
                                     {-0.001, -0.001, -0.001},
                                     {0.001, 0.001, 0.001},
                                     {10.5, 20.0, -3.0},
                                     {10.5, 19.2, -2.1}},
                                    1.0, vertices);
  EXPECT_EQ(v, (std::vector<Index>{0, 0, 1, 1, 2, 2}));
  EXPECT_EQ(vertices.size(), 3u);
}

TEST(Weld, NegativeToleranceMergesNothing) {
  std::vector<Vec3> vertices;
  const std::vector<Index> v = weld({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}, -1.0, vertices);
  EXPECT_EQ(v, (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(vertices.size(), 3u);
}

TEST(Weld, AppendsToExistingVertices) {
  for (const double tolerance : {-1.0, 0.0, 0.5}) {
    SCOPED_TRACE(tolerance);
    std::vector<Vec3> vertices{{7, 7, 7}, {8, 8, 8}};
    const std::vector<Index> v = weld({{1, 0, 0}, {2, 0, 0}, {1, 0, 0}}, tolerance, vertices);
    if (tolerance < 0) {
      EXPECT_EQ(v, (std::vector<Index>{2, 3, 4}));
    } else {
      EXPECT_EQ(v, (std::vector<Index>{2, 3, 2}));
    }
    ASSERT_GE(vertices.size(), 4u);
    EXPECT_EQ(vertices[0], (Vec3{7, 7, 7}));  // earlier vertices are neither moved nor merged into
    EXPECT_EQ(vertices[2], (Vec3{1, 0, 0}));
    EXPECT_EQ(vertices[3], (Vec3{2, 0, 0}));
  }
}

TEST(Weld, EmptyInput) {
  std::vector<Vec3> vertices;
  EXPECT_TRUE(weld({}, 0.0, vertices).empty());
  EXPECT_TRUE(weld({}, 1.0, vertices).empty());
  EXPECT_TRUE(vertices.empty());
}

}  // namespace
}  // namespace subdiv::detail
