// The grid path of the Butterfly schemes: triangle patches of reach 2 (the
// 27 points within two steps of a triangle), whose edge points read the
// four wing vertices. The declared 8-point rule is the masks' regular
// stencil with its published weights, its kernel reads only the patch and
// is symmetric, and refining with grids gives the masks' mesh.

#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "grid_test_support.h"
#include "refine/grid_triangles.h"
#include "refine/triangle_patch.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/butterfly.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using namespace grid_test;

Scheme butterfly_with_tension(double w) {
  Scheme s = butterfly_scheme();
  tension_parameters(s.parameters)->tension = w;
  return s;
}

std::vector<std::pair<std::string, Scheme>> butterfly_schemes() {
  return {{"butterfly", butterfly_scheme()},
          {"butterfly w=0.1", butterfly_with_tension(0.1)},
          {"modified-butterfly", modified_butterfly_scheme()}};
}

TEST(GridButterfly, PublishedWeights) {
  // Dyn, Levin, Gregory 1990 at w = 1/16: 1/2 at the ends, 1/8 opposite,
  // -1/16 at the wings; old points stay.
  for (const Scheme* scheme : {&butterfly_scheme(), &modified_butterfly_scheme()}) {
    const RegularTriangleGrid rule = *regular_triangle_grid_of(*scheme);
    EXPECT_EQ(rule.centre, 1.0);
    EXPECT_EQ(rule.ring, 0.0);
    EXPECT_EQ(rule.near, 0.5);
    EXPECT_EQ(rule.far, 0.125);
    EXPECT_EQ(rule.wing, -0.0625);
    EXPECT_EQ(rule.patch_reach(), 2);
  }
  const RegularTriangleGrid tense = *regular_triangle_grid_of(butterfly_with_tension(0.1));
  EXPECT_DOUBLE_EQ(tense.far, 0.2);
  EXPECT_DOUBLE_EQ(tense.wing, -0.1);
  EXPECT_EQ(regular_triangle_grid_of(loop_scheme())->patch_reach(), 1);
}

TEST(GridButterfly, DeclaredRuleIsTheMasksRegularStencil) {
  // One level of the masks recorded as stencils on a torus whose vertices
  // all have valence 6: each edge point's row is near on the ends, far on
  // the opposite vertices, wing on the four wings; each vertex point stays.
  const PolygonMesh mesh = triangulated_torus(8);
  const MeshTopology t(mesh);
  for (const auto& [name, scheme] : butterfly_schemes()) {
    SCOPED_TRACE(name);
    const RegularTriangleGrid rule = *regular_triangle_grid_of(scheme);
    const StencilTable table = refine_stencil_table(mesh, scheme, with_grids(false, 1));
    auto weight = [&](Index row, Index vertex) {
      const auto vs = table.row_vertices(row);
      const auto ws = table.row_weights(row);
      double w = 0.0;
      for (std::size_t j = 0; j < vs.size(); ++j)
        if (vs[j] == vertex) w += ws[j];
      return w;
    };
    const Index ne = t.edge_count();
    for (Index e = 0; e < ne; ++e) {
      const auto [a, b] = t.edge_vertices(e);
      EXPECT_DOUBLE_EQ(weight(e, a), rule.near);
      EXPECT_DOUBLE_EQ(weight(e, b), rule.near);
      double total = 2 * rule.near;
      std::size_t entries = 2;
      for (const Index c : t.edge_corners(e)) {
        // The opposite vertex, and the wings across the triangle's other two edges.
        EXPECT_DOUBLE_EQ(weight(e, t.corner_vertex(t.corner_prev(c))), rule.far);
        total += rule.far, ++entries;
        for (const Index side : {t.corner_next(c), t.corner_prev(c)}) {
          const Index across = t.corner_across(side);
          ASSERT_NE(across, kInvalidIndex);
          EXPECT_DOUBLE_EQ(weight(e, t.corner_vertex(t.corner_prev(across))), rule.wing);
          total += rule.wing, ++entries;
        }
      }
      EXPECT_EQ(table.row_vertices(e).size(), entries) << "edge " << e << " reads other vertices";
      EXPECT_NEAR(total, 1.0, 1e-15);
    }
    for (Index v = 0; v < t.vertex_count(); ++v) {
      EXPECT_DOUBLE_EQ(weight(ne + v, v), rule.centre);
      EXPECT_EQ(table.row_vertices(ne + v).size(), 1U);
    }
  }
}

TEST(GridButterfly, KernelReadsOnlyTheHexagonAndIsSymmetric) {
  // Each slot's unit impulse refined: the nine slots of the 6 x 6 array
  // outside the hexagon of reach 2 reach no point of the triangle, every
  // point's weights sum to 1, and mirroring the triangle across i = j
  // mirrors the weights.
  const RegularTriangleGrid rule = *regular_triangle_grid_of(butterfly_scheme());
  auto slot = [](int i, int j) { return static_cast<std::size_t>((i + 2) + 6 * (j + 2)); };
  for (int levels = 1; levels <= 4; ++levels) {
    const int n = 1 << levels;
    const std::vector<double> weights = detail::triangle_point_weights(rule, levels);
    ASSERT_EQ(weights.size(), static_cast<std::size_t>((n + 1) * (n + 1)) * 36);
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i) {
        const std::span<const double> w(weights.data() + static_cast<std::size_t>(i + (n + 1) * j) * 36, 36);
        const std::span<const double> mirrored(weights.data() + static_cast<std::size_t>(j + (n + 1) * i) * 36, 36);
        double sum = 0.0;
        for (const double x : w) sum += x;
        EXPECT_NEAR(sum, 1.0, 1e-14) << "point (" << i << ", " << j << ") after " << levels << " levels";
        for (int b = -2; b <= 3; ++b)
          for (int a = -2; a <= 3; ++a) {
            if (!detail::in_hexagon(a, b, 1, 2)) {
              EXPECT_EQ(w[slot(a, b)], 0.0) << "slot (" << a << ", " << b << ") reaches point (" << i << ", " << j << ")";
            }
            EXPECT_NEAR(w[slot(a, b)], mirrored[slot(b, a)], 1e-15);
          }
      }
  }
}

// Loop's refinement of a triangulated cube, and spot's quads refined by
// Catmull-Clark and split into triangles: extraordinary vertices far apart
// in regular triangles.
PolygonMesh loop_cube() { return refine(test::jittered(triangulate(test::cube()), 2), loop_scheme(), with_grids(false, 4)); }
PolygonMesh spot_triangles() {
  return triangulate(
      refine(read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh, catmull_clark_scheme(), with_grids(false, 2)));
}

TEST(GridButterfly, EqualsTheMasks) {
  const PolygonMesh open = test::jittered(test::triangle_grid(40, 40), 4);
  const PolygonMesh cube = loop_cube(), spot = spot_triangles();
  for (const auto& [name, scheme] : butterfly_schemes()) {
    SCOPED_TRACE(name);
    for (int levels = 3; levels <= 4; ++levels) {
      const std::string what = name + ", " + std::to_string(levels) + " levels";
      expect_grids_equal_masks(triangulated_torus(10), scheme, levels, "torus, " + what);
      expect_grids_equal_masks(with_channels(triangulated_torus(10)), scheme, levels, "torus with vertex channels, " + what);
      expect_grids_equal_masks(with_face_varying(triangulated_torus(10)), scheme, levels,
                               "torus with face-varying values, " + what);
      expect_grids_equal_masks(test::jittered(triangulate(test::cube()), 1), scheme, levels + 1, "cube, " + what);
    }
    expect_grids_equal_masks(open, scheme, 3, "open grid, " + name);
    expect_grids_equal_masks(cube, scheme, 3, "Loop's cube, " + name);
    expect_grids_equal_masks(spot, scheme, 3, "spot, " + name);
    // Both routes were compared: all-grid faces, and faces by the masks
    // around extraordinary vertices and the rim.
    EXPECT_TRUE(takes_grids(triangulated_torus(10), scheme, 3));
    EXPECT_TRUE(takes_grids(open, scheme, 3));
    EXPECT_TRUE(takes_grids(cube, scheme, 3));
  }
}

TEST(GridButterfly, EqualsTheMasksWithTags) {
  const Index n = 48;
  PolygonMesh mesh = triangulated_torus(n);
  for (Index i = 0; i < n; ++i) mesh.tags.creases.push_back({i, (i + 1) % n, 1.5});
  mesh.tags.creases.push_back({n * 12 + 3, n * 13 + 3, kInfiniteSharpness});
  mesh.tags.corners.push_back({.vertex = n * 30 + 9, .sharpness = 2.5, .type = CornerType::unspecified, .angle = {}});
  mesh.tags.holes = {3000, 37};
  for (const auto& [name, scheme] : butterfly_schemes()) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(takes_grids(mesh, scheme, 3));
    expect_grids_equal_masks(mesh, scheme, 3, "tagged torus, " + name);
    expect_grid_stencils_equal_masks(mesh, scheme, 3, "tagged torus, " + name, true);
  }
}

TEST(GridButterfly, StencilTablesEqualTheMasks) {
  const PolygonMesh cube = loop_cube();
  for (const auto& [name, scheme] : butterfly_schemes()) {
    expect_grid_stencils_equal_masks(triangulated_torus(10), scheme, 3, "torus, " + name, true);
    expect_grid_stencils_equal_masks(cube, scheme, 3, "Loop's cube, " + name, true);
  }
}

TEST(GridButterfly, SameResultForAnyThreadCount) {
  for (const auto& [name, scheme] : butterfly_schemes()) {
    SCOPED_TRACE(name);
    RefineOptions one = with_grids(true, 3), two = one;
    one.threads = 1;
    two.threads = 2;
    const PolygonMesh mesh = triangulated_torus(30);
    const PolygonMesh a = refine(mesh, scheme, one);
    const PolygonMesh b = refine(mesh, scheme, two);
    EXPECT_EQ(a.face_indices, b.face_indices);
    EXPECT_TRUE(a.positions == b.positions) << "positions differ between one and two threads";
  }
}

}  // namespace
}  // namespace subdiv
