#include "subdiv/rules/loop.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

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

}  // namespace
}  // namespace subdiv
