// The grid path of refine() (src/refine/grid_refine.h) against its
// definition, the masks: the declared grid rule is the masks' regular
// stencil; refining with grids gives the masks' mesh (faces identical,
// positions within 1e-14 of the mesh's size) and the masks' stencil tables
// on code-built, bundled and shared meshes, tags, vertex and face-varying
// channels included; results do not depend on the thread count; and the
// path declines what it does not cover.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

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

constexpr double kRelativeTolerance = 1e-14;  // of the bounding-box diagonal

// A closed torus of n x n quads, every vertex of valence 4, positions
// generic (no symmetry hides a misplaced weight).
PolygonMesh torus(int n) {
  PolygonMesh mesh;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / n;
      const double r = 1.0 + 0.3 * std::cos(v) + 0.05 * std::sin(7.0 * i + 3.0 * j);
      mesh.positions.push_back({r * std::cos(u), r * std::sin(u), 0.3 * std::sin(v) + 0.02 * std::cos(5.0 * i)});
    }
  auto id = [n](int i, int j) { return static_cast<Index>(((j + n) % n) * n + (i + n) % n); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) mesh.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return mesh;
}

double diagonal(const PolygonMesh& mesh) {
  Vec3 lo = mesh.positions.front(), hi = lo;
  for (const Vec3& p : mesh.positions)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  return std::max(norm(hi - lo), 1e-300);
}

RefineOptions with_grids(bool grids, int levels) {
  RefineOptions options;
  options.levels = levels;
  options.regular_grids = grids;
  return options;
}

// The grid path's result equals the masks': faces identical, positions close.
void expect_grids_equal_masks(const PolygonMesh& mesh, const Scheme& scheme, int levels, const std::string& what) {
  const PolygonMesh grids = refine(mesh, scheme, with_grids(true, levels));
  const PolygonMesh masks = refine(mesh, scheme, with_grids(false, levels));
  ASSERT_EQ(grids.face_offsets, masks.face_offsets) << what;
  ASSERT_EQ(grids.face_indices, masks.face_indices) << what;
  ASSERT_EQ(grids.vertex_count(), masks.vertex_count()) << what;
  EXPECT_EQ(grids.tags, masks.tags) << what;
  const double tolerance = kRelativeTolerance * diagonal(mesh);
  double worst = 0.0;
  Index at = 0;
  for (Index v = 0; v < grids.vertex_count(); ++v) {
    const double d = norm(grids.positions[static_cast<std::size_t>(v)] - masks.positions[static_cast<std::size_t>(v)]);
    if (d > worst) worst = d, at = v;
  }
  EXPECT_LE(worst, tolerance) << what << ": vertex " << at;
  // Face-varying values are midpoints and centroids made in the same order: identical.
  EXPECT_EQ(grids.face_varying_channels.size(), masks.face_varying_channels.size()) << what;
  for (std::size_t ch = 0; ch < grids.face_varying_channels.size() && ch < masks.face_varying_channels.size(); ++ch) {
    const FaceVaryingChannel& a = grids.face_varying_channels[ch];
    const FaceVaryingChannel& b = masks.face_varying_channels[ch];
    EXPECT_EQ(a.name, b.name) << what;
    EXPECT_EQ(a.components, b.components) << what;
    EXPECT_EQ(a.indices, b.indices) << what << ": face-varying channel " << a.name;
    EXPECT_TRUE(a.values == b.values) << what << ": face-varying channel " << a.name;
  }
  ASSERT_EQ(grids.vertex_channels.size(), masks.vertex_channels.size()) << what;
  for (std::size_t ch = 0; ch < grids.vertex_channels.size(); ++ch) {
    const VertexChannel& a = grids.vertex_channels[ch];
    const VertexChannel& b = masks.vertex_channels[ch];
    EXPECT_EQ(a.name, b.name) << what;
    EXPECT_EQ(a.components, b.components) << what;
    ASSERT_EQ(a.values.size(), b.values.size()) << what;
    double scale = 1.0;  // the channel's largest value
    for (const double v : b.values) scale = std::max(scale, std::abs(v));
    for (std::size_t i = 0; i < a.values.size(); ++i)
      ASSERT_NEAR(a.values[i], b.values[i], kRelativeTolerance * scale) << what << ": channel " << a.name << " value " << i;
  }
}

// The grid path's stencil table equals the masks': the same rows, with the
// same sources, weights within 1e-14.
void expect_grid_stencils_equal_masks(const PolygonMesh& mesh, const Scheme& scheme, int levels,
                                      const std::string& what) {
  const StencilTable grids = refine_stencil_table(mesh, scheme, with_grids(true, levels));
  const StencilTable masks = refine_stencil_table(mesh, scheme, with_grids(false, levels));
  ASSERT_EQ(grids.source_count(), masks.source_count()) << what;
  ASSERT_EQ(grids.row_count(), masks.row_count()) << what;
  for (Index r = 0; r < grids.row_count(); ++r) {
    const auto gv = grids.row_vertices(r), mv = masks.row_vertices(r);
    ASSERT_EQ(std::vector<Index>(gv.begin(), gv.end()), std::vector<Index>(mv.begin(), mv.end())) << what << ": row " << r;
    const auto gw = grids.row_weights(r), mw = masks.row_weights(r);
    for (std::size_t j = 0; j < gw.size(); ++j) ASSERT_NEAR(gw[j], mw[j], kRelativeTolerance) << what << ": row " << r;
  }
}

// The mesh with a face-varying channel of two components whose values are
// shared within rows of faces and split between them (seams).
PolygonMesh with_face_varying(PolygonMesh mesh) {
  FaceVaryingChannel uv{"uv", 2, {}, {}};
  for (Index f = 0; f < mesh.face_count(); ++f)
    for (Index c = 0; c < mesh.face_size(f); ++c) {
      const Vec3& p = mesh.positions[static_cast<std::size_t>(mesh.face(f)[static_cast<std::size_t>(c)])];
      uv.indices.push_back(static_cast<Index>(uv.values.size() / 2));
      uv.values.push_back(p.x / 3.0 + (f % 3 == 0 ? 0.5 : 0.0));
      uv.values.push_back(p.y * p.z);
    }
  mesh.face_varying_channels = {uv};
  return mesh;
}

// The mesh with two vertex channels, of one value and of three.
PolygonMesh with_channels(PolygonMesh mesh) {
  VertexChannel one{"height", 1, {}}, three{"colour", 3, {}};
  for (const Vec3& p : mesh.positions) {
    one.values.push_back(std::sin(3.0 * p.x + p.y));
    for (const double c : {std::cos(p.z), p.x * p.y, 0.5 - p.z}) three.values.push_back(c);
  }
  mesh.vertex_channels = {one, three};
  return mesh;
}

// Whether refine() takes the grid path for the last `remaining` levels of
// this mesh, as asked at its start.
bool takes_grids(const PolygonMesh& mesh, const Scheme& scheme, int remaining) {
  const MeshTopology topology(mesh);
  return detail::refine_as_grids(mesh, topology, scheme, with_grids(true, remaining), remaining).has_value();
}

TEST(GridRefine, DeclaredRuleIsTheMasksRegularStencil) {
  // One level of the masks recorded as stencils on the torus: each child's
  // row must be the tensor product of the declared line weights.
  const PolygonMesh mesh = torus(6);
  const MeshTopology t(mesh);
  for (const Scheme* scheme : {&catmull_clark_scheme(), &bilinear_scheme()}) {
    SCOPED_TRACE(std::string(scheme->name));
    const RegularGrid& rule = *scheme->fast_path.regular_grid;
    ASSERT_EQ(rule.even[0], rule.even[2]);  // symmetric, so the frame's direction does not matter
    ASSERT_EQ(rule.odd[0], rule.odd[1]);
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
      for (const Index v : t.face_vertices(f)) EXPECT_DOUBLE_EQ(weight(f, v), rule.odd[0] * rule.odd[1]);
      EXPECT_NEAR(row_sum(f), 4 * rule.odd[0] * rule.odd[1], 1e-15);
    }
    for (Index e = 0; e < ne; ++e) {  // edge point: odd along the edge, even across it
      const auto [a, b] = t.edge_vertices(e);
      EXPECT_DOUBLE_EQ(weight(nf + e, a), rule.odd[0] * rule.even[1]);
      EXPECT_DOUBLE_EQ(weight(nf + e, b), rule.odd[1] * rule.even[1]);
      double others = 0.0;  // the two quads' other corners, odd x even[0 or 2] each
      for (const Index c : t.edge_corners(e))
        for (const Index v : t.face_vertices(t.corner_face(c)))
          if (v != a && v != b) {
            EXPECT_DOUBLE_EQ(weight(nf + e, v), rule.odd[0] * rule.even[0]);
            others += weight(nf + e, v);
          }
      EXPECT_NEAR(row_sum(nf + e), weight(nf + e, a) + weight(nf + e, b) + others, 1e-15);
    }
    for (Index v = 0; v < t.vertex_count(); ++v) {  // vertex point: even x even
      const Index row = nf + ne + v;
      EXPECT_DOUBLE_EQ(weight(row, v), rule.even[1] * rule.even[1]);
      for (const Index e : t.vertex_edges(v)) EXPECT_DOUBLE_EQ(weight(row, t.other_vertex(e, v)), rule.even[0] * rule.even[1]);
      for (const Index c : t.vertex_corners(v))  // the diagonal: the corner opposite v
        EXPECT_DOUBLE_EQ(weight(row, t.corner_vertex(t.corner_next(t.corner_next(c)))), rule.even[0] * rule.even[2]);
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

}  // namespace
}  // namespace subdiv
