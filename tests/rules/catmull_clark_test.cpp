#include "subdiv/rules/catmull_clark.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "subdiv/refine/refine.h"
#include "support/stencil_rows.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// One level of Catmull-Clark stencils on a 4x4 grid (vertex (i, j) = 5j + i).
StencilTable grid_stencils(PolygonMesh mesh, std::optional<BoundaryInterpolation> boundary = {}) {
  RefineOptions o;
  o.boundary = boundary;
  return refine_stencils(mesh, catmull_clark_scheme(), o).at(0);
}

Index vertex_point(const PolygonMesh& mesh, Index v) { return mesh.face_count() + MeshTopology(mesh).edge_count() + v; }
Index edge_point(const PolygonMesh& mesh, Index a, Index b) { return mesh.face_count() + MeshTopology(mesh).find_edge(a, b); }

TEST(CatmullClark, RegularInteriorMasksAreTheBicubicBSpline) {
  const PolygonMesh grid = test::quad_grid(4, 4);
  const StencilTable t = grid_stencils(grid);
  const auto vp = test::merged_row(t, vertex_point(grid, 12));
  ASSERT_EQ(vp.size(), 9u);
  EXPECT_DOUBLE_EQ(vp.at(12), 9.0 / 16);
  for (const Index n : {7, 11, 13, 17}) EXPECT_DOUBLE_EQ(vp.at(n), 3.0 / 32);
  for (const Index d : {6, 8, 16, 18}) EXPECT_DOUBLE_EQ(vp.at(d), 1.0 / 64);
  const auto ep = test::merged_row(t, edge_point(grid, 12, 13));
  ASSERT_EQ(ep.size(), 6u);
  EXPECT_DOUBLE_EQ(ep.at(12), 3.0 / 8);
  EXPECT_DOUBLE_EQ(ep.at(13), 3.0 / 8);
  for (const Index n : {7, 8, 17, 18}) EXPECT_DOUBLE_EQ(ep.at(n), 1.0 / 16);
  const auto fp = test::merged_row(t, 0);
  for (const Index n : {0, 1, 5, 6}) EXPECT_DOUBLE_EQ(fp.at(n), 0.25);
}

TEST(CatmullClark, ExtraordinaryVertexUsesTheGeneralRule) {
  // The cube's vertices have valence 3: (k-2)/k = 1/3 on the vertex,
  // 1/k^2 on each neighbour plus 1/(4 k^2) per face corner.
  const PolygonMesh cube = test::cube();
  const auto row = test::merged_row(grid_stencils(cube), vertex_point(cube, 0));
  EXPECT_DOUBLE_EQ(row.at(0), 1.0 / 3 + 3.0 / 36);
  EXPECT_DOUBLE_EQ(row.at(1), 1.0 / 9 + 2.0 / 36);
  EXPECT_DOUBLE_EQ(row.at(2), 1.0 / 36);  // diagonal of face 0
}

TEST(CatmullClark, BoundaryCreaseAndCornerRules) {
  const PolygonMesh grid = test::quad_grid(4, 4);
  const StencilTable t = grid_stencils(grid);
  const auto boundary = test::merged_row(t, vertex_point(grid, 2));
  EXPECT_EQ(boundary, (std::map<Index, double>{{1, 0.125}, {2, 0.75}, {3, 0.125}}));
  EXPECT_EQ(test::merged_row(t, edge_point(grid, 1, 2)), (std::map<Index, double>{{1, 0.5}, {2, 0.5}}));
  EXPECT_EQ(test::merged_row(t, vertex_point(grid, 0)), (std::map<Index, double>{{0, 1.0}}));  // edge-and-corner
  const StencilTable edge_only = grid_stencils(grid, BoundaryInterpolation::edge_only);
  EXPECT_EQ(test::merged_row(edge_only, vertex_point(grid, 0)),
            (std::map<Index, double>{{0, 0.75}, {1, 0.125}, {5, 0.125}}));

  PolygonMesh creased = grid;
  creased.tags.creases = {{11, 12, 10.0}, {12, 13, 10.0}, {7, 12, 0.5}};
  const StencilTable c = grid_stencils(creased);
  EXPECT_EQ(test::merged_row(c, edge_point(creased, 11, 12)), (std::map<Index, double>{{11, 0.5}, {12, 0.5}}));
  // Semi-sharp edge (s = 0.5): half the smooth rule, half the midpoint.
  const auto half = test::merged_row(c, edge_point(creased, 7, 12));
  EXPECT_DOUBLE_EQ(half.at(7), 0.5 * 3.0 / 8 + 0.25);
  EXPECT_DOUBLE_EQ(half.at(6), 0.5 / 16);
  // Three sharp edges at 12 (one semi-sharp): a corner now, a crease one
  // level down, blended with the semi-sharp edge's sharpness 0.5.
  const auto v = test::merged_row(c, vertex_point(creased, 12));
  EXPECT_DOUBLE_EQ(v.at(12), 0.5 * 1.0 + 0.5 * 0.75);
  EXPECT_DOUBLE_EQ(v.at(11), 0.5 * 0.125);
  EXPECT_EQ(v.count(7), 0u);
}

// On a regular grid Catmull-Clark is the uniform bicubic B-spline: after two
// steps, the limit of every vertex far from the boundary (limit mask
// [1 4 1] x [1 4 1] / 36) is the spline evaluated analytically there. The x
// and y coordinates (linear in the grid indices) give the parameters.
TEST(CatmullClark, RegularGridReproducesTheBicubicBSpline) {
  const int n = 10;
  PolygonMesh grid = test::quad_grid(n, n);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> height(-1.0, 1.0);
  std::vector<double> h;
  for (Vec3& p : grid.positions) p.z = h.emplace_back(height(rng));
  auto basis = [](double t) {  // uniform cubic B-spline centred at 0
    t = std::fabs(t);
    return t < 1 ? 2.0 / 3.0 - t * t + t * t * t / 2 : t < 2 ? (2 - t) * (2 - t) * (2 - t) / 6 : 0.0;
  };
  auto spline = [&](double u, double v) {
    double z = 0;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) z += h[static_cast<std::size_t>(j * (n + 1) + i)] * basis(u - i) * basis(v - j);
    return z;
  };
  RefineOptions o;
  o.levels = 2;
  const PolygonMesh fine = refine(grid, catmull_clark_scheme(), o);
  const MeshTopology t(fine);
  int checked = 0;
  for (Index v = 0; v < fine.vertex_count(); ++v) {
    const Vec3 p = fine.positions[v];
    if (p.x < 3.5 || p.x > n - 3.5 || p.y < 3.5 || p.y > n - 3.5) continue;
    ASSERT_EQ(t.valence(v), 4);
    Vec3 limit = 16.0 * p;
    for (const Index e : t.vertex_edges(v)) limit += 4.0 * fine.positions[t.other_vertex(e, v)];
    for (const Index c : t.vertex_corners(v)) limit += fine.positions[t.corner_vertex(t.corner_next(t.corner_next(c)))];
    limit = (1.0 / 36.0) * limit;
    EXPECT_NEAR(limit.x, p.x, 1e-12);
    EXPECT_NEAR(limit.z, spline(limit.x, limit.y), 1e-12) << "at " << limit.x << ", " << limit.y;
    ++checked;
  }
  EXPECT_EQ(checked, 13 * 13);  // parameters 3.5 .. 6.5 in steps of 1/4
}

// A square pyramid: the base quad and four triangles, all of its edges smooth.
PolygonMesh pyramid(bool smooth_triangles) {
  PolygonMesh mesh = make_mesh({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 1.5}},
                               {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
  if (smooth_triangles) {
    mesh.tags.triangle_subdivision = TriangleSubdivision::smooth;
    mesh.tags.triangle_subdivision_set = true;
  }
  return mesh;
}

// OpenSubdiv's TRI_SUB_SMOOTH edge rule (Sdc catmarkScheme.h): face points
// weighted w = (w0 + w1) / 2 with 0.47 for a triangle, 1/4 for a quad; ends
// (1 - 2w) / 2. A face point is its face's centroid.
TEST(CatmullClark, SmoothTriangleRuleWeightsFacePointsNextToTriangles) {
  const PolygonMesh mesh = pyramid(true);
  const StencilTable t = grid_stencils(mesh);
  // Between two triangles (0, 1, 4) and (3, 0, 4): w = 0.47, ends 0.03.
  const auto apex_edge = test::merged_row(t, edge_point(mesh, 0, 4));
  ASSERT_EQ(apex_edge.size(), 4u);
  EXPECT_NEAR(apex_edge.at(0), 0.03 + 2 * 0.47 / 3, 1e-15);
  EXPECT_NEAR(apex_edge.at(4), 0.03 + 2 * 0.47 / 3, 1e-15);
  EXPECT_NEAR(apex_edge.at(1), 0.47 / 3, 1e-15);
  EXPECT_NEAR(apex_edge.at(3), 0.47 / 3, 1e-15);
  // Between the triangle (0, 1, 4) and the quad: w = 0.36, ends 0.14.
  const auto base_edge = test::merged_row(t, edge_point(mesh, 0, 1));
  ASSERT_EQ(base_edge.size(), 5u);
  EXPECT_NEAR(base_edge.at(0), 0.14 + 0.36 / 3 + 0.36 / 4, 1e-15);
  EXPECT_NEAR(base_edge.at(1), 0.14 + 0.36 / 3 + 0.36 / 4, 1e-15);
  EXPECT_NEAR(base_edge.at(4), 0.36 / 3, 1e-15);
  EXPECT_NEAR(base_edge.at(2), 0.36 / 4, 1e-15);
  EXPECT_NEAR(base_edge.at(3), 0.36 / 4, 1e-15);
  for (Index row = 0; row < t.row_count(); ++row) {
    double sum = 0.0;
    for (const auto& [vertex, weight] : test::merged_row(t, row)) sum += weight;
    EXPECT_NEAR(sum, 1.0, 1e-15) << "row " << row;
  }
}

TEST(CatmullClark, SmoothTriangleRuleLeavesOtherPointsAlone) {
  const StencilTable plain = grid_stencils(pyramid(false));
  const StencilTable smooth = grid_stencils(pyramid(true));
  const PolygonMesh mesh = pyramid(false);
  const Index edge_points_begin = mesh.face_count(), vertex_points_begin = edge_points_begin + MeshTopology(mesh).edge_count();
  ASSERT_EQ(plain.row_count(), smooth.row_count());
  for (Index row = 0; row < plain.row_count(); ++row) {
    const bool is_edge_point = row >= edge_points_begin && row < vertex_points_begin;
    // Every edge of the pyramid touches a triangle: every edge point moves, nothing else.
    EXPECT_EQ(test::merged_row(plain, row) != test::merged_row(smooth, row), is_edge_point) << "row " << row;
  }
  // A mesh without triangles refines the same with the tag or without.
  PolygonMesh cube = test::cube();
  const StencilTable before = grid_stencils(cube);
  cube.tags.triangle_subdivision = TriangleSubdivision::smooth;
  const StencilTable after = grid_stencils(cube);
  for (Index row = 0; row < before.row_count(); ++row)
    EXPECT_EQ(test::merged_row(before, row), test::merged_row(after, row)) << "row " << row;
  // The refined mesh has no triangles: the second level is the same either way.
  RefineOptions two;
  two.levels = 2;
  const std::vector<StencilTable> levels_plain = refine_stencils(pyramid(false), catmull_clark_scheme(), two);
  const std::vector<StencilTable> levels_smooth = refine_stencils(pyramid(true), catmull_clark_scheme(), two);
  for (Index row = 0; row < levels_plain.at(1).row_count(); ++row)
    EXPECT_EQ(test::merged_row(levels_plain.at(1), row), test::merged_row(levels_smooth.at(1), row)) << "row " << row;
}

TEST(CatmullClark, TriangleRuleOptionOverridesTheTag) {
  RefineOptions smooth;
  smooth.triangle_subdivision = TriangleSubdivision::smooth;
  RefineOptions catmark;
  catmark.triangle_subdivision = TriangleSubdivision::catmark;
  const StencilTable tagged = grid_stencils(pyramid(true));
  const StencilTable untagged = grid_stencils(pyramid(false));
  const StencilTable by_option = refine_stencils(pyramid(false), catmull_clark_scheme(), smooth).at(0);
  const StencilTable overridden = refine_stencils(pyramid(true), catmull_clark_scheme(), catmark).at(0);
  for (Index row = 0; row < tagged.row_count(); ++row) {
    EXPECT_EQ(test::merged_row(by_option, row), test::merged_row(tagged, row)) << "row " << row;
    EXPECT_EQ(test::merged_row(overridden, row), test::merged_row(untagged, row)) << "row " << row;
  }
  // The refined mesh's tags name the rule it was made with.
  const PolygonMesh child = refine(pyramid(false), catmull_clark_scheme(), smooth);
  EXPECT_EQ(child.tags.triangle_subdivision, TriangleSubdivision::smooth);
  EXPECT_TRUE(child.tags.triangle_subdivision_set);
  EXPECT_FALSE(refine(pyramid(false), catmull_clark_scheme(), {}).tags.triangle_subdivision_set);
}

}  // namespace
}  // namespace subdiv
