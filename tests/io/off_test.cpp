#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "subdiv/core/error.h"
#include "support/parse_errors.h"
#include "support/test_meshes.h"
#include "subdiv/io/off.h"

namespace subdiv {
namespace {

void expect_same_geometry(const PolygonMesh& a, const PolygonMesh& b) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i) EXPECT_EQ(a.positions[i], b.positions[i]) << "vertex " << i;
  EXPECT_EQ(a.face_offsets, b.face_offsets);
  EXPECT_EQ(a.face_indices, b.face_indices);
}


// The three-vertex, one-triangle mesh most of the variants below describe.
void expect_triangle(const MeshFile& file) {
  ASSERT_EQ(file.mesh.vertex_count(), 3);
  EXPECT_EQ(file.mesh.positions[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(file.mesh.positions[1], (Vec3{1, 0, 0}));
  EXPECT_EQ(file.mesh.positions[2], (Vec3{0, 1, 0.5}));
  EXPECT_EQ(file.mesh.face_offsets, (std::vector<Index>{0, 3}));
  EXPECT_EQ(file.mesh.face_indices, (std::vector<Index>{0, 1, 2}));
}

// --- round trips -----------------------------------------------------------------

TEST(Off, CubeRoundTrips) {
  std::vector<std::string> warnings;
  const std::string text = format_off(test::cube(), &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(text.rfind("OFF\n8 6 0\n0 0 0\n", 0), 0u);
  const MeshFile file = parse_off(text, "cube.off");
  expect_same_geometry(test::cube(), file.mesh);
  EXPECT_TRUE(file.warnings.empty());
  EXPECT_EQ(file.lines.path, "cube.off");
  EXPECT_EQ(file.lines.vertex_lines.size(), 8u);
  EXPECT_EQ(file.lines.vertex_lines.front(), 3u);
  EXPECT_EQ(file.lines.face_lines, (std::vector<std::uint32_t>{11, 12, 13, 14, 15, 16}));
}

TEST(Off, MixedFacesRoundTripExactly) {
  expect_same_geometry(test::hard_numbers_mesh(), parse_off(format_off(test::hard_numbers_mesh())).mesh);
}

TEST(Off, EmptyMeshRoundTrips) {
  const MeshFile file = parse_off(format_off(PolygonMesh{}));
  EXPECT_EQ(file.mesh.vertex_count(), 0);
  EXPECT_EQ(file.mesh.face_count(), 0);
}

TEST(Off, ChannelsAreReportedNotWritten) {
  PolygonMesh mesh = test::cube();
  mesh.vertex_channels.push_back({"color", 3, std::vector<double>(24, 0.5)});
  mesh.face_varying_channels.push_back({"uv", 2, {0, 0}, std::vector<Index>(24, 0)});
  std::vector<std::string> warnings;
  const std::string text = format_off(mesh, &warnings);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("vertex channel 'color'"), std::string::npos);
  EXPECT_NE(warnings[1].find("face-varying channel 'uv'"), std::string::npos);
  EXPECT_EQ(text, format_off(test::cube()));
}

// --- variants ------------------------------------------------------------------------

TEST(Off, ColorVertices) {
  // RGBA integers on some vertices, RGB floats on another; face colours too.
  expect_triangle(parse_off(
      "COFF\n3 1 3\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0.5 0.1 0.2 0.3\n3 0 1 2 255 255 0\n"));
}

TEST(Off, NormalVertices) {
  expect_triangle(parse_off("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0.5 0 0 1\n3 0 1 2\n"));
}

TEST(Off, TextureVertices) {
  expect_triangle(parse_off("STOFF\n3 1 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0.5 0 1\n3 0 1 2\n"));
}

TEST(Off, AllPrefixesTogether) {
  // x y z nx ny nz r g b a s t
  expect_triangle(parse_off(
      "STCNOFF\n3 1 0\n0 0 0 0 0 1 1 0 0 1 0 0\n1 0 0 0 0 1 0 1 0 1 1 0\n0 1 0.5 0 0 1 0 0 1 1 0 1\n3 0 1 2\n"));
  expect_triangle(parse_off("CNOFF\n3 1 0\n0 0 0 0 0 1 1 0 0\n1 0 0 0 0 1 0 1 0\n0 1 0.5 0 0 1 0 0 1\n3 0 1 2\n"));
}

TEST(Off, HomogeneousAndDimensionVariants) {
  expect_triangle(parse_off("4OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0.5 1\n3 0 1 2\n"));
  expect_triangle(parse_off("nOFF\n3\n3 1 0\n0 0 0\n1 0 0\n0 1 0.5\n3 0 1 2\n"));
  expect_triangle(parse_off("nOFF 5\n3 1 0\n0 0 0 7 7\n1 0 0 7 7\n0 1 0.5 7 7\n3 0 1 2\n"));
  expect_triangle(parse_off("4nOFF\n3\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0.5 1\n3 0 1 2\n"));
  const MeshFile flat = parse_off("nOFF\n2\n3 1 0\n0 0\n1 0\n0 1\n3 0 1 2\n");
  EXPECT_EQ(flat.mesh.positions[2], (Vec3{0, 1, 0}));
}

TEST(Off, CommentsAndBlankLines) {
  const MeshFile file = parse_off(
      "# a triangle\n"
      "\n"
      "OFF # the header\n"
      "   # counts follow\n"
      "3 1 0\n"
      "\n"
      "0 0 0\n"
      "# between vertices\n"
      "1 0 0 # trailing comment\n"
      "0 1 0.5\r\n"
      "\n"
      "3 0 1 2#glued comment\n");
  expect_triangle(file);
  EXPECT_EQ(file.lines.vertex_lines, (std::vector<std::uint32_t>{7, 9, 10}));
  EXPECT_EQ(file.lines.face_lines, (std::vector<std::uint32_t>{12}));
  EXPECT_TRUE(file.warnings.empty());
}

TEST(Off, CountsOnTheHeaderLine) {
  expect_triangle(parse_off("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0.5\n3 0 1 2\n"));
  expect_triangle(parse_off("OFF 3 1\n0 0 0\n1 0 0\n0 1 0.5\n3 0 1 2\n"));
}

TEST(Off, OptionalKeywordAndEdgeCount) {
  expect_triangle(parse_off("3 1 0\n0 0 0\n1 0 0\n0 1 0.5\n3 0 1 2\n"));
  expect_triangle(parse_off("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0.5\n3 0 1 2\n"));
}

TEST(Off, ValuesMayWrapAcrossLines) {
  const MeshFile file = parse_off("OFF\n3\n1\n0\n0 0\n1\n0 0\n0 1 0.5\n3\n0 1\n2\n");
  expect_triangle(file);
  EXPECT_EQ(file.lines.vertex_lines, (std::vector<std::uint32_t>{4, 6, 8}));
  EXPECT_EQ(file.lines.face_lines, (std::vector<std::uint32_t>{9}));
}

TEST(Off, FaceColoursAreIgnored) {
  const MeshFile file = parse_off(
      "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2 1.0 0.0 0.0 1.0\n3 0 2 3 255 0 0\n");
  EXPECT_EQ(file.mesh.face_indices, (std::vector<Index>{0, 1, 2, 0, 2, 3}));
}

TEST(Off, SmallFacesAreAccepted) {
  const MeshFile file = parse_off("OFF\n2 3 0\n0 0 0\n1 0 0\n0\n1 1\n2 0 1\n");
  EXPECT_EQ(file.mesh.face_offsets, (std::vector<Index>{0, 0, 1, 3}));
}

TEST(Off, TrailingDataIsAWarning) {
  const MeshFile file = parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0.5\n3 0 1 2\n\n2 0 1\n");
  expect_triangle(file);
  ASSERT_EQ(file.warnings.size(), 1u);
  EXPECT_NE(file.warnings[0].find("line 8"), std::string::npos) << file.warnings[0];
}

// --- errors ------------------------------------------------------------------------

TEST(OffErrors, BinaryIsRejected) {
  EXPECT_PARSE_ERROR(parse_off("OFF BINARY\n\x00\x00\x00\x03", "b.off"), "b.off:1: binary OFF is not supported");
  EXPECT_PARSE_ERROR(parse_off("COFF BINARY\n"), "binary OFF is not supported");
}

TEST(OffErrors, BadHeader) {
  EXPECT_PARSE_ERROR(parse_off(""), "empty file");
  EXPECT_PARSE_ERROR(parse_off("# only a comment\n\n"), "empty file");
  EXPECT_PARSE_ERROR(parse_off("PLY\n3 1 0\n", "h.off"), "h.off:1: not an OFF file");
  EXPECT_PARSE_ERROR(parse_off("XOFF\n3 1 0\n"), "not an OFF file");
  EXPECT_PARSE_ERROR(parse_off("NCOFF\n3 1 0\n"), "not an OFF file");  // prefixes out of order
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 x 0\n", "h.off"), "h.off:2: bad face count 'x'");
  EXPECT_PARSE_ERROR(parse_off("OFF\n-3 1 0\n"), "bad vertex count '-3'");
  EXPECT_PARSE_ERROR(parse_off("OFF\n"), "missing the vertex count");
  EXPECT_PARSE_ERROR(parse_off("nOFF\n0\n3 1 0\n"), "unsupported dimension 0");
}

TEST(OffErrors, LyingCounts) {
  for (const char* count : {"4000000000", "1000000000", "1099511627776"}) {
    const auto start = std::chrono::steady_clock::now();
    EXPECT_PARSE_ERROR(parse_off(std::string("OFF\n") + count + " 1 0\n0 0 0\n", "lie.off"),
                       std::string("lie.off:2: header declares ") + count + " vertices but the file holds at most 1");
    EXPECT_PARSE_ERROR(parse_off(std::string("OFF\n1 ") + count + " 0\n0 0 0\n3 0 0 0\n"),
                       std::string("header declares ") + count + " faces but the file holds at most ");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  }
  EXPECT_PARSE_ERROR(parse_off("OFF\n99999999999999999999999 1 0\n"), "bad vertex count");
  // A huge face size is bounded by the values actually there.
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n"),
                     "unexpected end of file in face 0");
}

TEST(OffErrors, IndexOutOfRangeNamesTheLine) {
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n\n3 0 1 7\n", "r.off"),
                     "r.off:8: face 1: vertex index 7 is out of range (the file has 3 vertices)");
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0\n-1 2\n", "r.off"),
                     "r.off:7: face 0: vertex index -1 is out of range");
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n", "r.off"),
                     "r.off:6: face 0: bad vertex index '1.5'");
}

TEST(OffErrors, TruncatedAndMalformedData) {
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1\n# a comment long enough to pass the size check\n"), "unexpected end of file in vertex 2");
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 2 0\n0.5 0.5 0.5\n1.5 0.5 0.5\n0.5 1.5 0.5\n3 0 1 2\n"),
                     "unexpected end of file in face 1");
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 20 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                     "header declares 20 faces but the file holds at most 5");
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", "m.off"),
                     "m.off:4: vertex 1: bad number 'zero'");
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 1 0\n0 0 0 red\n1 0 0\n0 1 0\n3 0 1 2\n", "m.off"),
                     "m.off:3: vertex 0: bad value 'red'");
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n", "m.off"),
                     "m.off:6: face 0: bad vertex count '-3'");
}

TEST(OffErrors, GarbageBytes) {
  std::string garbage;
  std::mt19937 rng(3);
  for (int i = 0; i < 4096; ++i) garbage += static_cast<char>(rng() & 0xff);
  EXPECT_PARSE_ERROR(parse_off(garbage), "");
  EXPECT_PARSE_ERROR(parse_off("OFF\n3 1 0\n" + garbage), "");
}

TEST(OffErrors, CorruptedFilesOnlyThrowParseError) {
  const std::vector<std::string> inputs{
      format_off(test::hard_numbers_mesh()), "STCNOFF\n3 1 0\n0 0 0 0 0 1 1 0 0 1 0 0\n1 0 0 0 0 1 0 1 0 1 1 0\n0 1 0.5 0 0 1 0 0 1 1 0 1\n3 0 1 2\n",
      "nOFF 4\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0.5 1\n3 0 1 2 # c\n"};
  std::mt19937 rng(99);
  for (const std::string& input : inputs) {
    for (std::size_t n = 0; n < input.size(); ++n) {
      try {
        parse_off(input.substr(0, n));
      } catch (const ParseError&) {
      }
    }
    for (int trial = 0; trial < 3000; ++trial) {
      std::string corrupt = input;
      for (int k = 0; k < 1 + static_cast<int>(rng() % 3); ++k) {
        const std::size_t at = rng() % corrupt.size();
        corrupt[at] = "0123456789 \n#-.eOFFCN4nx\xff"[rng() % 26];
      }
      try {
        const MeshFile file = parse_off(corrupt);
        check_indices(file.mesh);
      } catch (const ParseError&) {
      }
    }
  }
}

}  // namespace
}  // namespace subdiv
