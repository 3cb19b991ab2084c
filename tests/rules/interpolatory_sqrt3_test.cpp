#include "subdiv/rules/interpolatory_sqrt3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "subdiv/analysis/analyze.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/refine.h"
#include "support/refine_options.h"
#include "support/stencil_checks.h"
#include "support/stencil_rows.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::levels;

PolygonMesh closed_triangles(unsigned seed) { return test::jittered(triangulate(test::cube()), seed); }

// The extraordinary weights sum to one and are symmetric about the face's
// direction (u_i and u_{k-1-i}); k = 3 and 4 are the tabulated rules.
TEST(InterpolatorySqrt3, ExtraordinaryWeightsSumToOneAndAreSymmetric) {
  for (int k = 3; k <= 20; ++k) {
    const std::vector<double> w = interpolatory_sqrt3_weights(k);
    ASSERT_EQ(w.size(), static_cast<std::size_t>(k) + 1);
    double sum = 0.0;
    for (const double x : w) sum += x;
    EXPECT_NEAR(sum, 1.0, 1e-14) << k;
    for (int i = 0; i < k; ++i)
      EXPECT_NEAR(w[static_cast<std::size_t>(i)], w[static_cast<std::size_t>(k - 1 - i)], 1e-14) << k << " " << i;
  }
  const std::vector<double> w3 = interpolatory_sqrt3_weights(3), w4 = interpolatory_sqrt3_weights(4);
  EXPECT_EQ(w3, (std::vector<double>{4.0 / 27.0, -5.0 / 27.0, 4.0 / 27.0, 8.0 / 9.0}));
  EXPECT_EQ(w4, (std::vector<double>{2.0 / 9.0, -1.0 / 9.0, -1.0 / 9.0, 2.0 / 9.0, 7.0 / 9.0}));
  // k = 5: a = 2 cos(36 deg) / 3 = 0.539344..., centre 1 - a^2.
  EXPECT_NEAR(interpolatory_sqrt3_weights(5)[5], 1.0 - std::pow(2.0 * std::cos(std::numbers::pi / 5) / 3.0, 2), 1e-15);
}

// The 12-point rule, read off the stencils on a regular grid: 32/81 on the
// face's vertices, -1/81 three times, -2/81 six times.
TEST(InterpolatorySqrt3, RegularRuleGolden) {
  PolygonMesh grid = test::triangle_grid(6, 6);
  const Scheme& open = interpolatory_sqrt3_scheme();
  const StencilTable table = refine_stencil_table(grid, open, levels(1));
  const MeshTopology t(grid);
  int checked = 0;
  for (Index f = 0; f < grid.face_count(); ++f) {
    bool inner = true;
    for (const Index v : grid.face(f))
      inner = inner && grid.positions[v].x >= 2 && grid.positions[v].x <= 4 && grid.positions[v].y >= 2 && grid.positions[v].y <= 4;
    if (!inner) continue;
    const auto row = test::merged_row(table, f);
    ASSERT_EQ(row.size(), 12u) << f;
    int big = 0, tip = 0, outer = 0;
    for (const auto& [v, w] : row) {
      big += std::fabs(w - 32.0 / 81.0) < 1e-15;
      tip += std::fabs(w + 1.0 / 81.0) < 1e-15;
      outer += std::fabs(w + 2.0 / 81.0) < 1e-15;
    }
    EXPECT_EQ(big, 3);
    EXPECT_EQ(tip, 3);
    EXPECT_EQ(outer, 6);
    for (const Index v : grid.face(f)) EXPECT_NEAR(row.at(v), 32.0 / 81.0, 1e-15);
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

// Independent route: on a regular grid the 12-point rule reproduces cubic
// polynomials (the face point of a cubic height field is the cubic at the
// centroid), as the interpolatory Butterfly-type rules are built to.
TEST(InterpolatorySqrt3, RegularRuleReproducesCubics) {
  PolygonMesh grid = test::triangle_grid(7, 7);
  auto cubic = [](double x, double y) { return 0.3 * x * x * x - 0.2 * x * x * y + 0.1 * x * y * y + 0.05 * y * y * y - x * y + 2.0 * x - y + 1.0; };
  for (Vec3& p : grid.positions) p.z = cubic(p.x, p.y);
  const Scheme& open = interpolatory_sqrt3_scheme();
  const PolygonMesh child = refine(grid, open, levels(1));
  int checked = 0;
  for (Index f = 0; f < grid.face_count(); ++f) {
    Vec3 c;
    bool inner = true;
    for (const Index v : grid.face(f)) {
      c += (1.0 / 3.0) * grid.positions[v];
      inner = inner && grid.positions[v].x >= 2 && grid.positions[v].x <= 5 && grid.positions[v].y >= 2 && grid.positions[v].y <= 5;
    }
    if (!inner) continue;
    const Vec3 p = child.positions[static_cast<std::size_t>(f)];
    EXPECT_NEAR(p.x, c.x, 1e-13);
    EXPECT_NEAR(p.y, c.y, 1e-13);
    EXPECT_NEAR(p.z, cubic(c.x, c.y), 1e-12) << f;
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

// The scheme interpolates: every vertex keeps its position at every level;
// stencil rows sum to one; refinement commutes with affine maps.
TEST(InterpolatorySqrt3, InterpolatesAndRowsSumToOne) {
  const PolygonMesh mesh = closed_triangles(3);
  // Rows within 1e-14 of one, fast path within 1e-13 of the stencils.
  const PolygonMesh fast = test::expect_stencils_are_the_fast_path(mesh, interpolatory_sqrt3_scheme(), 3, 1e-14, 1e-13);
  const Index first_old = fast.vertex_count() - mesh.vertex_count();
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    EXPECT_EQ(norm(fast.positions[static_cast<std::size_t>(first_old + v)] - mesh.positions[v]), 0.0) << v;
  EXPECT_TRUE(validate(fast).ok());
  test::expect_refinement_commutes_with_an_affine_map(mesh, interpolatory_sqrt3_scheme(), 3, 1e-12);
}

// The analysis over two steps: the extraordinary rule's Fourier design
// gives lambda_1 = lambda_2 = a^2 = 4 cos^2(pi/k) / 9, Kobbelt's sqrt3
// value; 1/3 at k = 6 (the 12-point rule, a 3-ring neighbourhood). C1 at
// every valence 3..12.
TEST(InterpolatorySqrt3, AnalysisIsC1AtEveryValence) {
  for (int k = 3; k <= 12; ++k) {
    const ConfigurationAnalysis a =
        analyze(interpolatory_sqrt3_scheme(), {Configuration::Kind::interior, k, CornerType::convex});
    ASSERT_TRUE(a.matrix.invariant) << k << ": " << a.matrix.invariance_note;
    const double lambda = 4.0 * std::pow(std::cos(std::numbers::pi / k), 2) / 9.0;
    EXPECT_NEAR(a.leading[1].real(), lambda, 1e-12) << k;
    EXPECT_NEAR(a.leading[2].real(), lambda, 1e-12) << k;
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << k << ": " << a.reason;
    // Interpolating: the limit mask is the centre alone.
    ASSERT_TRUE(a.limit_mask.has_value()) << k;
    EXPECT_NEAR((*a.limit_mask)[0], 1.0, 1e-9) << k;
  }
}

// Boundaries. A face on the boundary takes the 12-point rule with the
// stencil's points beyond the boundary continued linearly (the apex across
// edge (p, q) of triangle (p, q, r) is p + q - r). Derived by hand for a face
// (a, b, c) with boundary edge (a, b) on a regular boundary: 1/3 on a and b,
// 37/81 on c, -1/81 on the apices across (b, c) and (c, a), -2/81 on a's and
// b's other boundary neighbours and on the two apices beyond those.
TEST(InterpolatorySqrt3, BoundaryFaceRuleGolden) {
  const int n = 6;
  const PolygonMesh grid = test::triangle_grid(n, n);
  const StencilTable table = refine_stencil_table(grid, interpolatory_sqrt3_scheme(), levels(1));
  auto at = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  Index face = kInvalidIndex;
  for (Index f = 0; f < grid.face_count(); ++f) {
    const auto v = grid.face(f);
    if (std::set<Index>(v.begin(), v.end()) == std::set<Index>{at(2, 0), at(3, 0), at(3, 1)}) face = f;
  }
  ASSERT_NE(face, kInvalidIndex);
  const auto row = test::merged_row(table, face);
  EXPECT_NEAR(row.at(at(2, 0)), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(row.at(at(3, 0)), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(row.at(at(3, 1)), 37.0 / 81.0, 1e-15);
  EXPECT_NEAR(row.at(at(1, 0)), -2.0 / 81.0, 1e-15);  // the boundary neighbours beyond
  EXPECT_NEAR(row.at(at(4, 0)), -2.0 / 81.0, 1e-15);
  int tips = 0, outer = 0;
  double sum = 0.0;
  for (const auto& [v, w] : row) {
    tips += std::fabs(w + 1.0 / 81.0) < 1e-15;
    outer += std::fabs(w + 2.0 / 81.0) < 1e-15;
    sum += w;
  }
  EXPECT_EQ(row.size(), 9u);
  EXPECT_EQ(tips, 2);
  EXPECT_EQ(outer, 4);
  EXPECT_NEAR(sum, 1.0, 1e-15);
}

// The trisecting steps refine the boundary by the ternary four-point rule
// (-5, 60, 30, -4)/81, the cubic through four boundary vertices: a boundary
// sampled from a cubic stays on it, whatever the interior does.
TEST(InterpolatorySqrt3, BoundaryCurveIsTheTernaryFourPointCurve) {
  const int n = 8;
  PolygonMesh grid = test::triangle_grid(n, n);
  auto cubic = [](double x) { return 0.02 * x * x * x - 0.3 * x * x + x; };
  std::mt19937 random(4);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  for (Vec3& p : grid.positions) p.z = p.y == 0 ? cubic(p.x) : noise(random);
  const PolygonMesh twice = refine(grid, interpolatory_sqrt3_scheme(), levels(2));  // the second step trisects
  int checked = 0;
  for (const Vec3& p : twice.positions) {
    if (std::fabs(p.y) > 1e-12 || p.x < 2 || p.x > n - 2) continue;
    EXPECT_NEAR(3.0 * p.x, std::round(3.0 * p.x), 1e-12);  // at the thirds
    EXPECT_NEAR(p.z, cubic(p.x), 1e-12) << p.x;
    ++checked;
  }
  EXPECT_EQ(checked, 3 * (n - 4) + 1);
}

// Open meshes: vertices stay, rows sum to one, the fast path agrees with
// the stencils, linear functions are reproduced (the boundary rules keep
// linear precision), and the result is a valid mesh.
TEST(InterpolatorySqrt3, OpenMeshesInterpolateAndReproduceLinearFunctions) {
  PolygonMesh grid = test::triangle_grid(5, 4);
  for (Vec3& p : grid.positions) p.z = 0.5 * p.x - 0.25 * p.y + 1.0;
  PolygonMesh last;
  const std::vector<StencilTable> tables = refine_stencils(grid, interpolatory_sqrt3_scheme(), levels(3), &last);
  test::expect_rows_sum_to_one(tables, 1e-14);
  const PolygonMesh fast = refine(grid, interpolatory_sqrt3_scheme(), levels(3));
  ASSERT_EQ(fast.positions.size(), last.positions.size());
  for (std::size_t i = 0; i < fast.positions.size(); ++i) {
    EXPECT_NEAR(norm(fast.positions[i] - last.positions[i]), 0.0, 1e-13);
    const Vec3 p = fast.positions[i];
    EXPECT_NEAR(p.z, 0.5 * p.x - 0.25 * p.y + 1.0, 1e-12) << i;
  }
  const Index first_old = fast.vertex_count() - grid.vertex_count();
  for (Index v = 0; v < grid.vertex_count(); ++v)
    EXPECT_EQ(norm(fast.positions[static_cast<std::size_t>(first_old + v)] - grid.positions[v]), 0.0) << v;
  EXPECT_TRUE(validate(fast).ok());
}

// The analysis at boundary sectors of 1..5 faces: C1 (the boundary curve's
// 1/3 over two steps, the cross direction below it).
TEST(InterpolatorySqrt3, ReifHoldsAtBoundarySectors) {
  for (int k = 1; k <= 5; ++k) {
    const ConfigurationAnalysis a = analyze(interpolatory_sqrt3_scheme(), {Configuration::Kind::boundary, k});
    ASSERT_TRUE(a.matrix.invariant) << k;
    EXPECT_NEAR(a.leading[1].real(), 1.0 / 3.0, 1e-12) << k;
    // Reif's criterion holds; the regular boundary's test does not apply to
    // these rules (see Sqrt3.BoundaryAnalysis), so the verdict stays open.
    EXPECT_TRUE(a.eigenvalue_condition) << k << ": " << a.reason;
    ASSERT_TRUE(a.characteristic_map) << k;
    EXPECT_TRUE(a.characteristic_map->regular && a.characteristic_map->injective) << k << ": " << a.reason;
    EXPECT_EQ(a.verdict, SmoothnessVerdict::inconclusive) << k << ": " << a.reason;
  }
}

}  // namespace
}  // namespace subdiv
