// The text writers format blocks of lines on several threads: the bytes
// must not depend on the thread count, and must read back to the mesh.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/test_meshes.h"
#include "subdiv/io/obj.h"
#include "subdiv/io/off.h"
#include "subdiv/io/ply.h"

namespace subdiv {
namespace {

// A 200 x 150 grid (30351 vertices, 30000 quads: two blocks of lines and
// more) with heights, colours, UVs and normals that need every digit.
PolygonMesh large_mesh_with_channels() {
  PolygonMesh mesh = test::with_random_heights(test::quad_grid(200, 150), 7);
  VertexChannel color{"color", 3, {}};
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    for (int i = 0; i < 3; ++i) color.values.push_back(std::fmod(0.1 * v + i / 3.0, 1.0));
  mesh.vertex_channels.push_back(color);
  for (const char* name : {"uv", "normal"}) {
    const int components = std::string(name) == "uv" ? 2 : 3;
    FaceVaryingChannel channel{name, components, {}, {}};
    for (Index c = 0; c < mesh.corner_count(); ++c) {
      channel.indices.push_back(c);
      for (int i = 0; i < components; ++i) channel.values.push_back(std::sin(1.0 + c + i / 7.0));
    }
    mesh.face_varying_channels.push_back(channel);
  }
  return mesh;
}

TEST(ParallelFormat, ObjBytesDoNotDependOnTheThreadCount) {
  const PolygonMesh mesh = large_mesh_with_channels();
  WriteOptions one;
  one.threads = 1;
  const std::string reference = format_obj(mesh, one);
  for (const int threads : {2, 3, 0}) {
    WriteOptions options;
    options.threads = threads;
    EXPECT_EQ(format_obj(mesh, options), reference) << threads << " threads";
  }
  const MeshFile back = parse_obj(reference);
  EXPECT_EQ(back.mesh.positions, mesh.positions);
  EXPECT_EQ(back.mesh.face_indices, mesh.face_indices);
  ASSERT_NE(back.mesh.find_face_varying_channel("normal"), nullptr);
  EXPECT_EQ(back.mesh.find_face_varying_channel("normal")->values, mesh.face_varying_channels[1].values);
}

TEST(ParallelFormat, PlyAsciiAndOffBytesDoNotDependOnTheThreadCount) {
  const PolygonMesh mesh = large_mesh_with_channels();
  const std::string ply = format_ply(mesh, PlyEncoding::ascii, nullptr, 1);
  const std::string off = format_off(mesh, nullptr, 1);
  for (const int threads : {2, 3, 0}) {
    EXPECT_EQ(format_ply(mesh, PlyEncoding::ascii, nullptr, threads), ply) << threads << " threads";
    EXPECT_EQ(format_off(mesh, nullptr, threads), off) << threads << " threads";
  }
  EXPECT_EQ(parse_ply(ply).mesh.positions, mesh.positions);
  EXPECT_EQ(parse_off(off).mesh.face_indices, mesh.face_indices);
}

}  // namespace
}  // namespace subdiv
