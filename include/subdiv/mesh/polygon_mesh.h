#pragma once
// A polygon mesh with faces of any size, stored as compact index arrays.

#include <span>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/primvar.h"
#include "subdiv/mesh/tags.h"

namespace subdiv {

/// A polyline over a mesh's vertices (an OBJ `l` line). A closed one joins
/// its last vertex to its first; the first vertex is not repeated at the end.
struct MeshPolyline {
  std::vector<Index> vertices;
  bool closed = false;
  friend bool operator==(const MeshPolyline&, const MeshPolyline&) = default;
};

/// Positions, faces (offsets + indices, like CSR), tags and data channels.
///
/// Face f uses face_indices[face_offsets[f] .. face_offsets[f+1]); its corners
/// are numbered by their position in face_indices ("corner" indices), which is
/// also how face-varying channels are addressed. Faces are counter-clockwise
/// seen from outside. A well-formed mesh has face_offsets.front() == 0,
/// non-decreasing offsets and indices in [0, vertex_count()); check_indices()
/// enforces this, validate() reports everything else (degenerate faces,
/// non-manifold elements...).
///
/// Polylines (OBJ `l` lines) are curves over the same positions; surface
/// refinement and analysis do not read them, curve schemes refine them.
struct PolygonMesh {
  std::vector<Vec3> positions;
  std::vector<Index> face_offsets{0};
  std::vector<Index> face_indices;
  Tags tags;
  std::vector<VertexChannel> vertex_channels;
  std::vector<FaceVaryingChannel> face_varying_channels;
  std::vector<MeshPolyline> polylines;

  Index vertex_count() const { return static_cast<Index>(positions.size()); }
  Index face_count() const { return static_cast<Index>(face_offsets.size()) - 1; }
  Index corner_count() const { return static_cast<Index>(face_indices.size()); }

  Index face_size(Index f) const { return face_offsets[f + 1] - face_offsets[f]; }
  std::span<const Index> face(Index f) const {
    return {face_indices.data() + face_offsets[f], static_cast<std::size_t>(face_size(f))};
  }

  /// Appends a face; returns its index. Does not check the indices.
  Index add_face(std::span<const Index> vertices);
  Index add_face(std::initializer_list<Index> vertices) {
    return add_face(std::span<const Index>(vertices.begin(), vertices.size()));
  }

  const VertexChannel* find_vertex_channel(const std::string& name) const;
  const FaceVaryingChannel* find_face_varying_channel(const std::string& name) const;
};

/// Throws InvalidInputError unless the face arrays are well formed: offsets
/// start at 0, never decrease and end at face_indices.size(), and every index
/// is in range. Names the first offending face or corner.
void check_face_arrays(const PolygonMesh& mesh);

/// check_face_arrays(), and also that channel sizes match and polyline
/// indices are in range. Throws
/// InvalidInputError unless the face arrays are well formed: offsets
/// start at 0, never decrease and end at face_indices.size(); every index is in
/// range; channel sizes match. Names the first offending face or corner.
void check_indices(const PolygonMesh& mesh);

/// Builds a mesh from positions and a list of faces (convenience for tests and
/// examples). Checks indices.
PolygonMesh make_mesh(std::vector<Vec3> positions,
                      const std::vector<std::vector<Index>>& faces);

}  // namespace subdiv
