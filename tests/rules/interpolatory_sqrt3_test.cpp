#include "subdiv/rules/interpolatory_sqrt3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "subdiv/analysis/analyze.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/refine.h"
#include "support/refine_options.h"
#include "support/stencil_rows.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::levels;

PolygonMesh closed_triangles(unsigned seed) {
  PolygonMesh mesh = triangulate(test::cube());
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  for (Vec3& p : mesh.positions) p += Vec3{jitter(random), jitter(random), jitter(random)};
  return mesh;
}

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
  Scheme open = interpolatory_sqrt3_scheme();
  open.needs_closed_mesh = false;
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
  Scheme open = interpolatory_sqrt3_scheme();
  open.needs_closed_mesh = false;
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
// stencil rows sum to one.
TEST(InterpolatorySqrt3, InterpolatesAndRowsSumToOne) {
  const PolygonMesh mesh = closed_triangles(3);
  PolygonMesh last;
  const std::vector<StencilTable> tables = refine_stencils(mesh, interpolatory_sqrt3_scheme(), levels(3), &last);
  for (const StencilTable& table : tables)
    for (Index r = 0; r < table.row_count(); ++r) {
      double sum = 0.0;
      for (const auto& [v, w] : test::merged_row(table, r)) sum += w;
      EXPECT_NEAR(sum, 1.0, 1e-14) << r;
    }
  const PolygonMesh fast = refine(mesh, interpolatory_sqrt3_scheme(), levels(3));
  ASSERT_EQ(fast.positions.size(), last.positions.size());
  const Index first_old = fast.vertex_count() - mesh.vertex_count();
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    EXPECT_EQ(norm(fast.positions[static_cast<std::size_t>(first_old + v)] - mesh.positions[v]), 0.0) << v;
  for (std::size_t i = 0; i < fast.positions.size(); ++i) EXPECT_NEAR(norm(fast.positions[i] - last.positions[i]), 0.0, 1e-13);
  EXPECT_TRUE(validate(fast).ok());
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

TEST(InterpolatorySqrt3, RefusesOpenMeshes) {
  try {
    refine(test::triangle_grid(2, 2), interpolatory_sqrt3_scheme(), levels(1));
    FAIL() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("interpolatory-sqrt3 needs a closed mesh"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace subdiv
