#pragma once
// What the grid path's tests share: meshes with generic positions, vertex
// and face-varying channels, and the comparisons of the grid path with its
// definition, the masks.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "refine/grid_refine.h"
#include "subdiv/core/stencil_table.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"

namespace subdiv::grid_test {

inline constexpr double kRelativeTolerance = 1e-14;  // of the bounding-box diagonal

// A closed torus of n x n quads, every vertex of valence 4, positions
// generic (no symmetry hides a misplaced weight).
inline PolygonMesh torus(int n) {
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

inline double diagonal(const PolygonMesh& mesh) {
  Vec3 lo = mesh.positions.front(), hi = lo;
  for (const Vec3& p : mesh.positions)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  return std::max(norm(hi - lo), 1e-300);
}

inline RefineOptions with_grids(bool grids, int levels) {
  RefineOptions options;
  options.levels = levels;
  options.regular_grids = grids;
  return options;
}

// The grid path's result equals the masks': faces identical, positions close.
inline void expect_grids_equal_masks(const PolygonMesh& mesh, const Scheme& scheme, int levels, const std::string& what) {
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
// same sources, weights within 1e-14. Where the rules have negative weights
// (the Butterfly's), contributions can cancel: a source whose weight sums
// to zero may be listed by one table and not the other, so rows are then
// compared as sparse vectors, an absent source weighing 0.
inline void expect_grid_stencils_equal_masks(const PolygonMesh& mesh, const Scheme& scheme, int levels,
                                      const std::string& what, bool cancelling = false) {
  const StencilTable grids = refine_stencil_table(mesh, scheme, with_grids(true, levels));
  const StencilTable masks = refine_stencil_table(mesh, scheme, with_grids(false, levels));
  ASSERT_EQ(grids.source_count(), masks.source_count()) << what;
  ASSERT_EQ(grids.row_count(), masks.row_count()) << what;
  for (Index r = 0; r < grids.row_count(); ++r) {
    const auto gv = grids.row_vertices(r), mv = masks.row_vertices(r);
    const auto gw = grids.row_weights(r), mw = masks.row_weights(r);
    if (!cancelling) {
      ASSERT_EQ(std::vector<Index>(gv.begin(), gv.end()), std::vector<Index>(mv.begin(), mv.end())) << what << ": row " << r;
      for (std::size_t j = 0; j < gw.size(); ++j) ASSERT_NEAR(gw[j], mw[j], kRelativeTolerance) << what << ": row " << r;
      continue;
    }
    std::size_t i = 0, j = 0;  // both rows are sorted by source
    while (i < gv.size() || j < mv.size()) {
      const Index g = i < gv.size() ? gv[i] : std::numeric_limits<Index>::max();
      const Index m = j < mv.size() ? mv[j] : std::numeric_limits<Index>::max();
      const double a = g <= m ? gw[i] : 0.0, b = m <= g ? mw[j] : 0.0;
      ASSERT_NEAR(a, b, kRelativeTolerance) << what << ": row " << r << ", source " << std::min(g, m);
      if (g <= m) ++i;
      if (m <= g) ++j;
    }
  }
}

// The mesh with a face-varying channel of two components whose values are
// shared within rows of faces and split between them (seams).
inline PolygonMesh with_face_varying(PolygonMesh mesh) {
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
inline PolygonMesh with_channels(PolygonMesh mesh) {
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
inline bool takes_grids(const PolygonMesh& mesh, const Scheme& scheme, int remaining) {
  const MeshTopology topology(mesh);
  return detail::refine_as_grids(mesh, topology, scheme, with_grids(true, remaining), remaining).has_value();
}

// The torus with each quad split along its first diagonal: every vertex of
// valence 6.
inline PolygonMesh triangulated_torus(int n) {
  const PolygonMesh quads = torus(n);
  PolygonMesh mesh;
  mesh.positions = quads.positions;
  for (Index f = 0; f < quads.face_count(); ++f) {
    const auto q = quads.face(f);
    mesh.add_face({q[0], q[1], q[2]});
    mesh.add_face({q[0], q[2], q[3]});
  }
  return mesh;
}

}  // namespace subdiv::grid_test
