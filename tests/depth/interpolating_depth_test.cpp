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
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/depth/depth.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/rules/bilinear.h"
#include "subdiv/rules/linear.h"
#include "subdiv/rules/scheme.h"
#include "depth/depth_test_meshes.h"
#include "depth/nested_linear_surface.h"
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

// --- The rotating splits: interpolatory-sqrt3 and interpolating-sqrt2 ---
//
// Their child faces straddle the parent's edges, but two steps nest (the
// sqrt3 split's second level is the 1-to-9 split, the sqrt2 split's the
// 1-to-4 split), and the bound counts periods of two steps.

// The points a level's faces give their two-step children, computed here
// from the faces alone: corners, the centre, and the edges' thirds (sqrt3)
// or midpoints (sqrt2).
std::vector<Vec3> parameter_points(const PolygonMesh& level, Index f, SplitRule rule) {
  std::vector<Vec3> points;
  const Index n = level.face_size(f);
  Vec3 centre{};
  for (Index i = 0; i < n; ++i) {
    const Vec3 a = level.positions[level.face_indices[level.face_offsets[f] + i]];
    const Vec3 b = level.positions[level.face_indices[level.face_offsets[f] + (i + 1) % n]];
    centre = centre + a;
    points.push_back(a);
    if (rule == SplitRule::sqrt3) {
      points.push_back((1.0 / 3.0) * (2.0 * a + b));
      points.push_back((1.0 / 3.0) * (a + 2.0 * b));
    } else {
      points.push_back(0.5 * (a + b));
    }
  }
  points.push_back((1.0 / static_cast<double>(n)) * centre);
  return points;
}

bool among(const Vec3& p, const std::vector<Vec3>& points) {
  return std::any_of(points.begin(), points.end(), [&](const Vec3& q) { return norm(p - q) < 1e-12; });
}

// Every face two steps down has its corners among the parameter points of
// one face of the level, and each face of the level holds 9 (sqrt3) or 4
// (sqrt2) of them: the nested surface tiles the level's faces.
void expect_nests(const PolygonMesh& level, const PolygonMesh& fine, SplitRule rule) {
  const Index per_face = rule == SplitRule::sqrt3 ? 9 : 4;
  ASSERT_EQ(fine.face_count(), per_face * level.face_count());
  std::vector<Index> held(static_cast<std::size_t>(level.face_count()), 0);
  for (Index g = 0; g < fine.face_count(); ++g) {
    Index home = kInvalidIndex;
    for (Index f = 0; f < level.face_count() && home == kInvalidIndex; ++f) {
      const std::vector<Vec3> points = parameter_points(level, f, rule);
      bool inside = true;
      for (Index c = fine.face_offsets[g]; c < fine.face_offsets[g + 1] && inside; ++c)
        inside = among(fine.positions[fine.face_indices[c]], points);
      if (inside) home = f;
    }
    ASSERT_NE(home, kInvalidIndex) << "face " << g << " two steps down lies in no face of the level";
    ++held[static_cast<std::size_t>(home)];
  }
  for (Index f = 0; f < level.face_count(); ++f) EXPECT_EQ(held[static_cast<std::size_t>(f)], per_face) << "face " << f;
}

PolygonMesh with_random_positions(PolygonMesh mesh, std::mt19937& random) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (Vec3& p : mesh.positions) p = {u(random), u(random), u(random)};
  return mesh;
}

TEST(InterpolatingDepth, TwoRotatingStepsNestInTheLevelsFaces) {
  std::mt19937 random(33);
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  const PolygonMesh l_shape = read_mesh(test::bundled_path("l_shape.obj")).mesh;
  // Random positions: every parameter point is distinct, so a misplaced
  // point cannot match another by accident.
  const Scheme& sqrt3 = *find_scheme("interpolatory-sqrt3");
  for (const PolygonMesh& mesh : {for_scheme(cube, sqrt3), for_scheme(l_shape, sqrt3), triangle_torus(5, 4, 2.0, 0.5)}) {
    const PolygonMesh level = with_random_positions(mesh, random);
    expect_nests(level, detail::nested_linear_refinement(level, 0, SplitRule::sqrt3), SplitRule::sqrt3);
  }
  // A closed mesh nests from odd levels too (no boundary steps alternate).
  const PolygonMesh torus = with_random_positions(triangle_torus(4, 5, 2.0, 0.5), random);
  expect_nests(torus, detail::nested_linear_refinement(torus, 1, SplitRule::sqrt3), SplitRule::sqrt3);
  for (const PolygonMesh& mesh : {cube, quad_torus(5, 4, 2.0, 0.5)}) {
    const PolygonMesh level = with_random_positions(mesh, random);
    expect_nests(level, detail::nested_linear_refinement(level, 0, SplitRule::sqrt2), SplitRule::sqrt2);
  }
}

// The level's linear surface at the vertices two steps down, and the
// scheme's own two steps: the same faces, and the same kept vertices.
TEST(InterpolatingDepth, NestedSurfaceMatchesTheSchemesNumbering) {
  for (const char* name : {"interpolatory-sqrt3", "interpolating-sqrt2"}) {
    SCOPED_TRACE(name);
    const Scheme& scheme = *find_scheme(name);
    const bool triangles = scheme.split == SplitRule::sqrt3;
    const PolygonMesh torus = triangles ? triangle_torus(6, 6, 2.0, 0.5) : quad_torus(6, 6, 2.0, 0.5);
    RefineOptions two;
    two.levels = 2;
    const PolygonMesh exact = refine(torus, scheme, two);
    const PolygonMesh nested = detail::nested_linear_refinement(torus, 0, scheme.split);
    EXPECT_EQ(nested.face_offsets, exact.face_offsets);
    EXPECT_EQ(nested.face_indices, exact.face_indices);
    // The scheme keeps its vertices: the old vertices are where the nested
    // surface puts them (vertex points are numbered last).
    for (Index v = 0; v < torus.vertex_count(); ++v) {
      const Index at = exact.vertex_count() - torus.vertex_count() + v;
      EXPECT_LT(norm(exact.positions[at] - nested.positions[at]), 1e-12) << "vertex " << v;
    }
  }
}

TEST(InterpolatingDepth, OddLevelsOfOpenSqrt3MeshesAndOtherSplitsAreRefused) {
  const PolygonMesh l_shape = for_scheme(read_mesh(test::bundled_path("l_shape.obj")).mesh, *find_scheme("sqrt3"));
  try {
    (void)detail::nested_linear_refinement(l_shape, 1, SplitRule::sqrt3);
    ADD_FAILURE() << "no refusal";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("only from an even level"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)detail::nested_linear_refinement(l_shape, 0, SplitRule::triangle), InvalidInputError);
  EXPECT_THROW((void)detail::nested_linear_refinement(l_shape, 0, SplitRule::sqrt2), InvalidInputError);
}

// The largest distance between `level`'s linear surface and the scheme's
// vertices two periods (four steps) down, which are on the limit.
double nested_surface_distance(const PolygonMesh& level, int number, const Scheme& scheme) {
  RefineOptions four;
  four.levels = 4;
  four.start_level = number;
  const PolygonMesh exact = refine(level, scheme, four);
  const PolygonMesh linear = detail::nested_linear_refinement(
      detail::nested_linear_refinement(level, number, scheme.split), number + 2, scheme.split);
  double worst = 0.0;
  for (std::size_t v = 0; v < exact.positions.size(); ++v)
    worst = std::max(worst, norm(exact.positions[v] - linear.positions[v]));
  return worst;
}

void check_period_bound_holds(const PolygonMesh& mesh, const Scheme& scheme, const std::string& name,
                              std::int64_t max_faces = 40000) {
  SCOPED_TRACE(name + ", " + std::string(scheme.name));
  const DepthBound bound = depth_bound(mesh, scheme);
  ASSERT_EQ(bound.measure, DepthMeasure::surface_to_limit);
  ASSERT_EQ(bound.steps_per_level, 2);
  PolygonMesh level = mesh;
  double first = 0.0;
  // Level k of the bound is 2k steps; the measurement reaches 4 steps further.
  const std::int64_t four_steps = scheme.split == SplitRule::sqrt3 ? 81 : 16;  // faces per face, 4 steps down
  for (int k = 0; std::int64_t{level.face_count()} * four_steps <= max_faces; ++k) {
    const double measured = nested_surface_distance(level, 2 * k, scheme);
    if (k == 0) first = measured;
    EXPECT_LE(measured, bound.at(k) * (1.0 + 1e-12)) << "level " << k;
    RefineOptions two;
    two.levels = 2;
    two.start_level = 2 * k;
    level = refine(level, scheme, two);
  }
  EXPECT_GT(first, 0.0);  // a curved mesh: the linear surface is not the limit
}

TEST(InterpolatingDepth, RotatingSplitsBoundHoldsOnBundledMeshes) {
  std::mt19937 random(34);
  const Scheme& sqrt3 = *find_scheme("interpolatory-sqrt3");
  for (const char* file : {"cube.obj", "tetrahedron.obj", "spot_control_mesh.obj"}) {
    const PolygonMesh mesh = for_scheme(read_mesh(test::bundled_path(file)).mesh, sqrt3);
    check_period_bound_holds(mesh, sqrt3, file);
    check_period_bound_holds(perturbed(mesh, 0.1, random), sqrt3, std::string(file) + " (perturbed)");
  }
  const Scheme& sqrt2 = *find_scheme("interpolating-sqrt2");
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  check_period_bound_holds(cube, sqrt2, "cube.obj");
  check_period_bound_holds(perturbed(cube, 0.1, random), sqrt2, "cube.obj (perturbed)");
}

TEST(InterpolatingDepth, RotatingSplitsBoundHoldsOnSharedMeshesAndPerturbations) {
  const std::string dir = test::shared_mesh_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared mesh collection not found at " << dir;
  std::mt19937 random(35);
  // Regular (the regular rules' rate alone), and genus 3 with valences 3 to 8.
  for (const char* file : {"opensubdiv/catmark_torus.obj", "cgal/3torus.obj"}) {
    const PolygonMesh original = read_mesh(dir + "/" + file).mesh;
    ASSERT_TRUE(all_quads(original)) << file;
    const double size = largest_extent(original);
    for (const char* name : {"interpolatory-sqrt3", "interpolating-sqrt2"}) {
      const Scheme& scheme = *find_scheme(name);
      const PolygonMesh mesh = for_scheme(original, scheme);
      check_period_bound_holds(mesh, scheme, file);
      check_period_bound_holds(perturbed(mesh, 0.05 * size, random), scheme, std::string(file) + " (perturbed)");
    }
  }
}

// The sqrt3 split's regular boundary rules are not read as a lattice rule
// (regular_boundary_rule()), so their contraction is unknown: an open mesh
// is refused, naming why.
TEST(InterpolatingDepth, OpenSqrt3MeshesAreRefusedNamingWhy) {
  const Scheme& scheme = *find_scheme("interpolatory-sqrt3");
  const PolygonMesh mesh = for_scheme(read_mesh(test::bundled_path("l_shape.obj")).mesh, scheme);
  try {
    (void)depth_bound(mesh, scheme);
    ADD_FAILURE() << "no refusal";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("no depth bound on a mesh with a boundary: the contraction of the regular "
                                         "boundary rules' second differences is not known"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace subdiv
