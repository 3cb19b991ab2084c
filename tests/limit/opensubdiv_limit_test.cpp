// Closed-form limits against OpenSubdiv's (Far::PrimvarRefiner::Limit with
// Sdc's limit masks) on regression shapes of the shared collection
// (../shared/data/meshes/opensubdiv), on both libraries' level-2 meshes:
// positions within 1e-12 of the bounding-box diagonal everywhere the closed
// forms apply; tangents and normals where both use the same formula.
//
// What is compared:
// - smooth and dart vertices: normals parallel (same orientation), and
//   t1 x t2 equal for Loop, ours = (A_k / 4)^2 / sin(2 pi/k) theirs for
//   Catmull-Clark (the masks of Halstead et al. against OpenSubdiv's scaling
//   of them, whose second tangent is the first turned by 2 pi/k; the pair
//   itself turns with the ring's first edge, which the libraries choose
//   differently);
// - crease and boundary vertices: the tangent along the curve (ours =
//   theirs for Catmull-Clark, theirs / 3 for Loop); normals for sectors of
//   one face, two quads or three triangles, where OpenSubdiv's cross tangent
//   is that of the standard rules. (For larger sectors it uses Biermann et
//   al.'s mask of the modified rules; ours is the standard rules' own, tested
//   in closed_form_limit_test.cpp.) On an interior crease both take the
//   sector counter-clockwise from the first sharp edge; the rings start at
//   different edges, so the normals are compared where the tangents along
//   the crease agree in direction (the same sector);
// - corners: normals where the corner has one face (both take its edges).
// The vertex correspondence follows the children level by level, as in
// tests/refine/opensubdiv_agreement_test.cpp.

#include <gtest/gtest.h>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyRefiner.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>

#include "subdiv/analysis/limit.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/catmull_clark.h"
#include "support/opensubdiv_refiner.h"
#include "support/opensubdiv_shapes.h"

namespace subdiv {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

constexpr int kLevels = 2;

using test::bbox_diagonal;
using test::OsdVertex;

Vec3 unit(const Vec3& v) { return (1.0 / norm(v)) * v; }

class OpenSubdivLimit : public ::testing::TestWithParam<const char*> {};

TEST_P(OpenSubdivLimit, ClosedFormsMatchOpenSubdiv) {
  const std::string shape = GetParam();
  const std::filesystem::path path = test::opensubdiv_shape_dir() / (shape + ".obj");
  if (!std::filesystem::exists(path))
    GTEST_SKIP() << "OpenSubdiv regression shapes not found at " << test::opensubdiv_shape_dir();
  const bool catmark = shape.starts_with("catmark_");
  const Scheme& scheme = *find_scheme(catmark ? "catmull-clark" : "loop");
  PolygonMesh mesh = read_mesh(path).mesh;
  ASSERT_EQ(test::unsupported_feature(mesh), "");
  test::round_sharpness_to_float(mesh.tags);
  const BoundaryInterpolation boundary = test::harness_boundary(mesh.tags);

  // Theirs: level kLevels and its limit.
  const auto refiner =
      test::make_refiner(mesh, catmark ? Sdc::SCHEME_CATMARK : Sdc::SCHEME_LOOP, kLevels, test::boundary_option(boundary));
  ASSERT_TRUE(refiner);
  std::vector<OsdVertex> src(mesh.positions.size());
  for (std::size_t v = 0; v < src.size(); ++v) src[v] = {mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z};
  const Far::PrimvarRefinerReal<double> primvar(*refiner);
  for (int l = 1; l <= kLevels; ++l) {
    std::vector<OsdVertex> dst(static_cast<std::size_t>(refiner->GetLevel(l).GetNumVertices()));
    OsdVertex* out = dst.data();
    primvar.Interpolate(l, src.data(), out);
    src = std::move(dst);
  }
  std::vector<OsdVertex> pos(src.size()), tan1(src.size()), tan2(src.size());
  primvar.Limit(src, pos, tan1, tan2);

  // Ours, level by level, with the correspondence ours -> theirs.
  RefineOptions one;
  one.levels = 1;
  one.boundary = boundary;
  std::vector<Far::Index> map(static_cast<std::size_t>(mesh.vertex_count()));
  std::vector<Far::Index> face_map(static_cast<std::size_t>(mesh.face_count()));
  for (std::size_t i = 0; i < map.size(); ++i) map[i] = static_cast<Far::Index>(i);
  for (std::size_t i = 0; i < face_map.size(); ++i) face_map[i] = static_cast<Far::Index>(i);
  PolygonMesh level = mesh;
  for (int l = 0; l < kLevels; ++l) {
    const Far::TopologyLevel& theirs = refiner->GetLevel(l);
    const MeshTopology t(level);
    PolygonMesh child = refine(level, scheme, one);
    const Index edge_points = scheme.split == SplitRule::quad ? level.face_count() : 0;
    const Index vertex_points = edge_points + t.edge_count();
    std::vector<Far::Index> child_map(static_cast<std::size_t>(child.vertex_count()), -1);
    for (Index f = 0; f < edge_points; ++f)
      child_map[static_cast<std::size_t>(f)] = theirs.GetFaceChildVertex(face_map[static_cast<std::size_t>(f)]);
    for (Index e = 0; e < t.edge_count(); ++e) {
      const auto [a, b] = t.edge_vertices(e);
      const Far::Index te = theirs.FindEdge(map[static_cast<std::size_t>(a)], map[static_cast<std::size_t>(b)]);
      ASSERT_NE(te, Far::INDEX_INVALID);
      child_map[static_cast<std::size_t>(edge_points + e)] = theirs.GetEdgeChildVertex(te);
    }
    for (Index v = 0; v < level.vertex_count(); ++v)
      child_map[static_cast<std::size_t>(vertex_points + v)] = theirs.GetVertexChildVertex(map[static_cast<std::size_t>(v)]);
    // Child faces, matched through a child vertex they share (faces are not
    // compared at the last level, so only their map is needed).
    std::vector<Far::Index> child_face_map(static_cast<std::size_t>(child.face_count()), -1);
    if (l + 1 < kLevels) {
      const Far::TopologyLevel& their_child = refiner->GetLevel(l + 1);
      for (Index f = 0; f < child.face_count(); ++f) {
        std::vector<Far::Index> mapped;
        for (const Index v : child.face(f)) mapped.push_back(child_map[static_cast<std::size_t>(v)]);
        std::sort(mapped.begin(), mapped.end());
        for (const Far::Index tf : their_child.GetVertexFaces(mapped.front())) {
          const auto fv = their_child.GetFaceVertices(tf);
          std::vector<Far::Index> sorted(fv.begin(), fv.end());
          std::sort(sorted.begin(), sorted.end());
          if (sorted == mapped) child_face_map[static_cast<std::size_t>(f)] = tf;
        }
        ASSERT_NE(child_face_map[static_cast<std::size_t>(f)], -1);
      }
    }
    map = std::move(child_map);
    face_map = std::move(child_face_map);
    level = std::move(child);
  }

  LimitOptions options;
  options.refine.boundary = boundary;
  options.max_resolve_levels = 0;  // compare on this level; semi-sharp neighbourhoods fall back and are skipped
  const LimitResult ours = limit_positions(level, scheme, options);
  const MeshTopology t(level);
  const LevelCreasing creasing = compute_creasing(level, t, boundary, level.tags.crease_method);
  const double tolerance = 1e-12 * bbox_diagonal(mesh.positions);
  int positions = 0, normals = 0, tangents = 0;
  for (Index v = 0; v < level.vertex_count(); ++v) {
    const auto vi = static_cast<std::size_t>(v);
    if (ours.sources[vi] != LimitSource::closed_form) continue;
    const auto ti = static_cast<std::size_t>(map[vi]);
    SCOPED_TRACE(shape + ", vertex " + std::to_string(v) + " (" + to_string(creasing.vertex_rule[vi]) + ")");
    EXPECT_LE(norm(ours.positions[vi] - pos[ti].vec()), tolerance);
    ++positions;
    const Vec3 n_theirs = cross(tan1[ti].vec(), tan2[ti].vec());
    const VertexRule rule = creasing.vertex_rule[vi];
    const int faces = t.vertex_face_count(v);
    bool compare_normal = false;
    if (rule == VertexRule::smooth || rule == VertexRule::dart) {
      const double scale = catmark ? (16.0 * catmull_clark_subdominant_eigenvalue(faces) - 4.0) / 4.0 : 1.0;
      // The rings start at different edges, which rotates the pair within
      // the tangent plane; t1 x t2 does not change. OpenSubdiv's second
      // Catmull-Clark tangent is its first turned by 2 pi/k, not pi/2.
      const Vec3 ours_cross = cross(ours.tangents1[vi], ours.tangents2[vi]);
      const double turn = catmark ? std::sin(2.0 * std::numbers::pi / faces) : 1.0;
      EXPECT_LE(norm(ours_cross - (scale * scale / turn) * n_theirs), 1e-10 * norm(ours_cross));
      ++tangents;
      compare_normal = true;
    } else if (rule == VertexRule::crease) {
      const Vec3 along = (catmark ? 1.0 : 1.0 / 3.0) * tan1[ti].vec();
      const bool same_sector = dot(ours.tangents1[vi], along) > 0.0;
      const Vec3 expected = same_sector ? along : -1.0 * along;
      EXPECT_LE(norm(ours.tangents1[vi] - expected), 1e-10 * norm(expected));
      ++tangents;
      int sector = 0;  // faces counter-clockwise from the first sharp edge to the next
      bool counting = false;
      for (std::size_t i = 0; i < t.vertex_edges(v).size(); ++i) {
        if (edge_sharpness_of(creasing, t.vertex_edges(v)[i]) > 0.0) {
          if (counting) break;
          counting = true;
        } else if (counting) {
          ++sector;
        }
      }
      ++sector;
      compare_normal = same_sector && (sector == 1 || sector == (catmark ? 2 : 3));
    } else {
      compare_normal = faces == 1;
    }
    if (compare_normal) {
      ASSERT_GT(norm(n_theirs), 0.0);
      EXPECT_GT(dot(ours.normals[vi], unit(n_theirs)), 1.0 - 1e-10) << "normals differ";
      ++normals;
    }
  }
  std::cout << "[ COMPARED ] " << shape << ": " << positions << " positions, " << tangents << " tangent pairs, "
            << normals << " normals of " << level.vertex_count() << " vertices\n";
  EXPECT_GT(positions, level.vertex_count() / 2);
  EXPECT_GT(normals, 0);
}

INSTANTIATE_TEST_SUITE_P(Shapes, OpenSubdivLimit,
                         ::testing::Values("catmark_cube", "catmark_cube_corner0", "catmark_cube_creases0",
                                           "catmark_dart_edgeonly", "catmark_edgecorner", "catmark_edgeonly",
                                           "catmark_xord_boundary", "catmark_pole8", "catmark_helmet",
                                           "catmark_torus_creases0", "catmark_nonquads", "loop_cube_creases0",
                                           "loop_icosahedron", "loop_triangle_edgeonly", "loop_xord_interior",
                                           "loop_saddle_edgeonly", "loop_pole8"),
                         [](const ::testing::TestParamInfo<const char*>& shape) { return std::string(shape.param); });

}  // namespace
}  // namespace subdiv
