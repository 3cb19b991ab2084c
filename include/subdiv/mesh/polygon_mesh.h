#pragma once
/// \file
/// A polygon mesh with faces of any size, stored as compact index arrays.

#include <span>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/primvar.h"
#include "subdiv/mesh/tags.h"

namespace subdiv {

/// A polyline over a mesh's vertices (an OBJ `l` line). A closed one joins
/// its last vertex to its first; the first vertex is not repeated at the end.
struct MeshPolyline {
  std::vector<Index> vertices;  ///< indices into PolygonMesh::positions, in order
  bool closed = false;          ///< whether the last vertex joins the first
  /// Member-wise equality.
  /// \param a first polyline.
  /// \param b second polyline.
  /// \return whether the vertices and closedness are equal.
  friend bool operator==(const MeshPolyline& a, const MeshPolyline& b) = default;
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
  std::vector<Vec3> positions;         ///< one per vertex
  std::vector<Index> face_offsets{0};  ///< face f's corners are [face_offsets[f], face_offsets[f+1]); face_count() + 1 entries
  std::vector<Index> face_indices;     ///< the vertex of every corner, faces concatenated
  Tags tags;                           ///< sharpness tags, holes and subdivision options
  std::vector<VertexChannel> vertex_channels;             ///< per-vertex data
  std::vector<FaceVaryingChannel> face_varying_channels;  ///< per-corner data
  std::vector<MeshPolyline> polylines;                    ///< curves over the positions

  /// \return the number of vertices, positions.size().
  Index vertex_count() const noexcept { return static_cast<Index>(positions.size()); }
  /// \return the number of faces, face_offsets.size() - 1 (-1 if face_offsets is empty).
  Index face_count() const noexcept { return static_cast<Index>(face_offsets.size()) - 1; }
  /// \return the number of face corners over all faces, face_indices.size().
  Index corner_count() const noexcept { return static_cast<Index>(face_indices.size()); }

  /// Number of corners of face \p f.
  /// \pre 0 <= f < face_count() (not checked).
  /// \param f the face.
  /// \return face_offsets[f+1] - face_offsets[f].
  Index face_size(Index f) const noexcept { return face_offsets[f + 1] - face_offsets[f]; }
  /// The vertices of face \p f, in order.
  /// \pre 0 <= f < face_count() and the face arrays are well formed (not checked).
  /// \param f the face.
  /// \return a view into face_indices, valid until the mesh's face arrays change.
  std::span<const Index> face(Index f) const noexcept {
    return {face_indices.data() + face_offsets[f], static_cast<std::size_t>(face_size(f))};
  }

  /// Appends a face. Does not check the indices, and does not extend
  /// face-varying channels' indices.
  /// \param vertices the face's vertices, counter-clockwise seen from outside.
  /// \return the new face's index.
  /// \throws std::bad_alloc if memory runs out.
  Index add_face(std::span<const Index> vertices);
  /// Appends a face, like add_face(std::span<const Index>).
  /// \param vertices the face's vertices, counter-clockwise seen from outside.
  /// \return the new face's index.
  /// \throws std::bad_alloc if memory runs out.
  Index add_face(std::initializer_list<Index> vertices) {
    return add_face(std::span<const Index>(vertices.begin(), vertices.size()));
  }

  /// The first vertex channel called \p name.
  /// \param name the channel's name.
  /// \return a pointer into vertex_channels, or null when there is none;
  ///         valid until vertex_channels changes.
  const VertexChannel* find_vertex_channel(const std::string& name) const noexcept;
  /// The first face-varying channel called \p name.
  /// \param name the channel's name.
  /// \return a pointer into face_varying_channels, or null when there is
  ///         none; valid until face_varying_channels changes.
  const FaceVaryingChannel* find_face_varying_channel(const std::string& name) const noexcept;
};

/// Checks that the face arrays are well formed: offsets start at 0, never
/// decrease and end at face_indices.size(), and every index is in
/// [0, vertex_count()). Channels, polylines and tags are not checked.
/// \param mesh the mesh to check.
/// \throws InvalidInputError naming the first offending face or corner
///         when the face arrays are malformed.
/// \throws std::bad_alloc if memory runs out while building the message.
void check_face_arrays(const PolygonMesh& mesh);

/// check_face_arrays(), and also that every polyline index is in range and
/// the channels fit the mesh: each vertex channel has components > 0 and
/// vertex_count() * components values; each face-varying channel has
/// components > 0, a whole number of values, one index per corner and every
/// index in [0, value_count()). Tags are not checked (validate() reports
/// bad ones).
/// \param mesh the mesh to check.
/// \throws InvalidInputError naming the first offending face, corner,
///         polyline or channel.
/// \throws std::bad_alloc if memory runs out while building the message.
void check_indices(const PolygonMesh& mesh);

/// Builds a mesh from positions and a list of faces (convenience for tests and
/// examples), then runs check_indices() on it.
/// \param positions the vertices' positions, taken over.
/// \param faces each face's vertices, counter-clockwise seen from outside.
/// \return the mesh, with default tags and no channels or polylines.
/// \throws InvalidInputError if a face refers to a vertex outside [0, positions.size()).
/// \throws std::bad_alloc if memory runs out.
PolygonMesh make_mesh(std::vector<Vec3> positions,
                      const std::vector<std::vector<Index>>& faces);

}  // namespace subdiv
