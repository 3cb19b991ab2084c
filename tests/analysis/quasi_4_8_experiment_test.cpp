// The quasi 4-8 eigenstructure experiment: the regular 4-8 grid gives the
// box-spline values 1, 1/2, 1/2, 1/4, 1/4 (two binary steps halve the grid:
// an independent fact), the hexagon and the triangle the same matrix (the
// paper: "the same subdivision as in the triangle").

#include "subdiv/analysis/quasi_4_8_experiment.h"

#include <gtest/gtest.h>

#include "subdiv/core/error.h"
#include "support/four_eight_meshes.h"

namespace subdiv {
namespace {

TEST(Quasi48Experiment, RegularGridHasTheDyadicSpectrum) {
  const PolygonMesh grid = test::four_eight_grid(16);
  for (const Index centre : {8 + 17 * 8, 9 + 17 * 8}) {  // valence 8 and valence 4 in the control grid
    const Quasi48Experiment x = quasi_4_8_experiment(grid, centre, 2);
    ASSERT_GT(x.rings, 0) << x.note;
    EXPECT_EQ(x.centre_valence, 8);
    const double expected[5] = {1.0, 0.5, 0.5, 0.25, 0.25};
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(std::abs(x.leading[static_cast<std::size_t>(i)]), expected[i], 1e-9);
    EXPECT_TRUE(x.eigenvalue_condition);
    EXPECT_TRUE(x.charmap_regular) << x.charmap_flipped << " of " << x.charmap_faces << " faces flipped";
    for (int r = 0; r < x.S.rows(); ++r) EXPECT_NEAR(x.S.row(r).sum(), 1.0, 1e-12);
  }
}

TEST(Quasi48Experiment, NRegularNeighbourhoods) {
  const Quasi48Experiment triangle = quasi_4_8_ngon_experiment(3, 6);
  const Quasi48Experiment hexagon = quasi_4_8_ngon_experiment(6, 6);
  const Quasi48Experiment square = quasi_4_8_ngon_experiment(4, 6);
  ASSERT_GT(triangle.rings, 0) << triangle.note;
  ASSERT_GT(hexagon.rings, 0) << hexagon.note;
  ASSERT_GT(square.rings, 0) << square.note;
  EXPECT_EQ(triangle.centre_valence, 6);
  EXPECT_EQ(hexagon.centre_valence, 6);
  EXPECT_EQ(square.centre_valence, 8);  // the regular 4-8 vertex
  // The same neighbourhood (up to where the numbering starts): one spectrum.
  ASSERT_EQ(triangle.size, hexagon.size);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(std::abs(triangle.leading[i] - hexagon.leading[i]), 0.0, 1e-9);
  EXPECT_NEAR(square.leading[1].real(), 0.5, 1e-9);
  // Valence 6 at the centre: a real double subdominant eigenvalue below 1/2,
  // above |lambda_3| = 1/4 (measured: 0.405113).
  EXPECT_NEAR(hexagon.leading[1].real(), hexagon.leading[2].real(), 1e-9);
  EXPECT_GT(hexagon.leading[1].real(), 0.4);
  EXPECT_LT(hexagon.leading[1].real(), 0.41);
  EXPECT_NEAR(std::abs(hexagon.leading[3]), 0.25, 1e-9);
  for (const int n : {3, 4, 5, 6, 8, 10, 12}) EXPECT_TRUE(quasi_4_8_ngon_experiment(n, 6).eigenvalue_condition) << n;
}

// The piecewise-linear characteristic map, refined two more 4-8 steps from a
// neighbourhood three rings wider: regular at valences 6, 8 and 10 (eight
// warm-up steps; after six the wider neighbourhood of n = 3 still reaches
// the n-gon's boundary, which the experiment says).
TEST(Quasi48Experiment, CharacteristicMapApproximation) {
  for (const int n : {3, 4, 5}) {
    const Quasi48Experiment x = quasi_4_8_ngon_experiment(n, 8);
    ASSERT_TRUE(x.eigenvalue_condition) << n << ": " << x.note;
    EXPECT_GT(x.charmap_faces, 1000) << n;
    EXPECT_EQ(x.charmap_flipped, 0) << n;
    EXPECT_EQ(std::abs(x.charmap_winding), 1) << n;
    EXPECT_TRUE(x.charmap_regular) << n;
  }
  const Quasi48Experiment early = quasi_4_8_ngon_experiment(3, 6);
  EXPECT_TRUE(early.eigenvalue_condition);
  EXPECT_EQ(early.charmap_faces, 0);
  EXPECT_NE(early.note.find("no characteristic map"), std::string::npos) << early.note;
}

// The map check can fail: on the 4-8 grid, the identity map (x, y) is
// regular; z^2 winds twice around the centre; (x, x) is flat.
TEST(Quasi48Experiment, PiecewiseLinearMapDetectsBadMaps) {
  const PolygonMesh grid = test::four_eight_grid(16);
  const Index centre = 8 + 17 * 8;
  std::vector<Index> vertices{centre};
  for (Index v = 0; v < grid.vertex_count(); ++v)
    if (v != centre && norm(grid.positions[v] - grid.positions[centre]) <= 5.0) vertices.push_back(v);
  const auto values = [&](auto f) {
    std::vector<Vec3> out;
    for (const Index v : vertices) out.push_back(f(grid.positions[v] - grid.positions[centre]));
    return out;
  };
  const PiecewiseLinearMap identity = piecewise_linear_map(grid, vertices, values([](Vec3 p) { return p; }), 1);
  EXPECT_TRUE(identity.regular);
  EXPECT_GT(identity.faces, 50);
  EXPECT_EQ(identity.winding, 1);
  const PiecewiseLinearMap square = piecewise_linear_map(grid, vertices, values([](Vec3 p) {
                                                           return Vec3{p.x * p.x - p.y * p.y, 2 * p.x * p.y, 0};
                                                         }),
                                                         1);
  EXPECT_FALSE(square.regular);
  EXPECT_EQ(square.winding, 2);
  const PiecewiseLinearMap flat = piecewise_linear_map(grid, vertices, values([](Vec3 p) {
                                                         return Vec3{p.x, p.x, 0};
                                                       }),
                                                       1);
  EXPECT_FALSE(flat.regular);
  EXPECT_EQ(flat.flipped, flat.faces);
}

TEST(Quasi48Experiment, SaysWhenThereIsNoMatrix) {
  const Quasi48Experiment x = quasi_4_8_ngon_experiment(5, 2);  // the boundary is too close
  EXPECT_EQ(x.rings, 0);
  EXPECT_FALSE(x.note.empty());
  EXPECT_THROW(quasi_4_8_ngon_experiment(2, 1), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
