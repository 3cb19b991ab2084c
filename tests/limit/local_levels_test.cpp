// The closed-form route refines only around the vertices it follows and
// the semi-sharp tags (LimitOptions::local_levels): every result equals,
// bit for bit, that of refining whole levels, on OpenSubdiv's meshes with
// semi-sharp creases and corners (uniform and Chaikin creasing, holes,
// valence 2, boundaries), and where the face budget stops it short.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "subdiv/analysis/limit.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

bool same(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

void expect_same_limits(const std::string& name, std::int64_t max_resolve_faces = std::int64_t{1} << 24) {
  SCOPED_TRACE(name);
  const std::string path = test::shared_mesh_dir() + "/opensubdiv/" + name;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared mesh collection absent: " << path;
  const PolygonMesh mesh = read_mesh(path).mesh;
  const Scheme& scheme = name.starts_with("loop") ? loop_scheme() : catmull_clark_scheme();
  LimitOptions whole;
  whole.normals = true;
  whole.local_levels = false;
  whole.max_resolve_faces = max_resolve_faces;
  LimitOptions local = whole;
  local.local_levels = true;
  const LimitResult a = limit_positions(mesh, scheme, whole);
  const LimitResult b = limit_positions(mesh, scheme, local);
  EXPECT_EQ(a.levels_refined, b.levels_refined);
  EXPECT_EQ(a.approximated, b.approximated);
  EXPECT_EQ(a.semi_sharp, b.semi_sharp);
  EXPECT_EQ(a.sharpness_left, b.sharpness_left);
  EXPECT_EQ(a.sources, b.sources);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    EXPECT_TRUE(same(a.positions[v], b.positions[v])) << "position of vertex " << v;
    EXPECT_TRUE(same(a.normals[v], b.normals[v])) << "normal of vertex " << v;
    EXPECT_TRUE(same(a.tangents1[v], b.tangents1[v]) && same(a.tangents2[v], b.tangents2[v])) << "tangents of vertex " << v;
  }
}

TEST(LocalLevels, SemiSharpCreasesAsWholeLevels) {
  for (const char* name : {"catmark_cube_creases1.obj", "catmark_cube_corner1.obj", "catmark_single_crease.obj",
                           "catmark_torus_creases0.obj", "catmark_pyramid_creases2.obj", "catmark_cubes_infsharp.obj",
                           "catmark_fvar_bound2.obj", "catmark_gregory_test3.obj", "catmark_edgeonly.obj",
                           "loop_cube_creases0.obj", "loop_triangle_edgeonly.obj"})
    expect_same_limits(name);
}

TEST(LocalLevels, ChaikinCreasingAsWholeLevels) {
  expect_same_limits("catmark_chaikin1.obj");
  expect_same_limits("loop_chaikin0.obj");
}

TEST(LocalLevels, HolesAndValenceTwoAsWholeLevels) {
  expect_same_limits("catmark_hole_test2.obj");
  expect_same_limits("catmark_val2_interior.obj");
}

TEST(LocalLevels, FaceBudgetStopsAtTheSameLevel) {
  // The rook's sharpness 7.9 needs 8 levels; 2^18 faces allow 4, leaving
  // vertices short of their limit with sharpness 3.9.
  expect_same_limits("catmark_rook.obj", std::int64_t{1} << 18);
  expect_same_limits("catmark_helmet.obj", std::int64_t{1} << 16);
}

}  // namespace
}  // namespace subdiv
