#include "subdiv/mesh/mesh_stats.h"

#include <gtest/gtest.h>

#include "support/test_meshes.h"

namespace subdiv {

TEST(MeshStats, Cube) {
  const PolygonMesh mesh = test::cube();
  const MeshStats s = compute_stats(mesh, MeshTopology(mesh));
  EXPECT_EQ(s.vertices, 8);
  EXPECT_EQ(s.faces, 6);
  EXPECT_EQ(s.edges, 12);
  EXPECT_EQ(s.corners, 24);
  EXPECT_EQ(s.quads, 6);
  EXPECT_EQ(s.face_sizes, (std::map<Index, Index>{{4, 6}}));
  EXPECT_EQ(s.valences, (std::map<Index, Index>{{3, 8}}));
  EXPECT_EQ(s.max_valence, 3);
  EXPECT_EQ(s.boundary_loops, 0);
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(s.euler_characteristic, 2);
  EXPECT_EQ(s.bbox_min, (Vec3{0, 0, 0}));
  EXPECT_EQ(s.bbox_max, (Vec3{1, 1, 1}));
}

TEST(MeshStats, GridWithMixedFacesAndAnIsolatedVertex) {
  PolygonMesh mesh = test::triangle_grid(2, 1);  // 4 triangles
  mesh.add_face({0, 1, 4, 3});                   // duplicates a quad over the triangles
  mesh.positions.push_back({9, 9, 9});
  const MeshStats s = compute_stats(mesh, MeshTopology(mesh));
  EXPECT_EQ(s.triangles, 4);
  EXPECT_EQ(s.quads, 1);
  EXPECT_EQ(s.isolated_vertices, 1);
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(s.valences.at(3), 2);  // vertices 0 and 5
  EXPECT_EQ(s.valences.at(4), 2);  // vertices 1 and 4
  EXPECT_EQ(s.non_manifold_edges, 1);  // 1-4: two triangles and the quad
}

TEST(MeshStats, TwoComponentsAndEuler) {
  PolygonMesh a = test::tetrahedron();
  const Index n = a.vertex_count();
  const PolygonMesh b = test::tetrahedron();
  for (const Vec3& p : b.positions) a.positions.push_back(p + Vec3{5, 0, 0});
  for (Index f = 0; f < b.face_count(); ++f) {
    std::vector<Index> face;
    for (const Index v : b.face(f)) face.push_back(v + n);
    a.add_face(face);
  }
  const MeshStats s = compute_stats(a, MeshTopology(a));
  EXPECT_EQ(s.components, 2);
  EXPECT_EQ(s.euler_characteristic, 4);
  EXPECT_EQ(s.degenerate_faces, 0);
}

}  // namespace subdiv
