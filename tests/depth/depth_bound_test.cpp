// The depth bounds against independent computations: Loop's contraction
// against its closed form and against refinement, Cheng's bound on a
// regular quad torus, the Doo-Sabin bound against tensor-product Chaikin
// refinement of a periodic grid (Doo-Sabin on valence-4 vertices).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/depth/depth.h"
#include "subdiv/depth/depth_bound.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "depth/depth_test_meshes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

TEST(LoopContraction, EqualsTheSquaredCentralEigenvalue) {
  // 5/8 - n beta(n) = (3/8 + 1/4 cos(2 pi / n))^2 by Loop's choice of beta.
  for (int n = 3; n <= 40; ++n) {
    const double root = 3.0 / 8.0 + 0.25 * std::cos(2.0 * std::numbers::pi / n);
    EXPECT_NEAR(loop_contraction(loop_scheme(), n), root * root, 1e-15) << "valence " << n;
  }
  EXPECT_DOUBLE_EQ(loop_contraction(loop_scheme(), 6), 0.25);
}

TEST(LoopContraction, OldVerticesApproachTheirLimitByExactlyThatFactor) {
  // Paper, proof of Theorem 3: a vertex point's distance to its limit is
  // (5/8 - n beta) times its parent's. Checked through the refinement
  // engine and the limit module on a closed mesh with valences 4 to 18.
  const PolygonMesh top = spinning_top(18, 1.0, 2.0, 1.5);
  const MeshTopology t(top);
  const LimitDistances before = limit_distances(top, loop_scheme());
  RefineOptions one;
  const PolygonMesh child = refine(top, loop_scheme(), one);
  const LimitDistances after = limit_distances(child, loop_scheme());
  const Index vertex_points = t.edge_count();  // triangle split: [edge points | vertex points]
  for (Index v = 0; v < t.vertex_count(); ++v) {
    const double expected = loop_contraction(loop_scheme(), t.valence(v)) * before.distances[static_cast<std::size_t>(v)];
    EXPECT_NEAR(after.distances[static_cast<std::size_t>(vertex_points + v)], expected, 1e-12) << "vertex " << v;
  }
}

TEST(DepthBound, DepthIsTheFirstLevelWithinEps) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.01, 0.8);
  for (int trial = 0; trial < 200; ++trial) {
    const DepthBound bound{"test", "test", trial % 2, {{"a", unit(random), unit(random)}, {"b", unit(random), 0.25}}};
    const double eps = unit(random) * 1e-3;
    const int depth = bound.depth_for(eps);
    EXPECT_LE(bound.at(depth), eps);
    if (depth > bound.start) {
      EXPECT_GT(bound.at(depth - 1), eps);
    }
  }
}

TEST(DepthBound, RefusesWhatCannotConverge) {
  const DepthBound bound{"test", "test", 0, {{"a", 1.0, 1.0}}};
  EXPECT_THROW((void)bound.depth_for(0.1), InvalidInputError);
  EXPECT_THROW((void)loop_paper_bound(loop_scheme(), 1.0, 6).depth_for(0.0), InvalidInputError);
  EXPECT_THROW((void)loop_paper_bound(loop_scheme(), 1.0, 6).depth_for(-1.0), InvalidInputError);
}

TEST(DepthBound, PaperFormulasInClosedForm) {
  // Corollary 2: i >= log4(M / (3 eps)); Corollary 5: one step, then
  // log4(M / (4 eps)); Corollary 3 at n = 6: log4(M0 / eps).
  for (const double eps : {0.3, 0.01, 1e-3, 2.5e-5}) {
    const double m = 7.0;
    EXPECT_EQ(cheng_catmull_clark_bound(m, 0).depth_for(eps),
              std::max(0, static_cast<int>(std::ceil(std::log(m / (3.0 * eps)) / std::log(4.0) - 1e-12))));
    EXPECT_EQ(doo_sabin_bound(m, 1).depth_for(eps),
              1 + std::max(0, static_cast<int>(std::ceil(std::log(m / (4.0 * eps)) / std::log(4.0) - 1e-12))));
    EXPECT_EQ(loop_paper_bound(loop_scheme(), m, 5).depth_for(eps),
              std::max(0, static_cast<int>(std::ceil(std::log(m / eps) / std::log(4.0) - 1e-12))));
  }
}

TEST(ChengBound, HoldsAtEveryLevelOnARegularTorus) {
  std::mt19937 random(11);
  const PolygonMesh torus = perturbed(quad_torus(8, 6, 3.0, 1.0), 0.2, random);
  const DepthBound bound = depth_bound(torus, catmull_clark_scheme());
  ASSERT_EQ(bound.terms.size(), 1u) << "a regular torus has no extraordinary vertex";
  EXPECT_EQ(bound.source, "paper");
  PolygonMesh level = torus;
  for (int k = 0; k <= 3; ++k) {
    const double measured = limit_distances(level, catmull_clark_scheme()).max;
    EXPECT_LE(measured, bound.at(k)) << "level " << k;
    level = refine(level, catmull_clark_scheme());
  }
}

// Doo-Sabin on a grid of valence-4 vertices is tensor-product Chaikin
// (weights 9/16, 3/16, 3/16, 1/16 = (3/4, 1/4) x (3/4, 1/4)); a control
// point's limit is the biquadratic B-spline at its patch centre,
// (1/8, 6/8, 1/8) x (1/8, 6/8, 1/8) over its 3 x 3 neighbours.
struct PeriodicGrid {
  int n = 0;
  int m = 0;
  std::vector<Vec3> p;
  Vec3& at(int i, int j) { return p[static_cast<std::size_t>(((i % n + n) % n) * m + (j % m + m) % m)]; }
};

PeriodicGrid chaikin(PeriodicGrid g) {
  PeriodicGrid rows{2 * g.n, g.m, std::vector<Vec3>(static_cast<std::size_t>(2 * g.n * g.m))};
  for (int i = 0; i < g.n; ++i)
    for (int j = 0; j < g.m; ++j) {
      rows.at(2 * i, j) = 0.75 * g.at(i, j) + 0.25 * g.at(i + 1, j);
      rows.at(2 * i + 1, j) = 0.25 * g.at(i, j) + 0.75 * g.at(i + 1, j);
    }
  PeriodicGrid out{2 * g.n, 2 * g.m, std::vector<Vec3>(static_cast<std::size_t>(4 * g.n * g.m))};
  for (int i = 0; i < 2 * g.n; ++i)
    for (int j = 0; j < g.m; ++j) {
      out.at(i, 2 * j) = 0.75 * rows.at(i, j) + 0.25 * rows.at(i, j + 1);
      out.at(i, 2 * j + 1) = 0.25 * rows.at(i, j) + 0.75 * rows.at(i, j + 1);
    }
  return out;
}

double max_biquadratic_limit_distance(PeriodicGrid g) {
  const double w[3] = {1.0 / 8.0, 6.0 / 8.0, 1.0 / 8.0};
  double worst = 0.0;
  for (int i = 0; i < g.n; ++i)
    for (int j = 0; j < g.m; ++j) {
      Vec3 limit;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) limit += (w[a] * w[b]) * g.at(i + a - 1, j + b - 1);
      worst = std::max(worst, norm(g.at(i, j) - limit));
    }
  return worst;
}

PolygonMesh grid_mesh(PeriodicGrid& g) {
  PolygonMesh mesh;
  mesh.positions = g.p;
  for (int i = 0; i < g.n; ++i)
    for (int j = 0; j < g.m; ++j) {
      const auto id = [&](int a, int b) { return static_cast<Index>(((a % g.n) * g.m) + b % g.m); };
      mesh.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh;
}

TEST(DooSabinBound, HoldsForBiquadraticRefinementOfAPeriodicGrid) {
  std::mt19937 random(5);
  const PolygonMesh torus = perturbed(quad_torus(6, 8, 3.0, 1.0), 0.3, random);
  // The torus grid stands for the mesh after the first Doo-Sabin step,
  // where every vertex has valence 4.
  PeriodicGrid grid{6, 8, torus.positions};
  const DepthBound bound = doo_sabin_bound(max_second_difference(grid_mesh(grid)), 1);
  for (int level = 1; level <= 5; ++level) {
    const double measured = max_biquadratic_limit_distance(grid);
    EXPECT_LE(measured, bound.at(level)) << "level " << level;
    grid = chaikin(grid);
  }
  // And the depth for an accuracy reaches it.
  for (const double eps : {0.05, 0.01, 0.002}) {
    PeriodicGrid g{6, 8, torus.positions};
    const int depth = bound.depth_for(eps);
    for (int level = 1; level < depth; ++level) g = chaikin(g);
    EXPECT_LE(max_biquadratic_limit_distance(g), eps) << "eps " << eps;
  }
}

TEST(MaxSecondDifference, IsZeroOnAnEvenPlanarGridAndSeesOneBump) {
  const PolygonMesh flat = test::quad_grid(5, 5);
  EXPECT_NEAR(max_second_difference(flat), 0.0, 1e-12);
  PolygonMesh bump = flat;
  bump.positions[2 * 6 + 2].z = 0.5;  // an interior vertex of the 6 x 6 vertex grid
  // |0 - 2 (0.5) + 0| on both lines through it; 0.5 on its neighbours' lines.
  EXPECT_NEAR(max_second_difference(bump), 1.0, 1e-12);
}

}  // namespace
}  // namespace subdiv
