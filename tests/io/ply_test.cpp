#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "subdiv/core/error.h"
#include "support/parse_errors.h"
#include "support/test_meshes.h"
#include "subdiv/io/ply.h"

namespace subdiv {
namespace {

constexpr PlyEncoding kAllEncodings[] = {PlyEncoding::ascii, PlyEncoding::binary_little_endian,
                                         PlyEncoding::binary_big_endian};

const char* name(PlyEncoding e) {
  switch (e) {
    case PlyEncoding::ascii: return "ascii";
    case PlyEncoding::binary_little_endian: return "binary_little_endian";
    case PlyEncoding::binary_big_endian: return "binary_big_endian";
  }
  return "?";
}

void expect_same_geometry(const PolygonMesh& a, const PolygonMesh& b) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i) {
    EXPECT_EQ(a.positions[i], b.positions[i]) << "vertex " << i;
    EXPECT_EQ(std::signbit(a.positions[i].y), std::signbit(b.positions[i].y)) << "vertex " << i;
  }
  EXPECT_EQ(a.face_offsets, b.face_offsets);
  EXPECT_EQ(a.face_indices, b.face_indices);
}

/// Builds binary PLY data in either byte order.
class Bytes {
 public:
  explicit Bytes(bool big_endian) : swap_(big_endian != (std::endian::native == std::endian::big)) {}
  Bytes& text(const std::string& s) {
    out_ += s;
    return *this;
  }
  template <typename T>
  Bytes& put(T value) {
    char buf[sizeof(T)];
    std::memcpy(buf, &value, sizeof(T));
    if (swap_) std::reverse(buf, buf + sizeof(T));
    out_.append(buf, sizeof(T));
    return *this;
  }
  Bytes& u8(int v) { return put(static_cast<std::uint8_t>(v)); }
  Bytes& i32(int v) { return put(static_cast<std::int32_t>(v)); }
  Bytes& f32(float v) { return put(v); }
  Bytes& f64(double v) { return put(v); }
  const std::string& str() const { return out_; }

 private:
  bool swap_;
  std::string out_;
};


// --- round trips ---------------------------------------------------------------

TEST(Ply, CubeRoundTripsInEveryEncoding) {
  const PolygonMesh mesh = test::cube();
  for (const PlyEncoding e : kAllEncodings) {
    SCOPED_TRACE(name(e));
    std::vector<std::string> warnings;
    const std::string data = format_ply(mesh, e, &warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(data.rfind("ply\nformat ", 0), 0u);
    EXPECT_NE(data.find("comment subdiv\n"), std::string::npos);
    EXPECT_NE(data.find("property list uchar int vertex_indices\n"), std::string::npos);
    const MeshFile file = parse_ply(data, "cube.ply");
    expect_same_geometry(mesh, file.mesh);
    EXPECT_TRUE(file.mesh.vertex_channels.empty());
    EXPECT_TRUE(file.warnings.empty());
    EXPECT_EQ(file.lines.path, "cube.ply");
  }
}

TEST(Ply, MixedFacesRoundTripExactly) {
  const PolygonMesh mesh = test::hard_numbers_mesh();
  for (const PlyEncoding e : kAllEncodings) {
    SCOPED_TRACE(name(e));
    const MeshFile file = parse_ply(format_ply(mesh, e));
    expect_same_geometry(mesh, file.mesh);
  }
}

TEST(Ply, AsciiRecordsLinesAndBinaryDoesNot) {
  const PolygonMesh mesh = test::hard_numbers_mesh();
  const MeshFile ascii = parse_ply(format_ply(mesh, PlyEncoding::ascii));
  // 10 header lines (ply, format, comment, element, 3 properties, element,
  // property, end_header), then 6 vertices and 3 faces.
  EXPECT_EQ(ascii.lines.vertex_lines, (std::vector<std::uint32_t>{11, 12, 13, 14, 15, 16}));
  EXPECT_EQ(ascii.lines.face_lines, (std::vector<std::uint32_t>{17, 18, 19}));
  const MeshFile binary = parse_ply(format_ply(mesh, PlyEncoding::binary_little_endian));
  EXPECT_TRUE(binary.lines.vertex_lines.empty());
  EXPECT_TRUE(binary.lines.face_lines.empty());
}

TEST(Ply, ChannelsRoundTrip) {
  PolygonMesh mesh = test::cube();
  std::vector<double> normals, uvs, colors;
  for (int v = 0; v < 8; ++v) {
    normals.insert(normals.end(), {0.5 * v, -0.25, 1.0 / 1024.0});
    uvs.insert(uvs.end(), {v / 8.0, 1.0 - v / 16.0});
    colors.insert(colors.end(), {v * 30 / 255.0, 1.0, 0.0});
  }
  mesh.vertex_channels.push_back({"normal", 3, normals});
  mesh.vertex_channels.push_back({"uv", 2, uvs});
  mesh.vertex_channels.push_back({"color", 3, colors});
  for (const PlyEncoding e : kAllEncodings) {
    SCOPED_TRACE(name(e));
    std::vector<std::string> warnings;
    const MeshFile file = parse_ply(format_ply(mesh, e, &warnings));
    EXPECT_TRUE(warnings.empty());
    expect_same_geometry(mesh, file.mesh);
    const VertexChannel* n = file.mesh.find_vertex_channel("normal");
    const VertexChannel* t = file.mesh.find_vertex_channel("uv");
    const VertexChannel* c = file.mesh.find_vertex_channel("color");
    ASSERT_TRUE(n && t && c);
    EXPECT_EQ(n->components, 3);
    EXPECT_EQ(t->components, 2);
    EXPECT_EQ(c->components, 3);
    EXPECT_EQ(n->values, normals);
    EXPECT_EQ(t->values, uvs);
    EXPECT_EQ(c->values, colors);
  }
}

TEST(Ply, ColorsAreClampedAndRounded) {
  PolygonMesh mesh = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  mesh.vertex_channels.push_back({"color", 3, {-1.0, 2.0, 0.5, 0.2, 0.0 / 1.0, 1.0, 0.999, 0.001, 0.5 / 255.0}});
  const MeshFile file = parse_ply(format_ply(mesh, PlyEncoding::ascii));
  const VertexChannel* c = file.mesh.find_vertex_channel("color");
  ASSERT_TRUE(c);
  const std::vector<double> expected{0.0, 1.0, 128 / 255.0, 51 / 255.0, 0.0, 1.0, 1.0, 0.0, 1 / 255.0};
  EXPECT_EQ(c->values, expected);
}

TEST(Ply, UnsupportedChannelsAreReported) {
  PolygonMesh mesh = test::cube();
  mesh.vertex_channels.push_back({"weight", 1, std::vector<double>(8, 1.0)});
  mesh.vertex_channels.push_back({"normal", 2, std::vector<double>(16, 1.0)});  // wrong component count
  FaceVaryingChannel fv{"uv", 2, {0, 0, 1, 1}, std::vector<Index>(24, 0)};
  mesh.face_varying_channels.push_back(fv);
  for (const PlyEncoding e : kAllEncodings) {
    std::vector<std::string> warnings;
    const MeshFile file = parse_ply(format_ply(mesh, e, &warnings));
    ASSERT_EQ(warnings.size(), 3u);
    EXPECT_NE(warnings[0].find("'weight'"), std::string::npos);
    EXPECT_NE(warnings[1].find("'normal'"), std::string::npos);
    EXPECT_NE(warnings[2].find("face-varying channel 'uv'"), std::string::npos);
    EXPECT_TRUE(file.mesh.vertex_channels.empty());
    expect_same_geometry(mesh, file.mesh);
    EXPECT_NO_THROW(format_ply(mesh, e, nullptr));
  }
}

TEST(Ply, LargeFacesUseAWideCountType) {
  std::vector<Vec3> positions;
  std::vector<Index> ring;
  for (int i = 0; i < 300; ++i) {
    positions.push_back({std::cos(i * 0.02), std::sin(i * 0.02), 0.0});
    ring.push_back(i);
  }
  const PolygonMesh mesh = make_mesh(positions, {ring, {0, 1, 2}});
  for (const PlyEncoding e : kAllEncodings) {
    SCOPED_TRACE(name(e));
    const std::string data = format_ply(mesh, e);
    EXPECT_NE(data.find("property list uint int vertex_indices"), std::string::npos);
    expect_same_geometry(mesh, parse_ply(data).mesh);
  }
}

TEST(Ply, EmptyMeshRoundTrips) {
  const PolygonMesh mesh;
  for (const PlyEncoding e : kAllEncodings) {
    const MeshFile file = parse_ply(format_ply(mesh, e));
    EXPECT_EQ(file.mesh.vertex_count(), 0);
    EXPECT_EQ(file.mesh.face_count(), 0);
  }
}

// --- hand-written files ----------------------------------------------------------

const char* const kRichHeader =
    "element camera 1\n"
    "property float focal\n"
    "property list uchar int ids\n"
    "element vertex 4\n"
    "property float x\n"
    "property double y\n"
    "property short z\n"
    "property float confidence\n"
    "property list uchar float extra\n"
    "property uchar red\n"
    "property uchar green\n"
    "property uchar blue\n"
    "property uchar alpha\n"
    "property float s\n"
    "property float t\n"
    "element material 2\n"
    "property uchar ambient_red\n"
    "property list ushort uint8 tags\n"
    "property double shininess\n"
    "element face 3\n"
    "property uchar flags\n"
    "property list uchar int vertex_indices\n"
    "property list uchar float texcoord\n"
    "property int material_index\n"
    "element edge 1\n"
    "property int vertex1\n"
    "property int vertex2\n"
    "end_header\n";

void expect_rich_mesh(const MeshFile& file) {
  const PolygonMesh& m = file.mesh;
  ASSERT_EQ(m.vertex_count(), 4);
  EXPECT_EQ(m.positions[0], (Vec3{0.5, 0.25, 1}));
  EXPECT_EQ(m.positions[1], (Vec3{1.5, -2.125, -3}));
  EXPECT_EQ(m.positions[2], (Vec3{-1, 1e-3, 300}));
  EXPECT_EQ(m.positions[3], (Vec3{0, 0, 0}));
  EXPECT_EQ(m.face_offsets, (std::vector<Index>{0, 3, 6, 8}));
  EXPECT_EQ(m.face_indices, (std::vector<Index>{0, 1, 2, 0, 2, 3, 3, 1}));
  const VertexChannel* color = m.find_vertex_channel("color");
  ASSERT_TRUE(color);
  EXPECT_EQ(color->values[0], 255 / 255.0);
  EXPECT_EQ(color->values[1], 0.0);
  EXPECT_EQ(color->values[2], 51 / 255.0);
  EXPECT_EQ(color->values[11], 102 / 255.0);
  const VertexChannel* uv = m.find_vertex_channel("uv");
  ASSERT_TRUE(uv);
  EXPECT_EQ(uv->values, (std::vector<double>{0, 1, 0.5, 0.5, 1, 0, 0.25, 0.75}));
  EXPECT_EQ(m.find_vertex_channel("normal"), nullptr);
  // Properties and elements that are not read are mentioned.
  std::string all;
  for (const auto& w : file.warnings) all += w + "\n";
  EXPECT_NE(all.find("confidence"), std::string::npos) << all;
  EXPECT_NE(all.find("material"), std::string::npos) << all;
  EXPECT_NE(all.find("flags"), std::string::npos) << all;
}

TEST(Ply, AsciiWithExtraElementsAndProperties) {
  const std::string text = std::string("ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info nothing\r\n") +
                           kRichHeader +
                           "35 3 1 2 3\n"
                           "0.5 0.25 1 0.9 2 7 8 255 0 51 255 0 1\n"
                           "1.5 -2.125 -3 0.9 0 255 255 255 255 0.5 0.5\r\n"
                           "\n"
                           "-1 1e-3 300 1 1 -1.5 0 0 0 0 1 0\n"
                           "0 0 0 0 3 1 2 3 102 102 102 0 0.25 0.75\n"
                           "1 2 3 4 0.5\n"
                           "2 0 0\n"
                           "1 3 0 1 2 6 0.1 0.2 0.3 0.4 0.5 0.6 7\n"
                           "0 3 0 2 3 0 8\n"
                           "0 2 3 1 0 -1\n"
                           "0 1\n"
                           "\n";
  const MeshFile file = parse_ply(text, "rich.ply");
  expect_rich_mesh(file);
  // The header has 32 lines; the camera is line 33, the blank line 36 is skipped.
  EXPECT_EQ(file.lines.vertex_lines, (std::vector<std::uint32_t>{34, 35, 37, 38}));
  EXPECT_EQ(file.lines.face_lines, (std::vector<std::uint32_t>{41, 42, 43}));
}

std::string rich_binary(bool big) {
  Bytes b(big);
  b.text(std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
         " 1.0\ncomment made by hand\n" + kRichHeader);
  // camera
  b.f32(35).u8(3).i32(1).i32(2).i32(3);
  // vertices: x y z confidence extra[] r g b a s t
  auto vertex = [&](float x, double y, std::int16_t z, std::vector<float> extra, int r, int g, int bl, float s,
                    float t) {
    b.f32(x).f64(y).put(z).f32(0.9f).u8(static_cast<int>(extra.size()));
    for (const float e : extra) b.f32(e);
    b.u8(r).u8(g).u8(bl).u8(255).f32(s).f32(t);
  };
  vertex(0.5f, 0.25, 1, {7, 8}, 255, 0, 51, 0, 1);
  vertex(1.5f, -2.125, -3, {}, 255, 255, 255, 0.5f, 0.5f);
  vertex(-1, 1e-3, 300, {-1.5f}, 0, 0, 0, 1, 0);
  vertex(0, 0, 0, {1, 2, 3}, 102, 102, 102, 0.25f, 0.75f);
  // materials: ambient_red, tags (ushort count), shininess
  b.u8(1).put(std::uint16_t{2}).u8(3).u8(4).f64(0.5);
  b.u8(2).put(std::uint16_t{0}).f64(0);
  // faces: flags, vertex_indices, texcoord, material_index
  b.u8(1).u8(3).i32(0).i32(1).i32(2).u8(6);
  for (int i = 1; i <= 6; ++i) b.f32(static_cast<float>(i) / 10);
  b.i32(7);
  b.u8(0).u8(3).i32(0).i32(2).i32(3).u8(0).i32(8);
  b.u8(0).u8(2).i32(3).i32(1).u8(0).i32(-1);
  // edge
  b.i32(0).i32(1);
  return b.str();
}

TEST(Ply, BinaryLittleEndianWithExtraElementsAndProperties) {
  const MeshFile file = parse_ply(rich_binary(false), "rich.ply");
  expect_rich_mesh(file);
  EXPECT_TRUE(file.lines.vertex_lines.empty());
  EXPECT_TRUE(file.lines.face_lines.empty());
}

TEST(Ply, BinaryBigEndianWithExtraElementsAndProperties) {
  expect_rich_mesh(parse_ply(rich_binary(true), "rich.ply"));
}

TEST(Ply, BigEndianValuesOfEveryType) {
  Bytes b(true);
  b.text(
      "ply\nformat binary_big_endian 1.0\n"
      "element vertex 2\n"
      "property int8 a\nproperty uint8 b\nproperty int16 c\nproperty uint16 d\n"
      "property int32 e\nproperty uint32 f\nproperty float32 g\nproperty float64 h\n"
      "property uint16 x\nproperty int32 y\nproperty char z\n"
      "element face 1\n"
      "property list ushort uint vertex_index\n"
      "end_header\n");
  for (int v = 0; v < 2; ++v) {
    b.put(std::int8_t{-1}).put(std::uint8_t{200}).put(std::int16_t{-300}).put(std::uint16_t{60000});
    b.put(std::int32_t{-70000}).put(std::uint32_t{4000000000u}).f32(1.5f).f64(-2.25);
    b.put(static_cast<std::uint16_t>(65000 + v)).put(std::int32_t{-123456789}).put(std::int8_t{-128});
  }
  b.put(std::uint16_t{2}).put(std::uint32_t{1}).put(std::uint32_t{0});
  const MeshFile file = parse_ply(b.str());
  ASSERT_EQ(file.mesh.vertex_count(), 2);
  EXPECT_EQ(file.mesh.positions[0], (Vec3{65000, -123456789, -128}));
  EXPECT_EQ(file.mesh.positions[1], (Vec3{65001, -123456789, -128}));
  EXPECT_EQ(file.mesh.face_indices, (std::vector<Index>{1, 0}));  // two-vertex faces are accepted
}

TEST(Ply, NormalsAndFloatColorsAreRead) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\n"
      "property double x\nproperty double y\nproperty double z\n"
      "property float nx\nproperty float ny\nproperty float nz\n"
      "property float red\nproperty float green\nproperty float blue\n"
      "property float texture_u\nproperty float texture_v\n"
      "element face 1\nproperty list uint8 uint32 vertex_indices\nend_header\n"
      "0 0 0 0 0 1 0.25 0.5 0.75 0.1 0.2\n"
      "1 0 0 0 0 1 1 1 1 0.3 0.4\n"
      "0 1 0 0 0 -1 0 0 0 0.5 0.6\n"
      "3 0 1 2\n";
  const MeshFile file = parse_ply(text);
  const VertexChannel* n = file.mesh.find_vertex_channel("normal");
  const VertexChannel* c = file.mesh.find_vertex_channel("color");
  const VertexChannel* t = file.mesh.find_vertex_channel("uv");
  ASSERT_TRUE(n && c && t);
  EXPECT_EQ(n->values, (std::vector<double>{0, 0, 1, 0, 0, 1, 0, 0, -1}));
  EXPECT_EQ(c->values, (std::vector<double>{0.25, 0.5, 0.75, 1, 1, 1, 0, 0, 0}));  // float colours kept
  EXPECT_EQ(t->values, (std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6}));
  EXPECT_TRUE(file.warnings.empty());
}

TEST(Ply, PartialChannelsAreNotCreated) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 1\n"
      "property float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float u\n"
      "end_header\n1 2 3 4 5\n";
  const MeshFile file = parse_ply(text);
  EXPECT_TRUE(file.mesh.vertex_channels.empty());
  EXPECT_EQ(file.mesh.positions[0], (Vec3{1, 2, 3}));
  EXPECT_EQ(file.mesh.face_count(), 0);
  ASSERT_EQ(file.warnings.size(), 1u);
  EXPECT_NE(file.warnings[0].find("nx, u"), std::string::npos);
}

TEST(Ply, SmallFacesAreAccepted) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 3\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 1 1\n0\n1 0\n2 0 1\n";
  const MeshFile file = parse_ply(text);
  EXPECT_EQ(file.mesh.face_offsets, (std::vector<Index>{0, 0, 1, 3}));
}

TEST(Ply, BinaryTrailingBytesAreAWarning) {
  std::string data = format_ply(test::cube(), PlyEncoding::binary_little_endian);
  data += "junk";
  const MeshFile file = parse_ply(data);
  EXPECT_EQ(file.mesh.face_count(), 6);
  ASSERT_EQ(file.warnings.size(), 1u);
  EXPECT_NE(file.warnings[0].find("4 bytes"), std::string::npos);
}

TEST(Ply, EndHeaderWithCrLfBeforeBinaryData) {
  std::string data = format_ply(test::cube(), PlyEncoding::binary_big_endian);
  const std::size_t at = data.find("end_header\n");
  ASSERT_NE(at, std::string::npos);
  data.replace(at, 11, "end_header\r\n");
  expect_same_geometry(test::cube(), parse_ply(data).mesh);
}

// --- errors ------------------------------------------------------------------------

TEST(PlyErrors, TruncatedBinary) {
  const std::string data = format_ply(test::cube(), PlyEncoding::binary_little_endian);
  const std::size_t header = data.find("end_header\n") + 11;
  EXPECT_PARSE_ERROR(parse_ply(data.substr(0, data.size() - 3), "t.ply"), "unexpected end of file in face 5");
  // A list count whose items are missing.
  EXPECT_PARSE_ERROR(parse_ply(data.substr(0, data.size() - 16)), "unexpected end of file in face 5");
  // Missing whole vertices: caught by the size check on the header counts.
  EXPECT_PARSE_ERROR(parse_ply(data.substr(0, header + 100)),
                     "header declares 8 vertices but the file holds at most 4");
  // Cut inside a face that follows variable-length data in other elements.
  const std::string rich = rich_binary(false);
  const std::size_t rich_header = rich.find("end_header\n") + 11;
  EXPECT_PARSE_ERROR(parse_ply(rich.substr(0, rich_header + 200)), "unexpected end of file in face 0");
  EXPECT_PARSE_ERROR(parse_ply(rich.substr(0, rich.size() - 1)), "unexpected end of file in edge 0");
  // Cut inside a vertex whose list makes it longer than its minimum size.
  Bytes b(true);
  b.text(
      "ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nproperty list uchar double extra\nend_header\n");
  for (int v = 0; v < 2; ++v) {
    b.f32(1).f32(2).f32(3).u8(10);
    for (int i = 0; i < 10; ++i) b.f64(i);
  }
  EXPECT_NO_THROW(parse_ply(b.str()));
  EXPECT_PARSE_ERROR(parse_ply(b.str().substr(0, b.str().size() - 1)), "unexpected end of file in vertex 1");
}

TEST(PlyErrors, TruncatedAscii) {
  const std::string data = format_ply(test::cube(), PlyEncoding::ascii);
  // Last line cut in the middle of the face.
  EXPECT_PARSE_ERROR(parse_ply(data.substr(0, data.size() - 4), "t.ply"), "t.ply:24: face 5: the line ends before");
  // Whole lines missing (blank lines after them keep the size check quiet).
  const std::string text = format_ply(test::hard_numbers_mesh(), PlyEncoding::ascii);
  std::size_t cut = 0;
  for (int line = 0; line < 10 + 4; ++line) cut = text.find('\n', cut) + 1;
  EXPECT_PARSE_ERROR(parse_ply(text.substr(0, cut) + std::string(200, '\n'), "t.ply"), "t.ply: unexpected end of file in vertex 4");
  // Whole lines missing in a file of short numbers: caught by the size check.
  EXPECT_PARSE_ERROR(parse_ply(data.substr(0, data.find("\n0 1 1\n") + 1)),
                     "header declares 8 vertices but the file holds at most 7");
}

TEST(PlyErrors, LyingVertexCountFailsBeforeAllocating) {
  for (const char* count : {"4000000000", "1000000000", "1099511627776", "9223372036854775807"}) {
    for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
      const std::string data = std::string("ply\nformat ") + format + " 1.0\nelement vertex " + count +
                               "\nproperty float x\nproperty float y\nproperty float z\n"
                               "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                               "0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0";
      const auto start = std::chrono::steady_clock::now();
      EXPECT_PARSE_ERROR(parse_ply(data, "lie.ply"),
                         std::string("lie.ply:3: header declares ") + count + " vertices but the file holds at most ");
      EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
    }
  }
  const std::string message = test::parse_error_message([] {
    parse_ply(
        "ply\nformat binary_little_endian 1.0\nelement vertex 1099511627776\nproperty float x\n"
        "property float y\nproperty float z\nend_header\n0123456789ab");
  });
  EXPECT_NE(message.find("header declares 1099511627776 vertices but the file holds at most 1"), std::string::npos)
      << message;
}

TEST(PlyErrors, LyingFaceAndOtherCounts) {
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\n";
  const std::string vertex(12, '\0');
  EXPECT_PARSE_ERROR(
      parse_ply(header + "element face 3000000000\nproperty list uchar int vertex_indices\nend_header\n" + vertex +
                "abc"),
      "header declares 3000000000 faces but the file holds at most 3");
  EXPECT_PARSE_ERROR(parse_ply(header + "element material 100\nproperty double a\nend_header\n" + vertex),
                     "header declares 100 'material' elements but the file holds at most 0");
}

TEST(PlyErrors, LyingListLength) {
  Bytes b(false);
  b.text(
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n");
  b.f32(0).f32(0).f32(0).put(std::uint32_t{4000000000u}).i32(0);
  EXPECT_PARSE_ERROR(parse_ply(b.str()), "unexpected end of file in face 0");
}

TEST(PlyErrors, UnknownFormat) {
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat binary_middle_endian 1.0\nend_header\n", "f.ply"),
                     "f.ply:2: unknown PLY format 'binary_middle_endian'");
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 2.0\nend_header\n"), "unsupported PLY version");
  EXPECT_PARSE_ERROR(parse_ply("ply\nelement vertex 0\nproperty float x\nend_header\n"), "no format line");
}

TEST(PlyErrors, MissingEndHeader) {
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"),
                     "no end_header");
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                               "property float z\n1 2 3\n"),
                     "unknown header line '1'");
}

TEST(PlyErrors, FaceIndexOutOfRange) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_PARSE_ERROR(parse_ply(header + "3 0 1 2\n3 0 1 3\n", "r.ply"),
                     "r.ply:14: face 1: vertex index 3 is out of range (the file has 3 vertices)");
  EXPECT_PARSE_ERROR(parse_ply(header + "3 0 -1 2\n3 0 1 2\n", "r.ply"), "r.ply:13: face 0: vertex index -1");

  Bytes b(true);
  b.text(
      "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty double x\nproperty double y\n"
      "property double z\nelement face 1\nproperty list uchar uint vertex_indices\nend_header\n");
  b.f64(0).f64(0).f64(0).u8(3).put(std::uint32_t{0}).put(std::uint32_t{0}).put(std::uint32_t{0xffffffffu});
  EXPECT_PARSE_ERROR(parse_ply(b.str()), "face 0: vertex index 4294967295 is out of range");
}

TEST(PlyErrors, NegativeIndexInBinary) {
  Bytes b(false);
  b.text(
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n");
  for (int i = 0; i < 9; ++i) b.f32(0);
  b.u8(3).i32(0).i32(1).i32(2).u8(3).i32(0).i32(-7).i32(2);
  EXPECT_PARSE_ERROR(parse_ply(b.str()), "face 1: vertex index -7 is out of range");
}

TEST(PlyErrors, NoVertexElement) {
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\n"
                               "end_header\n"),
                     "no vertex element");
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                               "end_header\n1 2\n"),
                     ":3: the vertex element has no 'z' property");
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 1\nproperty uchar flags\nend_header\n1 2 3\n0\n"),
                     "no vertex_indices list");
}

TEST(PlyErrors, BadHeaderDeclarations) {
  const std::string start = "ply\nformat ascii 1.0\nelement vertex 1\n";
  EXPECT_PARSE_ERROR(parse_ply(start + "property quad x\nend_header\n"), ":4: unknown property type 'quad'");
  EXPECT_PARSE_ERROR(parse_ply(start + "property list float int x\nend_header\n"), "count type must be an integer");
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 1.0\nproperty float x\nend_header\n"), "before any element");
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex -1\nend_header\n"), "bad count");
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\nend_header\n"),
                     "bad count");
  EXPECT_PARSE_ERROR(
      parse_ply(start + "property float x\nproperty float y\nproperty float z\nelement face 1\n"
                        "property list uchar float vertex_indices\nend_header\n0 0 0\n1 0\n"),
      "must hold integers");
  EXPECT_PARSE_ERROR(parse_ply("PLY\nformat ascii 1.0\nend_header\n"), "not a PLY file");
  EXPECT_PARSE_ERROR(parse_ply(""), "empty file");
}

TEST(PlyErrors, GarbageBytes) {
  std::string garbage;
  std::mt19937 rng(7);
  for (int i = 0; i < 4096; ++i) garbage += static_cast<char>(rng() & 0xff);
  EXPECT_PARSE_ERROR(parse_ply(garbage), "not a PLY file");
  EXPECT_PARSE_ERROR(parse_ply("ply\n" + garbage), "");
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 1.0\n\x01\xff\xfe garbage\nend_header\n"),
                     "unknown header line '\?\?\?'");
  // Data that is not numbers.
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                               "property float z\nend_header\n1 2 zebra\n"),
                     ":8: vertex 0: bad value 'zebra' for property 'z'");
  // Trailing garbage after ascii data.
  EXPECT_PARSE_ERROR(parse_ply(format_ply(test::cube(), PlyEncoding::ascii) + "\n\nxyz\n"),
                     ":27: unexpected data after the last element");
  // Too many values on a line.
  EXPECT_PARSE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                               "property float z\nend_header\n1 2 3 4\n"),
                     "more values on the line than the header declares");
}

// Every prefix and many corrupted variants of valid files either parse or
// throw ParseError: nothing else escapes, nothing crashes or hangs.
TEST(PlyErrors, CorruptedFilesOnlyThrowParseError) {
  PolygonMesh mesh = test::hard_numbers_mesh();
  mesh.vertex_channels.push_back({"normal", 3, std::vector<double>(18, 0.5)});
  mesh.vertex_channels.push_back({"color", 3, std::vector<double>(18, 0.5)});
  std::vector<std::string> inputs{rich_binary(false), rich_binary(true)};
  for (const PlyEncoding e : kAllEncodings) inputs.push_back(format_ply(mesh, e));
  std::mt19937 rng(12345);
  for (const std::string& input : inputs) {
    for (std::size_t n = 0; n < input.size(); ++n) {
      try {
        parse_ply(input.substr(0, n));
      } catch (const ParseError&) {
      }
    }
    for (int trial = 0; trial < 2000; ++trial) {
      std::string corrupt = input;
      const int flips = 1 + static_cast<int>(rng() % 4);
      for (int k = 0; k < flips; ++k) {
        const std::size_t at = rng() % corrupt.size();
        corrupt[at] = static_cast<char>(rng() % 3 == 0 ? corrupt[at] ^ (1 << (rng() % 8)) : rng() & 0xff);
      }
      try {
        const MeshFile file = parse_ply(corrupt);
        check_indices(file.mesh);  // whatever parses is well formed
      } catch (const ParseError&) {
      }
    }
  }
}

}  // namespace
}  // namespace subdiv
