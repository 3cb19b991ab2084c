#include "subdiv/io/gltf.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "subdiv/core/error.h"
#include "subdiv/version.h"
#include "gltf_extras.h"
#include "obj_tags.h"

namespace subdiv {

namespace {

// glTF sizes are 32-bit in the GLB container, and a .gltf's base64 grows a
// third: stay well inside both.
constexpr std::size_t kMaxBufferBytes = std::size_t{1} << 31;

// A channel as it is written: where its values come from and its attribute.
struct WrittenChannel {
  std::string attribute;
  std::string name;
  int components = 0;
  bool face_varying = false;
  const std::vector<double>* values = nullptr;
  const std::vector<Index>* indices = nullptr;  // face-varying only: per corner
};

// Whether every value of a three-component channel is a unit vector at
// float precision (glTF's NORMAL must be).
bool unit_vectors(const std::vector<double>& v) {
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
    const double length = std::sqrt(v[i] * v[i] + v[i + 1] * v[i + 1] + v[i + 2] * v[i + 2]);
    if (!(std::abs(length - 1.0) <= 5e-4)) return false;
  }
  return true;
}

bool in_unit_interval(const std::vector<double>& v) {
  for (const double x : v)
    if (!(x >= 0.0 && x <= 1.0)) return false;
  return true;
}

// The attribute a channel becomes: glTF's own where its constraints hold,
// else an application-specific `_name`.
std::string attribute_for(const std::string& name, int components, const std::vector<double>& values,
                          std::map<std::string, int>& used) {
  std::string attribute = "_" + name;
  if (name == "uv" && components == 2) attribute = "TEXCOORD_0";
  else if (name == "color" && (components == 3 || components == 4) && in_unit_interval(values)) attribute = "COLOR_0";
  else if (name == "normal" && components == 3 && unit_vectors(values)) attribute = "NORMAL";
  if (used[attribute]++ > 0) attribute = "_" + name + "_" + std::to_string(used[attribute] - 1);
  return attribute;
}

std::vector<WrittenChannel> channels_to_write(const PolygonMesh& mesh, std::vector<std::string>* warnings) {
  std::vector<WrittenChannel> out;
  std::map<std::string, int> used;
  const auto unwritable = [&](const std::string& name, int components, const char* why) {
    if (warnings)
      warnings->push_back("glTF has no place for channel '" + name + "' (" + std::to_string(components) +
                          " components): " + why + ", not written");
  };
  for (const VertexChannel& c : mesh.vertex_channels) {
    if (c.components < 1 || c.components > 4) { unwritable(c.name, c.components, "attributes hold 1 to 4"); continue; }
    if (c.value_count() != mesh.vertex_count()) { unwritable(c.name, c.components, "not one value per vertex"); continue; }
    out.push_back({attribute_for(c.name, c.components, c.values, used), c.name, c.components, false, &c.values, nullptr});
  }
  for (const FaceVaryingChannel& c : mesh.face_varying_channels) {
    if (c.components < 1 || c.components > 4) { unwritable(c.name, c.components, "attributes hold 1 to 4"); continue; }
    if (c.indices.size() != mesh.face_indices.size()) { unwritable(c.name, c.components, "not one index per corner"); continue; }
    bool in_range = true;
    for (const Index i : c.indices) in_range = in_range && i >= 0 && i < c.value_count();
    if (!in_range) { unwritable(c.name, c.components, "an index out of range"); continue; }
    out.push_back({attribute_for(c.name, c.components, c.values, used), c.name, c.components, true, &c.values, &c.indices});
  }
  return out;
}

// glTF vertices: one per mesh vertex when no face-varying channel is
// written, else one per distinct (vertex, face-varying values) of a corner,
// then one for every vertex no corner uses (so that none is lost).
struct GltfVertices {
  std::vector<Index> source;     // the mesh vertex of each glTF vertex
  std::vector<Index> of_corner;  // the glTF vertex of each corner
  bool split = false;
};

GltfVertices split_vertices(const PolygonMesh& mesh, const std::vector<WrittenChannel>& channels) {
  GltfVertices out;
  std::vector<const WrittenChannel*> varying;
  for (const WrittenChannel& c : channels)
    if (c.face_varying) varying.push_back(&c);
  const std::size_t corners = mesh.face_indices.size();
  out.of_corner.resize(corners);
  if (varying.empty()) {
    out.source.resize(static_cast<std::size_t>(mesh.vertex_count()));
    for (Index v = 0; v < mesh.vertex_count(); ++v) out.source[static_cast<std::size_t>(v)] = v;
    out.of_corner.assign(mesh.face_indices.begin(), mesh.face_indices.end());
    return out;
  }
  out.split = true;
  std::map<std::vector<Index>, Index> first;
  std::vector<char> used(static_cast<std::size_t>(mesh.vertex_count()), 0);
  std::vector<Index> key(varying.size() + 1);
  for (std::size_t c = 0; c < corners; ++c) {
    key[0] = mesh.face_indices[c];
    for (std::size_t k = 0; k < varying.size(); ++k) key[k + 1] = (*varying[k]->indices)[c];
    const auto [it, inserted] = first.try_emplace(key, static_cast<Index>(out.source.size()));
    if (inserted) out.source.push_back(key[0]);
    out.of_corner[c] = it->second;
    used[static_cast<std::size_t>(key[0])] = 1;
  }
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (!used[static_cast<std::size_t>(v)]) out.source.push_back(v);
  return out;
}

class BufferBuilder {
 public:
  explicit BufferBuilder(tinygltf::Model& model) : model_(model) {}

  // Appends one buffer view and its accessor; returns the accessor.
  int add_floats(const std::vector<float>& values, int components, bool with_bounds) {
    const int view = add_view(values.data(), values.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.count = values.size() / static_cast<std::size_t>(components);
    a.type = components == 1 ? TINYGLTF_TYPE_SCALAR : components == 2 ? TINYGLTF_TYPE_VEC2
             : components == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
    if (with_bounds) {
      a.minValues.assign(static_cast<std::size_t>(components), std::numeric_limits<double>::infinity());
      a.maxValues.assign(static_cast<std::size_t>(components), -std::numeric_limits<double>::infinity());
      for (std::size_t i = 0; i < values.size(); ++i) {
        const std::size_t k = i % static_cast<std::size_t>(components);
        a.minValues[k] = std::min(a.minValues[k], static_cast<double>(values[i]));
        a.maxValues[k] = std::max(a.maxValues[k], static_cast<double>(values[i]));
      }
    }
    model_.accessors.push_back(std::move(a));
    return static_cast<int>(model_.accessors.size() - 1);
  }

  int add_indices(const std::vector<std::uint32_t>& indices) {
    const int view = add_view(indices.data(), indices.size() * sizeof(std::uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.count = indices.size();
    a.type = TINYGLTF_TYPE_SCALAR;
    model_.accessors.push_back(std::move(a));
    return static_cast<int>(model_.accessors.size() - 1);
  }

  void finish() {
    tinygltf::Buffer buffer;
    buffer.data = std::move(bytes_);
    model_.buffers.push_back(std::move(buffer));
  }

 private:
  int add_view(const void* data, std::size_t size, int target) {
    if (bytes_.size() + size > kMaxBufferBytes)
      throw InvalidInputError("the mesh is too large for a glTF buffer (over 2 GiB)");
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = bytes_.size();  // every view's size is a multiple of 4: offsets stay aligned
    view.byteLength = size;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
    model_.bufferViews.push_back(std::move(view));
    return static_cast<int>(model_.bufferViews.size() - 1);
  }

  tinygltf::Model& model_;
  std::vector<unsigned char> bytes_;
};

float to_float(double x, const char* what, std::size_t element) {
  const auto f = static_cast<float>(x);
  if (!std::isfinite(f))
    throw InvalidInputError(std::string("glTF stores float32: ") + what + " " + std::to_string(element) +
                            (std::isfinite(x) ? " is beyond float32's range" : " is not finite"));
  return f;
}

tinygltf::Value int_array(const std::vector<Index>& values) {
  tinygltf::Value::Array a;
  a.reserve(values.size());
  for (const Index v : values) a.emplace_back(static_cast<int>(v));
  return tinygltf::Value(std::move(a));
}

}  // namespace

std::string format_gltf(const PolygonMesh& mesh, bool binary, std::vector<std::string>* warnings) {
  check_face_arrays(mesh);
  const std::vector<WrittenChannel> channels = channels_to_write(mesh, warnings);
  const GltfVertices vertices = split_vertices(mesh, channels);
  if (vertices.source.size() > static_cast<std::size_t>(std::numeric_limits<std::uint32_t>::max()))
    throw InvalidInputError("the mesh is too large for glTF's 32-bit indices");

  // Triangles: each polygon as a fan from its first corner, which the reader
  // undoes with the polygon sizes in the extras.
  std::vector<std::uint32_t> triangles;
  std::vector<Index> polygon_sizes;
  Index left_out = 0, split = 0;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Index n = mesh.face_size(f), first = mesh.face_offsets[static_cast<std::size_t>(f)];
    if (n < 3) { ++left_out; continue; }
    if (n > 3) ++split;
    polygon_sizes.push_back(n);
    for (Index k = 1; k + 1 < n; ++k)
      for (const Index corner : {first, first + k, first + k + 1})
        triangles.push_back(static_cast<std::uint32_t>(vertices.of_corner[static_cast<std::size_t>(corner)]));
  }
  if (triangles.empty())
    throw InvalidInputError("glTF needs at least one triangle: the mesh has no face of three or more corners");
  if (warnings) {
    if (left_out > 0)
      warnings->push_back(std::to_string(left_out) + (left_out == 1 ? " face" : " faces") +
                          " of fewer than three corners left out (glTF holds triangles)");
    if (split > 0)
      warnings->push_back("glTF holds triangles: " + std::to_string(split) +
                          (split == 1 ? " polygon" : " polygons") +
                          " written as fans of triangles (subdiv reads the polygons back from the extras; "
                          "other programs see the triangles)");
    if (!mesh.tags.empty())
      warnings->push_back("glTF has no field for tags: creases, corners and holes are kept in the extras, "
                          "which only subdiv reads");
  }

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = std::string("subdiv ") + version();
  BufferBuilder buffer(model);
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;

  std::vector<float> floats;
  floats.reserve(vertices.source.size() * 3);
  for (const Index v : vertices.source)
    for (int k = 0; k < 3; ++k)
      floats.push_back(to_float(mesh.positions[static_cast<std::size_t>(v)][k], "the position of vertex",
                                static_cast<std::size_t>(v)));
  primitive.attributes["POSITION"] = buffer.add_floats(floats, 3, true);

  // Face-varying values per glTF vertex: the value of any corner that made it.
  std::vector<Index> corner_of_vertex(vertices.source.size(), kInvalidIndex);
  for (std::size_t c = 0; c < vertices.of_corner.size(); ++c) {
    Index& corner = corner_of_vertex[static_cast<std::size_t>(vertices.of_corner[c])];
    if (corner == kInvalidIndex) corner = static_cast<Index>(c);
  }
  tinygltf::Value::Array written_channels;
  for (const WrittenChannel& c : channels) {
    const auto width = static_cast<std::size_t>(c.components);
    floats.assign(vertices.source.size() * width, 0.0f);
    for (std::size_t g = 0; g < vertices.source.size(); ++g) {
      std::size_t value;
      if (!c.face_varying) value = static_cast<std::size_t>(vertices.source[g]);
      else if (corner_of_vertex[g] != kInvalidIndex) value = static_cast<std::size_t>((*c.indices)[static_cast<std::size_t>(corner_of_vertex[g])]);
      else continue;  // a vertex no corner uses: no face-varying value
      for (std::size_t k = 0; k < width; ++k)
        floats[g * width + k] = to_float((*c.values)[value * width + k], "a value of channel", value);
    }
    primitive.attributes[c.attribute] = buffer.add_floats(floats, c.components, false);
    tinygltf::Value::Object entry;
    entry["attribute"] = tinygltf::Value(c.attribute);
    entry["name"] = tinygltf::Value(c.name);
    entry["face_varying"] = tinygltf::Value(c.face_varying);
    written_channels.emplace_back(std::move(entry));
  }
  primitive.indices = buffer.add_indices(triangles);
  buffer.finish();

  tinygltf::Value::Object extras;
  extras[gltf_extras::kVersionKey] = tinygltf::Value(gltf_extras::kVersion);
  extras[gltf_extras::kPolygonsKey] = int_array(polygon_sizes);
  extras[gltf_extras::kVertexCountKey] = tinygltf::Value(static_cast<int>(mesh.vertex_count()));
  if (vertices.split) extras[gltf_extras::kVerticesKey] = int_array(vertices.source);
  if (!written_channels.empty()) extras[gltf_extras::kChannelsKey] = tinygltf::Value(std::move(written_channels));
  if (!mesh.tags.empty()) {
    std::string lines;
    detail::append_obj_tag_lines(lines, mesh.tags);
    extras[gltf_extras::kTagsKey] = tinygltf::Value(lines);
  }
  tinygltf::Value::Object wrapper;
  wrapper[gltf_extras::kKey] = tinygltf::Value(std::move(extras));
  primitive.extras = tinygltf::Value(std::move(wrapper));

  tinygltf::Mesh gltf_mesh;
  gltf_mesh.primitives.push_back(std::move(primitive));
  model.meshes.push_back(std::move(gltf_mesh));
  tinygltf::Node node;
  node.mesh = 0;
  model.nodes.push_back(std::move(node));
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(std::move(scene));
  model.defaultScene = 0;

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, binary))
    throw Error("TinyGLTF could not serialise the glTF document");
  return std::move(out).str();
}

}  // namespace subdiv
