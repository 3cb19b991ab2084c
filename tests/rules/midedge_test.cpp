#include "subdiv/rules/midedge.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/limit.h"

#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/refine.h"
#include "support/stencil_rows.h"
#include "support/refine_options.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::levels;

// A closed mesh of triangles and quads: the cube with one face split into
// two triangles, positions jittered.
PolygonMesh closed_mixed_mesh() {
  PolygonMesh cube = test::cube();
  PolygonMesh mesh;
  mesh.positions = cube.positions;
  for (Index f = 0; f < cube.face_count(); ++f) {
    const auto q = cube.face(f);
    if (f == 0) {
      mesh.add_face({q[0], q[1], q[2]});
      mesh.add_face({q[0], q[2], q[3]});
    } else {
      mesh.add_face({q[0], q[1], q[2], q[3]});
    }
  }
  return test::jittered(mesh, 5);
}

TEST(Midedge, OneStepMakesAVertexPerEdgeAndAFacePerFaceAndVertex) {
  const PolygonMesh mesh = closed_mixed_mesh();
  const MeshTopology t(mesh);
  const PolygonMesh child = refine(mesh, midedge_scheme(), levels(1));
  EXPECT_EQ(child.vertex_count(), t.edge_count());
  EXPECT_EQ(child.face_count(), mesh.face_count() + mesh.vertex_count());
  const MeshTopology ct(child);
  EXPECT_TRUE(validate(child, ct).ok());
  for (Index v = 0; v < ct.vertex_count(); ++v) EXPECT_EQ(ct.valence(v), 4) << v;
  for (Index e = 0; e < t.edge_count(); ++e) {
    const auto [a, b] = t.edge_vertices(e);
    EXPECT_NEAR(norm(child.positions[static_cast<std::size_t>(e)] - 0.5 * (mesh.positions[a] + mesh.positions[b])), 0.0,
                1e-15);
  }
}

// Two steps are a Doo-Sabin type scheme (the survey, section 4.2): a vertex
// per parent corner at v/2 + (prev + next)/4, and the dual split's faces (a
// face per parent face, edge and vertex). Compared order-independently with
// that rule computed here.
TEST(Midedge, TwoStepsAreACornerCuttingDualScheme) {
  const PolygonMesh mesh = closed_mixed_mesh();
  const MeshTopology t(mesh);
  const PolygonMesh twice = refine(mesh, midedge_scheme(), levels(2));
  EXPECT_EQ(twice.vertex_count(), mesh.corner_count());
  EXPECT_EQ(twice.face_count(), mesh.face_count() + t.edge_count() + mesh.vertex_count());
  std::vector<bool> used(twice.positions.size(), false);
  for (Index c = 0; c < t.corner_count(); ++c) {
    const Vec3 expected = 0.5 * mesh.positions[t.corner_vertex(c)] +
                          0.25 * (mesh.positions[t.corner_vertex(t.corner_prev(c))] +
                                  mesh.positions[t.corner_vertex(t.corner_next(c))]);
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < twice.positions.size(); ++i)
      if (norm(twice.positions[i] - expected) < norm(twice.positions[nearest] - expected)) nearest = i;
    EXPECT_LT(norm(twice.positions[nearest] - expected), 1e-14) << c;
    EXPECT_FALSE(used[nearest]) << c;
    used[nearest] = true;
  }
}

TEST(Midedge, StencilRowsSumToOne) {
  const std::vector<StencilTable> tables = refine_stencils(closed_mixed_mesh(), midedge_scheme(), levels(3));
  for (const StencilTable& table : tables)
    for (Index r = 0; r < table.row_count(); ++r) {
      double sum = 0.0;
      for (const auto& [v, w] : test::merged_row(table, r)) sum += w;
      EXPECT_NEAR(sum, 1.0, 1e-15);
    }
}

// Two steps at an extraordinary face of k sides: the face's own block is
// the circulant of 1/2, 1/4, 1/4, whose Fourier transform gives
// lambda_1 = lambda_2 = (1 + cos(2 pi / k)) / 2 = cos^2(pi / k), above 1/2 for
// k > 4 (the survey's poor quality at extraordinary faces). Reif's criterion
// holds for k >= 4; at k = 3 the value 1/4 is triple and it does not apply.
TEST(Midedge, AnalysisAtExtraordinaryFaces) {
  for (int k = 3; k <= 10; ++k) {
    const ConfigurationAnalysis a = analyze(midedge_scheme(), {Configuration::Kind::interior, k, CornerType::convex});
    ASSERT_TRUE(a.matrix.invariant) << k << ": " << a.matrix.invariance_note;
    ASSERT_EQ(a.leading.size(), 4u);
    const double lambda = std::pow(std::cos(std::numbers::pi / k), 2);
    EXPECT_NEAR(a.leading[0].real(), 1.0, 1e-12) << k;
    EXPECT_NEAR(a.leading[1].real(), lambda, 1e-12) << k;
    EXPECT_NEAR(a.leading[2].real(), lambda, 1e-12) << k;
    if (k == 3) {
      EXPECT_NEAR(std::abs(a.leading[3]), 0.25, 1e-12);
      EXPECT_EQ(a.verdict, SmoothnessVerdict::inconclusive);
    } else {
      EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << k << ": " << a.reason;
    }
  }
}

// The split itself makes faces at boundaries too (the analysis' ring meshes
// need it); the scheme refuses open meshes.
TEST(Midedge, SplitOfAnOpenMeshIsValid) {
  const PolygonMesh grid = test::quad_grid(3, 3);
  PolygonMesh child;
  split_topology(grid, MeshTopology(grid), SplitRule::midedge, child);
  const MeshTopology ct(child);
  EXPECT_TRUE(validate(child, ct).ok());
  EXPECT_EQ(child.vertex_count(), MeshTopology(grid).edge_count());
  EXPECT_EQ(ct.boundary_loops().size(), 1u);
}

TEST(Midedge, RefusesBoundariesAndTags) {
  EXPECT_THROW(refine(test::quad_grid(2, 2), midedge_scheme(), levels(1)), InvalidInputError);
  PolygonMesh cube = test::cube();
  cube.tags.corners.push_back({0, kInfiniteSharpness, CornerType::unspecified, std::nullopt});
  EXPECT_THROW(refine(cube, midedge_scheme(), levels(1)), InvalidInputError);
}

}  // namespace
}  // namespace subdiv

namespace subdiv {
namespace {

// Limits through the V-faces (analysis/dual_limit.h): vertex v's limit is
// that of the face its first step makes around it (child face F + the rank
// of v among the vertices of three or more edges), whose descendants keep
// its index; their centroids are its limit at every level (each F-face of
// a face keeps the face's vertex centroid), and their normals turn towards
// the limit normal. A double pyramid: valences 4 and 5, where the analysis
// gives tangents (at 3 it is inconclusive and gives none).
TEST(Midedge, LimitsAreTheVFacesLimits) {
  const PolygonMesh mesh = test::jittered(test::bipyramid(5), 21);
  LimitOptions options;
  options.normals = true;
  const LimitResult limit = limit_positions(mesh, midedge_scheme(), options);
  EXPECT_EQ(limit.approximated, 0);
  const Index v_faces = mesh.face_count();
  double previous_angle = 4.0;
  for (int levels = 1; levels <= 7; levels += 2) {
    RefineOptions o;
    o.levels = levels;
    const PolygonMesh fine = refine(mesh, midedge_scheme(), o);
    double worst = 0.0, worst_angle = 0.0;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
      const auto face = fine.face(v_faces + v);
      Vec3 centroid, newell;
      for (std::size_t i = 0; i < face.size(); ++i) {
        const Vec3 a = fine.positions[static_cast<std::size_t>(face[i])];
        const Vec3 b = fine.positions[static_cast<std::size_t>(face[(i + 1) % face.size()])];
        centroid += a;
        newell += cross(a, b);
      }
      centroid = (1.0 / static_cast<double>(face.size())) * centroid;
      const auto vi = static_cast<std::size_t>(v);
      worst = std::max(worst, norm(centroid - limit.positions[vi]));
      const Vec3 n = limit.normals[vi];
      ASSERT_GT(norm(n), 0.5) << "vertex " << v;
      worst_angle = std::max(worst_angle, std::atan2(norm(cross(n, newell)), dot(n, newell)));
    }
    EXPECT_LT(worst, 1e-14) << "level " << levels;
    EXPECT_LT(worst_angle, previous_angle) << "level " << levels;
    previous_angle = worst_angle;
  }
  EXPECT_LT(previous_angle, 0.05);
}

}  // namespace
}  // namespace subdiv
