#include "subdiv/mesh/polygon_mesh.h"

#include <string>

#include "subdiv/core/error.h"

namespace subdiv {

Index PolygonMesh::add_face(std::span<const Index> vertices) {
  face_indices.insert(face_indices.end(), vertices.begin(), vertices.end());
  face_offsets.push_back(static_cast<Index>(face_indices.size()));
  return face_count() - 1;
}

const VertexChannel* PolygonMesh::find_vertex_channel(const std::string& name) const noexcept {
  for (const auto& c : vertex_channels)
    if (c.name == name) return &c;
  return nullptr;
}

const FaceVaryingChannel* PolygonMesh::find_face_varying_channel(const std::string& name) const noexcept {
  for (const auto& c : face_varying_channels)
    if (c.name == name) return &c;
  return nullptr;
}

void check_face_arrays(const PolygonMesh& mesh) {
  const auto& off = mesh.face_offsets;
  if (off.empty() || off.front() != 0)
    throw InvalidInputError("mesh: face_offsets must start with 0");
  if (static_cast<std::size_t>(off.back()) != mesh.face_indices.size())
    throw InvalidInputError("mesh: face_offsets ends at " + std::to_string(off.back()) +
                            " but there are " + std::to_string(mesh.face_indices.size()) +
                            " face indices");
  for (std::size_t f = 0; f + 1 < off.size(); ++f)
    if (off[f + 1] < off[f])
      throw InvalidInputError("mesh: face " + std::to_string(f) + " has a negative size");
  const Index n = mesh.vertex_count();
  for (std::size_t c = 0; c < mesh.face_indices.size(); ++c) {
    const Index v = mesh.face_indices[c];
    if (v < 0 || v >= n)
      throw InvalidInputError("mesh: corner " + std::to_string(c) + " refers to vertex " +
                              std::to_string(v) + ", outside [0, " + std::to_string(n) + ")");
  }
}

void check_indices(const PolygonMesh& mesh) {
  check_face_arrays(mesh);
  const Index n = mesh.vertex_count();
  for (std::size_t l = 0; l < mesh.polylines.size(); ++l)
    for (const Index v : mesh.polylines[l].vertices)
      if (v < 0 || v >= n)
        throw InvalidInputError("mesh: polyline " + std::to_string(l) + " refers to vertex " + std::to_string(v) +
                                ", outside [0, " + std::to_string(n) + ")");
  for (const auto& ch : mesh.vertex_channels) {
    if (ch.components <= 0 ||
        ch.values.size() != static_cast<std::size_t>(n) * static_cast<std::size_t>(ch.components))
      throw InvalidInputError("mesh: vertex channel '" + ch.name + "' has " +
                              std::to_string(ch.values.size()) + " values for " +
                              std::to_string(n) + " vertices");
  }
  for (const auto& ch : mesh.face_varying_channels) {
    if (ch.components <= 0 || ch.values.size() % static_cast<std::size_t>(ch.components) != 0)
      throw InvalidInputError("mesh: face-varying channel '" + ch.name +
                              "' has a value count that is not a multiple of its components");
    if (ch.indices.size() != mesh.face_indices.size())
      throw InvalidInputError("mesh: face-varying channel '" + ch.name + "' has " +
                              std::to_string(ch.indices.size()) + " indices for " +
                              std::to_string(mesh.face_indices.size()) + " face corners");
    const Index m = ch.value_count();
    for (std::size_t c = 0; c < ch.indices.size(); ++c)
      if (ch.indices[c] < 0 || ch.indices[c] >= m)
        throw InvalidInputError("mesh: face-varying channel '" + ch.name + "' corner " +
                                std::to_string(c) + " refers to value " +
                                std::to_string(ch.indices[c]) + ", outside [0, " +
                                std::to_string(m) + ")");
  }
}

PolygonMesh make_mesh(std::vector<Vec3> positions, const std::vector<std::vector<Index>>& faces) {
  PolygonMesh mesh;
  mesh.positions = std::move(positions);
  for (const auto& f : faces) mesh.add_face(f);
  check_indices(mesh);
  return mesh;
}

}  // namespace subdiv
