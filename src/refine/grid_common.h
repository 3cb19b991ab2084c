#pragma once
// What the grid path's quad and triangle splits share (grid_refine.h): the
// values refined per point, the checks before it applies, the masks' mesh
// around the faces that are not regular, and the result's arrays.

#include <optional>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/tags.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"

namespace subdiv::detail {

// Deeper runs take their first levels by the masks, while the mesh is
// small, so that a face's grid stays within a few megabytes.
constexpr int kMaxGridLevels = 8;

// The values refined per point: the position, then each vertex channel's.
struct PointValues {
  const PolygonMesh& mesh;
  int width = 3;

  explicit PointValues(const PolygonMesh& m);
  // Positions alone (the common case) inline; channels out of line.
  void gather(Index v, double* out) const {
    const Vec3& p = mesh.positions[static_cast<std::size_t>(v)];
    out[0] = p.x, out[1] = p.y, out[2] = p.z;
    if (width > 3) gather_channels(v, out + 3);
  }

 private:
  void gather_channels(Index v, double* out) const;
};

// Writes one point's channel values to vertex v of `out`.
void scatter_channels(const double* values, Index v, PolygonMesh& out);

// Writes one point's values (position, then channels) to vertex v of `out`.
inline void scatter(const double* values, Index v, PolygonMesh& out) {
  out.positions[static_cast<std::size_t>(v)] = {values[0], values[1], values[2]};
  if (!out.vertex_channels.empty()) scatter_channels(values + 3, v, out);
}

// Copies vertex `from` of `in` (position and channels) to vertex `to` of `out`.
void copy_point(const PolygonMesh& in, Index from, Index to, PolygonMesh& out);

// The options of a level's tags, without its element tags and without tags
// no module reads, which name the level's elements.
Tags tag_options(const Tags& parent);

// Per vertex: whether a crease or corner tag makes it sharp (the rules at
// it, and at the edges leaving it, are not the regular ones).
std::vector<char> sharp_vertices(const PolygonMesh& level, const MeshTopology& t);

// Whether the grid path covers `levels` levels of this level, every face
// of `face_size` corners, apart from the scheme and which faces are regular.
bool covers_level(const PolygonMesh& level, const MeshTopology& t, const RefineOptions& options, int levels,
                  Index face_size);

// The faces that are not regular patches and `rings` rings of faces around
// them (a ring: the faces sharing a vertex with those before), as a mesh of
// their own for the masks (its artificial boundary changes only points
// outside the faces taken from it), with the number each face has there
// (kInvalidIndex for faces not in it). Where the level has tags, one ring
// more: the sharpness and rules of the last ring's edges and vertices then
// see all their neighbours. With `close_pinches` (for schemes that refine
// manifold meshes only), a vertex whose taken faces form several fans takes
// all of its faces, so that the mesh does not pinch at its rim.
struct MasksMesh {
  PolygonMesh mesh;
  std::vector<Index> face_in_mesh;
  std::vector<Index> level_vertex;  // of each of its vertices
};

// nullopt where it would hold more than half the faces.
std::optional<MasksMesh> masks_mesh(const PolygonMesh& level, const MeshTopology& t, const std::vector<char>& regular,
                                    int rings = 1, bool close_pinches = false);

// The options refining the masks' mesh: `levels` levels by the masks alone.
RefineOptions masks_options(const RefineOptions& options, int levels);

// The result's arrays, sized for `vertices` vertices and `faces` faces of
// `face_size` corners, with `tags` and the crease method refinement used
// (as the masks' levels name it).
PolygonMesh sized_result(const PolygonMesh& level, const RefineOptions& options, Tags tags, std::int64_t vertices,
                         std::int64_t faces, Index face_size);

}  // namespace subdiv::detail
