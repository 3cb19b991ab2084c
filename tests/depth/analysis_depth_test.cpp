// The analysis's depth bound for the schemes no paper bounds: the sqrt3
// split (Kobbelt's sqrt3 and the composites that equal it or refine like
// it), the triangle-split composite that equals Loop, and gcc and midpoint
// of odd degree (composites of the quad split). Measured: the bound holds at
// every level, each level's limits through the scheme's own limit route, on
// the bundled meshes, shared meshes and random perturbations of them.

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "subdiv/depth/depth.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/rules/scheme.h"
#include "depth/depth_test_meshes.h"
#include "support/gcc_schemes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// The schemes with the largest level checked: composite schemes compose
// their masks vertex by vertex, and composite-sqrt3's wide masks take a
// second or more to analyse per valence (checked on the bundled meshes).
struct Case {
  Scheme scheme;
  std::int64_t max_faces;
};

std::vector<Case> cases() {
  return {{*find_scheme("sqrt3"), 12000},
          {*find_scheme("composite-loop"), 3000},
          {*find_scheme("composite-sqrt3-kobbelt"), 3000},
          {test::midpoint(3), 6000},
          {test::midpoint(5), 6000},
          {test::gcc(3, 0.5, 0.25), 6000},
          {test::gcc(5, 0.5, 0.25), 6000}};
}

TEST(AnalysisDepth, BoundHoldsOnBundledMeshes) {
  for (const char* file : {"cube.obj", "tetrahedron.obj"}) {
    const PolygonMesh mesh = read_mesh(test::bundled_path(file)).mesh;
    for (const Case& c : cases()) check_bound_holds(for_scheme(mesh, c.scheme), c.scheme, file, c.max_faces);
    const Scheme& composite_sqrt3 = *find_scheme("composite-sqrt3");
    check_bound_holds(for_scheme(mesh, composite_sqrt3), composite_sqrt3, file, 1000);
  }
}

TEST(AnalysisDepth, BoundHoldsOnSharedMeshesAndPerturbations) {
  const std::string dir = test::shared_mesh_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared mesh collection not found at " << dir;
  std::mt19937 random(2026);
  for (const char* file : {"opensubdiv/catmark_torus.obj", "cgal/3torus.obj"}) {  // closed: the composites need it
    const PolygonMesh original = read_mesh(dir + "/" + file).mesh;
    const double size = largest_extent(original);
    for (const Case& c : cases()) {
      const PolygonMesh mesh = for_scheme(original, c.scheme);
      check_bound_holds(mesh, c.scheme, file, c.max_faces);
      check_bound_holds(perturbed(mesh, 0.05 * size, random), c.scheme, std::string(file) + " (perturbed)",
                        c.max_faces);
    }
  }
}

// The sqrt3 split at a boundary, and around valence 8: its boundary steps
// alternate (trisecting every other step), and the new points of a step
// that does not trisect can lie further from their limits than the old
// vertices did (the bound's second term).
TEST(AnalysisDepth, Sqrt3BoundHoldsAtABoundary) {
  const std::string dir = test::shared_mesh_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared mesh collection not found at " << dir;
  const Scheme& sqrt3 = *find_scheme("sqrt3");
  std::mt19937 random(2027);
  for (const char* file : {"cgal/hole.obj", "opensubdiv/catmark_pole8.obj"}) {
    const PolygonMesh mesh = for_scheme(read_mesh(dir + "/" + file).mesh, sqrt3);
    check_bound_holds(mesh, sqrt3, file);
    check_bound_holds(perturbed(mesh, 0.05 * largest_extent(mesh), random), sqrt3, std::string(file) + " (perturbed)");
  }
}

// The period's second term is needed: without it the bound fails one step
// down on the pole mesh (the step that does not trisect its boundary).
TEST(AnalysisDepth, Sqrt3NeedsTheSecondStepsTerm) {
  const std::string dir = test::shared_mesh_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared mesh collection not found at " << dir;
  const Scheme& sqrt3 = *find_scheme("sqrt3");
  const PolygonMesh mesh = for_scheme(read_mesh(dir + "/opensubdiv/catmark_pole8.obj").mesh, sqrt3);
  const DepthBound bound = depth_bound(mesh, sqrt3);
  ASSERT_EQ(bound.terms.size(), 2u);
  RefineOptions one;
  one.levels = 1;
  LimitOptions at_level_1;
  at_level_1.refine.start_level = 1;
  const double measured = resolved_limit_distances(refine(mesh, sqrt3, one), sqrt3, at_level_1).max;
  EXPECT_GT(measured, bound.terms[0].amplitude * bound.terms[0].rate);
  EXPECT_LE(measured, bound.at(1) * (1.0 + 1e-12));
}

}  // namespace
}  // namespace subdiv
