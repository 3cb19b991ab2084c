#include "subdiv/mesh/polygon_mesh.h"

#include <gtest/gtest.h>

#include "subdiv/core/error.h"
#include "support/test_meshes.h"

namespace subdiv {

TEST(PolygonMesh, StoresFacesAsOffsetsAndIndices) {
  PolygonMesh mesh;
  mesh.positions.resize(5);
  EXPECT_EQ(mesh.add_face({0, 1, 2}), 0);
  EXPECT_EQ(mesh.add_face({0, 2, 3, 4}), 1);
  EXPECT_EQ(mesh.face_count(), 2);
  EXPECT_EQ(mesh.corner_count(), 7);
  EXPECT_EQ(mesh.face_offsets, (std::vector<Index>{0, 3, 7}));
  EXPECT_EQ(mesh.face_size(1), 4);
  EXPECT_EQ(mesh.face(1)[3], 4);
  EXPECT_NO_THROW(check_indices(mesh));
}

TEST(PolygonMesh, CheckIndicesNamesTheBadCorner) {
  PolygonMesh mesh = test::cube();
  mesh.face_indices[5] = 8;
  try {
    check_indices(mesh);
    FAIL();
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("corner 5 refers to vertex 8"), std::string::npos) << e.what();
  }
  mesh.face_indices[5] = -1;
  EXPECT_THROW(check_indices(mesh), InvalidInputError);
}

TEST(PolygonMesh, CheckIndicesRejectsMalformedOffsets) {
  PolygonMesh mesh = test::cube();
  mesh.face_offsets[2] = 1;  // face 1 would have a negative size
  EXPECT_THROW(check_indices(mesh), InvalidInputError);
  mesh = test::cube();
  mesh.face_offsets.back() = 23;
  EXPECT_THROW(check_indices(mesh), InvalidInputError);
  mesh = test::cube();
  mesh.face_offsets.clear();
  EXPECT_THROW(check_indices(mesh), InvalidInputError);
}

TEST(PolygonMesh, CheckIndicesChecksChannelSizes) {
  PolygonMesh mesh = test::cube();
  mesh.vertex_channels.push_back({"color", 3, std::vector<double>(24, 0.5)});
  EXPECT_NO_THROW(check_indices(mesh));
  mesh.vertex_channels[0].values.pop_back();
  EXPECT_THROW(check_indices(mesh), InvalidInputError);

  mesh = test::cube();
  FaceVaryingChannel uv{"uv", 2, {0, 0, 1, 0, 1, 1, 0, 1}, std::vector<Index>(24, 0)};
  mesh.face_varying_channels.push_back(uv);
  EXPECT_NO_THROW(check_indices(mesh));
  mesh.face_varying_channels[0].indices[7] = 4;  // only 4 values
  EXPECT_THROW(check_indices(mesh), InvalidInputError);
  mesh.face_varying_channels[0].indices.pop_back();
  EXPECT_THROW(check_indices(mesh), InvalidInputError);
}

TEST(PolygonMesh, FindsChannelsByName) {
  PolygonMesh mesh = test::cube();
  mesh.vertex_channels.push_back({"weight", 1, std::vector<double>(8, 1.0)});
  ASSERT_NE(mesh.find_vertex_channel("weight"), nullptr);
  EXPECT_EQ(mesh.find_vertex_channel("weight")->value_count(), 8);
  EXPECT_EQ(mesh.find_vertex_channel("uv"), nullptr);
  EXPECT_EQ(mesh.find_face_varying_channel("uv"), nullptr);
}

}  // namespace subdiv
