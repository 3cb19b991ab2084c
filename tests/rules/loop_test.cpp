#include "subdiv/rules/loop.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"
#include "support/stencil_rows.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

TEST(Loop, BetaValues) {
  EXPECT_DOUBLE_EQ(loop_beta(6), 1.0 / 16);  // regular: 5/8 - (3/8 + 1/8)^2 = 3/8, / 6
  EXPECT_DOUBLE_EQ(loop_beta(3), 3.0 / 16);  // Loop's formula at k = 3
  EXPECT_DOUBLE_EQ(loop_warren_beta(3), 3.0 / 16);
  EXPECT_DOUBLE_EQ(loop_warren_beta(6), 1.0 / 16);
  EXPECT_DOUBLE_EQ(loop_warren_beta(5), 3.0 / 40);
}

// The vertex-and-one-ring subdivision matrix read off the real stencils of a
// closed mesh whose vertex 0 has valence k and whose ring closes (tetrahedron
// k = 3, octahedron k = 4, icosahedron k = 5).
std::vector<double> ring_spectrum(const PolygonMesh& mesh, const Scheme& scheme) {
  const MeshTopology t(mesh);
  std::vector<Index> basis{0};
  for (const Index e : t.vertex_edges(0)) basis.push_back(t.other_vertex(e, 0));
  const StencilTable table = refine_stencils(mesh, scheme).at(0);
  const Index n = static_cast<Index>(basis.size());
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(n, n);
  for (Index r = 0; r < n; ++r) {
    const Index child = r == 0 ? t.edge_count() + 0 : t.find_edge(0, basis[static_cast<std::size_t>(r)]);
    for (const auto& [v, w] : test::merged_row(table, child)) {
      const auto it = std::find(basis.begin(), basis.end(), v);
      EXPECT_NE(it, basis.end()) << "the one-ring is not invariant";
      s(r, it - basis.begin()) = w;
    }
  }
  const Eigen::VectorXcd ev = s.eigenvalues();
  std::vector<double> out;
  for (Index i = 0; i < n; ++i) {
    EXPECT_NEAR(ev[i].imag(), 0.0, 1e-12);
    out.push_back(ev[i].real());
  }
  std::sort(out.rbegin(), out.rend());
  return out;
}

PolygonMesh octahedron() {
  return make_mesh({{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
                   {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}, {5, 2, 1}, {5, 3, 2}, {5, 4, 3}, {5, 1, 4}});
}

// Eigenvalues 1, 3/8 + 1/4 cos(2 pi j/k) (j = 1..k-1) and 5/8 - k beta: the
// subdominant pair must be 3/8 + 1/4 cos(2 pi / k). With beta(3) = 3/16 it
// is (1/4 > 1/16); the survey's 1/16 would give 5/8 - 3/16 = 7/16 > 1/4.
TEST(Loop, RingSpectrumFromTheRealRules) {
  for (const Scheme* scheme : {&loop_scheme(), &loop_warren_scheme()}) {
    for (const auto& [mesh, k] : {std::pair{test::tetrahedron(), 3}, std::pair{octahedron(), 4}}) {
      const auto ev = ring_spectrum(mesh, *scheme);
      const double beta = scheme == &loop_scheme() ? loop_beta(k) : loop_warren_beta(k);
      std::vector<double> expected{1.0, 0.625 - k * beta};
      for (int j = 1; j < k; ++j) expected.push_back(0.375 + 0.25 * std::cos(2 * std::numbers::pi * j / k));
      std::sort(expected.rbegin(), expected.rend());
      ASSERT_EQ(ev.size(), expected.size());
      for (std::size_t i = 0; i < ev.size(); ++i) EXPECT_NEAR(ev[i], expected[i], 1e-12) << scheme->name << " k=" << k;
      // Subdominant: the rotational pair, strictly above 5/8 - k beta.
      EXPECT_NEAR(ev[1], 0.375 + 0.25 * std::cos(2 * std::numbers::pi / k), 1e-12);
      EXPECT_GT(ev[1], 0.625 - k * beta + 1e-3);
    }
  }
  EXPECT_GT(0.625 - 3 * (1.0 / 16), 0.375 + 0.25 * std::cos(2 * std::numbers::pi / 3));  // why 1/16 is wrong
}

TEST(Loop, GoldenWeights) {
  const PolygonMesh grid = test::triangle_grid(4, 4);
  const MeshTopology t(grid);
  const StencilTable table = refine_stencils(grid, loop_scheme()).at(0);
  const Index centre = 12;  // (2, 2): valence 6
  ASSERT_EQ(t.valence(centre), 6);
  const auto v = test::merged_row(table, t.edge_count() + centre);
  EXPECT_DOUBLE_EQ(v.at(centre), 5.0 / 8);
  for (const Index e : t.vertex_edges(centre)) EXPECT_DOUBLE_EQ(v.at(t.other_vertex(e, centre)), 1.0 / 16);
  const auto e = test::merged_row(table, t.find_edge(12, 13));
  EXPECT_DOUBLE_EQ(e.at(12), 3.0 / 8);
  EXPECT_DOUBLE_EQ(e.at(13), 3.0 / 8);
  EXPECT_EQ(e.size(), 4u);
  const auto boundary = test::merged_row(table, t.edge_count() + 2);
  EXPECT_EQ(boundary, (std::map<Index, double>{{1, 0.125}, {2, 0.75}, {3, 0.125}}));
}

// The three-direction box spline with the directions (1, 0), (0, 1) and
// (1, 1) (the diagonal test::triangle_grid splits along) taken count[d]
// times each, by the recurrence of C. de Boor, K. Hollig, S. Riemenschneider,
// "Box Splines", Springer 1993, ch. I: for x = sum t_xi xi over the n vectors,
//   (n - 2) M(x) = sum_xi t_xi M_{Xi\xi}(x) + (1 - t_xi) M_{Xi\xi}(x - xi),
// where M_{Xi\xi} = 0 if Xi\xi does not span the plane. Every box is the limit
// from the direction (2, 1), which is on no break line, so the half-open base
// cases agree with each other on the break lines, where the dyadic points are.
double box_spline(std::array<int, 3> count, double x, double y) {
  static constexpr double dx[3] = {1, 0, 1}, dy[3] = {0, 1, 1};
  int p = -1, q = -1;  // two directions present: the basis of t
  for (int d = 2; d >= 0; --d)
    if (count[d] > 0) q = std::exchange(p, d);
  if (q < 0) return 0.0;
  const double det = dx[p] * dy[q] - dy[p] * dx[q];  // +-1: a and b are exact
  const double a = (x * dy[q] - y * dx[q]) / det, b = (dx[p] * y - dy[p] * x) / det;
  const int n = count[0] + count[1] + count[2];
  if (n == 2) {  // the unit square in (a, b), entered along (2, 1)
    const double za = (2 * dy[q] - dx[q]) / det, zb = (dx[p] - 2 * dy[p]) / det;
    auto in = [](double s, double z) { return (s > 0 || (s == 0 && z > 0)) && (s < 1 || (s == 1 && z < 0)); };
    return in(a, za) && in(b, zb) ? 1.0 : 0.0;
  }
  double sum = 0;
  for (int d = 0; d < 3; ++d) {
    if (count[d] == 0) continue;
    const double t = d == p ? a : d == q ? b : 0.0;  // summed over the copies of d
    std::array<int, 3> rest = count;
    --rest[d];
    sum += t * box_spline(rest, x, y) + (count[d] - t) * box_spline(rest, x - dx[d], y - dy[d]);
  }
  return sum / (n - 2);
}

// On a regular mesh Loop's scheme is the quartic box spline of the grid's
// three directions (Loop 1987). After two steps the limit of every vertex far
// from the boundary (3/(8 beta) = 6 on the vertex and 1 on each of its six
// neighbours, over their sum: 1/2 and 1/12, beta = 1/16) must be the spline
// evaluated at the vertex's lattice point.
TEST(Loop, RegularGridReproducesTheQuarticBoxSpline) {
  auto m = [](double x, double y) { return box_spline({2, 2, 2}, x + 2, y + 2); };  // centred on 0
  // The evaluator: its lattice values are the limit mask, its integer shifts
  // sum to one, it is symmetric.
  EXPECT_DOUBLE_EQ(m(0, 0), 0.5);
  for (const auto& [i, j] : {std::pair{1, 0}, {0, 1}, {1, 1}, {-1, 0}, {0, -1}, {-1, -1}})
    EXPECT_DOUBLE_EQ(m(i, j), 1.0 / 12);
  EXPECT_EQ(m(1, -1), 0.0);
  for (const auto& [x, y] : {std::pair{0.3, 0.7}, {0.25, 0.5}, {0.0, 0.75}, {-0.5, 0.125}}) {
    double sum = 0;
    for (int j = -3; j <= 3; ++j)
      for (int i = -3; i <= 3; ++i) sum += m(x - i, y - j);
    EXPECT_NEAR(sum, 1.0, 1e-14);
    EXPECT_NEAR(m(x, y), m(-x, -y), 1e-15);
    EXPECT_NEAR(m(x, y), m(y, x), 1e-15);
  }

  const int n = 12;
  const PolygonMesh grid = test::with_random_heights(test::triangle_grid(n, n), 5);
  auto spline = [&](double x, double y) {
    double z = 0;
    for (const Vec3& c : grid.positions)
      if (std::fabs(x - c.x) < 3 && std::fabs(y - c.y) < 3) z += c.z * m(x - c.x, y - c.y);
    return z;
  };
  RefineOptions o;
  o.levels = 2;
  const PolygonMesh fine = refine(grid, loop_scheme(), o);
  const MeshTopology t(fine);
  int checked = 0;
  for (Index v = 0; v < fine.vertex_count(); ++v) {
    const Vec3 p = fine.positions[v];
    if (p.x < 2.9 || p.x > n - 2.9 || p.y < 2.9 || p.y > n - 2.9) continue;  // 3 from the boundary
    const double x = std::round(4 * p.x) / 4, y = std::round(4 * p.y) / 4;   // linear data stays on the lattice
    EXPECT_NEAR(p.x, x, 1e-13);
    EXPECT_NEAR(p.y, y, 1e-13);
    ASSERT_EQ(t.valence(v), 6);
    double limit = 6 * p.z;
    for (const Index e : t.vertex_edges(v)) limit += fine.positions[t.other_vertex(e, v)].z;
    EXPECT_NEAR(limit / 12, spline(x, y), 1e-12) << "at " << x << ", " << y;
    ++checked;
  }
  EXPECT_EQ(checked, 25 * 25);  // 3 .. 9 in steps of 1/4
}

}  // namespace
}  // namespace subdiv
