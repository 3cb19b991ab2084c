#include "subdiv/io/mesh_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "subdiv/core/error.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

namespace fs = std::filesystem;

class MeshIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("subdiv_io_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::size_t files_in_dir() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }
  fs::path dir_;
};

TEST_F(MeshIoTest, FormatFollowsExtension) {
  EXPECT_EQ(format_from_path("a/b.obj"), FileFormat::obj);
  EXPECT_EQ(format_from_path("B.PLY"), FileFormat::ply);
  EXPECT_EQ(format_from_path("c.Off"), FileFormat::off);
  EXPECT_EQ(format_from_path("d.stl"), FileFormat::stl);
  EXPECT_EQ(format_from_path("e.GLTF"), FileFormat::gltf);
  EXPECT_EQ(format_from_path("f.glb"), FileFormat::glb);
  EXPECT_THROW(format_from_path("g.fbx"), InvalidInputError);
  EXPECT_THROW(format_from_path("noext"), InvalidInputError);
}

TEST_F(MeshIoTest, RoundTripThroughEveryFormat) {
  PolygonMesh mesh = test::cube();
  mesh.positions[2] = {1.0 / 3.0, 2.0 / 7.0, 1e-17};
  mesh.add_face({0, 1, 2});
  for (const char* name : {"m.obj", "m.ply", "m.off"}) {
    for (const PlyEncoding enc : {PlyEncoding::binary_little_endian, PlyEncoding::binary_big_endian, PlyEncoding::ascii}) {
      WriteOptions options;
      options.ply_encoding = enc;
      write_mesh(mesh, dir_ / name, options);
      const MeshFile back = read_mesh(dir_ / name);
      EXPECT_EQ(back.mesh.positions, mesh.positions) << name;
      EXPECT_EQ(back.mesh.face_offsets, mesh.face_offsets) << name;
      EXPECT_EQ(back.mesh.face_indices, mesh.face_indices) << name;
    }
  }
  EXPECT_EQ(files_in_dir(), 3u);  // no temporary files left behind
}

TEST_F(MeshIoTest, TagsSurviveObjAndAreReportedLostElsewhere) {
  PolygonMesh mesh = test::cube();
  mesh.tags.creases.push_back({0, 1, 2.5});
  EXPECT_TRUE(write_mesh(mesh, dir_ / "m.obj").empty());
  EXPECT_EQ(read_mesh(dir_ / "m.obj").mesh.tags, mesh.tags);
  const auto warnings = write_mesh(mesh, dir_ / "m.off");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("no place for tags"), std::string::npos);
}

// PLY and OFF have no hole tags: hole faces are left out (they are not part
// of the surface), with a note, unless asked for as ordinary faces.
TEST_F(MeshIoTest, HoleFacesLeftOutWhereTheFormatHasNoHoleTags) {
  PolygonMesh mesh = test::cube();
  mesh.tags.holes = {2};
  for (const char* name : {"h.ply", "h.off"}) {
    const auto warnings = write_mesh(mesh, dir_ / name);
    ASSERT_FALSE(warnings.empty()) << name;
    EXPECT_NE(warnings[0].find("1 hole face left out"), std::string::npos) << warnings[0];
    const PolygonMesh back = read_mesh(dir_ / name).mesh;
    ASSERT_EQ(back.face_count(), 5) << name;
    for (Index f = 0; f < back.face_count(); ++f) {
      const Index original = f < 2 ? f : f + 1;  // face 2 is gone, the others keep their order
      EXPECT_TRUE(std::ranges::equal(back.face(f), mesh.face(original))) << name << ", face " << f;
    }
    WriteOptions keep;
    keep.hole_faces_as_faces = true;
    write_mesh(mesh, dir_ / name, keep);
    EXPECT_EQ(read_mesh(dir_ / name).mesh.face_count(), 6) << name;
  }
  EXPECT_EQ(read_mesh([&] {
              write_mesh(mesh, dir_ / "h.obj");
              return dir_ / "h.obj";
            }())
                .mesh.face_count(),
            6);  // OBJ keeps the faces with their tag
}

TEST_F(MeshIoTest, WriteChannelsFalseLeavesChannelsOutOfObjAndPly) {
  PolygonMesh mesh = test::cube();
  mesh.vertex_channels.push_back({"color", 3, std::vector<double>(24, 0.5)});
  for (const char* name : {"m.obj", "m.ply"}) {
    WriteOptions options;
    EXPECT_TRUE(write_mesh(mesh, dir_ / name, options).empty()) << name;
    EXPECT_NE(read_mesh(dir_ / name).mesh.find_vertex_channel("color"), nullptr) << name;
    options.write_channels = false;
    write_mesh(mesh, dir_ / name, options);
    const MeshFile again = read_mesh(dir_ / name);
    EXPECT_EQ(again.mesh.find_vertex_channel("color"), nullptr) << name;
    EXPECT_EQ(again.mesh.positions, mesh.positions) << name;
  }
}

TEST_F(MeshIoTest, PolylinesSurviveObjAndAreReportedLostElsewhere) {
  PolygonMesh mesh = test::cube();
  mesh.polylines = {{{0, 1, 2, 3}, true}, {{4, 5}, false}};
  EXPECT_TRUE(write_mesh(mesh, dir_ / "m.obj").empty());
  EXPECT_EQ(read_mesh(dir_ / "m.obj").mesh.polylines, mesh.polylines);
  for (const char* name : {"m.ply", "m.off"}) {
    const auto warnings = write_mesh(mesh, dir_ / name);
    ASSERT_EQ(warnings.size(), 1u) << name;
    EXPECT_NE(warnings[0].find("no place for polylines (OBJ 'l' lines): 2 not written"), std::string::npos)
        << warnings[0];
    EXPECT_TRUE(read_mesh(dir_ / name).mesh.polylines.empty());
  }
}

TEST_F(MeshIoTest, ReadingMissingOrDirectoryFails) {
  try {
    read_mesh(dir_ / "missing.obj");
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.obj: cannot open"), std::string::npos) << e.what();
  }
  fs::create_directory(dir_ / "d.obj");
  EXPECT_THROW(read_mesh(dir_ / "d.obj"), IoError);
}

TEST_F(MeshIoTest, FailedWriteLeavesTheOldFileIntact) {
  const fs::path target = dir_ / "keep.obj";
  { std::ofstream(target) << "original contents\n"; }
  PolygonMesh broken = test::cube();
  broken.face_indices[0] = 99;  // refuses to serialise
  EXPECT_THROW(write_mesh(broken, target), InvalidInputError);
  EXPECT_EQ(slurp(target), "original contents\n");
  EXPECT_THROW(write_mesh(test::cube(), dir_ / "no_such_dir" / "x.obj"), IoError);
  EXPECT_THROW(write_mesh(test::cube(), dir_ / "x.fbx"), InvalidInputError);
  EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(MeshIoTest, OverwritesCompletely) {
  const fs::path target = dir_ / "m.obj";
  write_mesh(test::cube(), target);
  write_mesh(test::tetrahedron(), target);
  EXPECT_EQ(read_mesh(target).mesh.face_count(), 4);
  EXPECT_EQ(fs::status(target).permissions() & fs::perms::owner_read, fs::perms::owner_read);
}

TEST_F(MeshIoTest, BundledMeshesLoadAndAreValid) {
  for (const char* name : {"cube.obj", "tetrahedron.obj", "elephant.obj", "spot_control_mesh.obj"}) {
    const MeshFile f = read_mesh(test::bundled_path(name));
    EXPECT_GT(f.mesh.face_count(), 0) << name;
    EXPECT_TRUE(f.warnings.empty()) << name;
  }
  const MeshFile spot = read_mesh(test::bundled_path("spot_control_mesh.obj"));
  EXPECT_EQ(spot.mesh.vertex_count(), 188);
  EXPECT_EQ(spot.mesh.face_count(), 180);
  EXPECT_NE(spot.mesh.find_face_varying_channel("uv"), nullptr);
}

}  // namespace
}  // namespace subdiv
