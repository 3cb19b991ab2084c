#include "subdiv/io/obj.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "subdiv/core/error.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

std::string error_of(std::string_view text) {
  try {
    parse_obj(text, "t.obj");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(ObjReader, PositionsAndFaceForms) {
  const MeshFile f = parse_obj(
      "# comment\n"
      "o thing\ng group\ns 1\nusemtl red\n"
      "v 0 0 0\nv 1.5 0 0\r\nv 1 1e2 0\n\tv  0 1 -2.5e-3  \n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
      "vn 0 0 1\n"
      "f 1/1/1 2/2/1 3/3/1 4/4/1\n");
  const PolygonMesh& m = f.mesh;
  ASSERT_EQ(m.vertex_count(), 4);
  EXPECT_EQ(m.positions[1], (Vec3{1.5, 0, 0}));
  EXPECT_EQ(m.positions[2], (Vec3{1, 100, 0}));
  EXPECT_EQ(m.positions[3], (Vec3{0, 1, -2.5e-3}));
  ASSERT_EQ(m.face_count(), 1);
  EXPECT_EQ(std::vector<Index>(m.face(0).begin(), m.face(0).end()), (std::vector<Index>{0, 1, 2, 3}));
  const auto* uv = m.find_face_varying_channel("uv");
  ASSERT_NE(uv, nullptr);
  EXPECT_EQ(uv->components, 2);
  EXPECT_EQ(uv->indices, (std::vector<Index>{0, 1, 2, 3}));
  EXPECT_EQ(uv->values[5], 1.0);
  const auto* n = m.find_face_varying_channel("normal");
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(n->indices, (std::vector<Index>{0, 0, 0, 0}));
  EXPECT_EQ(f.lines.vertex_lines, (std::vector<std::uint32_t>{6, 7, 8, 9}));
  EXPECT_EQ(f.lines.face_lines, (std::vector<std::uint32_t>{15}));
  EXPECT_TRUE(f.warnings.empty());
}

TEST(ObjReader, OnlyNormalsAndNegativeIndices) {
  const MeshFile f = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf -3//-1 -2//-1 -1//-1\nv 1 1 0\nf 2 4 3\n");
  EXPECT_EQ(f.mesh.face_count(), 2);
  EXPECT_EQ(std::vector<Index>(f.mesh.face(0).begin(), f.mesh.face(0).end()), (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(std::vector<Index>(f.mesh.face(1).begin(), f.mesh.face(1).end()), (std::vector<Index>{1, 3, 2}));
  EXPECT_EQ(f.mesh.find_face_varying_channel("uv"), nullptr);
  // The second face has no normal index: the channel would have a gap.
  EXPECT_EQ(f.mesh.find_face_varying_channel("normal"), nullptr);
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("'normal' channel dropped"), std::string::npos);
}

TEST(ObjReader, VertexColours) {
  const MeshFile f = parse_obj("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n");
  const auto* c = f.mesh.find_vertex_channel("color");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->values, (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
  const MeshFile partial = parse_obj("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(partial.mesh.find_vertex_channel("color"), nullptr);
  EXPECT_EQ(partial.warnings.size(), 1u);
  // x y z w: the weight is accepted and not kept.
  EXPECT_EQ(parse_obj("v 1 2 3 1\n").mesh.positions[0], (Vec3{1, 2, 3}));
}

TEST(ObjReader, OpenSubdivTags) {
  const MeshFile f = parse_obj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"
      "t crease 2/1/0 0 1 10.0\n"
      "t crease 4/2/0 1 2 2 3 0.5 2.5\n"
      "t corner 1/1/0  3  4.5\n"
      "t corner 2/1/2 0 2 10 convex concave:270\n"
      "t hole 1/0/0 0\n"
      "t interpolateboundary 1/0/0 2\n"
      "t facevaryinginterpolateboundary 1/0/0 1\n"
      "t facevaryingpropagatecorners 1/0/0 1\n"
      "t creasemethod 0/0/1 chaikin\n"
      "t smoothtriangles 0/0/1 smooth\n"
      "t vertexedit 3/2/2 1 2 3 0.5 0.25 add P\n");
  const Tags& t = f.mesh.tags;
  ASSERT_EQ(t.creases.size(), 3u);
  EXPECT_EQ(t.creases[0], (CreaseTag{0, 1, 10.0}));
  EXPECT_EQ(t.creases[1], (CreaseTag{1, 2, 0.5}));
  EXPECT_EQ(t.creases[2], (CreaseTag{2, 3, 2.5}));
  ASSERT_EQ(t.corners.size(), 3u);
  EXPECT_EQ(t.corners[0].vertex, 3);
  EXPECT_EQ(t.corners[0].sharpness, 4.5);
  EXPECT_EQ(t.corners[0].type, CornerType::unspecified);
  EXPECT_EQ(t.corners[1].type, CornerType::convex);
  EXPECT_FALSE(t.corners[1].angle.has_value());
  EXPECT_EQ(t.corners[2].type, CornerType::concave);
  ASSERT_TRUE(t.corners[2].angle.has_value());
  EXPECT_NEAR(*t.corners[2].angle, 1.5 * std::numbers::pi, 1e-15);
  EXPECT_EQ(t.holes, (std::vector<Index>{0}));
  EXPECT_EQ(t.boundary_interpolation, BoundaryInterpolation::edge_only);
  EXPECT_EQ(t.face_varying_interpolation, FaceVaryingInterpolation::corners_only);
  EXPECT_TRUE(t.face_varying_propagate_corners);
  EXPECT_EQ(t.crease_method, CreaseMethod::chaikin);
  EXPECT_EQ(t.triangle_subdivision, TriangleSubdivision::smooth);
  ASSERT_EQ(t.other.size(), 1u);
  EXPECT_EQ(t.other[0], (RawTag{"vertexedit", {1, 2, 3}, {0.5, 0.25}, {"add", "P"}}));
  EXPECT_EQ(f.lines.crease_lines, (std::vector<std::uint32_t>{6, 7, 7}));
  EXPECT_EQ(f.lines.corner_lines, (std::vector<std::uint32_t>{8, 9, 9}));
  EXPECT_EQ(f.lines.hole_lines, (std::vector<std::uint32_t>{10}));
}

TEST(ObjReader, InterpolateBoundaryCodesFollowOpenSubdiv) {
  EXPECT_EQ(parse_obj("t interpolateboundary 1/0/0 0\n").mesh.tags.boundary_interpolation, BoundaryInterpolation::none);
  EXPECT_EQ(parse_obj("t interpolateboundary 1/0/0 1\n").mesh.tags.boundary_interpolation,
            BoundaryInterpolation::edge_and_corner);
  EXPECT_EQ(parse_obj("t interpolateboundary 1/0/0 2\n").mesh.tags.boundary_interpolation,
            BoundaryInterpolation::edge_only);
  EXPECT_FALSE(parse_obj("v 0 0 0\n").mesh.tags.boundary_interpolation_set);
}

TEST(ObjReader, UnknownKeywordsAreNotedOnce) {
  const MeshFile f = parse_obj("v 0 0 0\nfoo 1 2\nbar\nv 1 0 0\n");
  EXPECT_EQ(f.mesh.vertex_count(), 2);
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("line 2: unknown keyword 'foo'"), std::string::npos);
}

TEST(ObjReader, ErrorsNameFileLineAndProblem) {
  EXPECT_EQ(error_of("v 0 0 0\nv 1 x 0\n"), "t.obj:2: bad y coordinate 'x'");
  EXPECT_EQ(error_of("v 0 0\n"), "t.obj:1: missing z coordinate");
  EXPECT_EQ(error_of("v 0 0 0 1 2 3 4 5\n"), "t.obj:1: too many numbers on a vertex line (expected x y z [w] or x y z r g b)");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "t.obj:4: vertex index 0 is invalid (OBJ indices start at 1)");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\nf 1 2 4\n"),
            "t.obj:6: face 1 refers to vertex 4 but the file has 3 vertices");
  EXPECT_EQ(error_of("v 0 0 0\nf -2 -1 1\n"), "t.obj:2: relative vertex index -2 reaches before the first vertex (only 1 so far)");
  EXPECT_EQ(error_of("v 0 0 0\nf 1 a 1\n"), "t.obj:2: bad face vertex 'a'");
  EXPECT_EQ(error_of("v 0 0 0\nf 1/x 1 1\n"), "t.obj:2: bad texture index in face");
  EXPECT_EQ(error_of("f 99999999999999999999 1 2\n"), "t.obj:1: bad face vertex '99999999999999999999'");
  EXPECT_EQ(error_of("t crease 2/1/0 0 1\n"), "t.obj:1: tag 'crease': expected 1 numbers");
  EXPECT_EQ(error_of("t crease 3/1/0 0 1 2 1.0\n"), "t.obj:1: tag 'crease' expects vertex pairs and one sharpness, or one per pair");
  EXPECT_EQ(error_of("t crease x 0 1\n"), "t.obj:1: tag 'crease': expected argument counts ints/floats/strings, e.g. 2/1/0");
  EXPECT_EQ(error_of("t crease 2/1/0 0 1 2.0 extra\n"), "t.obj:1: tag 'crease': more arguments than its counts say");
  EXPECT_EQ(error_of("t interpolateboundary 1/0/0 7\n"), "t.obj:1: tag 'interpolateboundary' expects one integer in [0, 2]");
  EXPECT_EQ(error_of("t corner 1/1/1 0 1 sideways\n"),
            "t.obj:1: tag 'corner': type must be 'convex' or 'concave' (optionally ':degrees'), not 'sideways'");
  EXPECT_EQ(error_of("t corner 1/1/1 0 1 convex:400\n"), "t.obj:1: tag 'corner': angle in 'convex:400' must be in (0, 360) degrees");
  EXPECT_EQ(error_of(std::string("v 0 0 0\n\x01\x02\xff\n", 12)), "t.obj:2: unreadable line (binary data or a corrupted file?)");
}

TEST(ObjReader, HugeTagCountsFailWithoutAllocating) {
  EXPECT_EQ(error_of("t hole 2000000000/0/0 1\n"), "t.obj:1: tag 'hole': expected 2000000000 integers");
}

TEST(ObjReader, EmptyInputIsAnEmptyMesh) {
  const MeshFile f = parse_obj("");
  EXPECT_EQ(f.mesh.vertex_count(), 0);
  EXPECT_EQ(f.mesh.face_count(), 0);
}

TEST(ObjReader, Polylines) {
  const MeshFile f = parse_obj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
      "l 1 2 3\n"            // open
      "l 1 2 3 4 1\n"        // closed: the last index is the first
      "l -4/1 -3/2 -2 -4\n"  // relative indices and v/vt, closed
      "l 4 1\n");            // two points
  EXPECT_EQ(f.mesh.face_count(), 0);
  ASSERT_EQ(f.mesh.polylines.size(), 4u);
  EXPECT_EQ(f.mesh.polylines[0], (MeshPolyline{{0, 1, 2}, false}));
  EXPECT_EQ(f.mesh.polylines[1], (MeshPolyline{{0, 1, 2, 3}, true}));
  EXPECT_EQ(f.mesh.polylines[2], (MeshPolyline{{0, 1, 2}, true}));
  EXPECT_EQ(f.mesh.polylines[3], (MeshPolyline{{3, 0}, false}));
  EXPECT_EQ(f.lines.polyline_lines, (std::vector<std::uint32_t>{7, 8, 9, 10}));
  EXPECT_TRUE(f.warnings.empty());
  // Faces and polylines in one file are both kept, and the faces unchanged.
  const MeshFile both = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\n");
  EXPECT_EQ(both.mesh.face_count(), 1);
  EXPECT_EQ(both.mesh.polylines, (std::vector<MeshPolyline>{{{0, 1}, false}}));
  EXPECT_TRUE(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").mesh.polylines.empty());
}

TEST(ObjReader, PolylineErrorsNameFileAndLine) {
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nl 1 3\n"),
            "t.obj:3: polyline 0 refers to vertex 3 but the file has 2 vertices");
  EXPECT_EQ(error_of("v 0 0 0\nl 1 2\nv 1 0 0\nl 2 9 1\n"),
            "t.obj:4: polyline 1 refers to vertex 9 but the file has 2 vertices");
  EXPECT_EQ(error_of("v 0 0 0\nl 1\n"), "t.obj:2: polyline with 1 points (a polyline needs at least 2)");
  EXPECT_EQ(error_of("v 0 0 0\nl 1 1\n"), "t.obj:2: polyline with 1 distinct point (a polyline needs at least 2)");
  EXPECT_EQ(error_of("v 0 0 0\nl\n"), "t.obj:2: polyline with 0 points (a polyline needs at least 2)");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nl 1 0\n"), "t.obj:3: vertex index 0 is invalid (OBJ indices start at 1)");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nl 1 -3\n"),
            "t.obj:3: relative vertex index -3 reaches before the first vertex (only 2 so far)");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nl 1 x\n"), "t.obj:3: bad polyline vertex 'x'");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nl 1 2/\n"), "t.obj:3: bad texture index in polyline");
}

TEST(ObjWriter, PolylinesRoundTrip) {
  PolygonMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.5}, {2, 2, 2}};
  mesh.polylines = {{{0, 1, 2, 3}, true}, {{4, 2, 0}, false}, {{1, 3}, false}};
  const std::string text = format_obj(mesh);
  EXPECT_NE(text.find("\nl 1 2 3 4 1\nl 5 3 1\nl 2 4\n"), std::string::npos) << text;
  EXPECT_NE(text.find("3 polylines"), std::string::npos);
  const MeshFile back = parse_obj(text);
  EXPECT_EQ(back.mesh.positions, mesh.positions);
  EXPECT_EQ(back.mesh.polylines, mesh.polylines);
  EXPECT_EQ(back.mesh.face_count(), 0);
  // With faces, and read back again: the text is a fixed point.
  PolygonMesh with_faces = test::cube();
  with_faces.polylines = {{{0, 1, 2}, true}};
  const std::string once = format_obj(with_faces);
  const MeshFile again = parse_obj(once);
  EXPECT_EQ(again.mesh.polylines, with_faces.polylines);
  EXPECT_EQ(again.mesh.face_indices, with_faces.face_indices);
  EXPECT_EQ(format_obj(again.mesh), once);
  // A polyline through a vertex that is not there is refused.
  mesh.polylines.push_back({{0, 5}, false});
  EXPECT_THROW(format_obj(mesh), InvalidInputError);
}

TEST(ObjWriter, RoundTripIsExact) {
  PolygonMesh mesh = test::cube();
  mesh.positions[3] = {0.1, 1.0 / 3.0, -2.0e-300};
  mesh.add_face({0, 1, 2});
  mesh.vertex_channels.push_back({"color", 3, std::vector<double>(24, 0.25)});
  FaceVaryingChannel uv{"uv", 2, {0, 0, 1, 0, 0.5, 0.75}, {}};
  for (Index c = 0; c < mesh.corner_count(); ++c) uv.indices.push_back(c % 3);
  mesh.face_varying_channels.push_back(uv);
  mesh.tags.creases = {{0, 1, 10.0}, {1, 2, 0.25}};
  mesh.tags.corners = {{3, 2.0, CornerType::concave, 1.25 * std::numbers::pi}, {4, 10.0, CornerType::convex, std::nullopt}};
  mesh.tags.holes = {2, 4};
  mesh.tags.boundary_interpolation = BoundaryInterpolation::edge_only;
  mesh.tags.boundary_interpolation_set = true;
  mesh.tags.crease_method = CreaseMethod::chaikin;
  mesh.tags.crease_method_set = true;
  mesh.tags.other.push_back({"faceedit", {4, 0, 1}, {}, {"hole"}});

  std::vector<std::string> warnings;
  const std::string text = format_obj(mesh, {}, &warnings);
  EXPECT_TRUE(warnings.empty());
  const MeshFile back = parse_obj(text);
  EXPECT_EQ(back.mesh.positions, mesh.positions);
  EXPECT_EQ(back.mesh.face_offsets, mesh.face_offsets);
  EXPECT_EQ(back.mesh.face_indices, mesh.face_indices);
  ASSERT_EQ(back.mesh.vertex_channels.size(), 1u);
  EXPECT_EQ(back.mesh.vertex_channels[0].values, mesh.vertex_channels[0].values);
  ASSERT_EQ(back.mesh.face_varying_channels.size(), 1u);
  EXPECT_EQ(back.mesh.face_varying_channels[0].values, uv.values);
  EXPECT_EQ(back.mesh.face_varying_channels[0].indices, uv.indices);
  ASSERT_EQ(back.mesh.tags.corners.size(), 2u);
  EXPECT_NEAR(*back.mesh.tags.corners[0].angle, 1.25 * std::numbers::pi, 1e-14);
  Tags expected = mesh.tags;
  expected.corners[0].angle = back.mesh.tags.corners[0].angle;  // degrees in the file: compared above
  EXPECT_EQ(back.mesh.tags, expected);
}

TEST(ObjWriter, RefusesMalformedMeshes) {
  PolygonMesh mesh = test::cube();
  mesh.face_varying_channels.push_back({"uv", 2, {0, 0}, std::vector<Index>(24, 0)});
  mesh.face_varying_channels[0].indices[3] = 7;
  EXPECT_THROW(format_obj(mesh), InvalidInputError);
}

TEST(ObjWriter, KeptTagNamesRoundTripWhateverTheirBytes) {
  // Found by fuzz_obj: a name holding a NUL byte was written up to the NUL,
  // and the written file did not parse.
  const std::string text("v 0 0 0\nt a\0b 1/0/1 7 s\0t\n", 26);
  const MeshFile first = parse_obj(text);
  ASSERT_EQ(first.mesh.tags.other.size(), 1u);
  EXPECT_EQ(first.mesh.tags.other[0].name, std::string("a\0b", 3));
  const MeshFile back = parse_obj(format_obj(first.mesh));
  EXPECT_EQ(back.mesh.tags, first.mesh.tags);
}

TEST(ObjWriter, RefusesKeptTagsItCannotWriteAsTokens) {
  PolygonMesh mesh = test::cube();
  mesh.tags.other.push_back({"two words", {}, {}, {}});
  EXPECT_THROW(format_obj(mesh), InvalidInputError);
  mesh.tags.other.back() = {"faceedit", {}, {}, {"line\nbreak"}};
  EXPECT_THROW(format_obj(mesh), InvalidInputError);
  mesh.tags.other.back() = {"", {}, {}, {}};
  EXPECT_THROW(format_obj(mesh), InvalidInputError);
}

TEST(ObjWriter, WarnsAboutChannelsItCannotHold) {
  PolygonMesh mesh = test::cube();
  mesh.vertex_channels.push_back({"weight", 1, std::vector<double>(8, 1.0)});
  std::vector<std::string> warnings;
  const std::string text = format_obj(mesh, {}, &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("'weight'"), std::string::npos);
  WriteOptions no_tags;
  no_tags.write_tags = false;
  mesh.tags.creases.push_back({0, 1, 1.0});
  EXPECT_EQ(format_obj(mesh, no_tags).find("t crease"), std::string::npos);
  EXPECT_NE(format_obj(mesh).find("t crease 2/1/0 0 1 1\n"), std::string::npos);
}

}  // namespace
}  // namespace subdiv
