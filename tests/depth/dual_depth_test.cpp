// Doo-Sabin limit positions (the limit of each vertex's V-face) and the
// Doo-Sabin depth bound built on them (docs/depth.md, "Doo-Sabin").

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "subdiv/analysis/analyze.h"
#include "analysis/dual_limit.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/depth/depth.h"
#include "depth/dual_face_bound.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/doo_sabin.h"
#include "subdiv/rules/scheme.h"
#include "depth/depth_test_meshes.h"
#include "support/bsplines.h"
#include "support/refine_options.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::quadratic_bspline;

TEST(DualLimit, RegularTorusIsTheBiquadraticSplineAtEachVertex) {
  // On a regular grid Doo-Sabin is the biquadratic B-spline with the control
  // points at the integer parameters: the limit of vertex (i, j)'s V-face
  // centre is the spline at (i, j).
  const int n = 6, m = 8;
  std::mt19937 random(7);
  const PolygonMesh torus = perturbed(quad_torus(n, m, 3.0, 1.0), 0.3, random);
  const LimitResult limit = limit_positions(torus, doo_sabin_scheme());
  EXPECT_EQ(limit.approximated, 0);
  ASSERT_EQ(limit.positions.size(), torus.positions.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      Vec3 spline;
      for (int a = -2; a <= 2; ++a)
        for (int b = -2; b <= 2; ++b)
          spline += quadratic_bspline(a) * quadratic_bspline(b) *
                    torus.positions[static_cast<std::size_t>(((i + a + n) % n) * m + (j + b + m) % m)];
      const auto v = static_cast<std::size_t>(i * m + j);
      EXPECT_LT(norm(limit.positions[v] - spline), 1e-12) << "vertex " << i << ", " << j;
      EXPECT_EQ(limit.sources[v], LimitSource::generic);
    }
}

TEST(DualLimit, FaceConfigurationMaskIsTheFaceCentroid) {
  // A face's children (its F-face) depend on its own vertices only, and the
  // face map keeps the centroid: the eigenvalue-1 mask is 1/k on the k-gon
  // and zero on its ring, whatever the matching.
  for (int k = 3; k <= 8; ++k) {
    AnalysisOptions options;
    options.characteristic_map = false;
    const ConfigurationAnalysis a = analyze(doo_sabin_scheme(), {Configuration::Kind::interior, k}, options);
    ASSERT_TRUE(a.limit_mask) << k;
    ASSERT_EQ(a.limit_mask->size(), 4 * k);
    for (int i = 0; i < 4 * k; ++i) EXPECT_NEAR((*a.limit_mask)[i], i < k ? 1.0 / k : 0.0, 1e-10) << k << " " << i;
    EXPECT_NEAR(std::abs(a.leading[1]), 0.5, 1e-9) << k;
  }
}

TEST(DualLimit, ExtraordinaryVerticesTakeTheCentroidOfTheirVFace) {
  // The cube's vertices have 3 faces: V-faces are triangles, not in a
  // canonical ring; the limit is the triangle's centroid in the child.
  std::mt19937 random(9);
  const PolygonMesh cube = perturbed(read_mesh(test::bundled_path("cube.obj")).mesh, 0.1, random);
  const PolygonMesh child = refine(cube, doo_sabin_scheme());
  const MeshTopology t(cube);
  const LimitResult limit = limit_positions(cube, doo_sabin_scheme());
  EXPECT_EQ(limit.approximated, 0);
  for (Index v = 0; v < t.vertex_count(); ++v) {
    Vec3 centroid;
    for (const Index c : t.vertex_corners(v)) centroid += child.positions[static_cast<std::size_t>(c)];
    centroid = (1.0 / static_cast<double>(t.vertex_corners(v).size())) * centroid;
    EXPECT_LT(norm(limit.positions[static_cast<std::size_t>(v)] - centroid), 1e-12) << v;
    const Vec3 normal = limit.normals[static_cast<std::size_t>(v)];
    EXPECT_NEAR(norm(normal), 1.0, 1e-12);
    EXPECT_GT(dot(normal, cube.positions[static_cast<std::size_t>(v)]), 0.0) << "outward, like the faces";
  }
}

TEST(DualLimit, VFacesShrinkToTheLimit) {
  // Each vertex's limit is where its V-face's nested F-faces shrink to: the
  // F-face of child face f is child face f (dual_split.cpp), and its
  // vertices close in on the limit by 1/2 per step (lambda_1).
  std::mt19937 random(4);
  const PolygonMesh mesh = perturbed(read_mesh(test::bundled_path("cube.obj")).mesh, 0.2, random);
  const MeshTopology t(mesh);
  const LimitResult limit = limit_positions(mesh, doo_sabin_scheme());
  PolygonMesh level = refine(mesh, doo_sabin_scheme());
  std::vector<double> first(static_cast<std::size_t>(t.vertex_count()));
  const auto spread = [&](Index v) {
    double worst = 0.0;
    // V-faces follow the F- and E-faces, one per vertex (all have faces).
    const Index f = t.face_count() + t.edge_count() + v;
    for (const Index w : level.face(f))
      worst = std::max(worst, norm(level.positions[static_cast<std::size_t>(w)] - limit.positions[static_cast<std::size_t>(v)]));
    return worst;
  };
  for (Index v = 0; v < t.vertex_count(); ++v) first[static_cast<std::size_t>(v)] = spread(v);
  for (int l = 0; l < 6; ++l) level = refine(level, doo_sabin_scheme());
  for (Index v = 0; v < t.vertex_count(); ++v)
    EXPECT_LT(spread(v), first[static_cast<std::size_t>(v)] * std::pow(0.5, 6) * 1.5) << v;
}

double segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 d = b - a;
  const double t = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
  return norm(p - (a + t * d));
}

TEST(DualLimit, BoundaryVerticesLieOnTheBoundaryCurve) {
  // The child boundary polygon is Chaikin's refinement of the parent's: the
  // boundary limit at v is the quadratic B-spline there, (a + 6 v + b) / 8,
  // which the refined boundary polygon approaches like 4^-level.
  std::mt19937 random(2);
  const PolygonMesh grid = perturbed(test::quad_grid(4, 3), 0.2, random);
  const MeshTopology t(grid);
  const LimitResult limit = limit_positions(grid, doo_sabin_scheme());
  EXPECT_EQ(limit.approximated, 0);
  PolygonMesh level = grid;
  for (int l = 0; l < 8; ++l) level = refine(level, doo_sabin_scheme());
  const MeshTopology fine(level);
  for (Index v = 0; v < t.vertex_count(); ++v) {
    if (t.vertex_kind(v) != VertexKind::boundary) continue;
    EXPECT_EQ(limit.sources[static_cast<std::size_t>(v)], LimitSource::closed_form);
    double nearest = 1e300;
    for (Index e = 0; e < fine.edge_count(); ++e)
      if (fine.is_boundary_edge(e)) {
        const auto ends = fine.edge_vertices(e);
        nearest = std::min(nearest, segment_distance(limit.positions[static_cast<std::size_t>(v)],
                                                     level.positions[static_cast<std::size_t>(ends[0])],
                                                     level.positions[static_cast<std::size_t>(ends[1])]));
      }
    EXPECT_LT(nearest, 1e-4) << v;
  }
}

TEST(DualLimit, NeighbourhoodWalkIsCanonicalOnTheLayout) {
  for (int k = 3; k <= 6; ++k) {
    const RingMesh ring = ring_mesh(SplitRule::dual, {Configuration::Kind::interior, k}, 1);
    const MeshTopology t(ring.mesh);
    bool regular = false;
    const std::vector<Index> walk = face_neighbourhood(t, ring.centre_face, regular);
    EXPECT_TRUE(regular);
    EXPECT_EQ(walk.size(), static_cast<std::size_t>(4 * k));
  }
}

TEST(DooSabinDepth, PaperBoundPlusExtraordinaryFacesFromTheLevelTheyAreApart) {
  // The cube's triangles (its vertices' V-faces) are two rings apart after
  // one step: their two-ring neighbourhoods become canonical after two.
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  const DepthBound bound = depth_bound(cube, doo_sabin_scheme());
  EXPECT_EQ(bound.start, 2);
  ASSERT_EQ(bound.terms.size(), 2u);
  EXPECT_EQ(bound.source, "paper (regular) + local subdivision matrix (extraordinary)");
  const PolygonMesh second = refine(cube, doo_sabin_scheme(), test::levels(2));
  EXPECT_EQ(bound.terms[0].amplitude, max_second_difference(second) / 4.0);
  EXPECT_EQ(bound.terms[0].rate, 0.25);
  EXPECT_NE(bound.terms[1].what.find("face of 3 sides"), std::string::npos) << bound.terms[1].what;
  EXPECT_NEAR(bound.terms[1].rate, 0.5, 1e-9);
  // The amplitude is at least what it bounds at the start level itself.
  EXPECT_GE(bound.terms[1].amplitude, limit_distances(second, doo_sabin_scheme()).max);
  const int depth = bound.depth_for(0.01);
  const DepthCheck check = check_depth(cube, doo_sabin_scheme(), bound, depth);
  EXPECT_LE(check.measured, 0.01);
  EXPECT_EQ(check.approximated, 0);
}

TEST(DooSabinDepth, FaceOperatorFollowsRefinement) {
  // The operator's matrix, applied to a face's neighbourhood found in the
  // mesh, gives the neighbourhood of the face's descendant (child face f of
  // face f, dual_split.cpp) that refinement computes, and its distance
  // functionals give the measured vertex-to-limit distances there.
  std::mt19937 random(31);
  for (const int k : {3, 5, 6, 8}) {
    const DualFaceOperator op = dual_face_operator(doo_sabin_scheme(), k);
    const RingMesh ring = ring_mesh(SplitRule::dual, {Configuration::Kind::interior, k}, 5);
    PolygonMesh level = perturbed(ring.mesh, 0.2, random);
    for (Vec3& p : level.positions) p.z += 0.3 * (p.x * p.x - p.y * p.y);
    const std::optional<Eigen::MatrixXd> start =
        canonical_neighbourhood(op, MeshTopology(level), level.positions, ring.centre_face);
    ASSERT_TRUE(start) << k;
    Eigen::MatrixXd expected = *start;
    for (int m = 1; m <= 3; ++m) {
      level = refine(level, doo_sabin_scheme());
      expected = op.S * expected;
      const MeshTopology t(level);
      const std::optional<Eigen::MatrixXd> found = canonical_neighbourhood(op, t, level.positions, ring.centre_face);
      ASSERT_TRUE(found) << k << " level " << m;
      EXPECT_LT((*found - expected).cwiseAbs().maxCoeff(), 1e-12) << k << " level " << m;
      const LimitDistances measured = limit_distances(level, doo_sabin_scheme());
      double predicted = 0.0, at_face = 0.0;
      for (const auto& row : op.distance) {
        Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
        for (const auto& [j, w] : row) sum += w * expected.row(j);
        predicted = std::max(predicted, sum.norm());
      }
      for (const Index v : t.face_vertices(ring.centre_face))
        at_face = std::max(at_face, measured.distances[static_cast<std::size_t>(v)]);
      EXPECT_NEAR(at_face, predicted, 1e-12) << k << " level " << m;
    }
  }
}

TEST(DooSabinDepth, NeighbourhoodsTooCloseOrOddAreNotCanonical) {
  // Level 1 of the cube: each triangle's two-ring holds another triangle.
  const PolygonMesh first = refine(read_mesh(test::bundled_path("cube.obj")).mesh, doo_sabin_scheme());
  const MeshTopology t(first);
  const DualFaceOperator op = dual_face_operator(doo_sabin_scheme(), 3);
  int triangles = 0;
  for (Index f = 0; f < t.face_count(); ++f)
    if (t.face_size(f) == 3) {
      ++triangles;
      EXPECT_FALSE(canonical_neighbourhood(op, t, first.positions, f)) << f;
    }
  EXPECT_EQ(triangles, 8);
  // A face of the wrong size is never matched.
  const RingMesh ring = ring_mesh(SplitRule::dual, {Configuration::Kind::interior, 5}, 4);
  EXPECT_FALSE(canonical_neighbourhood(op, MeshTopology(ring.mesh), ring.mesh.positions, ring.centre_face));
}

TEST(DooSabinDepth, HoldsAndIsTightOnMeshesWithManyExtraordinaryFaces) {
  // The meshes on which an amplitude measured after the first step failed
  // (by 3% to 78%): the bound holds at every level, and depth - 1 would not
  // be enough (measured above half the bound, the rate 1/2 being the step).
  const std::string dir = test::shared_mesh_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared mesh collection not found at " << dir;
  for (const char* file : {"cgal/3torus.obj", "assimp/uv_sphere.obj", "geomview/mushroom.obj", "cgal/hole.obj"}) {
    const PolygonMesh mesh = read_mesh(dir + "/" + file).mesh;
    const DepthBound bound = depth_bound(mesh, doo_sabin_scheme());
    PolygonMesh level = refine(mesh, doo_sabin_scheme(), test::levels(bound.start));
    for (int k = bound.start; level.face_count() <= 60000; ++k) {
      const double measured = limit_distances(level, doo_sabin_scheme()).max;
      EXPECT_LE(measured, bound.at(k)) << file << " level " << k;
      EXPECT_GT(measured, 0.25 * bound.at(k)) << file << " level " << k;
      level = refine(level, doo_sabin_scheme());
    }
  }
}

TEST(DooSabinDepth, BoundaryFaceOperatorFollowsRefinement) {
  // A grid's corner vertex has one face: its V-face is a triangle on the
  // boundary, outside the canonical layout. Once the next level's
  // neighbourhood repeats this one's, the operator read off one step
  // predicts every later step that refinement computes.
  std::mt19937 random(5);
  PolygonMesh level = perturbed(test::quad_grid(3, 3), 0.2, random);
  for (Vec3& p : level.positions) p.z += 0.2 * p.x * p.y;
  level = refine(level, doo_sabin_scheme());
  std::optional<DualFaceOperator> op;
  Index corner_face = kInvalidIndex;
  for (int l = 1; l <= 4 && !op; ++l) {
    const MeshTopology t(level);
    const PolygonMesh child = refine(level, doo_sabin_scheme());
    for (Index f = 0; f < t.face_count() && corner_face == kInvalidIndex; ++f)
      if (t.face_size(f) == 3) corner_face = f;
    ASSERT_NE(corner_face, kInvalidIndex);
    op = local_face_operator(t, refine_stencil_table(level, doo_sabin_scheme()), MeshTopology(child), corner_face,
                             boundary_vertex_limit(doo_sabin_scheme()));
    if (!op) level = child;
  }
  ASSERT_TRUE(op) << "the corner's neighbourhood never repeats";
  EXPECT_EQ(op->k, 3);
  EXPECT_GT(op->rate, 0.0);
  EXPECT_LT(op->rate, 1.0);
  Eigen::MatrixXd expected = local_neighbourhood(MeshTopology(level), level.positions, corner_face);
  for (int m = 1; m <= 3; ++m) {
    level = refine(level, doo_sabin_scheme());
    expected = op->S * expected;
    const std::optional<Eigen::MatrixXd> found =
        canonical_neighbourhood(*op, MeshTopology(level), level.positions, corner_face);
    ASSERT_TRUE(found) << "level " << m;
    EXPECT_LT((*found - expected).cwiseAbs().maxCoeff(), 1e-12) << "level " << m;
  }
}

TEST(DooSabinDepth, HoldsOnOpenMeshesWithCorners) {
  // Grids (corner vertices of one face, boundary triangles) and the bundled
  // L without its corner tags, perturbed: the bound holds at every level
  // and is within a factor 4 of the measured distance.
  std::mt19937 random(17);
  PolygonMesh l_shape = read_mesh(test::bundled_path("l_shape.obj")).mesh;
  l_shape.tags = {};
  std::vector<PolygonMesh> meshes = {test::quad_grid(3, 3), perturbed(test::quad_grid(4, 3), 0.2, random),
                                     perturbed(l_shape, 0.1, random)};
  for (Vec3& p : meshes[1].positions) p.z += 0.3 * std::sin(p.x) * p.y;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const DepthBound bound = depth_bound(meshes[i], doo_sabin_scheme());
    EXPECT_EQ(bound.source, "paper (regular) + local subdivision matrix (extraordinary)") << i;
    PolygonMesh level = refine(meshes[i], doo_sabin_scheme(), test::levels(bound.start));
    for (int k = bound.start; k <= bound.start + 3; ++k) {
      const double measured = limit_distances(level, doo_sabin_scheme()).max;
      EXPECT_LE(measured, bound.at(k)) << i << " level " << k;
      EXPECT_GT(measured, 0.25 * bound.at(k)) << i << " level " << k;
      level = refine(level, doo_sabin_scheme());
    }
  }
}

TEST(DooSabinDepth, RegularTorusHasThePaperBoundOnly) {
  std::mt19937 random(13);
  const PolygonMesh torus = perturbed(quad_torus(8, 6, 3.0, 1.0), 0.2, random);
  const DepthBound bound = depth_bound(torus, doo_sabin_scheme());
  ASSERT_EQ(bound.terms.size(), 1u);
  EXPECT_EQ(bound.source, "paper");
  PolygonMesh level = refine(torus, doo_sabin_scheme());
  for (int k = 1; k <= 4; ++k) {
    EXPECT_LE(limit_distances(level, doo_sabin_scheme()).max, bound.at(k)) << "level " << k;
    level = refine(level, doo_sabin_scheme());
  }
}

TEST(DooSabinDepth, LevelCostsMatchRefinement) {
  std::vector<PolygonMesh> meshes = {read_mesh(test::bundled_path("cube.obj")).mesh,
                                     read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh,
                                     test::quad_grid(3, 2)};
  for (const PolygonMesh& mesh : meshes) {
    const std::vector<LevelCost> costs = level_costs(mesh, doo_sabin_scheme(), 3);
    PolygonMesh level = mesh;
    for (const LevelCost& cost : costs) {
      const MeshTopology t(level);
      EXPECT_EQ(cost.vertices, level.vertex_count()) << "level " << cost.level;
      EXPECT_EQ(cost.faces, level.face_count()) << "level " << cost.level;
      EXPECT_EQ(cost.corners, level.corner_count()) << "level " << cost.level;
      EXPECT_EQ(cost.edges, t.edge_count()) << "level " << cost.level;
      level = refine(level, doo_sabin_scheme());
    }
  }
}

}  // namespace
}  // namespace subdiv
