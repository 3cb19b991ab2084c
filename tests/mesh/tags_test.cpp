#include "subdiv/mesh/tags.h"

#include <gtest/gtest.h>

#include <string>

namespace subdiv {

TEST(Tags, DefaultsFollowOpenSubdiv) {
  const Tags t;
  EXPECT_TRUE(t.empty());
  EXPECT_EQ(t.boundary_interpolation, BoundaryInterpolation::edge_and_corner);
  EXPECT_EQ(t.face_varying_interpolation, FaceVaryingInterpolation::all);
  EXPECT_EQ(t.crease_method, CreaseMethod::uniform);
  EXPECT_EQ(t.triangle_subdivision, TriangleSubdivision::catmark);
  EXPECT_EQ(CreaseTag{}.sharpness, kInfiniteSharpness);
  EXPECT_EQ(CornerTag{}.type, CornerType::unspecified);
}

TEST(Tags, EmptyUntilSomethingIsSet) {
  Tags t;
  t.boundary_interpolation_set = true;
  EXPECT_FALSE(t.empty());
  t = Tags{};
  t.holes.push_back(0);
  EXPECT_FALSE(t.empty());
  t = Tags{};
  t.other.push_back({"vertexedit", {}, {}, {}});
  EXPECT_FALSE(t.empty());
}

TEST(Tags, NamesAreTheOnesUsersKnow) {
  EXPECT_STREQ(to_string(BoundaryInterpolation::edge_only), "edge-only");
  EXPECT_STREQ(to_string(BoundaryInterpolation::edge_and_corner), "edge-and-corner");
  EXPECT_STREQ(to_string(BoundaryInterpolation::none), "none");
  EXPECT_STREQ(to_string(FaceVaryingInterpolation::corners_plus1), "corners-plus1");
  EXPECT_STREQ(to_string(CreaseMethod::chaikin), "chaikin");
  EXPECT_STREQ(to_string(TriangleSubdivision::smooth), "smooth");
  EXPECT_STREQ(to_string(CornerType::concave), "concave");
}

TEST(Tags, EqualityComparesEverything) {
  Tags a, b;
  a.creases.push_back({0, 1, 2.0});
  b.creases.push_back({0, 1, 2.0});
  EXPECT_EQ(a, b);
  b.creases[0].sharpness = 2.5;
  EXPECT_NE(a, b);
  CornerTag c{3, 10.0, CornerType::convex, 1.0};
  CornerTag d = c;
  d.angle.reset();
  EXPECT_NE(c, d);
}

}  // namespace subdiv
