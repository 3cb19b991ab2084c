// The a priori depth measured: over the shared meshes and random
// perturbations of them, every vertex is within eps of its limit after the
// predicted depth, and the bound holds at every level on the way; the
// paper's qualitative results (regular torus, high-valence pole).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "subdiv/depth/depth.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/rules/four_eight.h"
#include "subdiv/rules/loop.h"
#include "subdiv/rules/scheme.h"
#include "depth/depth_test_meshes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// Small meshes with valences 3 to 32, n-gons, a boundary and genus 3.
const std::vector<std::string> kSharedMeshes = {
    "opensubdiv/catmark_torus.obj", "cgal/hole.obj",      "cgal/3torus.obj",
    "cgal/corner_poly.obj",         "assimp/uv_sphere.obj", "geomview/mushroom.obj",
    "opensubdiv/catmark_pole8.obj",
};

TEST(DepthProperty, BoundHoldsOnSharedMeshesAndPerturbations) {
  const std::string dir = test::shared_mesh_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared mesh collection not found at " << dir;
  std::mt19937 random(2024);
  for (const std::string& file : kSharedMeshes) {
    const PolygonMesh original = read_mesh(dir + "/" + file).mesh;
    const double size = largest_extent(original);
    for (const char* scheme_name : {"loop", "catmull-clark", "loop-warren", "doo-sabin"}) {
      const Scheme& scheme = *find_scheme(scheme_name);
      const PolygonMesh mesh = for_scheme(original, scheme);
      check_bound_holds(mesh, scheme, file);
      check_bound_holds(perturbed(mesh, 0.05 * size, random), scheme, file + " (perturbed)");
    }
  }
}

TEST(DepthProperty, BoundHoldsOnBundledMeshes) {
  for (const char* file : {"cube.obj", "tetrahedron.obj"})
    for (const char* scheme_name : {"loop", "catmull-clark", "loop-warren", "doo-sabin"}) {
      const Scheme& scheme = *find_scheme(scheme_name);
      check_bound_holds(for_scheme(read_mesh(test::bundled_path(file)).mesh, scheme), scheme, file);
    }
}

TEST(DepthProperty, InterpolatingSchemesNeedNoStep) {
  // Bilinear refinement keeps every vertex on its limit (the bilinear
  // patches): the amplitude is rounding, and depth 0 is enough.
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  const DepthBound bound = depth_bound(cube, *find_scheme("bilinear"));
  EXPECT_EQ(bound.source, "analysis");
  EXPECT_EQ(bound.depth_for(1e-9), 0);
  EXPECT_LE(check_depth(cube, *find_scheme("bilinear"), bound, 2).measured, 1e-12);
}

TEST(DepthProperty, RegularTorusGainsOneLevelPerFactorFour) {
  // Paper, Table 1: on a valence-6 torus the rate is 5/8 - 6 beta = 1/4, so
  // each division of eps by 4 costs exactly one more step, and each depth
  // is verified by refinement.
  std::mt19937 random(3);
  const PolygonMesh torus = perturbed(triangle_torus(8, 6, 3.0, 1.0), 0.1, random);
  const DepthBound bound = depth_bound(torus, loop_scheme());
  ASSERT_EQ(bound.terms.size(), 1u) << "no extraordinary vertex";
  EXPECT_EQ(bound.terms[0].rate, 0.25);
  const double eps0 = 0.3 * bound.terms[0].amplitude;
  const int depth0 = bound.depth_for(eps0);
  for (int i = 0; i < 3; ++i) {
    const double eps = eps0 / std::pow(4.0, i);
    EXPECT_EQ(bound.depth_for(eps), depth0 + i);
    const DepthCheck check = check_depth(torus, loop_scheme(), bound, depth0 + i);
    EXPECT_LE(check.measured, eps) << "eps " << eps;
  }
}

TEST(DepthProperty, HighValencePoleNeedsTheMaximumValence) {
  // Paper, Figure 13: a spinning top with valence-18 poles and valence-4
  // elsewhere. The depth computed with the mean valence 6 leaves the pole
  // further than eps; the bound with the maximum valence does not.
  const PolygonMesh top = spinning_top(18, 4.0, 7.0, 7.0);
  const LimitDistances start = limit_distances(top, loop_scheme());
  ASSERT_GE(top.positions[static_cast<std::size_t>(start.max_vertex)].z, 6.9) << "the pole is the furthest vertex";
  const double eps = start.max / 16.0 * 1.01;  // the mean valence's rate 1/4: two steps
  const DepthBound mean = loop_paper_bound(loop_scheme(), start.max, 6);
  const DepthBound bound = depth_bound(top, loop_scheme());
  const int mean_depth = mean.depth_for(eps);
  const int depth = bound.depth_for(eps);
  EXPECT_EQ(mean_depth, 2);
  EXPECT_GT(depth, mean_depth);
  EXPECT_GT(check_depth(top, loop_scheme(), bound, mean_depth).measured, eps);
  EXPECT_LE(check_depth(top, loop_scheme(), bound, depth).measured, eps);
}

TEST(DepthCost, CountsMatchRefinement) {
  for (const char* scheme_name : {"catmull-clark", "loop"}) {
    const Scheme& scheme = *find_scheme(scheme_name);
    const PolygonMesh mesh = for_scheme(read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh, scheme);
    const std::vector<LevelCost> costs = level_costs(mesh, scheme, 2);
    PolygonMesh level = mesh;
    for (const LevelCost& cost : costs) {
      EXPECT_EQ(cost.vertices, level.vertex_count()) << scheme_name << " level " << cost.level;
      EXPECT_EQ(cost.faces, level.face_count()) << scheme_name << " level " << cost.level;
      EXPECT_EQ(cost.corners, level.corner_count()) << scheme_name << " level " << cost.level;
      level = refine(level, scheme);
    }
  }
}

// The splits without a depth bound are counted too (the commands' memory
// guard reads the counts): exact on closed meshes, and for the sqrt3
// split's boundaries and quasi 4-8's bisection an upper bound.
TEST(DepthCost, EverySplitCountedOrBounded) {
  const PolygonMesh closed = triangulate(test::jittered(test::cube(), 5));
  const PolygonMesh open = test::jittered(test::triangle_grid(3, 3), 5);
  const PolygonMesh quads = test::jittered(test::cube(), 5);
  Scheme sqrt2 = *find_scheme("four-eight");
  sqrt2.fast_path = {};  // one sqrt2 step per level
  struct Case {
    const Scheme* scheme;
    const PolygonMesh* mesh;
    bool exact;
  };
  const std::vector<Case> cases = {{find_scheme("sqrt3"), &closed, true},  {find_scheme("sqrt3"), &open, false},
                                   {&sqrt2, &quads, true},                  {find_scheme("midedge"), &closed, true},
                                   {find_scheme("quasi-4-8"), &closed, false}, {find_scheme("quasi-4-8"), &open, false},
                                   {find_scheme("gcc"), &closed, true}};
  for (const Case& c : cases) {
    const std::vector<LevelCost> costs = level_costs(*c.mesh, *c.scheme, 3);
    const Hierarchy h = refine_hierarchy(*c.mesh, *c.scheme, [] {
      RefineOptions o;
      o.levels = 3;
      return o;
    }());
    for (std::size_t l = 0; l < costs.size(); ++l) {
      const PolygonMesh& level = h.levels[l].mesh;
      const std::string what = std::string(c.scheme->name) + (c.exact ? " (exact)" : " (bound)") + ", level " +
                               std::to_string(l);
      if (c.exact) {
        EXPECT_EQ(costs[l].vertices, level.vertex_count()) << what;
        EXPECT_EQ(costs[l].faces, level.face_count()) << what;
        EXPECT_EQ(costs[l].corners, level.corner_count()) << what;
        EXPECT_EQ(costs[l].edges, MeshTopology(level).edge_count()) << what;
      } else {
        EXPECT_GE(costs[l].vertices, level.vertex_count()) << what;
        EXPECT_GE(costs[l].faces, level.face_count()) << what;
        EXPECT_GE(costs[l].corners, level.corner_count()) << what;
        EXPECT_GE(costs[l].edges, MeshTopology(level).edge_count()) << what;
      }
    }
  }
}

// Four-eight: bounded through its two-step scheme (a quad split), in
// levels of two steps. Checked with four-eight's own steps and limits (the
// sqrt2 analysis' masks; the bound's amplitude comes from the quad-split
// scheme's): the bound holds at every level on closed meshes, perturbed
// too, and the level costs are the refined meshes' sizes.
void check_four_eight_bound_holds(const PolygonMesh& mesh, const std::string& name) {
  const Scheme& scheme = four_eight_scheme();
  const DepthBound bound = depth_bound(mesh, scheme);
  ASSERT_EQ(bound.steps_per_level, 2) << name;
  const int last = bound.start + 2;
  const std::vector<LevelCost> costs = level_costs(mesh, scheme, last);
  RefineOptions two;
  two.levels = 2;
  PolygonMesh level = mesh;
  for (int k = 0; k <= last; ++k) {
    EXPECT_EQ(costs[static_cast<std::size_t>(k)].vertices, level.vertex_count()) << name << " level " << k;
    EXPECT_EQ(costs[static_cast<std::size_t>(k)].faces, level.face_count()) << name << " level " << k;
    if (k >= bound.start) {
      EXPECT_LE(limit_distances(level, scheme).max, bound.at(k) * (1.0 + 1e-12)) << name << " level " << k;
    }
    if (k < last) level = refine(level, scheme, two);
  }
  const DepthCheck check = check_depth(mesh, scheme, bound, bound.start + 1);
  EXPECT_LE(check.measured, check.bound * (1.0 + 1e-12)) << name;
}

TEST(DepthProperty, FourEightInLevelsOfTwoSteps) {
  for (const char* file : {"cube.obj", "tetrahedron.obj", "spot_control_mesh.obj"})
    check_four_eight_bound_holds(read_mesh(test::bundled_path(file)).mesh, file);
  const std::string dir = test::shared_mesh_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared mesh collection not found at " << dir;
  std::mt19937 random(2025);
  for (const char* file : {"opensubdiv/catmark_torus.obj", "cgal/3torus.obj"}) {
    const PolygonMesh mesh = read_mesh(dir + "/" + file).mesh;
    check_four_eight_bound_holds(mesh, file);
    check_four_eight_bound_holds(perturbed(mesh, 0.05 * largest_extent(mesh), random), std::string(file) + " (perturbed)");
  }
}

}  // namespace
}  // namespace subdiv
