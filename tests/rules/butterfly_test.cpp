#include "subdiv/rules/butterfly.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <numbers>

#include "subdiv/analysis/analyze.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/refine/refine.h"
#include "support/stencil_rows.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

constexpr double kPi = std::numbers::pi;
const Scheme* const kBoth[] = {&butterfly_scheme(), &modified_butterfly_scheme()};

Configuration interior(int k) { return {Configuration::Kind::interior, k, CornerType::convex}; }

// Golden values computed by hand from ZSS96 (and the survey's Fig. 7 caption).
TEST(ModifiedButterfly, InteriorWeightsGolden) {
  EXPECT_DOUBLE_EQ(modified_butterfly_interior_weight(3, 0), 5.0 / 12);
  EXPECT_DOUBLE_EQ(modified_butterfly_interior_weight(3, 1), -1.0 / 12);
  EXPECT_DOUBLE_EQ(modified_butterfly_interior_weight(3, 2), -1.0 / 12);
  const double k4[] = {3.0 / 8, 0.0, -1.0 / 8, 0.0};
  for (int j = 0; j < 4; ++j) EXPECT_DOUBLE_EQ(modified_butterfly_interior_weight(4, j), k4[j]) << j;
  // k = 5: cos 72 = (sqrt5 - 1)/4, cos 144 = -(sqrt5 + 1)/4.
  const double c72 = (std::sqrt(5.0) - 1) / 4, c144 = -(std::sqrt(5.0) + 1) / 4;
  EXPECT_NEAR(modified_butterfly_interior_weight(5, 0), 1.75 / 5, 1e-15);
  EXPECT_NEAR(modified_butterfly_interior_weight(5, 1), (0.25 + c72 + 0.5 * c144) / 5, 1e-15);
  EXPECT_NEAR(modified_butterfly_interior_weight(5, 2), (0.25 + c144 + 0.5 * c72) / 5, 1e-15);
  // k = 6: 7/24, 1/12, -1/12, -1/24 (cos 60 = 1/2, cos 120 = -1/2, cos 180 = -1).
  const double k6[] = {7.0 / 24, 1.0 / 12, -1.0 / 12, -1.0 / 24, -1.0 / 12, 1.0 / 12};
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(modified_butterfly_interior_weight(6, j), k6[j], 1e-15) << j;
}

// The design behind s_j (ZSS96): with the centre weight 3/4, the ring's
// Fourier modes cos(2 pi m j / k) map to 1/2 (m = 1), 1/4 (m = 2) and 0 (m >= 3);
// the constant is kept (weights sum to 1). Checked independently of the
// formula, so the special k = 3 and k = 4 rules are tested too.
TEST(ModifiedButterfly, InteriorRuleFourierEigenvalues) {
  for (int k = 3; k <= 20; ++k) {
    double sum = 0.75;
    for (int j = 0; j < k; ++j) sum += modified_butterfly_interior_weight(k, j);
    EXPECT_NEAR(sum, 1.0, 1e-14) << k;
    for (int m = 1; m <= k / 2; ++m) {
      double image = 0.0;
      for (int j = 0; j < k; ++j) image += modified_butterfly_interior_weight(k, j) * std::cos(2 * kPi * m * j / k);
      const double expected = m == 1 || m == k - 1 ? 0.5 : m == 2 || m == k - 2 ? 0.25 : 0.0;
      EXPECT_NEAR(image, expected, 1e-14) << "k=" << k << " m=" << m;
    }
  }
}

TEST(ModifiedButterfly, CreaseWeightsGoldenAtThreeFaces) {
  // k = 3, i = 1, by hand: theta = 60 degrees.
  EXPECT_NEAR(modified_butterfly_crease_centre_weight(3, 1), 0.5, 1e-15);
  const double row[] = {1.0 / 16, 3.0 / 8, 1.0 / 8, -1.0 / 16};
  for (int j = 0; j <= 3; ++j) EXPECT_NEAR(modified_butterfly_crease_weight(3, 1, j), row[j], 1e-15) << j;
}

// The crease rule's design, checked without its formula: on a sector with k
// faces (theta = pi/k, centre 0) the ring functions sin(j theta) and
// cos(j theta) (across and along the crease) map to half themselves, and
// sin(2 j theta) to a quarter; rows sum to 1; the rule is symmetric under
// the sector's reflection i -> k - i, j -> k - j.
TEST(ModifiedButterfly, CreaseRuleEigenvectors) {
  for (int k = 2; k <= 12; ++k) {
    const double theta = kPi / k;
    for (int i = 1; i < k; ++i) {
      double sum = modified_butterfly_crease_centre_weight(k, i);
      double s1 = 0, c1 = 0, s2 = 0;
      for (int j = 0; j <= k; ++j) {
        const double w = modified_butterfly_crease_weight(k, i, j);
        sum += w;
        s1 += w * std::sin(j * theta);
        c1 += w * std::cos(j * theta);
        s2 += w * std::sin(2 * j * theta);
        EXPECT_NEAR(w, modified_butterfly_crease_weight(k, k - i, k - j), 1e-14);
      }
      EXPECT_NEAR(sum, 1.0, 1e-14) << "k=" << k << " i=" << i;
      EXPECT_NEAR(s1, 0.5 * std::sin(i * theta), 1e-14) << "k=" << k << " i=" << i;
      EXPECT_NEAR(c1, 0.5 * std::cos(i * theta), 1e-14) << "k=" << k << " i=" << i;
      if (k > 2) {
        EXPECT_NEAR(s2, 0.25 * std::sin(2 * i * theta), 1e-14) << "k=" << k << " i=" << i;
      }
    }
  }
}

PolygonMesh icosahedron() {
  const double p = (1 + std::sqrt(5.0)) / 2;
  return make_mesh({{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                    {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}},
                   {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                    {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}});
}

std::vector<PolygonMesh> sample_meshes() {
  PolygonMesh grid = test::triangle_grid(5, 4);
  for (auto& p : grid.positions) p[2] = std::sin(p[0]) * std::cos(p[1]);
  return {test::tetrahedron(), icosahedron(), grid,
          ring_mesh(SplitRule::triangle, interior(3), 3).mesh,
          ring_mesh(SplitRule::triangle, interior(9), 3).mesh,
          ring_mesh(SplitRule::triangle, {Configuration::Kind::boundary, 5, CornerType::convex}, 3).mesh};
}

TEST(Butterfly, InterpolatesAndRowsSumToOne) {
  for (const Scheme* scheme : kBoth) {
    int mesh_index = 0;
    for (const PolygonMesh& mesh : sample_meshes()) {
      SCOPED_TRACE(std::string(scheme->name) + " mesh " + std::to_string(mesh_index++));
      const MeshTopology t(mesh);
      const PolygonMesh child = refine(mesh, *scheme);
      for (Index v = 0; v < mesh.vertex_count(); ++v)
        EXPECT_EQ(child.positions[static_cast<std::size_t>(t.edge_count() + v)], mesh.positions[static_cast<std::size_t>(v)]);
      const StencilTable table = refine_stencils(mesh, *scheme).at(0);
      for (Index r = 0; r < table.row_count(); ++r) {
        double sum = 0;
        for (const auto& [v, w] : test::merged_row(table, r)) sum += w;
        EXPECT_NEAR(sum, 1.0, 1e-13) << "row " << r;
      }
    }
  }
}

double weight(const std::map<Index, double>& row, Index v) {
  const auto it = row.find(v);
  return it == row.end() ? 0.0 : it->second;
}

// Around an interior vertex of valence k (k != 6) with regular neighbours,
// the modified rule of edge p is 3/4 on the centre and s_j on ring vertex
// p + j; every rule is the first one turned. The original rule is turned the
// same way.
TEST(Butterfly, RulesTurnWithTheRing) {
  for (const Scheme* scheme : kBoth) {
    for (int k = 3; k <= 10; ++k) {
      SCOPED_TRACE(std::string(scheme->name) + " k=" + std::to_string(k));
      const RingMesh ring = ring_mesh(SplitRule::triangle, interior(k), 3);
      const MeshTopology t(ring.mesh);
      const auto edges = t.vertex_edges(ring.centre);
      ASSERT_EQ(static_cast<int>(edges.size()), k);
      const StencilTable table = refine_stencils(ring.mesh, *scheme).at(0);
      auto neighbour = [&](int j) { return t.other_vertex(edges[static_cast<std::size_t>(j % k)], ring.centre); };
      const auto first = test::merged_row(table, edges[0]);
      const bool extraordinary_rule = scheme == &modified_butterfly_scheme() && k != 6;
      for (int p = 0; p < k; ++p) {
        const auto row = test::merged_row(table, edges[static_cast<std::size_t>(p)]);
        EXPECT_EQ(row.size(), first.size());
        EXPECT_NEAR(weight(row, ring.centre), weight(first, ring.centre), 1e-15);
        for (int j = 0; j < k; ++j) {
          EXPECT_NEAR(weight(row, neighbour(p + j)), weight(first, neighbour(j)), 1e-15);
          if (extraordinary_rule) {
            EXPECT_NEAR(weight(row, neighbour(p + j)), modified_butterfly_interior_weight(k, j), 1e-15);
          }
        }
        if (extraordinary_rule) {
          EXPECT_NEAR(weight(row, ring.centre), 0.75, 1e-15);
          EXPECT_EQ(row.size(), static_cast<std::size_t>(k + 1));
        }
      }
    }
  }
}

// The 8-point rule on a regular mesh, written out: 1/2 on the edge's ends,
// 1/8 on the two opposite vertices, -1/16 on the four wings.
TEST(Butterfly, RegularRuleGolden) {
  const PolygonMesh grid = test::triangle_grid(6, 6);
  const MeshTopology t(grid);
  for (const Scheme* scheme : kBoth) {
    const StencilTable table = refine_stencils(grid, *scheme).at(0);
    int checked = 0;
    for (Index e = 0; e < t.edge_count(); ++e) {
      const auto [a, b] = t.edge_vertices(e);
      if (t.vertex_kind(a) != VertexKind::interior || t.vertex_kind(b) != VertexKind::interior) continue;
      ++checked;
      std::map<double, int> counts;
      for (const auto& [v, w] : test::merged_row(table, e)) ++counts[w];
      EXPECT_EQ(counts, (std::map<double, int>{{0.5, 2}, {0.125, 2}, {-0.0625, 4}})) << scheme->name << " edge " << e;
    }
    EXPECT_GT(checked, 30);
  }
}

using Poly = std::function<double(double, double)>;

// Largest |z - p(x, y)| over the edge points of edges whose ends are both
// interior (there both schemes use the regular 8-point rule), after one step
// on a regular grid carrying z = p(x, y).
double regular_error(const Scheme& scheme, const Poly& p) {
  PolygonMesh grid = test::triangle_grid(8, 8);
  for (auto& q : grid.positions) q[2] = p(q[0], q[1]);
  const MeshTopology t(grid);
  const PolygonMesh child = refine(grid, scheme);
  double error = 0;
  for (Index e = 0; e < t.edge_count(); ++e) {
    const auto [a, b] = t.edge_vertices(e);
    if (t.vertex_kind(a) != VertexKind::interior || t.vertex_kind(b) != VertexKind::interior) continue;
    const Vec3& q = child.positions[static_cast<std::size_t>(e)];
    error = std::max(error, std::fabs(q[2] - p(q[0], q[1])));
  }
  return error;
}

// Dyn, Levin and Gregory: with w = 1/16 the scheme reproduces cubic
// polynomials on a regular mesh; not quartics.
TEST(Butterfly, RegularRuleReproducesCubics) {
  const Poly cubics[] = {[](double x, double y) { return x * x * x - 2 * x * y * y + 0.5 * y - 3; },
                         [](double x, double y) { return y * y * y + x * x * y - x * y + 2 * x; },
                         [](double x, double y) { return x * x + y * y; }};
  const Poly quartic = [](double x, double y) { return x * x * y * y; };
  for (const Scheme* scheme : kBoth) {
    for (const Poly& p : cubics) EXPECT_LT(regular_error(*scheme, p), 1e-11) << scheme->name;
    EXPECT_GT(regular_error(*scheme, quartic), 1e-3) << scheme->name;
  }
}

// The tension is a parameter of `butterfly` (Dyn, Levin and Gregory's w):
// the regular rule puts 2w on the opposite vertices and -w on the wings;
// any w keeps linear functions (the weights still sum to 1), but only
// w = 1/16 reproduces the cubics, and w = 0 is the linear scheme.
TEST(Butterfly, TensionIsAParameter) {
  const PolygonMesh grid = test::triangle_grid(6, 6);
  const MeshTopology t(grid);
  for (const double w : {0.0, 0.03, 0.1}) {
    Scheme scheme = butterfly_scheme();
    std::get<TensionParameters>(scheme.parameters).tension = w;
    const StencilTable table = refine_stencils(grid, scheme).at(0);
    for (Index e = 0; e < t.edge_count(); ++e) {
      const auto [a, b] = t.edge_vertices(e);
      if (t.vertex_kind(a) != VertexKind::interior || t.vertex_kind(b) != VertexKind::interior) continue;
      std::map<double, int> counts;
      for (const auto& [v, weight] : test::merged_row(table, e)) ++counts[weight];
      const std::map<double, int> expected =
          w == 0.0 ? std::map<double, int>{{0.5, 2}, {0.0, 6}} : std::map<double, int>{{0.5, 2}, {2 * w, 2}, {-w, 4}};
      EXPECT_EQ(counts, expected) << "w = " << w << ", edge " << e;
    }
    EXPECT_LT(regular_error(scheme, [](double x, double y) { return 2 * x - y + 1; }), 1e-12) << w;
    EXPECT_GT(regular_error(scheme, [](double x, double y) { return x * x * x - 2 * x * y * y; }), 1e-4) << w;
  }
  EXPECT_TRUE(takes_tension(butterfly_scheme()));
  EXPECT_FALSE(takes_tension(modified_butterfly_scheme()));
}

// The four-point rule along a straight boundary reproduces cubics: edge
// points of the boundary row y = 0 whose four-point stencil stays on the row.
TEST(Butterfly, BoundaryFourPointReproducesCubics) {
  const int n = 8;
  const auto f = [](double x) { return 0.5 * x * x * x - x * x + 2 * x - 1; };
  PolygonMesh grid = test::triangle_grid(n, 3);
  for (auto& q : grid.positions) q[2] = f(q[0]) + q[1] * q[1] * q[1] * q[0];  // y^3 x is 0 on the row
  const MeshTopology t(grid);
  for (const Scheme* scheme : kBoth) {
    const PolygonMesh child = refine(grid, *scheme);
    int checked = 0;
    for (Index e = 0; e < t.edge_count(); ++e) {
      const auto [a, b] = t.edge_vertices(e);
      const Vec3 &pa = grid.positions[static_cast<std::size_t>(a)], &pb = grid.positions[static_cast<std::size_t>(b)];
      if (pa[1] != 0 || pb[1] != 0 || std::min(pa[0], pb[0]) < 1 || std::max(pa[0], pb[0]) > n - 1) continue;
      ++checked;
      const Vec3& q = child.positions[static_cast<std::size_t>(e)];
      EXPECT_NEAR(q[2], f(q[0]), 1e-12) << scheme->name << " edge " << e;
    }
    EXPECT_EQ(checked, n - 2);
  }
}

// A semi-sharp crease of sharpness 1/2 blends the smooth and the crease
// rule half and half (the engine's blend); the smooth half must be the rule
// of the uncreased mesh even where the crease runs on through the edge's
// ends (the smooth rule is evaluated while the edge itself is sharp).
TEST(Butterfly, SemiSharpCreaseBlendsTheTwoRules) {
  PolygonMesh grid = test::triangle_grid(8, 8);
  for (auto& q : grid.positions) q[2] = std::sin(0.7 * q[0] * q[1]);
  const MeshTopology t(grid);
  auto id = [](int i, int j) { return static_cast<Index>(j * 9 + i); };
  auto with_crease = [&](double sharpness) {
    PolygonMesh m = grid;
    for (int i = 1; i < 7; ++i) m.tags.creases.push_back({id(i, 4), id(i + 1, 4), sharpness});
    return m;
  };
  const Index e = t.find_edge(id(4, 4), id(5, 4));
  for (const Scheme* scheme : kBoth) {
    const Vec3 smooth = refine(grid, *scheme).positions[static_cast<std::size_t>(e)];
    const Vec3 crease = refine(with_crease(1.0), *scheme).positions[static_cast<std::size_t>(e)];
    const Vec3 half = refine(with_crease(0.5), *scheme).positions[static_cast<std::size_t>(e)];
    EXPECT_GT(std::fabs(smooth[2] - crease[2]), 1e-3) << scheme->name;  // the two rules differ here
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(half[c], 0.5 * (smooth[c] + crease[c]), 1e-14) << scheme->name;
  }
}

// The analysis of the rules as implemented (`subdiv analyze`). The survey
// (section 4, after Zorin's thesis) says the original scheme is not C1 at
// valence 3 and above 7: at k = 3 the subdominant eigenvalue 1/4 is triple
// (Reif's condition fails), and for k >= 8 the characteristic map overlaps
// itself.
TEST(ButterflyAnalysis, OriginalFailsAtThreeAndAboveSeven) {
  for (int k = 3; k <= 10; ++k) {
    const ConfigurationAnalysis a = analyze(butterfly_scheme(), interior(k));
    SCOPED_TRACE("k=" + std::to_string(k) + ": " + a.reason);
    if (k == 3) {
      EXPECT_FALSE(a.eigenvalue_condition);
      ASSERT_EQ(a.leading.size(), 4u);
      for (int i = 1; i < 4; ++i) EXPECT_NEAR(std::abs(a.leading[static_cast<std::size_t>(i)]), 0.25, 1e-10);
    } else if (k <= 7) {
      EXPECT_EQ(a.verdict, SmoothnessVerdict::c1);
    } else {
      EXPECT_TRUE(a.eigenvalue_condition);
      ASSERT_TRUE(a.characteristic_map.has_value());
      EXPECT_FALSE(a.characteristic_map->injective);
    }
    if (k == 3 || k > 7) {
      EXPECT_NE(a.verdict, SmoothnessVerdict::c1);
    }
  }
}

// The modified scheme: 1, 1/2, 1/2, 1/4 at every valence (the design of s_j,
// see InteriorRuleFourierEigenvalues), and C1; on a boundary, C1 for sectors
// of 2 to 8 faces, while a single-face sector has a simple 1/2 above a
// Jordan block at 1/4, where Reif's condition does not apply.
TEST(ButterflyAnalysis, ModifiedIsC1) {
  for (int k = 3; k <= 16; ++k) {
    const ConfigurationAnalysis a = analyze(modified_butterfly_scheme(), interior(k));
    SCOPED_TRACE("k=" + std::to_string(k) + ": " + a.reason);
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1);
    ASSERT_EQ(a.leading.size(), 4u);
    const double expected[] = {1.0, 0.5, 0.5, 0.25};
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(std::abs(a.leading[i]), expected[i], 1e-10);
  }
  for (int k = 1; k <= 8; ++k) {
    const ConfigurationAnalysis a =
        analyze(modified_butterfly_scheme(), {Configuration::Kind::boundary, k, CornerType::convex});
    SCOPED_TRACE("boundary k=" + std::to_string(k) + ": " + a.reason);
    if (k == 1) {
      EXPECT_FALSE(a.eigenvalue_condition);
    } else {
      EXPECT_EQ(a.verdict, SmoothnessVerdict::c1);
    }
  }
}

}  // namespace
}  // namespace subdiv
