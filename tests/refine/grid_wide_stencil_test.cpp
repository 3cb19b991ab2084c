// The grid path with stencils wider than Catmull-Clark's (RegularGrid
// patch reach 2 and 3): Kobbelt's four-point tensor product, and the
// generalized Catmull-Clark and midpoint schemes of degree 3, 5 and 7 (the
// uniform B-spline of that degree on regular grids). Each declared rule has
// its published weights, is the masks' own regular stencil (derived from a
// refinement by the masks), and refining with grids gives the masks' mesh.

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "grid_test_support.h"
#include "refine/grid_refine.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/generalized_catmull_clark.h"
#include "subdiv/rules/kobbelt.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using namespace grid_test;

Scheme kobbelt_with_tension(double w) {
  Scheme s = kobbelt_scheme();
  tension_parameters(s.parameters)->tension = w;
  return s;
}

Scheme of_degree(const Scheme& family, int degree) {
  Scheme s = family;
  set_degree(s, degree);
  return s;
}

// The schemes whose regular rule is a wide (or, for degree 3, Catmull-
// Clark's) tensor stencil, by name for the messages.
std::vector<std::pair<std::string, Scheme>> wide_schemes() {
  return {{"kobbelt", kobbelt_scheme()},
          {"kobbelt w=0.1", kobbelt_with_tension(0.1)},
          {"gcc n=3", generalized_catmull_clark_scheme()},
          {"gcc n=5", of_degree(generalized_catmull_clark_scheme(), 5)},
          {"gcc n=7", of_degree(generalized_catmull_clark_scheme(), 7)},
          {"midpoint n=3", midpoint_scheme()},
          {"midpoint n=5", of_degree(midpoint_scheme(), 5)},
          {"midpoint n=7", of_degree(midpoint_scheme(), 7)}};
}

TEST(GridWideStencil, PublishedWeights) {
  // The four-point rule (Dyn, Levin, Gregory 1987): -w, 1/2 + w, 1/2 + w, -w.
  const RegularGrid four_point = *regular_grid_of(kobbelt_scheme());
  EXPECT_EQ(four_point.even, (std::array<double, 5>{0, 0, 1, 0, 0}));
  EXPECT_EQ(four_point.odd, (std::array<double, 4>{-1.0 / 16, 9.0 / 16, 9.0 / 16, -1.0 / 16}));
  EXPECT_EQ(four_point.patch_reach(), 2);
  // The uniform B-spline of degree n refines by binomial(n + 1, j) / 2^n:
  // even taps at odd j, odd taps at even j.
  for (const int n : {3, 5, 7}) {
    SCOPED_TRACE("degree " + std::to_string(n));
    std::vector<double> binomial{1.0};
    for (int k = 0; k < n + 1; ++k) {
      std::vector<double> next(binomial.size() + 1, 0.0);
      for (std::size_t j = 0; j < binomial.size(); ++j) next[j] += binomial[j], next[j + 1] += binomial[j];
      binomial.swap(next);
    }
    const double scale = std::ldexp(1.0, -n);
    std::array<double, 5> even{};
    std::array<double, 4> odd{};
    const int h = (n + 1) / 2;  // the centre tap
    for (int d = -2; d <= 2; ++d)
      if (std::abs(2 * d) <= h) even[static_cast<std::size_t>(d + 2)] = binomial[static_cast<std::size_t>(h - 2 * d)] * scale;
    for (int d = -1; d <= 2; ++d)
      if (std::abs(1 - 2 * d) <= h) odd[static_cast<std::size_t>(d + 1)] = binomial[static_cast<std::size_t>(h + 1 - 2 * d)] * scale;
    for (const Scheme& family : {generalized_catmull_clark_scheme(), midpoint_scheme()}) {
      const RegularGrid rule = *regular_grid_of(of_degree(family, n));
      EXPECT_EQ(rule.even, even);
      EXPECT_EQ(rule.odd, odd);
      EXPECT_EQ(rule.patch_reach(), n == 3 ? 1 : n == 5 ? 2 : 3);
    }
  }
  // Degree 5 by hand: 1 6 15 20 15 6 1 over 32.
  const RegularGrid quintic = *regular_grid_of(of_degree(midpoint_scheme(), 5));
  EXPECT_EQ(quintic.even, (std::array<double, 5>{0, 6.0 / 32, 20.0 / 32, 6.0 / 32, 0}));
  EXPECT_EQ(quintic.odd, (std::array<double, 4>{1.0 / 32, 15.0 / 32, 15.0 / 32, 1.0 / 32}));
}

TEST(GridWideStencil, DeclinedWhereNoTensorProductFits) {
  EXPECT_FALSE(regular_grid_of(of_degree(generalized_catmull_clark_scheme(), 4)));  // dual
  EXPECT_FALSE(regular_grid_of(of_degree(generalized_catmull_clark_scheme(), 9)));  // reach 4
  Scheme other = of_degree(generalized_catmull_clark_scheme(), 5);  // B not separable at valence 4
  std::get<DegreeParameters>(other.parameters).smoothing = {{.rule = SmoothingWeights::Rule::constant, .alpha = 0.3, .beta = 0.5}};
  EXPECT_FALSE(regular_grid_of(other));
  EXPECT_FALSE(regular_grid_of(catmull_clark_scheme()) == std::nullopt);
}

TEST(GridWideStencil, DeclaredRuleIsTheMasksRegularStencil) {
  // Heights on a planar grid refined one level by the masks: away from the
  // rim every new height must be the declared stencil's product over the
  // coarse heights (x and y, linear, are reproduced and place each point).
  const int n = 18;
  const PolygonMesh grid = test::with_random_heights(test::quad_grid(n, n), 11);
  auto height = [&](int i, int j) { return grid.positions[static_cast<std::size_t>(j * (n + 1) + i)].z; };
  for (const auto& [name, scheme] : wide_schemes()) {
    SCOPED_TRACE(name);
    const RegularGrid rule = *regular_grid_of(scheme);
    EXPECT_DOUBLE_EQ(std::accumulate(rule.even.begin(), rule.even.end(), 0.0), 1.0);
    EXPECT_DOUBLE_EQ(std::accumulate(rule.odd.begin(), rule.odd.end(), 0.0), 1.0);
    for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(rule.even[k], rule.even[4 - k]);  // symmetric: either frame
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(rule.odd[k], rule.odd[3 - k]);
    // The line weights on coarse point c of fine point p.
    auto weight = [&](int p, int c) {
      const int d = c - p / 2;  // p >= 0 here
      if (p % 2 == 0) return d >= -2 && d <= 2 ? rule.even[static_cast<std::size_t>(d + 2)] : 0.0;
      return d >= -1 && d <= 2 ? rule.odd[static_cast<std::size_t>(d + 1)] : 0.0;
    };
    const PolygonMesh fine = refine(grid, scheme, with_grids(false, 1));
    int checked = 0;
    for (const Vec3& p : fine.positions) {
      const double x = 2 * p.x, y = 2 * p.y;
      if (x < 10 || x > 2 * n - 10 || y < 10 || y > 2 * n - 10) continue;
      const int px = static_cast<int>(std::lround(x)), py = static_cast<int>(std::lround(y));
      ASSERT_NEAR(x, px, 1e-12);
      ASSERT_NEAR(y, py, 1e-12);
      double z = 0.0;
      for (int j = py / 2 - 3; j <= py / 2 + 3; ++j)
        for (int i = px / 2 - 3; i <= px / 2 + 3; ++i) z += weight(px, i) * weight(py, j) * height(i, j);
      ASSERT_NEAR(p.z, z, 1e-14) << "at fine point (" << px << ", " << py << ")";
      ++checked;
    }
    EXPECT_EQ(checked, (2 * n - 19) * (2 * n - 19));
  }
}

// spot's quads refined three times by Catmull-Clark: extraordinary
// vertices far apart in regular quads, for a wide stencil's patches and the
// masks' rings around them to leave most faces to the grids.
PolygonMesh spot_quads() {
  return refine(read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh, catmull_clark_scheme(), with_grids(false, 3));
}

TEST(GridWideStencil, EqualsTheMasks) {
  const PolygonMesh spot = spot_quads();
  const PolygonMesh open = test::jittered(test::quad_grid(60, 60), 4);
  for (const auto& [name, scheme] : wide_schemes()) {
    SCOPED_TRACE(name);
    for (int levels = 1; levels <= 3; ++levels) {
      const std::string what = name + ", " + std::to_string(levels) + " levels";
      expect_grids_equal_masks(torus(12), scheme, levels, "torus, " + what);
      expect_grids_equal_masks(with_channels(torus(12)), scheme, levels, "torus with vertex channels, " + what);
      expect_grids_equal_masks(with_face_varying(torus(12)), scheme, levels, "torus with face-varying values, " + what);
      expect_grids_equal_masks(test::jittered(test::cube(), 1), scheme, levels + 2, "cube, " + what);
      if (levels <= 2) {
        expect_grids_equal_masks(open, scheme, levels, "open grid, " + what);
        expect_grids_equal_masks(spot, scheme, levels, "spot, " + what);
      }
    }
    // Both routes were compared: all-grid faces, and faces by the masks
    // around extraordinary vertices and the rim (on spot from the second
    // level on, where they are rarer).
    EXPECT_TRUE(takes_grids(torus(12), scheme, 2));
    EXPECT_TRUE(takes_grids(refine(spot, scheme, with_grids(false, 1)), scheme, 1));
    EXPECT_TRUE(takes_grids(open, scheme, 2));
  }
}

TEST(GridWideStencil, KobbeltWithTags) {
  // Kobbelt's sharp edges and corners (the other wide schemes have no tags).
  const Index n = 64;
  PolygonMesh mesh = torus(n);
  for (Index i = 0; i < n; ++i) mesh.tags.creases.push_back({i, (i + 1) % n, 1.5});
  mesh.tags.creases.push_back({n * 16 + 3, n * 17 + 3, kInfiniteSharpness});
  mesh.tags.corners.push_back({.vertex = n * 40 + 9, .sharpness = 2.5, .type = CornerType::unspecified, .angle = {}});
  mesh.tags.holes = {2900, 37};
  EXPECT_TRUE(takes_grids(mesh, kobbelt_scheme(), 2));
  for (int levels = 1; levels <= 3; ++levels) {
    expect_grids_equal_masks(mesh, kobbelt_scheme(), levels, "tagged torus, " + std::to_string(levels) + " levels");
    expect_grid_stencils_equal_masks(mesh, kobbelt_scheme(), levels, "tagged torus, " + std::to_string(levels) + " levels");
  }
}

TEST(GridWideStencil, StencilTablesEqualTheMasks) {
  const PolygonMesh spot = spot_quads();
  for (const auto& [name, scheme] : wide_schemes()) {
    for (int levels = 1; levels <= 2; ++levels)
      expect_grid_stencils_equal_masks(torus(12), scheme, levels, "torus, " + name + ", " + std::to_string(levels) + " levels");
    expect_grid_stencils_equal_masks(spot, scheme, 1, "spot, " + name + ", 1 level");
  }
}

TEST(GridWideStencil, SameResultForAnyThreadCount) {
  for (const auto& [name, scheme] : wide_schemes()) {
    SCOPED_TRACE(name);
    RefineOptions one = with_grids(true, 3), two = one;
    one.threads = 1;
    two.threads = 2;
    const PolygonMesh mesh = torus(30);
    const PolygonMesh a = refine(mesh, scheme, one);
    const PolygonMesh b = refine(mesh, scheme, two);
    EXPECT_EQ(a.face_indices, b.face_indices);
    EXPECT_TRUE(a.positions == b.positions) << "positions differ between one and two threads";
  }
}

}  // namespace
}  // namespace subdiv
