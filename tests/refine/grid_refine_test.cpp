// The grid path of refine() (src/refine/grid_refine.h) against its
// definition, the masks: the declared grid rule is the masks' regular
// stencil; refining with grids gives the masks' mesh (faces identical,
// positions within 1e-14 of the mesh's size) and the masks' stencil tables
// on code-built, bundled and shared meshes, tags, vertex and face-varying
// channels included; results do not depend on the thread count; and the
// path declines what it does not cover.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include "grid_test_support.h"
#include "refine/grid_patch.h"
#include "refine/grid_refine.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/bilinear.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/opensubdiv_shapes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

namespace fs = std::filesystem;

using namespace grid_test;

TEST(GridRefine, DeclaredRuleIsTheMasksRegularStencil) {
  // One level of the masks recorded as stencils on the torus: each child's
  // row must be the tensor product of the declared line weights.
  const PolygonMesh mesh = torus(6);
  const MeshTopology t(mesh);
  for (const Scheme* scheme : {&catmull_clark_scheme(), &bilinear_scheme()}) {
    SCOPED_TRACE(std::string(scheme->name));
    const RegularGrid& rule = *scheme->fast_path.regular_grid;
    ASSERT_EQ(rule.patch_reach(), 1);  // the outer weights are 0: even[1..3], odd[1..2] below
    ASSERT_EQ(rule.even[1], rule.even[3]);  // symmetric, so the frame's direction does not matter
    ASSERT_EQ(rule.odd[1], rule.odd[2]);
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
    const Index nf = t.face_count(), ne = t.edge_count();
    for (Index f = 0; f < nf; ++f) {  // face point: odd x odd on the face's corners
      for (const Index v : t.face_vertices(f)) EXPECT_DOUBLE_EQ(weight(f, v), rule.odd[1] * rule.odd[2]);
      EXPECT_NEAR(row_sum(f), 4 * rule.odd[1] * rule.odd[2], 1e-15);
    }
    for (Index e = 0; e < ne; ++e) {  // edge point: odd along the edge, even across it
      const auto [a, b] = t.edge_vertices(e);
      EXPECT_DOUBLE_EQ(weight(nf + e, a), rule.odd[1] * rule.even[2]);
      EXPECT_DOUBLE_EQ(weight(nf + e, b), rule.odd[2] * rule.even[2]);
      double others = 0.0;  // the two quads' other corners, odd x even[1 or 3] each
      for (const Index c : t.edge_corners(e))
        for (const Index v : t.face_vertices(t.corner_face(c)))
          if (v != a && v != b) {
            EXPECT_DOUBLE_EQ(weight(nf + e, v), rule.odd[1] * rule.even[1]);
            others += weight(nf + e, v);
          }
      EXPECT_NEAR(row_sum(nf + e), weight(nf + e, a) + weight(nf + e, b) + others, 1e-15);
    }
    for (Index v = 0; v < t.vertex_count(); ++v) {  // vertex point: even x even
      const Index row = nf + ne + v;
      EXPECT_DOUBLE_EQ(weight(row, v), rule.even[2] * rule.even[2]);
      for (const Index e : t.vertex_edges(v)) EXPECT_DOUBLE_EQ(weight(row, t.other_vertex(e, v)), rule.even[1] * rule.even[2]);
      for (const Index c : t.vertex_corners(v))  // the diagonal: the corner opposite v
        EXPECT_DOUBLE_EQ(weight(row, t.corner_vertex(t.corner_next(t.corner_next(c)))), rule.even[1] * rule.even[3]);
      EXPECT_NEAR(row_sum(row), 1.0, 1e-15);
    }
  }
}

TEST(GridRefine, EqualsTheMasksOnCodeBuiltMeshes) {
  for (const Scheme* scheme : {&catmull_clark_scheme(), &bilinear_scheme()}) {
    for (int levels = 1; levels <= 4; ++levels) {
      const std::string what = std::string(scheme->name) + ", " + std::to_string(levels) + " levels";
      expect_grids_equal_masks(torus(5), *scheme, levels, "torus, " + what);
      expect_grids_equal_masks(test::jittered(test::quad_grid(7, 5), 3), *scheme, levels, "open grid, " + what);
      expect_grids_equal_masks(test::jittered(test::cube(), 1), *scheme, levels + 2, "cube, " + what);
      if (levels <= 2) {
        expect_grids_equal_masks(test::jittered(test::quad_grid(24, 20), 4), *scheme, levels, "open grid, " + what);
        expect_grids_equal_masks(with_channels(test::jittered(test::quad_grid(24, 20), 4)), *scheme, levels,
                                 "open grid with vertex channels, " + what);
      }
      expect_grids_equal_masks(with_channels(torus(5)), *scheme, levels, "torus with vertex channels, " + what);
      expect_grids_equal_masks(with_face_varying(torus(6)), *scheme, levels, "torus with face-varying values, " + what);
    }
  }
  // The comparisons above covered both routes of the path: all-grid faces
  // (the torus) and faces refined by the masks around them (the grid's rim).
  EXPECT_TRUE(takes_grids(torus(5), catmull_clark_scheme(), 3));
  EXPECT_TRUE(takes_grids(test::quad_grid(24, 20), catmull_clark_scheme(), 3));
}

// A torus with every kind of tag: a loop of semi-sharp edges, an infinitely
// sharp edge, corner tags (semi-sharp and infinite) and holes, one listed
// twice.
PolygonMesh tagged_torus() {
  const Index n = 32;
  PolygonMesh mesh = torus(n);
  for (Index i = 0; i < n; ++i) mesh.tags.creases.push_back({i, (i + 1) % n, 1.5});
  mesh.tags.creases.push_back({n * 8 + 3, n * 9 + 3, kInfiniteSharpness});
  mesh.tags.corners.push_back({.vertex = n * 4 + 9, .sharpness = 2.5, .type = CornerType::unspecified, .angle = {}});
  mesh.tags.corners.push_back(
      {.vertex = n * 20 + 2, .sharpness = kInfiniteSharpness, .type = CornerType::unspecified, .angle = {}});
  mesh.tags.holes = {700, 37, 700};
  return mesh;
}

TEST(GridRefine, EqualsTheMasksWithTags) {
  const PolygonMesh mesh = tagged_torus();
  EXPECT_TRUE(takes_grids(mesh, catmull_clark_scheme(), 3));
  for (int levels = 1; levels <= 4; ++levels) {
    expect_grids_equal_masks(mesh, catmull_clark_scheme(), levels, "tagged torus, " + std::to_string(levels) + " levels");
    expect_grid_stencils_equal_masks(mesh, catmull_clark_scheme(), levels,
                                     "tagged torus, " + std::to_string(levels) + " levels");
  }
}

TEST(GridRefine, EqualsTheMasksOnRealMeshes) {
  std::vector<fs::path> files;
  for (const char* name : {"cube.obj", "l_shape.obj", "spot_control_mesh.obj", "elephant.obj"})
    files.emplace_back(test::bundled_path(name));
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
    if (!test::rejection(mesh, catmull_clark_scheme(), with_grids(true, 1)).empty()) continue;
    for (int levels = 1; levels <= 3; ++levels)
      expect_grids_equal_masks(mesh, catmull_clark_scheme(), levels, file.filename().string());
    // Where the path applies from some level on, it is the one compared.
    const bool grids = takes_grids(refine(mesh, catmull_clark_scheme(), with_grids(false, 2)), catmull_clark_scheme(), 1);
    by_grids += grids;
    ++compared;
  }
  EXPECT_GE(compared, 4);
  // spot, and on the shared shapes the tori, a dart and the face-varying tests.
  EXPECT_GE(by_grids, fs::is_directory(shapes) ? 5 : 1) << "the grid path took too few meshes to be tested by them";
  if (!fs::is_directory(shapes)) GTEST_SKIP() << "shared OpenSubdiv shapes not found at " << shapes << "; bundled meshes only";
}

TEST(GridRefine, StencilTablesEqualTheMasks) {
  for (const Scheme* scheme : {&catmull_clark_scheme(), &bilinear_scheme()})
    for (int levels = 1; levels <= 3; ++levels) {
      const std::string what = std::string(scheme->name) + ", " + std::to_string(levels) + " levels";
      expect_grid_stencils_equal_masks(torus(5), *scheme, levels, "torus, " + what);
      expect_grid_stencils_equal_masks(test::jittered(test::quad_grid(24, 20), 4), *scheme, levels, "open grid, " + what);
      expect_grid_stencils_equal_masks(test::cube(), *scheme, levels + 2, "cube, " + what);
      expect_grid_stencils_equal_masks(read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh, *scheme, levels,
                                       "spot, " + what);
    }
}

TEST(GridRefine, SameResultForAnyThreadCount) {
  for (const PolygonMesh& mesh : {torus(40), test::jittered(test::quad_grid(30, 20), 5)}) {
    RefineOptions one = with_grids(true, 3), two = one;
    one.threads = 1;
    two.threads = 2;
    const PolygonMesh a = refine(mesh, catmull_clark_scheme(), one);
    const PolygonMesh b = refine(mesh, catmull_clark_scheme(), two);
    EXPECT_EQ(a.face_indices, b.face_indices);
    EXPECT_TRUE(a.positions == b.positions) << "positions differ between one and two threads";
    const StencilTable c = refine_stencil_table(mesh, catmull_clark_scheme(), one);
    const StencilTable d = refine_stencil_table(mesh, catmull_clark_scheme(), two);
    ASSERT_EQ(c.row_count(), d.row_count());
    for (Index r = 0; r < c.row_count(); ++r) {
      ASSERT_TRUE(std::ranges::equal(c.row_vertices(r), d.row_vertices(r))) << "row " << r;
      ASSERT_TRUE(std::ranges::equal(c.row_weights(r), d.row_weights(r))) << "row " << r;
    }
  }
}

TEST(GridRefine, DeclinesWhatItDoesNotCover) {
  const PolygonMesh plain = torus(6);
  EXPECT_TRUE(takes_grids(plain, catmull_clark_scheme(), 2));

  PolygonMesh creased = torus(20);  // a semi-sharp edge: its faces by the masks, the rest as grids
  creased.tags.creases.push_back({0, 1, 2.0});
  EXPECT_TRUE(takes_grids(creased, catmull_clark_scheme(), 2));
  creased.tags.crease_method = CreaseMethod::chaikin;  // whose creasing reads the edge's neighbours
  EXPECT_FALSE(takes_grids(creased, catmull_clark_scheme(), 2));

  EXPECT_TRUE(takes_grids(with_channels(plain), catmull_clark_scheme(), 2));
  PolygonMesh face_varying = plain;  // a face-varying channel, then one naming a value it does not have
  face_varying.face_varying_channels.push_back(
      {"uv", 1, std::vector<double>(plain.face_indices.size(), 0.5), std::vector<Index>(plain.face_indices.size())});
  for (std::size_t i = 0; i < plain.face_indices.size(); ++i) face_varying.face_varying_channels[0].indices[i] = static_cast<Index>(i);
  EXPECT_TRUE(takes_grids(face_varying, catmull_clark_scheme(), 2));
  face_varying.face_varying_channels[0].indices[5] = static_cast<Index>(plain.face_indices.size());
  EXPECT_FALSE(takes_grids(face_varying, catmull_clark_scheme(), 2));

  PolygonMesh with_triangle = plain;
  with_triangle.add_face({0, 7, 1});
  EXPECT_FALSE(takes_grids(with_triangle, catmull_clark_scheme(), 2));

  const MeshTopology topology(plain);
  RefineOptions piecewise = with_grids(true, 2);
  piecewise.boundary_rules = BoundaryRules::piecewise_smooth;
  EXPECT_FALSE(detail::refine_as_grids(plain, topology, catmull_clark_scheme(), piecewise, 2));
  EXPECT_FALSE(detail::refine_as_grids(plain, topology, loop_scheme(), with_grids(true, 2), 2));
  // Meshes that are mostly extraordinary take the masks first.
  EXPECT_FALSE(takes_grids(test::cube(), catmull_clark_scheme(), 2));
}

// On a 3 x 3 torus every vertex is regular, but a face's 4 x 4 patch wraps
// round and holds points twice: no face is a grid, and refine() takes the
// masks. On a 4 x 4 torus the patches just fit.
TEST(GridRefine, PatchesHoldingAPointTwiceAreNotGrids) {
  for (const int n : {3, 4}) {
    const PolygonMesh mesh = torus(n);
    const MeshTopology t(mesh);
    const std::vector<char> sharp(static_cast<std::size_t>(t.vertex_count()));
    std::array<Index, detail::kMaxPatchPoints> patch;
    for (Index f = 0; f < t.face_count(); ++f)
      EXPECT_EQ(detail::gather_patch(t, f, 1, sharp, patch), n == 4) << n << " x " << n << " torus, face " << f;
    EXPECT_EQ(takes_grids(mesh, catmull_clark_scheme(), 2), n == 4);
  }
}

TEST(GridRefine, SetAndDistinctFindsEveryRepeatAndGap) {
  std::array<Index, 16> points;
  std::iota(points.begin(), points.end(), 0);
  for (Index& p : points) p *= 1 << 26;  // equal high bits after hashing would collide: probing must still tell
  EXPECT_TRUE(detail::set_and_distinct(points));
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (i == j) continue;
      std::array<Index, 16> repeated = points;
      repeated[j] = repeated[i];
      EXPECT_FALSE(detail::set_and_distinct(repeated)) << i << " repeated at " << j;
    }
    std::array<Index, 16> gap = points;
    gap[i] = kInvalidIndex;
    EXPECT_FALSE(detail::set_and_distinct(gap)) << "gap at " << i;
  }
}

}  // namespace
}  // namespace subdiv
