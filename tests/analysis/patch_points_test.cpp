// The regular Catmull-Clark and Loop patches' control points found by
// walking the topology (src/analysis/patch_points.h): the lattice's own
// points in order from every starting corner, refusals where a patch is not
// regular, and, on perturbed tori, the patch at each corner equal to the
// scheme's limit of that vertex.
#include "analysis/patch_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis/patch_basis.h"
#include "depth/depth_test_meshes.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/rules/scheme.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

TEST(PatchPoints, LatticeGivesTheGridFromEveryCorner) {
  const PolygonMesh mesh = test::quad_grid(6, 6);
  const MeshTopology topology(mesh);
  // The central face, corners (3,3) (4,3) (4,4) (3,4).
  Index face = kInvalidIndex;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (mesh.positions[static_cast<std::size_t>(mesh.face(f)[0])] == Vec3{3, 3, 0}) face = f;
  }
  ASSERT_NE(face, kInvalidIndex);
  for (Index k = 0; k < 4; ++k) {
    const Index corner = topology.face_first_corner(face) + k;
    const auto points = bicubic_patch_points(topology, corner);
    ASSERT_TRUE(points.has_value()) << "corner " << k;
    // The frame of corner k: its vertex is the origin, u toward the next
    // corner, v toward the previous one.
    const Vec3 origin = mesh.positions[static_cast<std::size_t>(topology.corner_vertex(corner))];
    const Vec3 u = mesh.positions[static_cast<std::size_t>(topology.corner_vertex(topology.corner_next(corner)))] - origin;
    const Vec3 v = mesh.positions[static_cast<std::size_t>(topology.corner_vertex(topology.corner_prev(corner)))] - origin;
    for (int j = -1; j <= 2; ++j) {
      for (int i = -1; i <= 2; ++i) {
        const Vec3 expected = origin + static_cast<double>(i) * u + static_cast<double>(j) * v;
        const Index vertex = (*points)[static_cast<std::size_t>((i + 1) + 4 * (j + 1))];
        EXPECT_EQ(mesh.positions[static_cast<std::size_t>(vertex)], expected) << "corner " << k << ", grid (" << i << ", " << j << ")";
      }
    }
  }
}

TEST(PatchPoints, RefusesIrregularPatches) {
  // Valence 3 everywhere.
  const PolygonMesh box = test::cube();
  const MeshTopology box_topology(box);
  for (Index c = 0; c < box_topology.corner_count(); ++c) EXPECT_FALSE(bicubic_patch_points(box_topology, c).has_value());
  // The lattice's faces touching its boundary.
  const PolygonMesh mesh = test::quad_grid(4, 4);
  const MeshTopology topology(mesh);
  int regular = 0;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (bicubic_patch_points(topology, topology.face_first_corner(f))) ++regular;
  }
  EXPECT_EQ(regular, 4);  // the 2 x 2 faces whose corners are all interior
  // A 3 x 3 torus is regular but its patches repeat vertices.
  const PolygonMesh small = quad_torus(3, 3, 3.0, 1.0);
  const MeshTopology small_topology(small);
  EXPECT_FALSE(bicubic_patch_points(small_topology, 0).has_value());
}

/// On a perturbed regular torus, every corner's patch evaluated at (0, 0)
/// must be the scheme's closed-form limit of the corner's vertex.
template <int N, typename Points, typename Weights>
void expect_patch_corners_are_limits(const PolygonMesh& torus, const char* scheme_name, Points points_of,
                                     Weights weights) {
  const MeshTopology topology(torus);
  const Scheme* scheme = find_scheme(scheme_name);
  ASSERT_NE(scheme, nullptr);
  const LimitResult limit = limit_positions(torus, *scheme);
  const auto at_origin = weights(0.0, 0.0);
  for (Index c = 0; c < topology.corner_count(); ++c) {
    const auto points = points_of(topology, c);
    ASSERT_TRUE(points.has_value()) << "corner " << c;
    Vec3 p{};
    for (std::size_t k = 0; k < static_cast<std::size_t>(N); ++k) {
      p = p + at_origin.value[k] * torus.positions[static_cast<std::size_t>((*points)[k])];
    }
    const Vec3 expected = limit.positions[static_cast<std::size_t>(topology.corner_vertex(c))];
    EXPECT_LT(norm(p - expected), 1e-12) << scheme_name << ", corner " << c;
  }
}

TEST(PatchPoints, PatchCornersAreTheLimitPositions) {
  std::mt19937 random(11);
  expect_patch_corners_are_limits<16>(perturbed(quad_torus(8, 6, 3.0, 1.0), 0.2, random), "catmull-clark",
                                      bicubic_patch_points, bicubic_bspline_weights);
}

TEST(PatchPoints, TriangleLatticeGivesTheBoxSplinePointsFromEveryCorner) {
  const PolygonMesh mesh = test::box_spline_grid(6, 6);
  const MeshTopology topology(mesh);
  // Both triangles of the central cell: (3,3) (4,3) (3,4) and (4,3) (4,4) (3,4).
  int checked = 0;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Vec3 first = mesh.positions[static_cast<std::size_t>(mesh.face(f)[0])];
    if (first != Vec3{3, 3, 0} && first != Vec3{4, 3, 0}) continue;
    if (mesh.positions[static_cast<std::size_t>(mesh.face(f)[2])] != Vec3{3, 4, 0}) continue;
    for (Index k = 0; k < 3; ++k) {
      const Index corner = topology.face_first_corner(f) + k;
      const auto points = box_spline_patch_points(topology, corner);
      ASSERT_TRUE(points.has_value()) << "face " << f << ", corner " << k;
      const Vec3 origin = mesh.positions[static_cast<std::size_t>(topology.corner_vertex(corner))];
      const Vec3 u = mesh.positions[static_cast<std::size_t>(topology.corner_vertex(topology.corner_next(corner)))] - origin;
      const Vec3 v = mesh.positions[static_cast<std::size_t>(topology.corner_vertex(topology.corner_prev(corner)))] - origin;
      for (std::size_t p = 0; p < 12; ++p) {
        const Vec3 expected =
            origin + static_cast<double>(kBoxSplineLattice[p][0]) * u + static_cast<double>(kBoxSplineLattice[p][1]) * v;
        EXPECT_EQ(mesh.positions[static_cast<std::size_t>((*points)[p])], expected) << "face " << f << ", corner " << k << ", point " << p;
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, 6);
  // Faces touching the boundary have no patch; quads neither.
  EXPECT_FALSE(box_spline_patch_points(topology, 0).has_value());
  const MeshTopology quads(test::quad_grid(6, 6));
  for (Index c = 0; c < quads.corner_count(); ++c) EXPECT_FALSE(box_spline_patch_points(quads, c).has_value());
}

TEST(PatchPoints, BoxSplineCornersAreLoopsLimitPositions) {
  std::mt19937 random(13);
  expect_patch_corners_are_limits<12>(perturbed(triangle_torus(8, 6, 3.0, 1.0), 0.1, random), "loop",
                                      box_spline_patch_points, box_spline_weights);
}

// Without sharp edges the reflected patches are the plain ones, point for
// point, at every corner (on a torus and on an open grid's inside).
TEST(PatchPoints, StencilsWithoutSharpEdgesAreThePlainPatches) {
  const auto expect_same = [](const PolygonMesh& mesh, auto plain, auto stencils) {
    const MeshTopology topology(mesh);
    const LevelCreasing creasing =
        compute_creasing(mesh, topology, BoundaryInterpolation::edge_only, CreaseMethod::uniform);
    int patches = 0;
    for (Index c = 0; c < topology.corner_count(); ++c) {
      const auto a = plain(topology, c);
      const auto b = stencils(topology, creasing, c);
      // Next to the grid's boundary only the stencils have a patch.
      if (!a) continue;
      ASSERT_TRUE(b.has_value()) << "corner " << c;
      for (std::size_t i = 0; i < a->size(); ++i) {
        ASSERT_EQ((*b)[i].size, 1) << "corner " << c << ", point " << i;
        EXPECT_EQ((*b)[i].vertex[0], (*a)[i]) << "corner " << c << ", point " << i;
      }
      ++patches;
    }
    EXPECT_GT(patches, 0);
  };
  expect_same(quad_torus(8, 6, 3.0, 1.0), bicubic_patch_points, bicubic_patch_stencils);
  expect_same(test::quad_grid(6, 5), bicubic_patch_points, bicubic_patch_stencils);
  expect_same(triangle_torus(8, 6, 3.0, 1.0), box_spline_patch_points, box_spline_patch_stencils);
  expect_same(test::box_spline_grid(6, 5), box_spline_patch_points, box_spline_patch_stencils);
}

}  // namespace
}  // namespace subdiv
