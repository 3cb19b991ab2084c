// Limit positions where semi-sharp features need more than four levels
// (OpenSubdiv's catmark_cube_creases1: every cube edge of sharpness 5 but
// one of 0.1, so six corners of three semi-sharp edges and two crease
// vertices):
// - the closed-form route refines until the sharpness has decayed (5
//   levels) and puts every vertex at its limit, the generic masks after 6
//   levels agreeing, and refinement closing on them;
// - where fewer levels are taken (a cap, a face budget, or the generic
//   route's isolation levels) the semi-sharp corners are not taken as kept
//   where they are, and every vertex short of its limit is counted with the
//   sharpness that is left.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "subdiv/analysis/limit.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/rules/catmull_clark.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

const std::string kCreases1 = test::shared_mesh_dir() + "/opensubdiv/catmark_cube_creases1.obj";

TEST(SemiSharpLimit, CubeCreases1IsAtItsLimitByDefault) {
  if (!std::filesystem::exists(kCreases1)) GTEST_SKIP() << "shared mesh collection absent: " << kCreases1;
  const PolygonMesh mesh = read_mesh(kCreases1).mesh;
  const LimitResult closed = limit_positions(mesh, catmull_clark_scheme());
  EXPECT_EQ(closed.levels_refined, 5);
  EXPECT_EQ(closed.approximated, 0);
  EXPECT_EQ(closed.sharpness_left, 0.0);
  for (const LimitSource s : closed.sources) EXPECT_EQ(s, LimitSource::closed_form);

  LimitOptions generic;
  generic.route = LimitRoute::generic;
  generic.isolation_levels = 6;
  const LimitResult masks = limit_positions(mesh, catmull_clark_scheme(), generic);
  ASSERT_EQ(masks.approximated, 0);
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    EXPECT_LT(norm(closed.positions[static_cast<std::size_t>(v)] - masks.positions[static_cast<std::size_t>(v)]), 1e-12)
        << "vertex " << v;
  // Refinement closes on the limits once the sharpness has decayed: the
  // vertex points (numbered last) move by 1/6 of their distance per level
  // from level 6 on (valence 3), having kept (corners) or crept along the
  // crease until then.
  PolygonMesh level = mesh;
  RefineOptions one;
  one.levels = 1;
  std::vector<double> previous(static_cast<std::size_t>(mesh.vertex_count()));
  for (int l = 1; l <= 9; ++l) {
    level = refine(level, catmull_clark_scheme(), one);
    const Index first_vertex_point = level.vertex_count() - mesh.vertex_count();
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
      const auto i = static_cast<std::size_t>(v);
      const double d = norm(level.positions[static_cast<std::size_t>(first_vertex_point + v)] - closed.positions[i]);
      if (l > 6) {
        EXPECT_LE(d, previous[i] / 5.0) << "vertex " << v << ", level " << l;
      }
      if (l == 9) {
        EXPECT_LT(d, 1e-3 * norm(mesh.positions[i] - closed.positions[i])) << "vertex " << v;
      }
      previous[i] = d;
    }
  }
}

TEST(SemiSharpLimit, FewerLevelsCountEveryVertexShortOfItsLimit) {
  if (!std::filesystem::exists(kCreases1)) GTEST_SKIP() << "shared mesh collection absent: " << kCreases1;
  const PolygonMesh mesh = read_mesh(kCreases1).mesh;
  // The former cap: four levels leave sharpness 1 on every edge at the
  // corners, which would move on the next level; none is at its limit.
  LimitOptions capped;
  capped.max_resolve_levels = 4;
  const LimitResult four = limit_positions(mesh, catmull_clark_scheme(), capped);
  EXPECT_EQ(four.levels_refined, 4);
  EXPECT_EQ(four.approximated, 8);
  EXPECT_EQ(four.semi_sharp, 8);
  EXPECT_EQ(four.sharpness_left, 1.0);
  for (const LimitSource s : four.sources) EXPECT_EQ(s, LimitSource::refined_position);
  // A face budget stops before the level that would pass it (6, 24, 96,
  // 384 faces).
  LimitOptions budget;
  budget.max_resolve_faces = 100;
  const LimitResult small = limit_positions(mesh, catmull_clark_scheme(), budget);
  EXPECT_EQ(small.levels_refined, 2);
  EXPECT_EQ(small.semi_sharp, 8);
  EXPECT_EQ(small.sharpness_left, 3.0);
  // The generic route takes its isolation levels.
  LimitOptions generic;
  generic.route = LimitRoute::generic;
  const LimitResult two = limit_positions(mesh, catmull_clark_scheme(), generic);
  EXPECT_EQ(two.levels_refined, 2);
  EXPECT_EQ(two.approximated, 8);
  EXPECT_EQ(two.semi_sharp, 8);
  EXPECT_EQ(two.sharpness_left, 3.0);
}

}  // namespace
}  // namespace subdiv
