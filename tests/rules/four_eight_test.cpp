#include "subdiv/rules/four_eight.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/ring_mesh.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/refine.h"
#include "support/refine_options.h"
#include "support/stencil_checks.h"
#include "support/stencil_rows.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::levels;

// The dyadic mask of the four-direction box spline with every direction
// doubled, from its symbol 4 prod_d ((1 + z^d) / 2)^2 over d = (1,0), (0,1),
// (1,1), (1,-1) (fine-lattice units), centred: a(g) weights coarse point alpha
// in the fine point q (coarse units) with g = 2 q - 2 alpha.
std::map<std::pair<int, int>, double> box_spline_mask() {
  std::map<std::pair<int, int>, double> p{{{0, 0}, 4.0}};
  const int directions[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  for (const auto& d : directions)
    for (int twice = 0; twice < 2; ++twice) {
      std::map<std::pair<int, int>, double> next;
      for (const auto& [g, w] : p) {
        next[g] += 0.5 * w;
        next[{g.first + d[0], g.second + d[1]}] += 0.5 * w;
      }
      p = std::move(next);
    }
  std::map<std::pair<int, int>, double> centred;  // the centre is the sum of the directions, (3, 1)
  for (const auto& [g, w] : p) centred[{g.first - 3, g.second - 1}] = w;
  return centred;
}

Scheme open_four_eight() {
  Scheme s = four_eight_scheme();
  s.needs_closed_mesh = false;
  return s;
}

TEST(FourEight, SplitMakesAQuadPerEdge) {
  const PolygonMesh cube = test::cube();
  const MeshTopology t(cube);
  const PolygonMesh child = refine(cube, four_eight_scheme(), levels(1));
  EXPECT_EQ(child.vertex_count(), cube.vertex_count() + cube.face_count());
  EXPECT_EQ(child.face_count(), t.edge_count());
  const MeshTopology ct(child);
  EXPECT_TRUE(validate(child, ct).ok());
  for (Index f = 0; f < child.face_count(); ++f) EXPECT_EQ(child.face_size(f), 4);
  for (Index f = 0; f < cube.face_count(); ++f) EXPECT_EQ(ct.valence(f), 4);  // face points
  for (Index v = 0; v < cube.vertex_count(); ++v) EXPECT_EQ(ct.valence(cube.face_count() + v), t.valence(v));
  // Two steps: the quad split's topology (V + E + F vertices, 4F faces).
  const PolygonMesh twice = refine(cube, four_eight_scheme(), levels(2));
  EXPECT_EQ(twice.vertex_count(), cube.vertex_count() + t.edge_count() + cube.face_count());
  EXPECT_EQ(twice.face_count(), 4 * cube.face_count());
}

// Golden weights: face point 1/4 each; vertex point 1/2 and 1/(2k).
TEST(FourEight, WeightsGolden) {
  const PolygonMesh cube = test::cube();
  const StencilTable table = refine_stencil_table(cube, four_eight_scheme(), levels(1));
  for (Index f = 0; f < cube.face_count(); ++f) {
    const auto row = test::merged_row(table, f);
    ASSERT_EQ(row.size(), 4u);
    for (const Index v : cube.face(f)) EXPECT_EQ(row.at(v), 0.25);
  }
  const MeshTopology t(cube);
  for (Index v = 0; v < cube.vertex_count(); ++v) {
    const auto row = test::merged_row(table, cube.face_count() + v);
    ASSERT_EQ(row.size(), 4u);  // valence 3
    EXPECT_EQ(row.at(v), 0.5);
    for (const Index e : t.vertex_edges(v)) EXPECT_NEAR(row.at(t.other_vertex(e, v)), 1.0 / 6.0, 1e-15);
  }
}

// Independent route: two steps on a regular quad grid are one dyadic step of
// the doubled four-direction box spline (C4), compared with its mask
// computed from the symbol.
TEST(FourEight, TwoStepsOnARegularGridAreTheC4BoxSpline) {
  const int n = 14;
  const PolygonMesh grid = test::with_random_heights(test::quad_grid(n, n), 3);
  const PolygonMesh twice = refine(grid, open_four_eight(), levels(2));
  const auto mask = box_spline_mask();
  double sum = 0.0;
  for (const auto& [g, w] : mask) sum += w;
  EXPECT_NEAR(sum, 4.0, 1e-14);
  int checked = 0;
  for (const Vec3& q : twice.positions) {
    if (q.x < 5 || q.x > n - 5 || q.y < 5 || q.y > n - 5) continue;  // away from the grid's boundary
    const int qi = static_cast<int>(std::lround(2 * q.x)), qj = static_cast<int>(std::lround(2 * q.y));
    ASSERT_NEAR(q.x, 0.5 * qi, 1e-12);  // linear functions are reproduced
    ASSERT_NEAR(q.y, 0.5 * qj, 1e-12);
    double expected = 0.0;
    for (Index v = 0; v < grid.vertex_count(); ++v) {
      const int ai = static_cast<int>(std::lround(grid.positions[v].x)), aj = static_cast<int>(std::lround(grid.positions[v].y));
      const auto it = mask.find({qi - 2 * ai, qj - 2 * aj});
      if (it != mask.end()) expected += it->second * grid.positions[v].z;
    }
    EXPECT_NEAR(q.z, expected, 1e-13) << q.x << " " << q.y;
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

// Stencil rows sum to one, the fast path agrees with the stencils, and
// refinement commutes with affine maps.
TEST(FourEight, RowsSumToOneAndAffineInvariance) {
  const PolygonMesh mesh = test::jittered(test::cube(), 5);
  test::expect_stencils_are_the_fast_path(mesh, four_eight_scheme(), 3, 1e-14);
  test::expect_refinement_commutes_with_an_affine_map(mesh, four_eight_scheme(), 3, 1e-12);
}

// The analysis over two steps (period 2). Regular (k = 4): the matrix is the
// box spline's, entry for entry (S(a, b) = a(p_a - 2 p_b) on the layout
// points), with subdominant eigenvalue 1/2; C1 at valences 3..12.
TEST(FourEight, AnalysisRegularIsTheBoxSplineAndC1Elsewhere) {
  const ConfigurationAnalysis regular = analyze(four_eight_scheme(), {Configuration::Kind::interior, 4, CornerType::convex});
  ASSERT_TRUE(regular.matrix.invariant) << regular.matrix.invariance_note;
  const auto mask = box_spline_mask();
  const LocalSubdivisionMatrix& m = regular.wide_matrix;
  for (Eigen::Index a = 0; a < m.S.rows(); ++a)
    for (Eigen::Index b = 0; b < m.S.cols(); ++b) {
      const Vec3 pa = m.layout[static_cast<std::size_t>(a)], pb = m.layout[static_cast<std::size_t>(b)];
      const auto it = mask.find({static_cast<int>(std::lround(pa.x - 2 * pb.x)), static_cast<int>(std::lround(pa.y - 2 * pb.y))});
      EXPECT_NEAR(m.S(a, b), it == mask.end() ? 0.0 : it->second, 1e-14) << a << " " << b;
    }
  EXPECT_NEAR(regular.leading[1].real(), 0.5, 1e-12);
  EXPECT_NEAR(regular.leading[2].real(), 0.5, 1e-12);
  EXPECT_NEAR(std::abs(regular.leading[3]), 0.25, 1e-12);
  for (int k = 3; k <= 12; ++k) {
    const ConfigurationAnalysis a = analyze(four_eight_scheme(), {Configuration::Kind::interior, k, CornerType::convex});
    ASSERT_TRUE(a.matrix.invariant) << k;
    EXPECT_EQ(a.matrix.period, 2);
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << k << ": " << a.reason;
  }
}

TEST(FourEight, RefusesOpenMeshesAndSharpFeatures) {
  try {
    refine(test::quad_grid(2, 2), four_eight_scheme(), levels(1));
    FAIL() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("four-eight needs a closed mesh"), std::string::npos) << e.what();
  }
  PolygonMesh cube = test::cube();
  cube.tags.creases.push_back({0, 1, 1.0});
  EXPECT_THROW(refine(cube, four_eight_scheme(), levels(1)), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
