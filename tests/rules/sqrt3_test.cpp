#include "subdiv/rules/sqrt3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "subdiv/analysis/analyze.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/interpolatory_sqrt3.h"
#include "support/bsplines.h"
#include "support/refine_options.h"
#include "support/stencil_checks.h"
#include "support/stencil_rows.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::levels;

// A planar annulus of 2n triangles between an n-gon of radius 1 and one of
// radius 2 turned by half a step: two closed boundary loops, every boundary
// vertex on 3 faces, no corners.
PolygonMesh annulus(int n) {
  PolygonMesh mesh;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n, b = a + std::numbers::pi / n;
    mesh.positions.push_back({std::cos(a), std::sin(a), 0.0});            // inner i = 2i
    mesh.positions.push_back({2.0 * std::cos(b), 2.0 * std::sin(b), 0.0});  // outer i = 2i + 1
  }
  for (int i = 0; i < n; ++i) {
    const Index in = 2 * i, out = 2 * i + 1, in_next = 2 * ((i + 1) % n), out_next = 2 * ((i + 1) % n) + 1;
    mesh.add_face({in, out, in_next});
    mesh.add_face({in_next, out, out_next});
  }
  return mesh;
}

using test::jittered;

double signed_area(const PolygonMesh& mesh, Index f) {
  const auto t = mesh.face(f);
  const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

TEST(Sqrt3, AlphaIsKobbelts) {
  EXPECT_NEAR(sqrt3_alpha(6), 1.0 / 3.0, 1e-15);  // the regular case
  EXPECT_NEAR(sqrt3_alpha(3), 5.0 / 9.0, 1e-15);  // cos(2 pi / 3) = -1/2
  EXPECT_NEAR(sqrt3_alpha(4), 4.0 / 9.0, 1e-15);
}

// One step on a closed mesh: a vertex per face added, three triangles per
// triangle, old vertices keep their valence, face points have valence 6.
TEST(Sqrt3, SplitOnClosedMeshes) {
  PolygonMesh mesh = test::tetrahedron();
  for (int l = 1; l <= 3; ++l) {
    const PolygonMesh child = refine(mesh, sqrt3_scheme(), levels(1));
    const MeshTopology t(mesh), ct(child);
    EXPECT_EQ(child.vertex_count(), mesh.vertex_count() + mesh.face_count());
    EXPECT_EQ(child.face_count(), 3 * mesh.face_count());
    EXPECT_TRUE(validate(child, ct).ok());
    const Index points = mesh.face_count();
    for (Index f = 0; f < points; ++f) EXPECT_EQ(ct.valence(f), 6) << f;  // 3 corners, 3 neighbouring face points
    for (Index v = 0; v < mesh.vertex_count(); ++v) EXPECT_EQ(ct.valence(points + v), t.valence(v)) << v;
    mesh = child;
  }
}

// Two steps split every triangle 1-to-9, aligned with it, boundary edges
// included (the trisecting second step): with the linear placement on the
// regular planar layout every child triangle has a ninth of the area and the
// parent's orientation.
TEST(Sqrt3, TwoStepsAreAOneToNineSplit) {
  const RingMesh ring = ring_mesh(SplitRule::triangle, {Configuration::Kind::interior, 6, CornerType::convex}, 3);
  const double area = signed_area(ring.mesh, 0);
  ASSERT_GT(area, 0.0);
  const PolygonMesh twice = refine(ring.mesh, layout_placement(SplitRule::sqrt3), levels(2));
  EXPECT_EQ(twice.face_count(), 9 * ring.mesh.face_count());
  const MeshTopology t(ring.mesh), t2(twice);
  EXPECT_TRUE(validate(twice, t2).ok());
  Index boundary = 0, boundary2 = 0;
  for (Index e = 0; e < t.edge_count(); ++e) boundary += t.is_boundary_edge(e);
  for (Index e = 0; e < t2.edge_count(); ++e) boundary2 += t2.is_boundary_edge(e);
  EXPECT_EQ(boundary2, 3 * boundary);
  for (Index f = 0; f < twice.face_count(); ++f) EXPECT_NEAR(signed_area(twice, f), area / 9.0, 1e-12) << f;
}

// Golden weights, read off the stencils: face point 1/3 each; vertex point
// 1 - alpha_n and alpha_n / n; boundary vertices kept on the first step and
// (4, 19, 4) / 27 on the second; boundary points (1, 16, 10) / 27.
TEST(Sqrt3, WeightsGolden) {
  const PolygonMesh mesh = annulus(8);
  const MeshTopology t(mesh);
  const std::vector<StencilTable> tables = refine_stencils(mesh, sqrt3_scheme(), levels(2));
  const Index nf = mesh.face_count();
  for (Index f = 0; f < nf; ++f) {
    const auto row = test::merged_row(tables[0], f);
    ASSERT_EQ(row.size(), 3u);
    for (const Index v : mesh.face(f)) EXPECT_NEAR(row.at(v), 1.0 / 3.0, 1e-15);
  }
  for (Index v = 0; v < mesh.vertex_count(); ++v) {  // all on the boundary: kept
    const auto row = test::merged_row(tables[0], nf + v);
    ASSERT_EQ(row.size(), 1u);
    EXPECT_EQ(row.at(v), 1.0);
  }
  // Level 1: the inner loop's vertices 2i are still on the boundary, with
  // neighbours 2i +- 2 along it.
  PolygonMesh level1;
  refine_stencils(mesh, sqrt3_scheme(), levels(1), &level1);
  const MeshTopology t1(level1);
  Index boundary_edges = 0;
  for (Index e = 0; e < t1.edge_count(); ++e) boundary_edges += t1.is_boundary_edge(e);
  const Index face_points2 = level1.face_count() - boundary_edges;  // boundary faces get none
  for (int i = 0; i < 8; ++i) {
    const Index v = nf + 2 * i, prev = nf + 2 * ((i + 7) % 8), next = nf + 2 * ((i + 1) % 8);
    const auto row = test::merged_row(tables[1], face_points2 + 2 * boundary_edges + v);
    ASSERT_EQ(row.size(), 3u);
    EXPECT_NEAR(row.at(v), 19.0 / 27.0, 1e-15);
    EXPECT_NEAR(row.at(prev), 4.0 / 27.0, 1e-15);
    EXPECT_NEAR(row.at(next), 4.0 / 27.0, 1e-15);
  }
  // Boundary points: two per boundary edge, the one near edge_vertices(e)[0] first.
  Index rank = 0;
  for (Index e = 0; e < t1.edge_count(); ++e) {
    if (!t1.is_boundary_edge(e)) continue;
    const auto [a, b] = t1.edge_vertices(e);
    for (int end = 0; end < 2; ++end) {
      const Index near = end == 0 ? a : b, far = end == 0 ? b : a;
      Index beyond = kInvalidIndex;
      for (const Index f : t1.vertex_edges(near))
        if (t1.is_boundary_edge(f) && t1.other_vertex(f, near) != far) beyond = t1.other_vertex(f, near);
      const auto row = test::merged_row(tables[1], face_points2 + 2 * rank + end);
      ASSERT_EQ(row.size(), 3u);
      EXPECT_NEAR(row.at(near), 16.0 / 27.0, 1e-15);
      EXPECT_NEAR(row.at(far), 10.0 / 27.0, 1e-15);
      EXPECT_NEAR(row.at(beyond), 1.0 / 27.0, 1e-15);
    }
    ++rank;
  }
  // An interior vertex of valence n.
  const PolygonMesh closed = test::tetrahedron();
  const StencilTable once = refine_stencil_table(closed, sqrt3_scheme(), levels(1));
  const auto row = test::merged_row(once, closed.face_count());  // vertex 0, valence 3
  EXPECT_NEAR(row.at(0), 1.0 - 5.0 / 9.0, 1e-15);
  for (Index u = 1; u < 4; ++u) EXPECT_NEAR(row.at(u), 5.0 / 27.0, 1e-15);
}

// Every row sums to one over three steps on an open and a closed mesh, and
// the fast path gives the stencils' positions; also with a semi-sharp
// corner, whose rule blends into the smooth one.
TEST(Sqrt3, StencilRowsSumToOneAndTheFastPathAgrees) {
  PolygonMesh semi_sharp = jittered(test::tetrahedron(), 6);
  CornerTag corner;
  corner.vertex = 0;
  corner.sharpness = 1.5;
  semi_sharp.tags.corners.push_back(corner);
  for (const PolygonMesh& mesh : {jittered(annulus(7), 3), jittered(test::triangle_grid(3, 2), 4),
                                  jittered(test::tetrahedron(), 5), semi_sharp})
    EXPECT_TRUE(validate(test::expect_stencils_are_the_fast_path(mesh, sqrt3_scheme(), 3, 1e-14)).ok());
}

// The boundary curve is the cubic B-spline of the boundary polygon: after
// two steps the inner loop's 3n vertices are the control points of the same
// curve at a third of the knot spacing (compared through the basis
// functions, not the mask), and the curve does not depend on the interior.
TEST(Sqrt3, BoundaryIsTheCubicBSplineOfTheBoundaryPolygon) {
  const int n = 9;
  const PolygonMesh mesh = jittered(annulus(n), 7);
  const PolygonMesh twice = refine(mesh, sqrt3_scheme(), levels(2));
  const MeshTopology t(twice);
  // The inner loop, starting at old vertex 0 and running as the old one does.
  const Index start = twice.vertex_count() - mesh.vertex_count();  // vertex point of vertex 0
  const BoundaryLoop* inner = nullptr;
  for (const BoundaryLoop& loop : t.boundary_loops())
    if (std::find(loop.vertices.begin(), loop.vertices.end(), start) != loop.vertices.end()) inner = &loop;
  ASSERT_NE(inner, nullptr);
  ASSERT_TRUE(inner->ordered);
  ASSERT_EQ(inner->vertices.size(), 3u * n);
  std::vector<Index> q(inner->vertices.begin(), inner->vertices.end());
  std::rotate(q.begin(), std::find(q.begin(), q.end(), start), q.end());
  if (q[3] != start + 2) std::reverse(q.begin() + 1, q.end());  // old vertex 1 (inner 2) three steps on
  ASSERT_EQ(q[3], start + 2);
  for (double s = 0.0; s < n; s += 0.37) {
    Vec3 coarse, fine;
    for (int j = -n; j < 2 * n; ++j) {
      const auto at = static_cast<std::size_t>(((j % n) + n) % n);
      coarse += test::cubic_bspline(s - j) * mesh.positions[2 * at];
    }
    for (int i = -3 * n; i < 6 * n; ++i) {
      const auto at = static_cast<std::size_t>(((i % (3 * n)) + 3 * n) % (3 * n));
      fine += test::cubic_bspline(3.0 * s - i) * twice.positions[static_cast<std::size_t>(q[at])];
    }
    EXPECT_NEAR(norm(coarse - fine), 0.0, 1e-13) << s;
  }
}

// Refinement commutes with affine maps.
TEST(Sqrt3, AffineInvariance) {
  test::expect_refinement_commutes_with_an_affine_map(jittered(test::tetrahedron(), 9), sqrt3_scheme(), 3, 1e-12);
}

// The analysis over two steps (period 2): the one-ring is invariant, and
// the spectrum is the closed form of the two-step matrix (derived in
// docs/schemes/sqrt3.md): 1, (2 + 2 cos(2 pi j / k)) / 9 for j = 1 .. k - 1, and
// (2/3 - alpha_k)^2, which Kobbelt's alpha makes lambda_1^2. Regular: 1/3
// (edges shrink by sqrt 3 per step). C1 at every valence.
TEST(Sqrt3, AnalysisIsC1AtEveryValence) {
  for (int k = 3; k <= 12; ++k) {
    const ConfigurationAnalysis a = analyze(sqrt3_scheme(), {Configuration::Kind::interior, k, CornerType::convex});
    ASSERT_TRUE(a.matrix.invariant) << k << ": " << a.matrix.invariance_note;
    EXPECT_EQ(a.matrix.period, 2);
    EXPECT_EQ(a.matrix.rings, 1) << k;
    std::vector<double> expected{1.0, std::pow(2.0 / 3.0 - sqrt3_alpha(k), 2)};
    for (int j = 1; j < k; ++j) expected.push_back((2.0 + 2.0 * std::cos(2.0 * std::numbers::pi * j / k)) / 9.0);
    std::vector<double> got;
    for (const auto& l : a.spectrum.expanded()) {
      EXPECT_NEAR(l.imag(), 0.0, 1e-12) << k;
      got.push_back(l.real());
    }
    // The wide matrix has more eigenvalues (zeros and the second ring's);
    // the one-ring's must be among them, the leading ones first.
    std::sort(expected.rbegin(), expected.rend());
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(a.leading[i].real(), expected[i], 1e-12) << k << " " << i;
    for (const double e : expected)
      EXPECT_TRUE(std::any_of(got.begin(), got.end(), [&](double g) { return std::fabs(g - e) < 1e-10; })) << k << " " << e;
    EXPECT_NEAR(std::pow(2.0 / 3.0 - sqrt3_alpha(k), 2), std::pow(expected[1], 2), 1e-15) << k;
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << k << ": " << a.reason;
  }
  const ConfigurationAnalysis regular = analyze(sqrt3_scheme(), {Configuration::Kind::interior, 6, CornerType::convex});
  EXPECT_NEAR(regular.leading[1].real(), 1.0 / 3.0, 1e-14);
}

// Boundary vertices with k faces: the curve's eigenvalue 1/3 and the
// interior's, which is that of an interior vertex of valence 2k; C1 for
// k = 1 .. 5. From k = 6 the interior's lambda_1 passes 1/3 and meets a
// Jordan block at 1/3: Reif's condition fails (Kobbelt's boundary rules
// keep the interior rule next to the boundary).
TEST(Sqrt3, BoundaryAnalysis) {
  for (int k = 1; k <= 7; ++k) {
    const ConfigurationAnalysis a = analyze(sqrt3_scheme(), {Configuration::Kind::boundary, k, CornerType::convex});
    ASSERT_TRUE(a.matrix.invariant) << k << ": " << a.matrix.invariance_note;
    bool has_curve = false;
    for (const auto& l : a.spectrum.expanded()) has_curve = has_curve || std::abs(l - 1.0 / 3.0) < 1e-12;
    EXPECT_TRUE(has_curve) << k;
    if (k >= 2) {
      EXPECT_NEAR(std::max(1.0 / 3.0, (2.0 + 2.0 * std::cos(std::numbers::pi / k)) / 9.0), a.leading[1].real(), 1e-12) << k;
    }
    if (k <= 5) {
      // Reif's criterion holds at the sector; the verdict stays open since the
      // regular boundary's own test does not apply to these boundary rules
      // (regular_smoothness.h: their children are not on a lattice).
      EXPECT_TRUE(a.eigenvalue_condition) << k << ": " << a.reason;
      ASSERT_TRUE(a.characteristic_map) << k;
      EXPECT_TRUE(a.characteristic_map->regular && a.characteristic_map->injective) << k << ": " << a.reason;
      EXPECT_EQ(a.verdict, SmoothnessVerdict::inconclusive) << k << ": " << a.reason;
      EXPECT_NE(a.reason.find("boundary regular rules not read"), std::string::npos) << a.reason;
    } else {
      EXPECT_NE(a.verdict, SmoothnessVerdict::c1) << k;
    }
  }
}

// Corner tags are kept (the split keeps the vertices): a corner stays
// where it is, and its new boundary neighbours sit at the thirds of its edges.
TEST(Sqrt3, CornersStayAndEndTheBoundaryCurves) {
  PolygonMesh mesh = jittered(annulus(6), 11);
  mesh.tags.corners.push_back({0, kInfiniteSharpness, CornerType::convex, std::nullopt});
  const std::vector<StencilTable> tables = refine_stencils(mesh, sqrt3_scheme(), levels(2));
  PolygonMesh twice;
  refine_stencils(mesh, sqrt3_scheme(), levels(2), &twice);
  const Index corner = twice.vertex_count() - mesh.vertex_count();
  ASSERT_EQ(twice.tags.corners.size(), 1u);
  EXPECT_EQ(twice.tags.corners[0].vertex, corner);
  EXPECT_EQ(norm(twice.positions[static_cast<std::size_t>(corner)] - mesh.positions[0]), 0.0);
  const MeshTopology t(twice);
  for (const Index e : t.vertex_edges(corner)) {
    if (!t.is_boundary_edge(e)) continue;
    const auto row = test::merged_row(tables[1], t.other_vertex(e, corner));
    ASSERT_EQ(row.size(), 2u);  // 2/3 on the corner, 1/3 on the edge's other end
    for (const auto& [v, w] : row) EXPECT_TRUE(std::fabs(w - 2.0 / 3.0) < 1e-15 || std::fabs(w - 1.0 / 3.0) < 1e-15) << w;
  }
}

// Under edge-and-corner interpolation a boundary vertex with one face is a
// corner. The sqrt3 split gives it a second face on every other step; it
// stays a corner (sqrt3_keep_one_face_corners) and so in place, for sqrt3 and
// interpolatory sqrt3 alike. Under edge-only interpolation it is a boundary
// vertex and moves along the boundary curve.
TEST(Sqrt3, OneFaceBoundaryVerticesStayCornersUnderEdgeAndCorner) {
  PolygonMesh grid = jittered(test::triangle_grid(4, 3), 3);
  const MeshTopology t(grid);
  std::vector<Index> one_face;
  for (Index v = 0; v < grid.vertex_count(); ++v)
    if (t.vertex_kind(v) == VertexKind::boundary && t.vertex_face_count(v) == 1) one_face.push_back(v);
  ASSERT_EQ(one_face.size(), 2u);  // two of the grid's four corners have one triangle
  for (const Scheme* scheme : {&sqrt3_scheme(), &interpolatory_sqrt3_scheme()}) {
    for (const BoundaryInterpolation b : {BoundaryInterpolation::edge_and_corner, BoundaryInterpolation::edge_only}) {
      RefineOptions o = levels(4);
      o.boundary = b;
      std::vector<PolygonMesh> meshes;
      o.on_level = [&](int, const PolygonMesh& m) { meshes.push_back(m); };
      const PolygonMesh fine = refine(grid, *scheme, o);
      Index offset = 0;  // vertex points come last
      for (std::size_t l = 0; l < meshes.size(); ++l) {
        offset += meshes[l].vertex_count() - (l == 0 ? grid.vertex_count() : meshes[l - 1].vertex_count());
        for (const Index v : one_face) {
          const double moved = norm(meshes[l].positions[static_cast<std::size_t>(offset + v)] - grid.positions[v]);
          if (b == BoundaryInterpolation::edge_and_corner || scheme == &interpolatory_sqrt3_scheme()) {
            EXPECT_EQ(moved, 0.0) << scheme->name << " level " << l + 1 << " vertex " << v;
          } else if (l + 1 == meshes.size()) {
            EXPECT_GT(moved, 1e-3) << scheme->name << " edge-only, vertex " << v;
          }
        }
      }
    }
  }
}

TEST(Sqrt3, RefusesWhatItHasNoRulesFor) {
  PolygonMesh mesh = test::cube();
  EXPECT_THROW(refine(mesh, sqrt3_scheme(), levels(1)), InvalidInputError);  // quads
  PolygonMesh tet = test::tetrahedron();
  tet.tags.creases.push_back({0, 1, 2.0});
  try {
    refine(tet, sqrt3_scheme(), levels(1));
    FAIL() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("sqrt3 has no crease rules"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace subdiv
