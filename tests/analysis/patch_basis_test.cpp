// The regular patches' basis functions (src/analysis/patch_basis.h):
// invariants (partition of unity, linear precision), derivatives against
// finite differences, and agreement with the schemes' own refinement and
// limit masks at the refined vertices inside the patch.
#include "analysis/patch_basis.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "subdiv/analysis/limit.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

constexpr std::array<std::array<double, 2>, 6> kParameters = {
    {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.25, 0.5}, {0.1, 0.7}, {1.0 / 3.0, 1.0 / 3.0}}};

/// Lattice point of bicubic control point k (i + 4 j is grid point (i - 1, j - 1)).
std::array<double, 2> grid_point(std::size_t k) {
  return {static_cast<double>(k % 4) - 1.0, static_cast<double>(k / 4) - 1.0};
}

std::array<double, 2> lattice_point(std::size_t k) {
  return {static_cast<double>(kBoxSplineLattice[k][0]), static_cast<double>(kBoxSplineLattice[k][1])};
}

/// Sums of every weight family, and of each family times the points.
template <int N, typename Point>
void expect_partition_and_linear_precision(const PatchWeights<N>& w, Point point, double u, double v) {
  const std::array<const std::array<double, N>*, 6> families = {&w.value, &w.du, &w.dv, &w.duu, &w.duv, &w.dvv};
  // The weighted points of each family: (u, v) for the values, (1, 0) and
  // (0, 1) for the first derivatives, 0 for the second.
  const std::array<std::array<double, 3>, 6> expected = {
      {{1.0, u, v}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}};
  for (std::size_t f = 0; f < families.size(); ++f) {
    double sum = 0.0, x = 0.0, y = 0.0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(N); ++k) {
      const double weight = (*families[f])[k];
      sum += weight;
      x += weight * point(k)[0];
      y += weight * point(k)[1];
    }
    EXPECT_NEAR(sum, expected[f][0], 1e-14) << "family " << f << " at (" << u << ", " << v << ")";
    EXPECT_NEAR(x, expected[f][1], 1e-14) << "family " << f << " at (" << u << ", " << v << ")";
    EXPECT_NEAR(y, expected[f][2], 1e-14) << "family " << f << " at (" << u << ", " << v << ")";
  }
}

TEST(PatchBasis, PartitionOfUnityAndLinearPrecision) {
  for (const auto& [u, v] : kParameters) {
    expect_partition_and_linear_precision(bicubic_bspline_weights(u, v), grid_point, u, v);
    expect_partition_and_linear_precision(box_spline_weights(u, v), lattice_point, u, v);
  }
}

TEST(PatchBasis, CornersCarryTheRegularLimitMasks) {
  // Catmull-Clark's regular vertex limit: 4/9 on the vertex, 1/9 on each
  // edge neighbour, 1/36 on each diagonal one (the B-spline at a knot).
  const PatchWeights<16> b = bicubic_bspline_weights(0.0, 0.0);
  for (std::size_t k = 0; k < 16; ++k) {
    const auto [x, y] = grid_point(k);
    const double distance = std::abs(x) + std::abs(y);
    const double expected = (x > 1.0 || y > 1.0) ? 0.0 : distance == 0 ? 4.0 / 9.0 : distance == 1 ? 1.0 / 9.0 : 1.0 / 36.0;
    EXPECT_NEAR(b.value[k], expected, 1e-15) << "point " << k;
  }
  // Loop's regular vertex limit: 1/2 on the vertex, 1/12 on each of its six
  // neighbours, at each corner of the triangle.
  const std::array<std::array<double, 2>, 3> corners = {{{0, 0}, {1, 0}, {0, 1}}};
  for (const auto& corner : corners) {
    const PatchWeights<12> w = box_spline_weights(corner[0], corner[1]);
    for (std::size_t k = 0; k < 12; ++k) {
      const int dx = kBoxSplineLattice[k][0] - static_cast<int>(corner[0]);
      const int dy = kBoxSplineLattice[k][1] - static_cast<int>(corner[1]);
      // The six lattice neighbours: (+-1, 0), (0, +-1), (1, -1), (-1, 1).
      const bool centre = dx == 0 && dy == 0;
      const bool neighbour = (std::abs(dx) + std::abs(dy) == 1) || (dx == 1 && dy == -1) || (dx == -1 && dy == 1);
      EXPECT_NEAR(w.value[k], centre ? 0.5 : neighbour ? 1.0 / 12.0 : 0.0, 1e-15)
          << "corner (" << corner[0] << ", " << corner[1] << "), point " << k;
    }
  }
}

template <int N, typename Weights>
void expect_derivatives_match_differences(Weights weights, double u, double v) {
  const double h = 1e-4;
  const PatchWeights<N> w = weights(u, v);
  const PatchWeights<N> pu = weights(u + h, v), mu = weights(u - h, v);
  const PatchWeights<N> pv = weights(u, v + h), mv = weights(u, v - h);
  for (std::size_t k = 0; k < static_cast<std::size_t>(N); ++k) {
    EXPECT_NEAR(w.du[k], (pu.value[k] - mu.value[k]) / (2 * h), 1e-8) << k;
    EXPECT_NEAR(w.dv[k], (pv.value[k] - mv.value[k]) / (2 * h), 1e-8) << k;
    EXPECT_NEAR(w.duu[k], (pu.du[k] - mu.du[k]) / (2 * h), 1e-7) << k;
    EXPECT_NEAR(w.duv[k], (pv.du[k] - mv.du[k]) / (2 * h), 1e-7) << k;
    EXPECT_NEAR(w.dvv[k], (pv.dv[k] - mv.dv[k]) / (2 * h), 1e-7) << k;
  }
}

TEST(PatchBasis, DerivativesMatchFiniteDifferences) {
  for (const auto& [u, v] : kParameters) {
    expect_derivatives_match_differences<16>(bicubic_bspline_weights, u, v);
    expect_derivatives_match_differences<12>(box_spline_weights, u, v);
  }
}

/// Refines a random-height 8 x 8 lattice two levels and takes the limit of
/// every refined vertex (closed-form masks). A vertex whose limit lies over
/// the central face, the cell at (4, 4), has its limit (x, y) - (4, 4) as
/// parameter: the schemes reproduce linear functions. Its limit height must
/// be the patch's.
template <int N, typename Weights, typename Point>
void expect_patch_is_the_limit(const char* scheme_name, bool triangles, Weights weights, Point point) {
  const Scheme* scheme = find_scheme(scheme_name);
  ASSERT_NE(scheme, nullptr);
  const int r = 4;
  const PolygonMesh control =
      test::with_random_heights(triangles ? test::box_spline_grid(2 * r, 2 * r) : test::quad_grid(2 * r, 2 * r), 7);
  std::array<double, N> patch_heights{};
  for (std::size_t k = 0; k < static_cast<std::size_t>(N); ++k) {
    const auto [x, y] = point(k);
    patch_heights[k] = control.positions[static_cast<std::size_t>((y + r) * (2 * r + 1) + (x + r))].z;
  }
  RefineOptions options;
  options.levels = 2;
  const PolygonMesh refined = refine(control, *scheme, options);
  const LimitResult limit = limit_positions(refined, *scheme);
  int inside = 0;
  for (Vec3 p : limit.positions) {
    p.x -= r;
    p.y -= r;
    const bool in_face = triangles ? (p.x >= -1e-12 && p.y >= -1e-12 && p.x + p.y <= 1 + 1e-12)
                                   : (p.x >= -1e-12 && p.y >= -1e-12 && p.x <= 1 + 1e-12 && p.y <= 1 + 1e-12);
    if (!in_face) continue;
    ++inside;
    // The parameter is a dyadic point: the limit's (x, y) to rounding.
    const double u = std::round(p.x * 4) / 4, v = std::round(p.y * 4) / 4;
    ASSERT_NEAR(p.x, u, 1e-12);
    ASSERT_NEAR(p.y, v, 1e-12);
    const PatchWeights<N> w = weights(u, v);
    double z = 0.0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(N); ++k) z += w.value[k] * patch_heights[k];
    EXPECT_NEAR(z, p.z, 1e-12) << scheme_name << " at (" << u << ", " << v << ")";
  }
  // Level 2 puts (4 + 1)^2 vertices on the quad and 15 on the triangle.
  EXPECT_EQ(inside, triangles ? 15 : 25);
}

TEST(PatchBasis, BicubicIsCatmullClarksLimit) {
  expect_patch_is_the_limit<16>("catmull-clark", false, bicubic_bspline_weights, grid_point);
}

TEST(PatchBasis, BoxSplineIsLoopsLimit) {
  expect_patch_is_the_limit<12>("loop", true, box_spline_weights, lattice_point);
}

/// The evaluators' direct routes (a tensor product, a polynomial) equal the
/// weights applied to random control points.
TEST(PatchBasis, DirectPatchPointsEqualTheWeights) {
  std::mt19937 random(13);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  const auto random_point = [&] { return Vec3{coordinate(random), coordinate(random), coordinate(random)}; };
  const auto expect_equal = [](const PatchPoint& direct, const auto& w, const auto& points, double u, double v) {
    PatchPoint weighted{};
    for (std::size_t i = 0; i < points.size(); ++i) {
      weighted.position += w.value[i] * points[i];
      weighted.du += w.du[i] * points[i];
      weighted.dv += w.dv[i] * points[i];
      weighted.duu += w.duu[i] * points[i];
      weighted.duv += w.duv[i] * points[i];
      weighted.dvv += w.dvv[i] * points[i];
    }
    const std::array<std::pair<Vec3, Vec3>, 6> pairs = {{{direct.position, weighted.position}, {direct.du, weighted.du},
                                                         {direct.dv, weighted.dv}, {direct.duu, weighted.duu},
                                                         {direct.duv, weighted.duv}, {direct.dvv, weighted.dvv}}};
    for (const auto& [a, b] : pairs) EXPECT_LT(norm(a - b), 1e-13) << "at (" << u << ", " << v << ")";
  };
  for (const auto& [u, v] : kParameters) {
    std::array<Vec3, 16> grid;
    for (Vec3& p : grid) p = random_point();
    expect_equal(bicubic_bspline_point([&](std::size_t i) { return grid[i]; }, u, v), bicubic_bspline_weights(u, v),
                 grid, u, v);
    std::array<Vec3, 12> lattice;
    for (Vec3& p : lattice) p = random_point();
    expect_equal(box_spline_point(lattice, u, v), box_spline_weights(u, v), lattice, u, v);
  }
}

}  // namespace
}  // namespace subdiv
