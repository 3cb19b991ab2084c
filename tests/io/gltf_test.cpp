// glTF 2.0 reading and writing: round trips through subdiv's extras, files
// from other programs (split vertices, node transforms), the validator's
// checkable rules on what subdiv writes, and hostile inputs. The documents
// are inspected and edited with nlohmann::json, independently of TinyGLTF.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "subdiv/core/error.h"
#include "subdiv/io/file_io.h"
#include "subdiv/io/gltf.h"
#include "subdiv/io/mesh_io.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using nlohmann::json;

constexpr const char* kDataUriPrefix = "data:application/octet-stream;base64,";

std::vector<unsigned char> base64_decode(const std::string& text) {
  static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> out;
  unsigned bits = 0;
  int count = 0;
  for (const char c : text) {
    if (c == '=') break;
    const std::size_t v = alphabet.find(c);
    if (v == std::string::npos) throw std::runtime_error("not base64");
    bits = (bits << 6) | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<unsigned char>((bits >> count) & 0xFF));
    }
  }
  return out;
}

std::string base64_encode(const std::vector<unsigned char>& data) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < data.size(); i += 3) {
    const unsigned n = (unsigned{data[i]} << 16) | (unsigned{data[i + 1]} << 8) | data[i + 2];
    for (int k = 3; k >= 0; --k) out += alphabet[(n >> (6 * k)) & 63];
  }
  if (i < data.size()) {
    const unsigned n = (unsigned{data[i]} << 16) | (i + 1 < data.size() ? unsigned{data[i + 1]} << 8 : 0u);
    out += alphabet[(n >> 18) & 63];
    out += alphabet[(n >> 12) & 63];
    out += i + 1 < data.size() ? alphabet[(n >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::vector<unsigned char> buffer_bytes(const json& doc) {
  const std::string uri = doc["buffers"][0]["uri"];
  EXPECT_EQ(uri.rfind(kDataUriPrefix, 0), 0u);
  return base64_decode(uri.substr(std::strlen(kDataUriPrefix)));
}

template <class T>
T load(const std::vector<unsigned char>& bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

// Through a volatile float: Debian's GCC 12.2 at -O2 drops the rounding of
// x and y when the three casts sit in one aggregate (SLP vectorization).
double float_rounded(double x) {
  volatile float f = static_cast<float>(x);
  return static_cast<double>(f);
}

Vec3 float_rounded(Vec3 p) { return {float_rounded(p.x), float_rounded(p.y), float_rounded(p.z)}; }

PolygonMesh mixed_polygons() {
  PolygonMesh mesh = test::jittered(test::quad_grid(3, 2), 7);
  mesh.add_face({0, 5, 4});                  // a triangle over the grid's first vertices
  mesh.add_face({2, 3, 7, 11, 10, 6});       // a hexagon
  return mesh;
}

// The mesh written as a .gltf, read back.
MeshFile round_trip(const PolygonMesh& mesh, bool binary, std::vector<std::string>* warnings = nullptr) {
  return parse_gltf(format_gltf(mesh, binary, warnings), "round-trip.gltf", binary);
}

json document(const PolygonMesh& mesh) { return json::parse(format_gltf(mesh, false)); }

MeshFile read_document(const json& doc, const ReadOptions& options = {}) {
  return parse_gltf(doc.dump(), "edited.gltf", false, options);
}

std::string parse_error(const json& doc) {
  try {
    read_document(doc);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "(no error)";
}

// --- round trips through subdiv's extras -----------------------------------------

TEST(Gltf, PolygonsComeBackFromTheExtras) {
  for (const bool binary : {false, true}) {
    std::vector<std::string> warnings;
    const PolygonMesh mesh = mixed_polygons();
    const MeshFile file = round_trip(mesh, binary, &warnings);
    EXPECT_EQ(file.mesh.face_offsets, mesh.face_offsets);
    EXPECT_EQ(file.mesh.face_indices, mesh.face_indices);
    ASSERT_EQ(file.mesh.vertex_count(), mesh.vertex_count());
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      EXPECT_EQ(file.mesh.positions[v], float_rounded(mesh.positions[v])) << "vertex " << v;
    EXPECT_TRUE(file.warnings.empty()) << file.warnings.front();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("7 polygons written as fans of triangles"), std::string::npos) << warnings[0];
  }
}

TEST(Gltf, FloatExactPositionsComeBackBitForBit) {
  const MeshFile file = round_trip(test::cube(), true);
  EXPECT_EQ(file.mesh.positions, test::cube().positions);
  EXPECT_EQ(file.mesh.face_indices, test::cube().face_indices);
}

TEST(Gltf, UnusedVerticesKeepTheirPlace) {
  PolygonMesh mesh = test::cube();
  mesh.positions.push_back({5, 6, 7});  // no face uses it
  EXPECT_EQ(round_trip(mesh, false).mesh.positions, mesh.positions);
}

TEST(Gltf, ChannelsComeBackPerVertexAndPerCorner) {
  PolygonMesh mesh = test::cube();
  VertexChannel weight{"weight", 1, {}};
  VertexChannel color{"color", 3, {}};
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    weight.values.push_back(0.1 * v);
    for (int k = 0; k < 3; ++k) color.values.push_back(mesh.positions[v][k] * 0.5 + 0.25);
  }
  // Face-varying UVs with seams: each face's corners get their own values.
  FaceVaryingChannel uv{"uv", 2, {}, {}};
  for (Index c = 0; c < mesh.corner_count(); ++c) {
    uv.values.insert(uv.values.end(), {0.01 * c, 1.0 - 0.02 * c});
    uv.indices.push_back(c);
  }
  mesh.vertex_channels = {weight, color};
  mesh.face_varying_channels = {uv};

  const std::string text = format_gltf(mesh, false);
  const json doc = json::parse(text);
  const json& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
  EXPECT_TRUE(attributes.contains("TEXCOORD_0"));
  EXPECT_TRUE(attributes.contains("COLOR_0"));
  EXPECT_TRUE(attributes.contains("_weight"));
  // 24 corners with distinct UVs: 24 glTF vertices.
  EXPECT_EQ(doc["accessors"][attributes["POSITION"].get<int>()]["count"], 24);

  const MeshFile file = parse_gltf(text, "channels.gltf", false);
  EXPECT_EQ(file.mesh.vertex_count(), 8);
  EXPECT_EQ(file.mesh.face_indices, mesh.face_indices);
  ASSERT_EQ(file.mesh.vertex_channels.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const VertexChannel& in = mesh.vertex_channels[i];
    const VertexChannel& out = file.mesh.vertex_channels[i];
    EXPECT_EQ(out.name, in.name);
    ASSERT_EQ(out.values.size(), in.values.size());
    for (std::size_t k = 0; k < in.values.size(); ++k)
      EXPECT_EQ(out.values[k], float_rounded(in.values[k])) << in.name << " " << k;
  }
  ASSERT_EQ(file.mesh.face_varying_channels.size(), 1u);
  const FaceVaryingChannel& read_uv = file.mesh.face_varying_channels[0];
  EXPECT_EQ(read_uv.name, "uv");
  ASSERT_EQ(read_uv.indices.size(), uv.indices.size());
  for (std::size_t c = 0; c < uv.indices.size(); ++c)
    for (std::size_t k = 0; k < 2; ++k)
      EXPECT_EQ(read_uv.values[2 * static_cast<std::size_t>(read_uv.indices[c]) + k],
                float_rounded(uv.values[2 * static_cast<std::size_t>(uv.indices[c]) + k]))
          << "corner " << c;
}

TEST(Gltf, NonUnitNormalsAndWideChannelsAreNotPassedOffAsStandard) {
  PolygonMesh mesh = test::cube();
  mesh.vertex_channels.push_back({"normal", 3, std::vector<double>(24, 2.0)});      // not unit vectors
  mesh.vertex_channels.push_back({"tensor", 6, std::vector<double>(48, 1.0)});      // no glTF type holds six
  std::vector<std::string> warnings;
  const json doc = json::parse(format_gltf(mesh, false, &warnings));
  const json& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
  EXPECT_FALSE(attributes.contains("NORMAL"));
  EXPECT_TRUE(attributes.contains("_normal"));
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings[0].find("'tensor'"), std::string::npos) << warnings[0];
}

TEST(Gltf, TagsComeBackFromTheExtras) {
  PolygonMesh mesh = test::cube();
  mesh.tags.creases.push_back({0, 1, 2.5});
  mesh.tags.creases.push_back({4, 5, kInfiniteSharpness});
  CornerTag corner{6, 3.0, CornerType::concave, std::numbers::pi * 1.5};
  mesh.tags.corners.push_back(corner);
  mesh.tags.holes.push_back(2);
  mesh.tags.boundary_interpolation = BoundaryInterpolation::edge_only;
  mesh.tags.boundary_interpolation_set = true;
  mesh.tags.crease_method = CreaseMethod::chaikin;
  mesh.tags.crease_method_set = true;
  std::vector<std::string> warnings;
  const MeshFile file = round_trip(mesh, true, &warnings);
  EXPECT_EQ(file.mesh.tags, mesh.tags);
  EXPECT_NE(warnings.back().find("kept in the extras"), std::string::npos);
}

TEST(Gltf, ThroughThePathsExtension) {
  const auto dir = std::filesystem::temp_directory_path() / ("subdiv_gltf_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const char* name : {"cube.gltf", "cube.glb", "CUBE.GLB"}) {
    const auto path = dir / name;
    write_mesh(test::cube(), path);
    const std::string bytes = read_file(path);
    const bool glb = path.extension() != ".gltf";
    EXPECT_EQ(bytes.substr(0, glb ? 4 : 1), glb ? "glTF" : "{") << name;
    const MeshFile file = read_mesh(path);
    EXPECT_EQ(file.mesh.face_indices, test::cube().face_indices) << name;
  }
  std::filesystem::remove_all(dir);
}

// --- the validator's rules, checked on what subdiv writes --------------------------

TEST(Gltf, WrittenDocumentsKeepTheValidatorsRules) {
  PolygonMesh mesh = mixed_polygons();
  FaceVaryingChannel uv{"uv", 2, {}, {}};
  for (Index c = 0; c < mesh.corner_count(); ++c) {
    uv.values.insert(uv.values.end(), {0.5 * (c % 3), 0.25 * (c % 5)});
    uv.indices.push_back(c);
  }
  mesh.face_varying_channels = {uv};
  const json doc = document(mesh);
  EXPECT_EQ(doc["asset"]["version"], "2.0");
  const std::vector<unsigned char> bytes = buffer_bytes(doc);
  EXPECT_EQ(doc["buffers"][0]["byteLength"], bytes.size());
  for (const json& view : doc["bufferViews"]) {
    const std::size_t offset = view.value("byteOffset", 0), length = view["byteLength"];
    EXPECT_LE(offset + length, bytes.size());
    EXPECT_EQ(offset % 4, 0u);
  }
  const json& primitive = doc["meshes"][0]["primitives"][0];
  EXPECT_EQ(primitive.value("mode", 4), 4);
  const json& position = doc["accessors"][primitive["attributes"]["POSITION"].get<int>()];
  ASSERT_EQ(position["componentType"], 5126);
  ASSERT_EQ(position["type"], "VEC3");
  const std::size_t vertices = position["count"];
  // POSITION's bounds are required and must be the values' exact bounds.
  const json& view = doc["bufferViews"][position["bufferView"].get<int>()];
  const std::size_t base = view.value("byteOffset", 0) + position.value("byteOffset", 0);
  EXPECT_GE(view["byteLength"].get<std::size_t>(), vertices * 12);
  for (int k = 0; k < 3; ++k) {
    float lo = load<float>(bytes, base + 4 * k), hi = lo;
    for (std::size_t v = 0; v < vertices; ++v) {
      const float x = load<float>(bytes, base + 12 * v + 4 * k);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    EXPECT_EQ(position["min"][k].get<double>(), lo);
    EXPECT_EQ(position["max"][k].get<double>(), hi);
  }
  // Indices: unsigned, a multiple of three, each naming a vertex.
  const json& indices = doc["accessors"][primitive["indices"].get<int>()];
  EXPECT_EQ(indices["componentType"], 5125);
  const std::size_t count = indices["count"];
  EXPECT_EQ(count % 3, 0u);
  const json& index_view = doc["bufferViews"][indices["bufferView"].get<int>()];
  EXPECT_EQ(index_view["target"], 34963);
  const std::size_t index_base = index_view.value("byteOffset", 0) + indices.value("byteOffset", 0);
  for (std::size_t i = 0; i < count; ++i) EXPECT_LT(load<std::uint32_t>(bytes, index_base + 4 * i), vertices);
  // Every attribute has the vertices' count and fits its view.
  for (const auto& [name, accessor] : primitive["attributes"].items()) {
    const json& a = doc["accessors"][accessor.get<int>()];
    EXPECT_EQ(a["count"], vertices) << name;
    const int width = a["type"] == "VEC2" ? 2 : a["type"] == "VEC3" ? 3 : a["type"] == "VEC4" ? 4 : 1;
    EXPECT_LE(a.value("byteOffset", 0) + vertices * 4 * width,
              doc["bufferViews"][a["bufferView"].get<int>()]["byteLength"].get<std::size_t>()) << name;
  }
}

TEST(Gltf, BinaryContainerHasConsistentChunks) {
  const std::string glb = format_gltf(mixed_polygons(), true);
  const std::vector<unsigned char> bytes(glb.begin(), glb.end());
  ASSERT_GE(bytes.size(), 28u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_EQ(load<std::uint32_t>(bytes, 4), 2u);
  EXPECT_EQ(load<std::uint32_t>(bytes, 8), bytes.size());
  const std::uint32_t json_length = load<std::uint32_t>(bytes, 12);
  EXPECT_EQ(json_length % 4, 0u);
  EXPECT_EQ(load<std::uint32_t>(bytes, 16), 0x4E4F534Au);  // "JSON"
  const std::size_t bin = 20 + json_length;
  ASSERT_LE(bin + 8, bytes.size());
  const std::uint32_t bin_length = load<std::uint32_t>(bytes, bin);
  EXPECT_EQ(load<std::uint32_t>(bytes, bin + 4), 0x004E4942u);  // "BIN\0"
  EXPECT_EQ(bin + 8 + bin_length, bytes.size());
  const json doc = json::parse(glb.substr(20, json_length));
  EXPECT_FALSE(doc["buffers"][0].contains("uri"));
  EXPECT_LE(doc["buffers"][0]["byteLength"].get<std::size_t>(), bin_length);
}

TEST(Gltf, RefusesWhatItCannotWrite) {
  EXPECT_THROW(format_gltf(PolygonMesh{}, false), InvalidInputError);
  PolygonMesh far = test::cube();
  far.positions[3].x = 1e300;  // beyond float32
  EXPECT_THROW(format_gltf(far, false), InvalidInputError);
}

// --- files from other programs ------------------------------------------------------

// A document as another program writes it: subdiv's extras gone.
json foreign(json doc) {
  doc["meshes"][0]["primitives"][0].erase("extras");
  return doc;
}

TEST(Gltf, SplitVerticesAreWeldedAndAttributesBecomeFaceVarying) {
  PolygonMesh mesh = test::cube();
  FaceVaryingChannel uv{"uv", 2, {}, {}};
  for (Index c = 0; c < mesh.corner_count(); ++c) {
    uv.values.insert(uv.values.end(), {0.125 * (c % 4), 0.25 * (c / 4)});
    uv.indices.push_back(c);
  }
  mesh.face_varying_channels = {uv};
  const MeshFile file = read_document(foreign(document(mesh)));
  EXPECT_EQ(file.mesh.vertex_count(), 8);  // 24 glTF vertices, welded
  EXPECT_EQ(file.mesh.face_count(), 12);   // triangles
  ASSERT_EQ(file.mesh.face_varying_channels.size(), 1u);
  EXPECT_EQ(file.mesh.face_varying_channels[0].name, "uv");
  EXPECT_EQ(file.mesh.face_varying_channels[0].indices.size(), 36u);
  ASSERT_FALSE(file.warnings.empty());
  EXPECT_NE(file.warnings.back().find("glTF stores triangles: 12"), std::string::npos) << file.warnings.back();
  // Without welding, every glTF vertex stays apart.
  ReadOptions apart;
  apart.weld_tolerance = -1;
  EXPECT_EQ(read_document(foreign(document(mesh)), apart).mesh.vertex_count(), 24);
}

TEST(Gltf, WeldingToleranceMergesNearPositions) {
  PolygonMesh mesh = test::quad_grid(2, 1);
  FaceVaryingChannel uv{"uv", 2, std::vector<double>(16, 0.0), {0, 1, 2, 3, 4, 5, 6, 7}};
  mesh.face_varying_channels = {uv};  // splits the two shared vertices
  json doc = foreign(document(mesh));
  // Nudge the first glTF vertex of the second quad's copy of vertex 1 by 1e-5.
  std::vector<unsigned char> bytes = buffer_bytes(doc);
  const json& position = doc["accessors"][doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"].get<int>()];
  const std::size_t base = doc["bufferViews"][position["bufferView"].get<int>()].value("byteOffset", 0);
  const std::size_t count = position["count"];
  std::size_t nudged = count;
  for (std::size_t v = 4; v < count && nudged == count; ++v)
    if (load<float>(bytes, base + 12 * v) == 1.0f) nudged = v;
  ASSERT_LT(nudged, count);
  const float x = 1.00001f;
  std::memcpy(bytes.data() + base + 12 * nudged, &x, 4);
  doc["buffers"][0]["uri"] = kDataUriPrefix + base64_encode(bytes);
  EXPECT_EQ(read_document(doc).mesh.vertex_count(), 7);  // exact welding: the nudged copy stays apart
  ReadOptions near;
  near.weld_tolerance = 1e-4;
  EXPECT_EQ(read_document(doc, near).mesh.vertex_count(), 6);
}

TEST(Gltf, NodeTransformsPlaceTheMeshAndMirrorsKeepItFacingOut) {
  json doc = foreign(document(test::cube()));
  doc["nodes"][0]["translation"] = {10, 0, 0};
  doc["nodes"][0]["scale"] = {-1, 1, 1};  // a mirror: the winding must flip back
  const MeshFile file = read_document(doc);
  ASSERT_EQ(file.mesh.vertex_count(), 8);
  for (const Vec3& p : file.mesh.positions) EXPECT_TRUE(p.x == 10 || p.x == 9) << p.x;
  // Outward normals: each triangle's normal points away from the centre (9.5, 0.5, 0.5).
  for (Index f = 0; f < file.mesh.face_count(); ++f) {
    const auto t = file.mesh.face(f);
    const Vec3 a = file.mesh.positions[t[0]], b = file.mesh.positions[t[1]], c = file.mesh.positions[t[2]];
    const Vec3 centroid = (1.0 / 3.0) * (a + b + c);
    EXPECT_GT(dot(cross(b - a, c - a), centroid - Vec3{9.5, 0.5, 0.5}), 0.0) << "triangle " << f;
  }
}

TEST(Gltf, InstancedMeshesAreEachPlaced) {
  json doc = foreign(document(test::cube()));
  doc["nodes"] = json::array({{{"mesh", 0}}, {{"mesh", 0}, {"translation", {5, 0, 0}}}});
  doc["scenes"][0]["nodes"] = {0, 1};
  const MeshFile file = read_document(doc);
  EXPECT_EQ(file.mesh.vertex_count(), 16);
  EXPECT_EQ(file.mesh.face_count(), 24);
}

TEST(Gltf, PointsAndLinesAreLeftOutWithANote) {
  json doc = foreign(document(test::cube()));
  json points = doc["meshes"][0]["primitives"][0];
  points["mode"] = 0;
  points.erase("indices");
  doc["meshes"][0]["primitives"].push_back(points);
  const MeshFile file = read_document(doc);
  EXPECT_EQ(file.mesh.face_count(), 12);
  EXPECT_NE(file.warnings.front().find("1 primitive of points or lines left out"), std::string::npos);
}

TEST(Gltf, ExtrasThatDisagreeAreIgnoredWithANote) {
  json doc = document(test::cube());
  doc["meshes"][0]["primitives"][0]["extras"]["subdiv"]["polygons"] = {4, 4, 4, 4, 4, 3};
  const MeshFile file = read_document(doc);
  EXPECT_EQ(file.mesh.face_count(), 12);
  EXPECT_NE(file.warnings.front().find("extras do not match"), std::string::npos) << file.warnings.front();
}

// --- hostile inputs --------------------------------------------------------------------

TEST(Gltf, MalformedDocumentsGetOneLineErrors) {
  EXPECT_NE(parse_error(json::parse("{\"asset\": {\"version\": \"1.0\"}}")).find("edited.gltf"), std::string::npos);
  const json good = foreign(document(test::cube()));
  const int positions = good["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
  const int indices = good["meshes"][0]["primitives"][0]["indices"];

  json d = good;
  d["accessors"][positions]["count"] = 9;  // more than its view holds
  EXPECT_NE(parse_error(d).find("run past the end of its buffer view"), std::string::npos) << parse_error(d);
  d = good;
  d["accessors"][positions]["count"] = 4000000000LL;
  EXPECT_NE(parse_error(d).find("edited.gltf"), std::string::npos) << parse_error(d);
  d = good;
  d["bufferViews"][0]["byteLength"] = 1 << 20;  // beyond the buffer
  EXPECT_NE(parse_error(d).find("edited.gltf"), std::string::npos) << parse_error(d);
  d = good;
  d["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
  EXPECT_NE(parse_error(d).find("no POSITION"), std::string::npos) << parse_error(d);
  d = good;
  d["accessors"][indices]["count"] = 3;
  d["accessors"][indices]["byteOffset"] = 0;
  d["accessors"][positions]["count"] = 2;  // the first triangle names vertex 2 or more
  EXPECT_NE(parse_error(d).find("out of range"), std::string::npos) << parse_error(d);
  d = good;
  d["nodes"][0]["children"] = {0};  // a cycle
  EXPECT_NE(parse_error(d).find("deep (a cycle?)"), std::string::npos) << parse_error(d);
  d = good;
  d["nodes"] = json::array();
  for (int n = 0; n < 40; ++n) d["nodes"].push_back({{"children", {n + 1, n + 1}}});  // 2^40 paths
  d["nodes"].push_back({{"mesh", 0}});
  EXPECT_NE(parse_error(d).find("edited.gltf: the scene"), std::string::npos) << parse_error(d);
  d = good;
  d["accessors"][positions]["sparse"] = {{"count", 1},
                                         {"indices", {{"bufferView", indices}, {"componentType", 5125}}},
                                         {"values", {{"bufferView", 0}}}};
  EXPECT_NE(parse_error(d).find("edited.gltf"), std::string::npos) << parse_error(d);
  d = good;
  d["buffers"][0]["uri"] = "/dev/zero";  // a device, not a file: refused, never read
  EXPECT_NE(parse_error(d).find("edited.gltf"), std::string::npos) << parse_error(d);
}

TEST(Gltf, TruncatedAndCorruptContainersAreRefused) {
  const std::string glb = format_gltf(test::cube(), true);
  for (const std::size_t keep : {std::size_t{0}, std::size_t{11}, std::size_t{20}, glb.size() / 2, glb.size() - 1}) {
    EXPECT_THROW(parse_gltf(glb.substr(0, keep), "cut.glb", true), ParseError) << keep;
  }
  std::string wrong = glb;
  wrong[8] = static_cast<char>(0xFF);  // the total length
  EXPECT_THROW(parse_gltf(wrong, "wrong.glb", true), ParseError);
  EXPECT_THROW(parse_gltf("not json at all", "text.gltf", false), ParseError);
}

}  // namespace
}  // namespace subdiv
