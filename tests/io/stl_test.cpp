#include "subdiv/io/stl.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/mesh/validation.h"
#include "support/parse_errors.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

namespace fs = std::filesystem;

/// Each triangle's three corner positions, in order: what an STL file holds.
std::vector<Vec3> corner_positions(const PolygonMesh& mesh) {
  std::vector<Vec3> out;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k)
      for (const Index v : {face[0], face[k], face[k + 1]}) out.push_back(mesh.positions[static_cast<std::size_t>(v)]);
  }
  return out;
}

Vec3 rounded_to_float(Vec3 p) {
  return {static_cast<double>(static_cast<float>(p.x)), static_cast<double>(static_cast<float>(p.y)),
          static_cast<double>(static_cast<float>(p.z))};
}

bool same_bits(Vec3 a, Vec3 b) {
  return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
         std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
         std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

std::uint32_t u32_at(const std::string& bytes, std::size_t offset) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(bytes[offset + static_cast<std::size_t>(i)]);
  return v;
}

float f32_at(const std::string& bytes, std::size_t offset) { return std::bit_cast<float>(u32_at(bytes, offset)); }

void put_u32(std::string& bytes, std::size_t offset, std::uint32_t v) {
  for (std::size_t i = 0; i < 4; ++i) bytes[offset + i] = static_cast<char>((v >> (8 * i)) & 0xFFu);
}

/// One ASCII facet with the given corners.
std::string facet(const std::string& a, const std::string& b, const std::string& c) {
  return "facet normal 0 0 1\n  outer loop\n    vertex " + a + "\n    vertex " + b + "\n    vertex " + c +
         "\n  endloop\nendfacet\n";
}

std::string solid(const std::string& facets) { return "solid test\n" + facets + "endsolid test\n"; }

/// The ParseError `text` raises, for checking its line as well as its message.
ParseError parse_error(const std::string& text) {
  try {
    parse_stl(text, "bad.stl");
  } catch (const ParseError& e) {
    return e;
  }
  return ParseError("", 0, "NO EXCEPTION");
}

// --- round trips -----------------------------------------------------------------

TEST(Stl, AsciiCubeComesBackWeldedAsEightVerticesAndTwelveTriangles) {
  const PolygonMesh cube = test::cube();
  std::vector<std::string> notes;
  const std::string text = format_stl(cube, StlEncoding::ascii, &notes);
  EXPECT_EQ(notes, (std::vector<std::string>{"6 faces with more than three corners written as fans of triangles"}));
  EXPECT_EQ(text.rfind("solid subdiv\nfacet normal 0 0 -1\n  outer loop\n    vertex 0 0 0\n", 0), 0u);
  const MeshFile file = parse_stl(text, "cube.stl");
  EXPECT_TRUE(file.warnings.empty());
  ASSERT_EQ(file.mesh.vertex_count(), 8);
  EXPECT_EQ(file.mesh.face_count(), 12);
  EXPECT_EQ(corner_positions(file.mesh), corner_positions(cube));
  EXPECT_TRUE(validate(file.mesh).ok()) << validate(file.mesh).first_error();
  // Vertices in order of first use, faces the fans in order.
  EXPECT_EQ(file.mesh.positions[1], cube.positions[3]);
  EXPECT_EQ((std::vector<Index>(file.mesh.face_indices.begin(), file.mesh.face_indices.begin() + 6)),
            (std::vector<Index>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(file.lines.path, "cube.stl");
  ASSERT_EQ(file.lines.face_lines.size(), 12u);
  EXPECT_EQ(file.lines.face_lines[0], 2u);
  EXPECT_EQ(file.lines.face_lines[1], 9u);
  EXPECT_EQ(file.lines.vertex_lines.size(), 8u);
  EXPECT_EQ(file.lines.vertex_lines[0], 4u);
}

TEST(Stl, AsciiRoundTripIsBitExact) {
  const PolygonMesh mesh = test::hard_numbers_mesh();
  std::vector<std::string> notes;
  const MeshFile file = parse_stl(format_stl(mesh, StlEncoding::ascii, &notes));
  EXPECT_EQ(notes.size(), 1u);
  // The triangle, the quad's two triangles and the pentagon's three; the
  // vertices are first used in their original order.
  EXPECT_EQ(file.mesh.face_indices, (std::vector<Index>{0, 1, 2, 0, 2, 3, 0, 3, 4, 1, 5, 4, 1, 4, 3, 1, 3, 2}));
  ASSERT_EQ(file.mesh.positions.size(), mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    EXPECT_TRUE(same_bits(file.mesh.positions[v], mesh.positions[v])) << "vertex " << v;
}

TEST(Stl, BinaryRoundTripGivesFloatRoundedPositions) {
  const PolygonMesh mesh = test::jittered(test::cube(), 7);
  const MeshFile file = parse_stl(format_stl(mesh, StlEncoding::binary));
  EXPECT_EQ(file.mesh.vertex_count(), 8);
  EXPECT_EQ(file.mesh.face_count(), 12);
  EXPECT_TRUE(file.lines.face_lines.empty());
  EXPECT_TRUE(file.lines.vertex_lines.empty());
  std::vector<Vec3> expected = corner_positions(mesh);
  for (Vec3& p : expected) p = rounded_to_float(p);
  EXPECT_EQ(corner_positions(file.mesh), expected);
}

TEST(Stl, EmptyMeshRoundTripsInBothEncodings) {
  for (const StlEncoding e : {StlEncoding::ascii, StlEncoding::binary}) {
    const std::string data = format_stl(PolygonMesh{}, e);
    if (e == StlEncoding::binary) {
      EXPECT_EQ(data.size(), 84u);
    }
    const MeshFile file = parse_stl(data);
    EXPECT_EQ(file.mesh.vertex_count(), 0);
    EXPECT_EQ(file.mesh.face_count(), 0);
  }
}

TEST(Stl, ReadAndWrittenThroughAnStlPathInEitherCase) {
  const fs::path dir = fs::temp_directory_path() / ("subdiv_stl_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const char* name : {"m.stl", "M.STL"})
    for (const StlEncoding e : {StlEncoding::binary, StlEncoding::ascii}) {
      SCOPED_TRACE(name);
      WriteOptions options;
      options.stl_encoding = e;
      const std::vector<std::string> notes = write_mesh(test::tetrahedron(), dir / name, options);
      EXPECT_TRUE(notes.empty());
      const MeshFile file = read_mesh(dir / name);
      EXPECT_EQ(file.mesh.vertex_count(), 4);
      EXPECT_EQ(file.mesh.face_count(), 4);
      EXPECT_EQ(file.lines.path, (dir / name).string());
    }
  fs::remove_all(dir);
}

// --- binary -----------------------------------------------------------------------

TEST(Stl, BinaryWriterBytes) {
  PolygonMesh mesh = make_mesh({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}}, {{0, 1, 2}, {0, 1, 3}});
  mesh.positions[3] = {4, 0, 0};  // the second triangle is degenerate: zero normal
  const std::string bytes = format_stl(mesh, StlEncoding::binary);
  ASSERT_EQ(bytes.size(), 84u + 50u * 2u);
  EXPECT_NE(bytes.rfind("solid", 0), 0u);
  EXPECT_EQ(bytes.substr(0, 10), "subdiv STL");
  EXPECT_EQ(u32_at(bytes, 80), 2u);
  EXPECT_EQ(f32_at(bytes, 84), 0.0f);
  EXPECT_EQ(f32_at(bytes, 92), 1.0f);            // the normal's z
  EXPECT_EQ(f32_at(bytes, 84 + 12 + 12), 2.0f);  // the second corner's x
  EXPECT_EQ(bytes[132], '\0');                   // the attribute count
  EXPECT_EQ(bytes[133], '\0');
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(f32_at(bytes, 134 + 4 * k), 0.0f);
}

TEST(Stl, BinaryHeaderStartingWithSolidReadsAsBinary) {
  std::string bytes = format_stl(test::tetrahedron(), StlEncoding::binary);
  bytes.replace(0, 11, "solid cube\n");
  const MeshFile file = parse_stl(bytes);
  EXPECT_EQ(file.mesh.vertex_count(), 4);
  EXPECT_EQ(file.mesh.face_count(), 4);
}

TEST(Stl, BinaryAttributeBytesAreIgnored) {
  std::string bytes = format_stl(test::tetrahedron(), StlEncoding::binary);
  bytes[84 + 48] = '\x7f';
  bytes[84 + 49] = '\x12';
  EXPECT_EQ(parse_stl(bytes).mesh.face_indices,
            parse_stl(format_stl(test::tetrahedron(), StlEncoding::binary)).mesh.face_indices);
}

TEST(Stl, BinaryWriterRefusesWhatItCannotHold) {
  PolygonMesh huge = test::tetrahedron();
  huge.positions[1].y = 1e300;
  std::vector<std::string> notes;
  EXPECT_THROW(format_stl(huge, StlEncoding::binary, &notes), InvalidInputError);
  EXPECT_TRUE(notes.empty());
  EXPECT_NO_THROW(format_stl(huge, StlEncoding::ascii));
  PolygonMesh nan = test::tetrahedron();
  nan.positions[2].z = std::nan("");
  EXPECT_THROW(format_stl(nan, StlEncoding::ascii), InvalidInputError);
  PolygonMesh broken = test::tetrahedron();
  broken.face_indices[0] = 9;
  EXPECT_THROW(format_stl(broken, StlEncoding::binary), InvalidInputError);
}

// --- writing polygons and channels -------------------------------------------------

TEST(Stl, PentagonIsWrittenAsAFanOfThreeTriangles) {
  const PolygonMesh pentagon =
      make_mesh({{1, 0, 0}, {0.3, 0.95, 0}, {-0.8, 0.6, 0}, {-0.8, -0.6, 0}, {0.3, -0.95, 0}}, {{0, 1, 2, 3, 4}});
  std::vector<std::string> notes;
  const std::string text = format_stl(pentagon, StlEncoding::ascii, &notes);
  EXPECT_EQ(notes, (std::vector<std::string>{"1 faces with more than three corners written as fans of triangles"}));
  const MeshFile file = parse_stl(text);
  EXPECT_EQ(file.mesh.face_count(), 3);
  EXPECT_EQ(file.mesh.face_indices, (std::vector<Index>{0, 1, 2, 0, 2, 3, 0, 3, 4}));
  EXPECT_EQ(format_stl(pentagon, StlEncoding::binary).size(), 84u + 3u * 50u);
  EXPECT_NE(text.find("facet normal 0 0 1\n"), std::string::npos);
}

TEST(Stl, FacesOfFewerThanThreeCornersAreLeftOutWithANote) {
  const PolygonMesh mesh = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 1}, {2}});
  std::vector<std::string> notes;
  const std::string bytes = format_stl(mesh, StlEncoding::binary, &notes);
  EXPECT_EQ(bytes.size(), 84u + 50u);
  EXPECT_EQ(notes, (std::vector<std::string>{"2 faces with fewer than three corners left out"}));
}

TEST(Stl, DroppedChannelsAreNotedOncePerKind) {
  PolygonMesh mesh = test::tetrahedron();
  mesh.vertex_channels.push_back({"normal", 3, std::vector<double>(12, 0.0)});
  mesh.vertex_channels.push_back({"color", 3, std::vector<double>(12, 0.5)});
  mesh.face_varying_channels.push_back({"uv", 2, {0, 0}, std::vector<Index>(12, 0)});
  std::vector<std::string> notes;
  format_stl(mesh, StlEncoding::ascii, &notes);
  EXPECT_EQ(notes, (std::vector<std::string>{"STL has no place for vertex channels ('normal', 'color'): not written",
                                             "STL has no place for face-varying channels ('uv'): not written"}));
}

// --- ASCII variants ----------------------------------------------------------------

TEST(Stl, AsciiToleratesCaseCrlfBlankLinesAndTrailingSpace) {
  const std::string text =
      "SOLID Part 1 \r\n\r\n  FACET NORMAL 0 0 1\t\r\n OUTER LOOP\r\n  Vertex 0 0 0 \r\n  VERTEX 1 0 0\r\n"
      "  vertex 0 1 0\r\n\r\n ENDLOOP \r\n EndFacet\r\nENDSOLID Part 1\r\n\r\n";
  const MeshFile file = parse_stl(text, "crlf.stl");
  EXPECT_EQ(file.mesh.positions, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(file.mesh.face_indices, (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(file.lines.face_lines, (std::vector<std::uint32_t>{3}));
  EXPECT_EQ(file.lines.vertex_lines, (std::vector<std::uint32_t>{5, 6, 7}));
}

TEST(Stl, SeveralSolidsMakeOneMesh) {
  const std::string text = solid(facet("0 0 0", "1 0 0", "0 1 0")) + "\n" + solid(facet("1 0 0", "1 1 0", "0 1 0"));
  const MeshFile file = parse_stl(text);
  EXPECT_EQ(file.mesh.vertex_count(), 4);
  EXPECT_EQ(file.mesh.face_indices, (std::vector<Index>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(file.lines.face_lines, (std::vector<std::uint32_t>{2, 12}));
}

TEST(Stl, ValidationNamesTheFacetLine) {
  // Three triangles on one edge: the third makes it non-manifold.
  const std::string text =
      solid(facet("0 0 0", "1 0 0", "0 1 0") + facet("1 0 0", "0 0 0", "0 -1 0") + facet("0 0 0", "1 0 0", "0 0 1"));
  const MeshFile file = parse_stl(text, "fin.stl");
  const ValidationReport report = validate(file.mesh, &file.lines);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.first_error("fin.stl").find("fin.stl:16:"), std::string::npos) << report.first_error("fin.stl");
}

// --- welding -----------------------------------------------------------------------

TEST(Stl, WeldToleranceMergesNearPointsAndZeroDoesNot) {
  const std::string text =
      solid(facet("0 0 0", "1 0 0", "0 1 0") + facet("1.0000001 0 0", "1 1 0", "0 1.0000001 -1e-9"));
  const MeshFile exact = parse_stl(text);
  EXPECT_EQ(exact.mesh.vertex_count(), 6);
  EXPECT_TRUE(exact.warnings.empty());
  const MeshFile welded = parse_stl(text, "", {.weld_tolerance = 1e-6});
  EXPECT_EQ(welded.mesh.vertex_count(), 4);
  EXPECT_EQ(welded.mesh.face_indices, (std::vector<Index>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(welded.mesh.positions[1], (Vec3{1, 0, 0}));  // the earliest position is kept
  EXPECT_EQ(welded.warnings, (std::vector<std::string>{"2 corners moved onto a vertex within the weld tolerance"}));
}

TEST(Stl, NegativeToleranceKeepsThreeVerticesPerTriangle) {
  const MeshFile file = parse_stl(format_stl(test::cube(), StlEncoding::ascii), "", {.weld_tolerance = -1.0});
  EXPECT_EQ(file.mesh.vertex_count(), 36);
  EXPECT_EQ(file.mesh.face_count(), 12);
  EXPECT_EQ(file.lines.vertex_lines.size(), 36u);
}

TEST(Stl, TrianglesCollapsedByWeldingAreLeftOutWithANote) {
  // The first triangle has two equal corners; the second collapses only
  // with a tolerance. The vertex only the first uses is left out as well.
  const std::string text =
      solid(facet("5 5 5", "0 0 0", "0 0 0") + facet("0 0 0", "1 0 0", "0 1 0") + facet("2 0 0", "2.001 0 0", "2 1 0"));
  const MeshFile exact = parse_stl(text);
  EXPECT_EQ(exact.mesh.face_count(), 2);
  EXPECT_EQ(exact.mesh.vertex_count(), 6);
  EXPECT_EQ(exact.mesh.positions[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(exact.lines.face_lines, (std::vector<std::uint32_t>{9, 16}));
  EXPECT_EQ(exact.warnings,
            (std::vector<std::string>{"1 triangles collapsed by welding (two corners on one vertex) left out"}));
  const MeshFile welded = parse_stl(text, "", {.weld_tolerance = 0.01});
  EXPECT_EQ(welded.mesh.face_count(), 1);
  EXPECT_EQ(welded.mesh.vertex_count(), 3);
  ASSERT_FALSE(welded.warnings.empty());
  EXPECT_EQ(welded.warnings[0], "2 triangles collapsed by welding (two corners on one vertex) left out");
  EXPECT_EQ(parse_stl(text, "", {.weld_tolerance = -1}).mesh.face_count(), 3);
}

// --- malformed input ----------------------------------------------------------------

TEST(Stl, EmptyFile) {
  EXPECT_PARSE_ERROR(parse_stl("", "e.stl"), "e.stl: empty file");
  EXPECT_PARSE_ERROR(parse_stl("\n  \r\n", "e.stl"), "e.stl: empty file");
}

TEST(Stl, MissingSolid) {
  EXPECT_PARSE_ERROR(parse_stl("\nfacet normal 0 0 1\n", "s.stl"), "s.stl:2: not an STL file (too short");
  EXPECT_PARSE_ERROR(parse_stl(std::string(200, 'x'), "s.stl"), "s.stl:1: not an STL file (ASCII STL starts with");
}

TEST(Stl, TruncatedBinaryIsReadAsAsciiAndRefused) {
  std::string bytes = format_stl(test::tetrahedron(), StlEncoding::binary);
  bytes.pop_back();
  const ParseError e = parse_error(bytes);
  EXPECT_EQ(e.line(), 1u);
  EXPECT_NE(std::string(e.what()).find("not an STL file"), std::string::npos) << e.what();
}

TEST(Stl, BinaryWithSolidHeaderAndWrongCountFailsCleanly) {
  std::string bytes = format_stl(test::tetrahedron(), StlEncoding::binary);
  bytes.replace(0, 6, "solid ");
  put_u32(bytes, 80, 5);  // four triangles follow
  const ParseError e = parse_error(bytes);
  EXPECT_GE(e.line(), 1u);
  EXPECT_NE(std::string(e.what()).find("bad.stl:"), std::string::npos) << e.what();
}

TEST(Stl, HugeCountInAnEmptyBinaryFileFailsFast) {
  std::string bytes(84, '\0');
  put_u32(bytes, 80, 0xFFFFFFFFu);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_PARSE_ERROR(parse_stl(bytes, "h.stl"), "h.stl:1: not an STL file (ASCII STL starts with");
  bytes.replace(0, 6, "solid ");
  EXPECT_PARSE_ERROR(parse_stl(bytes, "h.stl"), "h.stl:1: unexpected end of file: no 'endsolid'");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

TEST(Stl, NonFiniteCoordinates) {
  EXPECT_PARSE_ERROR(parse_stl(solid(facet("0 0 0", "nan 0 0", "0 1 0")), "n.stl"),
                     "n.stl:5: vertex: non-finite coordinate");
  EXPECT_PARSE_ERROR(parse_stl(solid(facet("0 0 0", "1 0 0", "0 1 1e999")), "n.stl"), "n.stl:6: vertex:");
  std::string bytes = format_stl(test::tetrahedron(), StlEncoding::binary);
  const std::uint32_t nan = std::bit_cast<std::uint32_t>(std::numeric_limits<float>::quiet_NaN());
  put_u32(bytes, 84 + 50 + 12 + 4, nan);  // triangle 1, first corner's y
  EXPECT_PARSE_ERROR(parse_stl(bytes, "n.stl"), "n.stl: triangle 1: non-finite coordinate");
  EXPECT_EQ(parse_error(bytes).line(), 0u);
}

TEST(Stl, BadNumbersAndExtraText) {
  EXPECT_PARSE_ERROR(parse_stl(solid(facet("0 0 0", "1 x 0", "0 1 0")), "b.stl"), "b.stl:5: vertex: bad number 'x'");
  EXPECT_PARSE_ERROR(parse_stl(solid(facet("0 0 0", "1 0", "0 1 0")), "b.stl"), "b.stl:5: vertex: bad number ''");
  EXPECT_PARSE_ERROR(parse_stl(solid(facet("0 0 0", "1 0 0 1", "0 1 0")), "b.stl"),
                     "b.stl:5: unexpected text after the vertex: '1'");
  EXPECT_PARSE_ERROR(parse_stl("solid\nfacet normal 0 zero 1\n", "b.stl"), "b.stl:2: facet normal: bad number 'zero'");
  EXPECT_PARSE_ERROR(parse_stl("solid\nfacet 0 0 1\n", "b.stl"), "b.stl:2: expected 'facet normal nx ny nz'");
  EXPECT_PARSE_ERROR(parse_stl("solid\nfacet normal 0 0 1\nvertex 0 0 0\n", "b.stl"),
                     "b.stl:3: expected 'outer loop', found 'vertex'");
  EXPECT_PARSE_ERROR(parse_stl("solid\nvertex 0 0 0\n", "b.stl"), "b.stl:2: expected 'facet' or 'endsolid'");
}

TEST(Stl, FacetsWithOtherThanThreeVertices) {
  const std::string four =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\n"
      "endloop\nendfacet\n";
  EXPECT_PARSE_ERROR(parse_stl(solid(four), "f.stl"), "f.stl:7: facet at line 2 has more than three vertices");
  const std::string two = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n";
  EXPECT_PARSE_ERROR(parse_stl(solid(two), "f.stl"), "f.stl:6: facet at line 2 has 2 vertices (expected 3)");
}

TEST(Stl, TruncatedAscii) {
  EXPECT_PARSE_ERROR(parse_stl("solid x\n" + facet("0 0 0", "1 0 0", "0 1 0"), "t.stl"),
                     "t.stl:8: unexpected end of file: no 'endsolid'");
  EXPECT_PARSE_ERROR(parse_stl("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0", "t.stl"),
                     "t.stl:4: unexpected end of file");
}

TEST(Stl, TextAfterEndsolid) {
  EXPECT_PARSE_ERROR(parse_stl(solid(facet("0 0 0", "1 0 0", "0 1 0")) + "\ngarbage\n", "a.stl"),
                     "a.stl:11: unexpected text after 'endsolid': 'garbage'");
}

}  // namespace
}  // namespace subdiv
