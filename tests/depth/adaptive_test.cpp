// Adaptive refinement: the output is conforming (closed inputs stay closed
// with every edge on exactly two faces, so no T-junction), every vertex is a
// vertex of a uniform level at that level's position and within eps of its
// limit, and it needs fewer faces than uniform refinement.

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

#include "subdiv/core/error.h"
#include "subdiv/depth/adaptive.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/mesh_stats.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/rules/butterfly.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/kobbelt.h"
#include "subdiv/rules/loop.h"
#include "depth/depth_test_meshes.h"
#include "support/gcc_schemes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

void expect_conforming_and_within(const PolygonMesh& input, const Scheme& scheme, double eps,
                                  const std::string& name) {
  const AdaptiveResult result = adaptive_refine(input, scheme, eps);
  const MeshTopology t(result.mesh);
  for (Index e = 0; e < t.edge_count(); ++e) {
    ASSERT_EQ(t.edge_face_count(e), 2) << name << ": edge " << t.edge_vertices(e)[0] << "-" << t.edge_vertices(e)[1];
  }
  const MeshTopology input_topology(input);
  EXPECT_EQ(compute_stats(result.mesh, t).euler_characteristic,
            compute_stats(input, input_topology).euler_characteristic)
      << name;
  EXPECT_TRUE(validate(result.mesh).ok()) << name;
  // Every vertex, independently: the uniform level it names, refined here by
  // the masks as adaptive refinement refines (refine()'s grid path gives the
  // same points up to rounding), has it at that position, and its distance
  // to the limit there is <= eps.
  RefineOptions by_masks;
  by_masks.regular_grids = false;
  std::vector<PolygonMesh> levels{input};
  std::vector<LimitDistances> distances{limit_distances(input, scheme)};
  for (std::size_t v = 0; v < result.sources.size(); ++v) {
    const AdaptiveVertexSource source = result.sources[v];
    while (static_cast<int>(levels.size()) <= source.level) {
      levels.push_back(refine(levels.back(), scheme, by_masks));
      distances.push_back(limit_distances(levels.back(), scheme));
    }
    const auto level = static_cast<std::size_t>(source.level);
    const auto index = static_cast<std::size_t>(source.index);
    ASSERT_EQ(result.mesh.positions[v], levels[level].positions[index]) << name << ": vertex " << v;
    EXPECT_LE(distances[level].distances[index], eps) << name << ": vertex " << v;
  }
}

TEST(Adaptive, ConformingAndWithinEpsOnBundledMeshes) {
  std::mt19937 random(9);
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  expect_conforming_and_within(triangulate(cube), loop_scheme(), 0.01, "cube (loop)");
  expect_conforming_and_within(cube, catmull_clark_scheme(), 0.01, "cube (catmull-clark)");
  expect_conforming_and_within(perturbed(triangulate(cube), 0.1, random), loop_scheme(), 0.005, "perturbed cube (loop)");
  expect_conforming_and_within(perturbed(cube, 0.1, random), catmull_clark_scheme(), 0.005,
                               "perturbed cube (catmull-clark)");
  expect_conforming_and_within(spinning_top(18, 4.0, 7.0, 7.0), loop_scheme(), 0.05, "spinning top (loop)");
  expect_conforming_and_within(spinning_top(7, 4.0, 7.0, 3.0), catmull_clark_scheme(), 0.05,
                               "spinning top (catmull-clark)");
}

TEST(Adaptive, ConformingAndWithinEpsOnSharedMeshes) {
  const std::string dir = test::shared_mesh_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared mesh collection not found at " << dir;
  std::mt19937 random(12);
  for (const char* file : {"cgal/hole.obj", "cgal/3torus.obj", "opensubdiv/catmark_torus.obj"}) {
    const PolygonMesh mesh = read_mesh(dir + "/" + file).mesh;
    const double eps = 0.02 * (mesh.positions.empty() ? 1.0 : limit_distances(mesh, catmull_clark_scheme()).max);
    expect_conforming_and_within(triangulate(mesh), loop_scheme(), eps, std::string(file) + " (loop)");
    expect_conforming_and_within(mesh, catmull_clark_scheme(), eps, std::string(file) + " (catmull-clark)");
    expect_conforming_and_within(perturbed(mesh, eps, random), catmull_clark_scheme(), eps,
                                 std::string(file) + " (perturbed, catmull-clark)");
  }
}

// Composite schemes of the quad and triangle splits refine adaptively on
// their uniform levels as any scheme of their split: gcc and midpoint of
// odd degree, and composite-loop, whose adaptive mesh is Loop's (same faces,
// positions to rounding: its levels equal Loop's to 1e-14).
TEST(Adaptive, CompositeSchemesOfThePrimalSplits) {
  std::mt19937 random(14);
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  for (const Scheme& scheme : {test::midpoint(3), test::midpoint(5), test::gcc(5, 0.5, 0.25)}) {
    const std::string name = std::string(scheme.name) + " of degree " +
                             std::to_string(std::get<DegreeParameters>(scheme.parameters).degree);
    expect_conforming_and_within(cube, scheme, 0.01, "cube (" + name + ")");
    expect_conforming_and_within(perturbed(cube, 0.1, random), scheme, 0.005, "perturbed cube (" + name + ")");
  }
  const Scheme& composite_loop = *find_scheme("composite-loop");
  const PolygonMesh bumpy = perturbed(triangulate(cube), 0.1, random);
  expect_conforming_and_within(bumpy, composite_loop, 0.005, "perturbed cube (composite-loop)");
  const PolygonMesh top = spinning_top(7, 4.0, 7.0, 3.0);
  const AdaptiveResult composite = adaptive_refine(top, composite_loop, 0.05);
  const AdaptiveResult loop = adaptive_refine(top, loop_scheme(), 0.05);
  ASSERT_GT(composite.transition_faces, 0);
  ASSERT_EQ(composite.mesh.face_indices, loop.mesh.face_indices);
  ASSERT_EQ(composite.mesh.vertex_count(), loop.mesh.vertex_count());
  for (std::size_t v = 0; v < loop.mesh.positions.size(); ++v)
    ASSERT_LE(norm(composite.mesh.positions[v] - loop.mesh.positions[v]), 1e-12 * test::radius(top)) << v;
}

TEST(Adaptive, HalvesTheFacesOnARealMesh) {
  // Spot's control mesh: smooth body, sharp ears and horns. Uniform
  // refinement must go as deep everywhere as the worst place needs.
  const PolygonMesh spot = read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh;
  const AdaptiveResult cc = adaptive_refine(spot, catmull_clark_scheme(), 0.004);
  EXPECT_GE(static_cast<double>(cc.uniform_faces), 2.0 * cc.mesh.face_count());
  const AdaptiveResult loop = adaptive_refine(triangulate(spot), loop_scheme(), 0.004);
  EXPECT_GE(static_cast<double>(loop.uniform_faces), 2.0 * loop.mesh.face_count());
}

TEST(Adaptive, NothingToDoKeepsTheMesh) {
  // eps above every distance: the control mesh is the answer.
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  const AdaptiveResult result = adaptive_refine(cube, catmull_clark_scheme(), 10.0);
  EXPECT_EQ(result.mesh.face_count(), cube.face_count());
  EXPECT_EQ(result.transition_faces, 0);
  EXPECT_EQ(result.uniform_depth, 0);
}

TEST(Adaptive, RefusesBadAccuracy) {
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  EXPECT_THROW((void)adaptive_refine(cube, catmull_clark_scheme(), 0.0), InvalidInputError);
  AdaptiveOptions shallow;
  shallow.max_level = 1;
  EXPECT_THROW((void)adaptive_refine(cube, catmull_clark_scheme(), 1e-6, shallow), InvalidInputError);
}

// Interpolating schemes with wide masks: every vertex is on the limit
// surface, so a vertex-to-limit accuracy would keep the control mesh.
TEST(Adaptive, RefusesInterpolatingSchemes) {
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  EXPECT_THROW((void)adaptive_refine(cube, kobbelt_scheme(), 0.01), InvalidInputError);
  EXPECT_THROW((void)adaptive_refine(triangulate(cube), butterfly_scheme(), 0.01), InvalidInputError);
  EXPECT_THROW((void)adaptive_refine(triangulate(cube), modified_butterfly_scheme(), 0.01), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
