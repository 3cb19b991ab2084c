// The depth bound of interpolating schemes (the Butterflies, Kobbelt's):
// their vertices are on the limit, so the bound is on the level's linear
// surface (flat triangles, bilinear quads) against the limit. Measured
// here on its own: the level refined two more steps by the scheme (those
// vertices are on the limit) against the same level refined two steps by
// the linear or bilinear scheme (its linear surface at the same parameters),
// at every level up to the bound's depth, on bundled and shared meshes and
// perturbations of them.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>

#include "subdiv/core/error.h"
#include "subdiv/depth/depth.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/rules/bilinear.h"
#include "subdiv/rules/linear.h"
#include "subdiv/rules/scheme.h"
#include "depth/depth_test_meshes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// The largest distance, at the vertices two levels down, between the limit
// (those vertices) and `level`'s linear surface.
double surface_distance(const PolygonMesh& level, int number, const Scheme& scheme) {
  const Scheme& flat = scheme.split == SplitRule::quad ? bilinear_scheme() : linear_scheme();
  RefineOptions two;
  two.levels = 2;
  two.start_level = number;
  const PolygonMesh exact = refine(level, scheme, two);
  const PolygonMesh linear = refine(level, flat, two);
  double worst = 0.0;
  for (std::size_t v = 0; v < exact.positions.size(); ++v)
    worst = std::max(worst, norm(exact.positions[v] - linear.positions[v]));
  return worst;
}

bool all_quads(const PolygonMesh& mesh) {
  for (Index f = 0; f < mesh.face_count(); ++f)
    if (mesh.face_size(f) != 4) return false;
  return true;
}

void check_surface_bound_holds(const PolygonMesh& mesh, const Scheme& scheme, const std::string& name,
                               std::int64_t max_faces = 3000) {
  SCOPED_TRACE(name + ", " + std::string(scheme.name));
  const DepthBound bound = depth_bound(mesh, scheme);
  ASSERT_EQ(bound.measure, DepthMeasure::surface_to_limit);
  const std::vector<LevelCost> costs = level_costs(mesh, scheme, 6);
  int target = 0;
  while (target + 1 < static_cast<int>(costs.size()) && costs[static_cast<std::size_t>(target + 1)].faces <= max_faces)
    ++target;
  PolygonMesh level = mesh;
  double first = 0.0;
  for (int k = 0; k <= target; ++k) {
    const double measured = surface_distance(level, k, scheme);
    if (k == 0) first = measured;
    EXPECT_LE(measured, bound.at(k) * (1.0 + 1e-12)) << "level " << k;
    // The vertices are on the limit: the vertex measure says nothing.
    LimitOptions at_level;
    at_level.refine.start_level = k;
    EXPECT_LE(limit_distances(level, scheme, at_level).max, 1e-12 * test::radius(mesh)) << "level " << k;
    RefineOptions one;
    one.levels = 1;
    one.start_level = k;
    level = refine(level, scheme, one);
  }
  EXPECT_GT(first, 0.0);  // a curved mesh: the linear surface is not the limit
}

TEST(InterpolatingDepth, BoundHoldsOnBundledMeshes) {
  std::mt19937 random(31);
  for (const char* file : {"cube.obj", "tetrahedron.obj", "spot_control_mesh.obj"}) {
    const PolygonMesh mesh = read_mesh(test::bundled_path(file)).mesh;
    for (const char* name : {"butterfly", "modified-butterfly"}) {
      const Scheme& scheme = *find_scheme(name);
      check_surface_bound_holds(for_scheme(mesh, scheme), scheme, file);
    }
  }
  const Scheme& kobbelt = *find_scheme("kobbelt");
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  check_surface_bound_holds(cube, kobbelt, "cube.obj");
  check_surface_bound_holds(perturbed(cube, 0.1, random), kobbelt, "cube.obj (perturbed)");
}

TEST(InterpolatingDepth, BoundHoldsOnSharedMeshesAndPerturbations) {
  const std::string dir = test::shared_mesh_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared mesh collection not found at " << dir;
  std::mt19937 random(32);
  // A regular torus (the regular rules' rate alone), genus 3, boundaries, valence 8.
  for (const char* file : {"opensubdiv/catmark_torus.obj", "cgal/3torus.obj", "cgal/hole.obj",
                           "opensubdiv/catmark_pole8.obj"}) {
    const PolygonMesh original = read_mesh(dir + "/" + file).mesh;
    const double size = largest_extent(original);
    for (const char* name : {"butterfly", "modified-butterfly", "kobbelt"}) {
      const Scheme& scheme = *find_scheme(name);
      if (scheme.traits.needs_quads && !all_quads(original)) continue;
      const PolygonMesh mesh = for_scheme(original, scheme);
      check_surface_bound_holds(mesh, scheme, file);
      check_surface_bound_holds(perturbed(mesh, 0.05 * size, random), scheme, std::string(file) + " (perturbed)");
    }
  }
}

// The sqrt3 split's interpolating scheme is refused (as the sqrt2 split's,
// whose analysis takes seconds): a level's linear surface does not contain
// the next level's.
TEST(InterpolatingDepth, RotatingSplitsAreRefusedNamingWhy) {
  const Scheme& scheme = *find_scheme("interpolatory-sqrt3");
  const PolygonMesh mesh = for_scheme(read_mesh(test::bundled_path("cube.obj")).mesh, scheme);
  try {
    (void)depth_bound(mesh, scheme);
    ADD_FAILURE() << "no refusal";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("on the sqrt3 split (TP, arity sqrt 3): its vertices are on the limit, and "
                                         "a level's linear surface does not contain the next level's"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace subdiv
