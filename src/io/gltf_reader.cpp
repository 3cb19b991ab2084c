#include "subdiv/io/gltf.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "subdiv/core/error.h"
#include "subdiv/io/obj.h"
#include "gltf_extras.h"
#include "weld.h"

namespace subdiv {

namespace {

// Nodes nest at most this deep (a guard against cycles in hostile files),
// and a scene places at most this many vertices (instancing multiplies a
// small file's geometry): refused before the memory is taken.
constexpr int kMaxNodeDepth = 256;
constexpr std::size_t kMaxPlacedVertices = std::size_t{1} << 27;
constexpr std::size_t kMaxNodeVisits = std::size_t{1} << 20;
// Buffers and images in separate files: at most this large each.
constexpr std::uintmax_t kMaxExternalFileBytes = std::uintmax_t{1} << 32;

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw ParseError(path, 0, what); }

// File access for buffers and images stored beside the document: regular
// files only (never a device or a pipe, which could block or never end),
// and no writing.
bool file_exists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}
std::string expand_path(const std::string& path, void*) { return path; }
bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    if (err) *err += "'" + path + "' is not a regular file\n";
    return false;
  }
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxExternalFileBytes) {
    if (err) *err += "'" + path + "' cannot be read or is over 4 GiB\n";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  out->resize(static_cast<std::size_t>(size));
  if (size > 0 && !in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
    if (err) *err += "'" + path + "' cannot be read\n";
    return false;
  }
  return true;
}
bool refuse_writing(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing is not allowed while reading\n";
  return false;
}
// Images are not read: subdiv has no use for textures.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

tinygltf::Model load_model(std::string_view bytes, const std::string& path, bool binary, std::vector<std::string>& warnings) {
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) fail(path, "the file is over 4 GiB");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&skip_image, nullptr);
  loader.SetFsCallbacks({&file_exists, &expand_path, &read_whole_file, &refuse_writing, nullptr});
  loader.SetStoreOriginalJSONForExtrasAndExtensions(true);
  tinygltf::Model model;
  std::string err, warn;
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  const auto length = static_cast<unsigned int>(bytes.size());
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                                       reinterpret_cast<const unsigned char*>(bytes.data()), length, base_dir)
                         : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), length, base_dir);
  if (!ok) {
    std::string first = err.substr(0, err.find('\n'));
    if (first.empty()) first = "not a glTF 2.0 file";
    fail(path, "not a readable glTF 2.0 " + std::string(binary ? "binary (.glb) " : "") + "file: " + first);
  }
  if (model.asset.version.rfind("2.", 0) != 0)
    fail(path, "glTF version '" + model.asset.version.substr(0, 20) + "' is not supported (subdiv reads glTF 2.x)");
  if (!warn.empty()) warnings.push_back("TinyGLTF: " + warn.substr(0, warn.find('\n')));
  return model;
}

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;  // matrices: no mesh attribute uses them
  }
}

int component_bytes(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

template <class T>
T load(const unsigned char* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));  // glTF is little-endian, like every host subdiv builds on
  return value;
}

double component_value(const unsigned char* p, int component_type, bool normalized) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const double v = load<std::int8_t>(p);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? load<std::uint8_t>(p) / 255.0 : load<std::uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const double v = load<std::int16_t>(p);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return normalized ? load<std::uint16_t>(p) / 65535.0 : load<std::uint16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load<std::uint32_t>(p);
    default: return static_cast<double>(load<float>(p));
  }
}

// An accessor's values as doubles, `components` per element, after checking
// that every byte it reads lies inside its buffer view and buffer.
std::vector<double> read_accessor(const tinygltf::Model& model, int index, const std::string& path,
                                  const std::string& what) {
  const std::string where = what + " (accessor " + std::to_string(index) + ")";
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) fail(path, where + " does not exist");
  const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
  if (a.sparse.isSparse) fail(path, where + " is sparse, which is not supported");
  const int components = component_count(a.type);
  const int bytes = component_bytes(a.componentType);
  if (components == 0 || bytes == 0) fail(path, where + " has an unsupported type or component type");
  if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size())
    fail(path, where + " has no buffer view (implicit zeros are not supported)");
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
    fail(path, where + ": its buffer view names no buffer");
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  const std::size_t element = static_cast<std::size_t>(components) * static_cast<std::size_t>(bytes);
  const std::size_t stride = view.byteStride == 0 ? element : view.byteStride;
  if (stride < element || stride % static_cast<std::size_t>(bytes) != 0)
    fail(path, where + ": byte stride " + std::to_string(stride) + " does not fit its elements");
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
    fail(path, where + ": its buffer view runs past the end of its buffer");
  if (a.count == 0) return {};
  // The last element ends at offset + stride * (count - 1) + element, inside the view.
  const std::size_t room = view.byteLength;
  if (a.byteOffset > room || element > room - a.byteOffset ||
      (a.count - 1) > (room - a.byteOffset - element) / stride)
    fail(path, where + ": " + std::to_string(a.count) + " elements run past the end of its buffer view");
  std::vector<double> values;
  values.reserve(a.count * static_cast<std::size_t>(components));
  const unsigned char* base = buffer.data() + view.byteOffset + a.byteOffset;
  for (std::size_t i = 0; i < a.count; ++i)
    for (int k = 0; k < components; ++k)
      values.push_back(component_value(base + i * stride + static_cast<std::size_t>(k * bytes), a.componentType,
                                       a.normalized));
  return values;
}

// Components per element; 0 for a matrix or an accessor that does not exist
// (read_accessor() refuses those with the reason).
int accessor_components(const tinygltf::Model& model, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) return 0;
  return component_count(model.accessors[static_cast<std::size_t>(index)].type);
}

Eigen::Matrix4d local_transform(const tinygltf::Node& node) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  if (node.matrix.size() == 16) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m(r, c) = node.matrix[static_cast<std::size_t>(4 * c + r)];
    return m;
  }
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  if (node.translation.size() == 3) t.translate(Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4)
    t.rotate(Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]).normalized());
  if (node.scale.size() == 3) t.scale(Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]));
  return t.matrix();
}

// Every mesh the default scene draws, with its node's world transform.
struct Instance {
  int mesh;
  Eigen::Matrix4d transform;
};

std::size_t position_count(const tinygltf::Model& model, const tinygltf::Mesh& mesh) {
  std::size_t count = 0;
  for (const tinygltf::Primitive& p : mesh.primitives) {
    const auto position = p.attributes.find("POSITION");
    if (position != p.attributes.end() && position->second >= 0 &&
        static_cast<std::size_t>(position->second) < model.accessors.size())
      count += model.accessors[static_cast<std::size_t>(position->second)].count;
  }
  return count;
}

void collect(const tinygltf::Model& model, int node_index, const Eigen::Matrix4d& parent, int depth,
             std::vector<Instance>& out, std::size_t& visits, std::size_t& placed, const std::string& path) {
  if (node_index < 0 || static_cast<std::size_t>(node_index) >= model.nodes.size())
    fail(path, "node " + std::to_string(node_index) + " does not exist");
  if (depth > kMaxNodeDepth) fail(path, "nodes nest more than " + std::to_string(kMaxNodeDepth) + " deep (a cycle?)");
  if (++visits > kMaxNodeVisits)
    fail(path, "the scene visits more than " + std::to_string(kMaxNodeVisits) + " nodes (a node listed as a child many times?)");
  const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(node_index)];
  const Eigen::Matrix4d world = parent * local_transform(node);
  if (node.mesh >= 0) {
    if (static_cast<std::size_t>(node.mesh) >= model.meshes.size())
      fail(path, "node " + std::to_string(node_index) + " names mesh " + std::to_string(node.mesh) + ", which does not exist");
    placed += position_count(model, model.meshes[static_cast<std::size_t>(node.mesh)]);
    if (placed > kMaxPlacedVertices)
      fail(path, "the scene places more than " + std::to_string(kMaxPlacedVertices) + " vertices (instanced meshes), "
                 "more than subdiv reads");
    out.push_back({node.mesh, world});
  }
  for (const int child : node.children) collect(model, child, world, depth + 1, out, visits, placed, path);
}

std::vector<Instance> instances(const tinygltf::Model& model, const std::string& path) {
  std::vector<Instance> out;
  if (model.scenes.empty()) {  // no scene: every mesh once, where it stands
    for (std::size_t m = 0; m < model.meshes.size(); ++m) out.push_back({static_cast<int>(m), Eigen::Matrix4d::Identity()});
    return out;
  }
  const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (static_cast<std::size_t>(scene) >= model.scenes.size()) fail(path, "the default scene does not exist");
  std::size_t visits = 0, placed = 0;
  for (const int node : model.scenes[static_cast<std::size_t>(scene)].nodes)
    collect(model, node, Eigen::Matrix4d::Identity(), 0, out, visits, placed, path);
  return out;
}

// The triangles of a primitive, as its vertex indices, in glTF's winding.
std::vector<std::uint32_t> primitive_triangles(const tinygltf::Model& model, const tinygltf::Primitive& p,
                                               std::size_t vertex_count, const std::string& path,
                                               const std::string& what) {
  std::vector<std::uint32_t> strip;
  if (p.indices >= 0) {
    const std::vector<double> indices = read_accessor(model, p.indices, path, what + " indices");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(p.indices)];  // read_accessor checked it
    if (accessor_components(model, p.indices) != 1 || a.normalized ||
        (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
      fail(path, what + ": the indices are not unsigned integer scalars");
    strip.reserve(indices.size());
    for (const double i : indices) {
      if (i >= static_cast<double>(vertex_count))  // unsigned integers: never negative or fractional
        fail(path, what + ": index " + std::to_string(static_cast<long long>(i)) + " is out of range (" +
                       std::to_string(vertex_count) + " vertices)");
      strip.push_back(static_cast<std::uint32_t>(i));
    }
  } else {
    strip.resize(vertex_count);
    for (std::size_t i = 0; i < vertex_count; ++i) strip[i] = static_cast<std::uint32_t>(i);
  }
  std::vector<std::uint32_t> out;
  if (p.mode == TINYGLTF_MODE_TRIANGLES) {
    out.assign(strip.begin(), strip.end() - static_cast<std::ptrdiff_t>(strip.size() % 3));
  } else if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 0; i + 2 < strip.size(); ++i)
      if (i % 2 == 0) out.insert(out.end(), {strip[i], strip[i + 1], strip[i + 2]});
      else out.insert(out.end(), {strip[i + 1], strip[i], strip[i + 2]});
  } else {  // a fan
    for (std::size_t i = 1; i + 1 < strip.size(); ++i) out.insert(out.end(), {strip[0], strip[i], strip[i + 1]});
  }
  return out;
}

bool is_triangles(int mode) {
  return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// One attribute over every glTF vertex read: its values, or nothing when a
// primitive lacks it (or holds another width).
struct Attribute {
  std::string attribute;
  int components = 0;
  std::vector<double> values;
  bool complete = true;
};

// What every primitive contributes, concatenated: glTF vertices (positions
// placed by their nodes), triangles over them, and attributes.
struct Soup {
  std::vector<Vec3> positions;
  std::vector<std::uint32_t> triangles;
  std::vector<Attribute> attributes;
};

Soup read_soup(const tinygltf::Model& model, const std::vector<Instance>& drawn, const std::vector<std::string>& wanted,
               const std::string& path, std::vector<std::string>& warnings) {
  Soup soup;
  for (const std::string& a : wanted) soup.attributes.push_back({a, 0, {}, true});
  std::size_t skipped = 0;
  for (const Instance& instance : drawn) {
    const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(instance.mesh)];
    for (std::size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
      const tinygltf::Primitive& p = mesh.primitives[pi];
      if (!is_triangles(p.mode)) {
        ++skipped;
        continue;
      }
      const std::string what = "mesh " + std::to_string(instance.mesh) + " primitive " + std::to_string(pi);
      const auto position = p.attributes.find("POSITION");
      if (position == p.attributes.end()) fail(path, what + " has no POSITION");
      const std::vector<double> xyz = read_accessor(model, position->second, path, what + " POSITION");
      if (accessor_components(model, position->second) != 3) fail(path, what + ": POSITION is not VEC3");
      const std::size_t count = xyz.size() / 3, base = soup.positions.size();
      if (base + count > static_cast<std::size_t>(std::numeric_limits<Index>::max()))
        fail(path, "more vertices than subdiv's 32-bit indices hold");
      for (std::size_t v = 0; v < count; ++v) {
        const Eigen::Vector4d q = instance.transform * Eigen::Vector4d(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2], 1.0);
        const Vec3 placed{q.x() / q.w(), q.y() / q.w(), q.z() / q.w()};
        if (!std::isfinite(placed.x) || !std::isfinite(placed.y) || !std::isfinite(placed.z))
          fail(path, what + ": vertex " + std::to_string(v) + " has a non-finite position");
        soup.positions.push_back(placed);
      }
      std::vector<std::uint32_t> triangles = primitive_triangles(model, p, count, path, what);
      const bool mirrored = instance.transform.topLeftCorner<3, 3>().determinant() < 0.0;
      for (std::size_t t = 0; t < triangles.size(); t += 3) {
        if (mirrored) std::swap(triangles[t + 1], triangles[t + 2]);  // keep the faces facing out
        for (int k = 0; k < 3; ++k) soup.triangles.push_back(static_cast<std::uint32_t>(base) + triangles[t + static_cast<std::size_t>(k)]);
      }
      for (Attribute& attribute : soup.attributes) {
        const auto found = p.attributes.find(attribute.attribute);
        if (found == p.attributes.end()) attribute.complete = false;
        if (!attribute.complete) continue;
        std::vector<double> values = read_accessor(model, found->second, path, what + " " + attribute.attribute);
        const int width = accessor_components(model, found->second);
        if (width == 0 || (attribute.components != 0 && width != attribute.components)) attribute.complete = false;
        if (!attribute.complete) continue;
        attribute.components = width;
        if (values.size() != count * static_cast<std::size_t>(width))
          fail(path, what + ": " + attribute.attribute + " has another count than POSITION");
        attribute.values.insert(attribute.values.end(), values.begin(), values.end());
      }
    }
  }
  if (skipped > 0)
    warnings.push_back(std::to_string(skipped) + (skipped == 1 ? " primitive" : " primitives") +
                       " of points or lines left out (subdiv reads surfaces)");
  return soup;
}

// subdiv's extras, when the file holds exactly one primitive that carries
// them and they agree with it; otherwise nullopt (with a note when they
// were there but did not fit).
struct Extras {
  std::vector<Index> polygons;
  Index vertex_count = 0;
  std::vector<Index> vertices;
  struct Channel {
    std::string attribute, name;
    bool face_varying = false;
  };
  std::vector<Channel> channels;
  std::string tags;
};

std::optional<std::vector<Index>> index_array(const nlohmann::json& j) {
  if (!j.is_array()) return std::nullopt;
  std::vector<Index> out;
  out.reserve(j.size());
  for (const auto& v : j) {
    if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > std::numeric_limits<Index>::max())
      return std::nullopt;
    out.push_back(static_cast<Index>(v.get<long long>()));
  }
  return out;
}

std::optional<Extras> parse_extras(const std::string& json_text) {
  const nlohmann::json doc = nlohmann::json::parse(json_text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object() || !doc.contains(gltf_extras::kKey)) return std::nullopt;
  const nlohmann::json& s = doc[gltf_extras::kKey];
  if (!s.is_object()) return std::nullopt;
  Extras e;
  if (!s.contains(gltf_extras::kVersionKey) || s[gltf_extras::kVersionKey] != gltf_extras::kVersion) return std::nullopt;
  const auto polygons = s.contains(gltf_extras::kPolygonsKey) ? index_array(s[gltf_extras::kPolygonsKey]) : std::nullopt;
  if (!polygons) return std::nullopt;
  e.polygons = *polygons;
  if (!s.contains(gltf_extras::kVertexCountKey) || !s[gltf_extras::kVertexCountKey].is_number_integer()) return std::nullopt;
  const long long count = s[gltf_extras::kVertexCountKey].get<long long>();
  if (count < 0 || count > std::numeric_limits<Index>::max()) return std::nullopt;
  e.vertex_count = static_cast<Index>(count);
  if (s.contains(gltf_extras::kVerticesKey)) {
    const auto vertices = index_array(s[gltf_extras::kVerticesKey]);
    if (!vertices) return std::nullopt;
    e.vertices = *vertices;
  }
  if (s.contains(gltf_extras::kChannelsKey)) {
    if (!s[gltf_extras::kChannelsKey].is_array()) return std::nullopt;
    for (const auto& c : s[gltf_extras::kChannelsKey]) {
      if (!c.is_object() || !c.contains("attribute") || !c["attribute"].is_string() || !c.contains("name") ||
          !c["name"].is_string() || !c.contains("face_varying") || !c["face_varying"].is_boolean())
        return std::nullopt;
      e.channels.push_back({c["attribute"].get<std::string>(), c["name"].get<std::string>(), c["face_varying"].get<bool>()});
    }
  }
  if (s.contains(gltf_extras::kTagsKey)) {
    if (!s[gltf_extras::kTagsKey].is_string()) return std::nullopt;
    e.tags = s[gltf_extras::kTagsKey].get<std::string>();
  }
  return e;
}

// The mesh as subdiv wrote it, from the extras; nullopt (and why) where the
// extras and the triangles disagree.
std::optional<PolygonMesh> mesh_from_extras(const Soup& soup, const Extras& e, const std::string& path, std::string& why) {
  const std::size_t glverts = soup.positions.size();
  if (!e.vertices.empty() && e.vertices.size() != glverts) { why = "the vertex map's length"; return std::nullopt; }
  const auto source = [&](std::size_t g) { return e.vertices.empty() ? static_cast<Index>(g) : e.vertices[g]; };
  PolygonMesh mesh;
  mesh.positions.resize(static_cast<std::size_t>(e.vertex_count));
  std::vector<char> placed(static_cast<std::size_t>(e.vertex_count), 0);
  for (std::size_t g = 0; g < glverts; ++g) {
    const Index v = source(g);
    if (v >= e.vertex_count) { why = "a vertex beyond the vertex count"; return std::nullopt; }
    if (!placed[static_cast<std::size_t>(v)]) mesh.positions[static_cast<std::size_t>(v)] = soup.positions[g];
    placed[static_cast<std::size_t>(v)] = 1;
  }
  if (std::find(placed.begin(), placed.end(), 0) != placed.end()) { why = "a vertex without a position"; return std::nullopt; }

  // Undo the fans: polygon i's triangles are (c0, c_k, c_k+1) for k = 1 .. n-2.
  std::vector<std::uint32_t> corners;  // the glTF vertex of each corner
  std::size_t t = 0;
  const std::size_t triangles = soup.triangles.size() / 3;
  for (const Index n : e.polygons) {
    if (n < 3 || static_cast<std::size_t>(n - 2) > triangles - t) { why = "the polygon sizes"; return std::nullopt; }
    const std::uint32_t* tri = &soup.triangles[3 * t];
    corners.insert(corners.end(), {tri[0], tri[1], tri[2]});
    for (Index k = 1; k < n - 2; ++k) {
      const std::uint32_t* next = &soup.triangles[3 * (t + static_cast<std::size_t>(k))];
      if (next[0] != tri[0] || next[1] != corners.back()) { why = "a polygon that is not a fan"; return std::nullopt; }
      corners.push_back(next[2]);
    }
    mesh.face_offsets.push_back(static_cast<Index>(corners.size()));
    t += static_cast<std::size_t>(n - 2);
  }
  if (t != triangles) { why = "the polygon sizes"; return std::nullopt; }
  mesh.face_indices.reserve(corners.size());
  for (const std::uint32_t g : corners) mesh.face_indices.push_back(source(g));

  for (const Extras::Channel& c : e.channels) {
    const auto a = std::find_if(soup.attributes.begin(), soup.attributes.end(),
                                [&](const Attribute& x) { return x.attribute == c.attribute; });
    if (a == soup.attributes.end() || !a->complete || a->components == 0) { why = "channel '" + c.name + "'"; return std::nullopt; }
    const auto width = static_cast<std::size_t>(a->components);
    if (c.face_varying) {
      FaceVaryingChannel f{c.name, a->components, a->values, {}};
      f.indices.assign(corners.begin(), corners.end());
      mesh.face_varying_channels.push_back(std::move(f));
    } else {
      VertexChannel v{c.name, a->components, std::vector<double>(static_cast<std::size_t>(e.vertex_count) * width)};
      for (std::size_t g = glverts; g-- > 0;)  // the first glTF vertex of each mesh vertex wins
        std::copy_n(a->values.begin() + static_cast<std::ptrdiff_t>(g * width), width,
                    v.values.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(source(g)) * width));
      mesh.vertex_channels.push_back(std::move(v));
    }
  }
  if (!e.tags.empty()) {
    MeshFile tags;
    try {
      tags = parse_obj(e.tags, path + " (extras.subdiv.tags)");
    } catch (const ParseError& error) {
      why = std::string("the tags: ") + error.what();
      return std::nullopt;
    }
    if (tags.mesh.vertex_count() > 0 || tags.mesh.face_count() > 0 || !tags.mesh.polylines.empty()) {
      why = "the tags hold more than tag lines";
      return std::nullopt;
    }
    mesh.tags = std::move(tags.mesh.tags);
  }
  return mesh;
}

// A glTF from another program: welded positions, triangles, and the
// standard attributes as face-varying channels.
PolygonMesh mesh_from_soup(const Soup& soup, const ReadOptions& options, std::vector<std::string>& warnings) {
  PolygonMesh mesh;
  const std::vector<Index> vertex_of = detail::weld(soup.positions, options.weld_tolerance, mesh.positions);
  std::vector<std::uint32_t> kept;  // the glTF vertex of each corner of a kept triangle
  std::size_t collapsed = 0;
  for (std::size_t t = 0; t + 2 < soup.triangles.size(); t += 3) {
    const std::uint32_t* tri = &soup.triangles[t];
    const Index a = vertex_of[tri[0]], b = vertex_of[tri[1]], c = vertex_of[tri[2]];
    if (a == b || b == c || a == c) { ++collapsed; continue; }
    mesh.add_face({a, b, c});
    kept.insert(kept.end(), tri, tri + 3);
  }
  if (collapsed > 0)
    warnings.push_back(std::to_string(collapsed) + (collapsed == 1 ? " triangle" : " triangles") +
                       " with a repeated vertex left out");
  static const std::array<std::pair<const char*, const char*>, 3> kStandard{
      {{"TEXCOORD_0", "uv"}, {"COLOR_0", "color"}, {"NORMAL", "normal"}}};
  for (const Attribute& a : soup.attributes) {
    const auto standard = std::find_if(kStandard.begin(), kStandard.end(), [&](const auto& s) { return a.attribute == s.first; });
    if (standard == kStandard.end()) continue;
    if (!a.complete || a.components == 0) {
      if (a.components != 0)
        warnings.push_back(a.attribute + " is missing from some primitives or differs in width: '" +
                           standard->second + "' channel dropped");
      continue;
    }
    FaceVaryingChannel c{standard->second, a.components, a.values, {}};
    c.indices.assign(kept.begin(), kept.end());
    mesh.face_varying_channels.push_back(std::move(c));
  }
  warnings.push_back("glTF stores triangles: " + std::to_string(mesh.face_count()) +
                     " read as such (quad schemes such as catmull-clark need the polygons of an OBJ, PLY or OFF file)");
  return mesh;
}

}  // namespace

MeshFile parse_gltf(std::string_view bytes, const std::string& path, bool binary, const ReadOptions& options) {
  MeshFile file;
  file.lines.path = path;
  const tinygltf::Model model = load_model(bytes, path, binary, file.warnings);
  std::vector<std::string> wanted{"TEXCOORD_0", "COLOR_0", "NORMAL"};
  std::optional<Extras> extras;
  // subdiv's extras describe a file of one primitive; they name the attributes to read.
  const std::vector<Instance> all = instances(model, path);
  const auto single = [&]() -> const tinygltf::Primitive* {
    if (all.size() != 1) return nullptr;
    const tinygltf::Mesh& m = model.meshes[static_cast<std::size_t>(all.front().mesh)];
    return m.primitives.size() == 1 ? &m.primitives.front() : nullptr;
  }();
  if (single && single->mode == TINYGLTF_MODE_TRIANGLES && !single->extras_json_string.empty()) {
    extras = parse_extras(single->extras_json_string);
    if (extras)
      for (const Extras::Channel& c : extras->channels)
        if (std::find(wanted.begin(), wanted.end(), c.attribute) == wanted.end()) wanted.push_back(c.attribute);
  }
  const Soup soup = read_soup(model, all, wanted, path, file.warnings);
  if (extras) {
    std::string why;
    if (std::optional<PolygonMesh> mesh = mesh_from_extras(soup, *extras, path, why)) {
      file.mesh = std::move(*mesh);
      return file;
    }
    file.warnings.push_back("subdiv's extras do not match the triangles (" + why + "): read as a plain glTF");
  }
  file.mesh = mesh_from_soup(soup, options, file.warnings);
  return file;
}

}  // namespace subdiv
