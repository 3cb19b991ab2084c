// Interpolating sqrt2 (rules/interpolating_sqrt2.h):
// - golden weights of a face point on a regular quad torus: 5/16 on the
//   quad's corners, -1/32 on its 8 outer vertices, nothing else;
// - the rule reproduces every cubic polynomial on the grid, and not x^2 y^2
//   (so its precision is exactly cubic);
// - old vertices stay, bit for bit, at every level;
// - the regular rules are C1 (difference schemes); with the virtual points
//   Reif's eigenvalue condition holds at valences 3..16 and the full verdict
//   (characteristic map included) is C1 at 3, 7 and 16; the same stencil
//   without them is not shown C1 at 7 (its characteristic map overlaps);
// - stencil rows sum to one and refinement commutes with affine maps at
//   valences 3, 5 and 6;
// - open meshes and other faces than quads are refused.

#include "subdiv/rules/interpolating_sqrt2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <numbers>
#include <string>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/regular_smoothness.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/refine.h"
#include "support/stencil_checks.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// An n x n quad torus on the integer lattice: vertex (i, j) at (i, j, 0) as
// far as the rules go (the positions do not matter to the stencils, only
// the lattice coordinates the test assigns).
PolygonMesh lattice_torus(int n) {
  PolygonMesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) m.positions.push_back({std::cos(2 * std::numbers::pi * i / n) * (2 + std::cos(2 * std::numbers::pi * j / n)),
                                                       std::sin(2 * std::numbers::pi * i / n) * (2 + std::cos(2 * std::numbers::pi * j / n)),
                                                       std::sin(2 * std::numbers::pi * j / n)});
  auto at = [n](int i, int j) { return static_cast<Index>(((j + n) % n) * n + (i + n) % n); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return m;
}

// The face point of face (0, 0) of the torus: its stencil row, read as
// (lattice offset from the face's centre (1/2, 1/2), weight).
struct Tap {
  double x, y, w;
};
std::vector<Tap> face_point_taps(int n) {
  const PolygonMesh torus = lattice_torus(n);
  RefineOptions once;
  once.levels = 1;
  const StencilTable table = refine_stencil_table(torus, interpolating_sqrt2_scheme(), once);
  const Index face_point = 0;  // the sqrt2 split numbers face points first, face f's as f
  std::vector<Tap> taps;
  const auto vs = table.row_vertices(face_point);
  const auto ws = table.row_weights(face_point);
  for (std::size_t k = 0; k < vs.size(); ++k) {
    int i = vs[k] % n, j = vs[k] / n;
    if (i > n / 2) i -= n;
    if (j > n / 2) j -= n;
    taps.push_back({i - 0.5, j - 0.5, ws[k]});
  }
  return taps;
}

TEST(InterpolatingSqrt2, GoldenWeightsOnTheRegularGrid) {
  const std::vector<Tap> taps = face_point_taps(8);
  ASSERT_EQ(taps.size(), 12u);
  double sum = 0.0;
  for (const Tap& t : taps) {
    sum += t.w;
    const bool corner = std::fabs(t.x) == 0.5 && std::fabs(t.y) == 0.5;
    const bool outer = (std::fabs(t.x) == 1.5 && std::fabs(t.y) == 0.5) || (std::fabs(t.x) == 0.5 && std::fabs(t.y) == 1.5);
    ASSERT_TRUE(corner || outer) << t.x << ", " << t.y;
    EXPECT_EQ(t.w, corner ? 5.0 / 16.0 : -1.0 / 32.0) << t.x << ", " << t.y;
  }
  EXPECT_NEAR(sum, 1.0, 1e-15);
}

TEST(InterpolatingSqrt2, ReproducesCubicsExactly) {
  const std::vector<Tap> taps = face_point_taps(8);
  auto apply = [&](const std::function<double(double, double)>& p) {
    double s = 0.0;
    for (const Tap& t : taps) s += t.w * p(t.x, t.y);
    return s;
  };
  for (int a = 0; a <= 3; ++a)
    for (int b = 0; a + b <= 3; ++b)
      EXPECT_NEAR(apply([&](double x, double y) { return std::pow(x + 0.3, a) * std::pow(y - 0.2, b); }),
                  std::pow(0.3, a) * std::pow(-0.2, b), 1e-14)
          << "x^" << a << " y^" << b;
  EXPECT_GT(std::fabs(apply([](double x, double y) { return x * x * y * y; })), 1e-3);  // not quartic
}

TEST(InterpolatingSqrt2, KeepsOldVertices) {
  const PolygonMesh cube = test::jittered(test::cube(), 3);
  RefineOptions o;
  o.levels = 4;
  const PolygonMesh fine = refine(cube, interpolating_sqrt2_scheme(), o);
  // Every split numbers vertex points last: the old vertices are the last ones, twice over.
  const Index first = fine.vertex_count() - cube.vertex_count();
  for (Index v = 0; v < cube.vertex_count(); ++v)
    EXPECT_EQ(fine.positions[static_cast<std::size_t>(first + v)], cube.positions[static_cast<std::size_t>(v)]);
}

TEST(InterpolatingSqrt2, C1AtValencesThreeToSixteen) {
  EXPECT_EQ(regular_smoothness_of(interpolating_sqrt2_scheme(), {}, false).verdict, SmoothnessVerdict::c1);
  AnalysisOptions spectrum;
  spectrum.characteristic_map = false;
  spectrum.masks = false;
  for (int k = 3; k <= 16; ++k)
    EXPECT_TRUE(
        analyze(interpolating_sqrt2_scheme(), {Configuration::Kind::interior, k, CornerType::convex}, spectrum)
            .eigenvalue_condition)
        << "k = " << k;
  for (const int k : {3, 7, 16})
    EXPECT_EQ(analyze(interpolating_sqrt2_scheme(), {Configuration::Kind::interior, k, CornerType::convex}).verdict,
              SmoothnessVerdict::c1)
        << "k = " << k;
}

// Without the virtual points (a scheme of the same stencil read off the
// topology, defined here) valence 7's characteristic map overlaps itself.
void plain_face_point(const LevelView& level, Index f, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  if (t.face_size(f) != 4) {
    for (const Index v : t.face_vertices(f)) mask.add(v, 1.0 / static_cast<double>(t.face_size(f)));
    return;
  }
  for (Index c = t.face_first_corner(f); c < t.face_first_corner(f) + 4; ++c) {
    mask.add(t.corner_vertex(c), 5.0 / 16.0);
    const Index g = t.corner_across(c);
    const Index x = g == kInvalidIndex ? t.corner_vertex(c) : t.corner_vertex(t.corner_next(t.corner_next(g)));
    const Index y = g == kInvalidIndex ? t.corner_vertex(t.corner_next(c)) : t.corner_vertex(t.corner_prev(g));
    mask.add(x, -1.0 / 32.0);
    mask.add(y, -1.0 / 32.0);
  }
}

TEST(InterpolatingSqrt2, WithoutVirtualPointsValenceSevenIsNotShownC1) {
  Scheme plain = interpolating_sqrt2_scheme();
  plain.masks.face_point = plain_face_point;
  const ConfigurationAnalysis seven = analyze(plain, {Configuration::Kind::interior, 7, CornerType::convex});
  ASSERT_GE(seven.leading.size(), 2u);
  EXPECT_NEAR(std::abs(seven.leading[1]), 0.489405, 1e-6);  // the virtual points' is 0.586512
  EXPECT_TRUE(seven.eigenvalue_condition);
  ASSERT_TRUE(seven.characteristic_map.has_value());
  EXPECT_FALSE(seven.characteristic_map->injective);
  EXPECT_NE(seven.verdict, SmoothnessVerdict::c1);
}

TEST(InterpolatingSqrt2, RowsSumToOneAndRefinementIsAffine) {
  // Spot after one Catmull-Clark level: closed quads, valences 3, 4, 5 and 6.
  RefineOptions once;
  once.levels = 1;
  const PolygonMesh quads = refine(read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh,
                                   *find_scheme("catmull-clark"), once);
  EXPECT_TRUE(validate(test::expect_stencils_are_the_fast_path(quads, interpolating_sqrt2_scheme(), 2, 1e-13)).ok());
  test::expect_refinement_commutes_with_an_affine_map(quads, interpolating_sqrt2_scheme(), 2, 1e-11);
}

TEST(InterpolatingSqrt2, RefusesOpenMeshesAndOtherFaces) {
  RefineOptions o;
  o.levels = 1;
  EXPECT_THROW(refine(test::quad_grid(3, 3), interpolating_sqrt2_scheme(), o), InvalidInputError);
  EXPECT_THROW(refine(test::tetrahedron(), interpolating_sqrt2_scheme(), o), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
