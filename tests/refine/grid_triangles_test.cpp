// The grid path of the triangle split (src/refine/grid_triangles.h) against
// its definition, the masks: the declared three-direction rule is the
// masks' regular stencil; the lattice kernel reads only the points it holds;
// refining with grids gives the masks' mesh (faces identical, positions
// within 1e-14 of the mesh's size) and the masks' stencil tables on
// code-built, bundled and shared meshes, tags, vertex and face-varying
// channels included; results do not depend on the thread count; and the
// path declines what it does not cover.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "grid_test_support.h"
#include "refine/grid_triangles.h"
#include "refine/triangle_patch.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/linear.h"
#include "subdiv/rules/loop.h"
#include "support/opensubdiv_shapes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

namespace fs = std::filesystem;
using namespace grid_test;

std::vector<const Scheme*> triangle_schemes() { return {&loop_scheme(), &loop_warren_scheme(), &linear_scheme()}; }

TEST(GridTriangles, DeclaredRuleIsTheMasksRegularStencil) {
  // One level of the masks recorded as stencils on the torus, every vertex
  // of valence 6: each child's row must be the declared weights.
  const PolygonMesh mesh = triangulated_torus(6);
  const MeshTopology t(mesh);
  for (const Scheme* scheme : triangle_schemes()) {
    SCOPED_TRACE(std::string(scheme->name));
    const RegularTriangleGrid& rule = *scheme->fast_path.regular_triangle_grid;
    const StencilTable table = refine_stencil_table(mesh, *scheme, with_grids(false, 1));
    auto weight = [&](Index row, Index vertex) {
      const auto vs = table.row_vertices(row);
      const auto ws = table.row_weights(row);
      double w = 0.0;
      for (std::size_t j = 0; j < vs.size(); ++j)
        if (vs[j] == vertex) w += ws[j];
      return w;
    };
    auto row_sum = [&](Index row) {
      double s = 0.0;
      for (const double w : table.row_weights(row)) s += w;
      return s;
    };
    const Index ne = t.edge_count();
    for (Index e = 0; e < ne; ++e) {  // edge points first: near at the ends, far at the opposite vertices
      const auto [a, b] = t.edge_vertices(e);
      EXPECT_DOUBLE_EQ(weight(e, a), rule.near);
      EXPECT_DOUBLE_EQ(weight(e, b), rule.near);
      ASSERT_EQ(t.edge_corners(e).size(), 2U);
      for (const Index c : t.edge_corners(e)) EXPECT_DOUBLE_EQ(weight(e, t.corner_vertex(t.corner_prev(c))), rule.far);
      EXPECT_NEAR(row_sum(e), 2 * rule.near + 2 * rule.far, 1e-15);
    }
    for (Index v = 0; v < t.vertex_count(); ++v) {  // then vertex points: centre and ring
      ASSERT_EQ(t.valence(v), 6);
      EXPECT_DOUBLE_EQ(weight(ne + v, v), rule.centre);
      for (const Index e : t.vertex_edges(v)) EXPECT_DOUBLE_EQ(weight(ne + v, t.other_vertex(e, v)), rule.ring);
      EXPECT_NEAR(row_sum(ne + v), rule.centre + 6 * rule.ring, 1e-15);
    }
  }
}

TEST(GridTriangles, KernelReadsOnlyTheHexagonAndIsSymmetric) {
  // Each slot's unit impulse refined: the four slots outside the hexagon
  // ((-1, -1), (2, 1), (1, 2), (2, 2)) must reach no point of the triangle,
  // every point's weights sum to 1, and mirroring the triangle across its
  // line i = j (swapping i and j) mirrors the weights.
  const RegularTriangleGrid& rule = *loop_scheme().fast_path.regular_triangle_grid;
  ASSERT_EQ(rule.patch_reach(), 1);
  auto slot = [](int i, int j) { return static_cast<std::size_t>((i + 1) + 4 * (j + 1)); };
  for (int levels = 1; levels <= 5; ++levels) {
    const int n = 1 << levels;
    const std::vector<double> weights = detail::triangle_point_weights(rule, levels);
    ASSERT_EQ(weights.size(), static_cast<std::size_t>((n + 1) * (n + 1)) * 16);
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i) {
        const std::span<const double> w(weights.data() + static_cast<std::size_t>(i + (n + 1) * j) * 16, 16);
        const std::span<const double> mirrored(weights.data() + static_cast<std::size_t>(j + (n + 1) * i) * 16, 16);
        double sum = 0.0;
        for (const double x : w) sum += x;
        EXPECT_NEAR(sum, 1.0, 1e-14) << "point (" << i << ", " << j << ") after " << levels << " levels";
        for (const auto& [a, b] : {std::pair{-1, -1}, std::pair{2, 1}, std::pair{1, 2}, std::pair{2, 2}})
          EXPECT_EQ(w[slot(a, b)], 0.0) << "slot (" << a << ", " << b << ") reaches point (" << i << ", " << j << ")";
        for (int b = -1; b <= 2; ++b)
          for (int a = -1; a <= 2; ++a) EXPECT_NEAR(w[slot(a, b)], mirrored[slot(b, a)], 1e-15);
      }
  }
}

TEST(GridTriangles, EqualsTheMasksOnCodeBuiltMeshes) {
  for (const Scheme* scheme : triangle_schemes()) {
    for (int levels = 1; levels <= 4; ++levels) {
      const std::string what = std::string(scheme->name) + ", " + std::to_string(levels) + " levels";
      expect_grids_equal_masks(triangulated_torus(5), *scheme, levels, "torus, " + what);
      expect_grids_equal_masks(test::jittered(test::triangle_grid(7, 5), 3), *scheme, levels, "open grid, " + what);
      expect_grids_equal_masks(test::jittered(triangulate(test::cube()), 1), *scheme, levels + 2, "cube, " + what);
      expect_grids_equal_masks(test::tetrahedron(), *scheme, levels + 2, "tetrahedron, " + what);
      if (levels <= 2) {
        expect_grids_equal_masks(test::jittered(test::triangle_grid(24, 20), 4), *scheme, levels, "open grid, " + what);
        expect_grids_equal_masks(with_channels(test::jittered(test::triangle_grid(24, 20), 4)), *scheme, levels,
                                 "open grid with vertex channels, " + what);
      }
      expect_grids_equal_masks(with_channels(triangulated_torus(5)), *scheme, levels,
                               "torus with vertex channels, " + what);
      expect_grids_equal_masks(with_face_varying(triangulated_torus(6)), *scheme, levels,
                               "torus with face-varying values, " + what);
    }
  }
  // Both routes were compared: all-grid faces (the torus) and faces refined
  // by the masks around them (the open grid's rim).
  EXPECT_TRUE(takes_grids(triangulated_torus(5), loop_scheme(), 3));
  EXPECT_TRUE(takes_grids(test::triangle_grid(24, 20), loop_scheme(), 3));
}

// A triangulated torus with every kind of tag: a loop of semi-sharp edges,
// an infinitely sharp edge, corner tags (semi-sharp and infinite) and
// holes, one listed twice.
PolygonMesh tagged_triangulated_torus() {
  const Index n = 32;
  PolygonMesh mesh = triangulated_torus(n);
  for (Index i = 0; i < n; ++i) mesh.tags.creases.push_back({i, (i + 1) % n, 1.5});
  mesh.tags.creases.push_back({n * 8 + 3, n * 9 + 3, kInfiniteSharpness});
  mesh.tags.corners.push_back({.vertex = n * 4 + 9, .sharpness = 2.5, .type = CornerType::unspecified, .angle = {}});
  mesh.tags.corners.push_back(
      {.vertex = n * 20 + 2, .sharpness = kInfiniteSharpness, .type = CornerType::unspecified, .angle = {}});
  mesh.tags.holes = {1400, 37, 1400};
  return mesh;
}

TEST(GridTriangles, EqualsTheMasksWithTags) {
  const PolygonMesh mesh = tagged_triangulated_torus();
  EXPECT_TRUE(takes_grids(mesh, loop_scheme(), 3));
  for (int levels = 1; levels <= 4; ++levels) {
    const std::string what = "tagged torus, " + std::to_string(levels) + " levels";
    expect_grids_equal_masks(mesh, loop_scheme(), levels, what);
    expect_grid_stencils_equal_masks(mesh, loop_scheme(), levels, what);
  }
}

TEST(GridTriangles, EqualsTheMasksOnRealMeshes) {
  std::vector<fs::path> files;
  const fs::path shapes = test::opensubdiv_shape_dir();
  if (fs::is_directory(shapes))
    for (const auto& entry : fs::directory_iterator(shapes))
      if (entry.path().extension() == ".obj") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  int compared = 0, by_grids = 0;
  for (const fs::path& file : files) {
    PolygonMesh mesh;
    try {
      mesh = read_mesh(file.string()).mesh;
    } catch (const Error&) {
      continue;  // the deliberately broken shapes
    }
    mesh.tags.boundary_interpolation = BoundaryInterpolation::edge_and_corner;
    if (!test::rejection(mesh, loop_scheme(), with_grids(true, 1)).empty()) continue;  // not triangles, or not refinable
    // These small shapes are mostly extraordinary: the path applies after
    // a level or two of the masks, so five are compared where that is quick.
    for (int levels = 2; levels <= (mesh.face_count() <= 200 ? 5 : 4); ++levels)
      expect_grids_equal_masks(mesh, loop_scheme(), levels, file.filename().string());
    if (mesh.face_count() <= 200)
      by_grids += takes_grids(refine(mesh, loop_scheme(), with_grids(false, 2)), loop_scheme(), 3);
    ++compared;
  }
  if (!fs::is_directory(shapes)) GTEST_SKIP() << "shared OpenSubdiv shapes not found at " << shapes;
  EXPECT_GE(compared, 4);
  // loop_cube and the face-varying boundary shapes.
  EXPECT_GE(by_grids, 4) << "the grid path took too few meshes to be tested by them";
}

TEST(GridTriangles, StencilTablesEqualTheMasks) {
  for (const Scheme* scheme : triangle_schemes())
    for (int levels = 1; levels <= 3; ++levels) {
      const std::string what = std::string(scheme->name) + ", " + std::to_string(levels) + " levels";
      expect_grid_stencils_equal_masks(triangulated_torus(5), *scheme, levels, "torus, " + what);
      expect_grid_stencils_equal_masks(test::jittered(test::triangle_grid(24, 20), 4), *scheme, levels,
                                       "open grid, " + what);
      expect_grid_stencils_equal_masks(triangulate(test::cube()), *scheme, levels + 2, "cube, " + what);
    }
}

TEST(GridTriangles, SameResultForAnyThreadCount) {
  for (const PolygonMesh& mesh : {triangulated_torus(40), test::jittered(test::triangle_grid(30, 20), 5)}) {
    RefineOptions one = with_grids(true, 3), two = one;
    one.threads = 1;
    two.threads = 2;
    const PolygonMesh a = refine(mesh, loop_scheme(), one);
    const PolygonMesh b = refine(mesh, loop_scheme(), two);
    EXPECT_EQ(a.face_indices, b.face_indices);
    EXPECT_TRUE(a.positions == b.positions) << "positions differ between one and two threads";
    const StencilTable c = refine_stencil_table(mesh, loop_scheme(), one);
    const StencilTable d = refine_stencil_table(mesh, loop_scheme(), two);
    ASSERT_EQ(c.row_count(), d.row_count());
    for (Index r = 0; r < c.row_count(); ++r) {
      ASSERT_TRUE(std::ranges::equal(c.row_vertices(r), d.row_vertices(r))) << "row " << r;
      ASSERT_TRUE(std::ranges::equal(c.row_weights(r), d.row_weights(r))) << "row " << r;
    }
  }
}

// refine() takes triangles as grids from 2 remaining levels on
// (kMinTriangleGridLevels); the path itself covers 1 level too (its
// numbering's shortest case, and the direct evaluation's).
TEST(GridTriangles, OneAndTwoLevelsEqualTheMasks) {
  for (const PolygonMesh& mesh : {with_face_varying(with_channels(triangulated_torus(6))), tagged_triangulated_torus(),
                                  test::jittered(test::triangle_grid(24, 20), 4)})
    for (int levels = 1; levels <= 2; ++levels) {
      const MeshTopology topology(mesh);
      const std::optional<PolygonMesh> grids =
          detail::refine_triangles_as_grids(mesh, topology, loop_scheme(), with_grids(true, levels), levels);
      ASSERT_TRUE(grids.has_value()) << levels << " levels";
      const PolygonMesh masks = refine(mesh, loop_scheme(), with_grids(false, levels));
      EXPECT_EQ(grids->face_indices, masks.face_indices) << levels << " levels";
      EXPECT_EQ(grids->tags, masks.tags) << levels << " levels";
      ASSERT_EQ(grids->vertex_count(), masks.vertex_count());
      for (Index v = 0; v < masks.vertex_count(); ++v)
        ASSERT_LE(norm(grids->positions[static_cast<std::size_t>(v)] - masks.positions[static_cast<std::size_t>(v)]),
                  kRelativeTolerance * diagonal(mesh))
            << levels << " levels, vertex " << v;
      ASSERT_EQ(grids->face_varying_channels.size(), masks.face_varying_channels.size());
      for (std::size_t ch = 0; ch < masks.face_varying_channels.size(); ++ch) {
        EXPECT_EQ(grids->face_varying_channels[ch].indices, masks.face_varying_channels[ch].indices);
        EXPECT_TRUE(grids->face_varying_channels[ch].values == masks.face_varying_channels[ch].values);
      }
    }
}

TEST(GridTriangles, DeclinesWhatItDoesNotCover) {
  EXPECT_TRUE(takes_grids(triangulated_torus(6), loop_scheme(), detail::kMinTriangleGridLevels));
  // too few levels to repay the grids
  EXPECT_FALSE(takes_grids(triangulated_torus(6), loop_scheme(), detail::kMinTriangleGridLevels - 1));
  // Two faces on the same three vertices: the split's numbering merges
  // their children's edges (a non-manifold edge, so refined only when
  // allowed), which the generic construction handles.
  PolygonMesh closed_pillow;
  closed_pillow.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  closed_pillow.add_face({0, 1, 2});
  closed_pillow.add_face({0, 2, 1});
  RefineOptions grids = with_grids(true, 3), masks = with_grids(false, 3);
  grids.allow_non_manifold = masks.allow_non_manifold = true;
  EXPECT_FALSE(detail::refine_triangles_as_grids(closed_pillow, MeshTopology(closed_pillow), loop_scheme(), grids, 3));
  EXPECT_EQ(refine(closed_pillow, loop_scheme(), grids).face_indices,
            refine(closed_pillow, loop_scheme(), masks).face_indices);
  // Quads are not its faces; piecewise-smooth rules are the masks'.
  EXPECT_FALSE(takes_grids(torus(6), loop_scheme(), 3));
  const PolygonMesh torus6 = triangulated_torus(6);
  const MeshTopology topology(torus6);
  RefineOptions piecewise = with_grids(true, 3);
  piecewise.boundary_rules = BoundaryRules::piecewise_smooth;
  EXPECT_FALSE(detail::refine_as_grids(torus6, topology, loop_scheme(), piecewise, 3));
  // Mostly extraordinary meshes take the masks first.
  EXPECT_FALSE(takes_grids(test::tetrahedron(), loop_scheme(), 3));
}

}  // namespace
}  // namespace subdiv
