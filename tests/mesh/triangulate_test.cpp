#include "subdiv/mesh/triangulate.h"

#include <gtest/gtest.h>

#include "subdiv/mesh/validation.h"
#include "support/test_meshes.h"

namespace subdiv {

TEST(Triangulate, FansPolygonsAndKeepsData) {
  PolygonMesh mesh = make_mesh({{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}, {3, 0, 0}},
                               {{0, 1, 2, 3, 4}, {1, 5, 2}});
  mesh.face_varying_channels.push_back({"uv", 1, {0, 1, 2, 3, 4, 5}, {0, 1, 2, 3, 4, 1, 5, 2}});
  mesh.tags.holes = {0};
  mesh.tags.creases = {{0, 1, 10.0}};
  const PolygonMesh t = triangulate(mesh);
  EXPECT_EQ(t.face_count(), 4);
  EXPECT_EQ(t.face_indices, (std::vector<Index>{0, 1, 2, 0, 2, 3, 0, 3, 4, 1, 5, 2}));
  EXPECT_EQ(t.face_varying_channels[0].indices, (std::vector<Index>{0, 1, 2, 0, 2, 3, 0, 3, 4, 1, 5, 2}));
  EXPECT_EQ(t.tags.holes, (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(t.tags.creases, mesh.tags.creases);
  EXPECT_TRUE(validate(t).ok());
  EXPECT_EQ(triangulate(test::tetrahedron()).face_indices, test::tetrahedron().face_indices);
}

}  // namespace subdiv
