#pragma once
// How a level of adaptive refinement's face hierarchy nests in the next
// (docs/depth.md, "Adaptive refinement"). One step of the quad and triangle
// splits nests: each face's children lie inside it, each edge gets its
// midpoint. Two steps of the sqrt3 split nest too: each triangle's nine
// grandchildren lie inside it (the 1-to-9 split), each edge gets its thirds,
// and each face its centre (the first step's face point); so do two steps of
// the sqrt2 split on quads (the 1-to-4 split, each edge its midpoint).

#include <span>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/topology/split.h"

namespace subdiv::detail {

/// A level's vertices, edges and faces in the next level of the hierarchy.
struct Nesting {
  /// Vertex v of the level is vertex `vertex_points + v` of the next: the
  /// vertex points are the next level's last block.
  Index vertex_points = 0;
  /// Points per edge: 1 (the midpoint) or 2 (the thirds).
  int points_per_edge = 1;
  /// The next level's vertices on each edge e, from edge_vertices(e)[0] on:
  /// entries [points_per_edge * e, points_per_edge * (e + 1)).
  std::vector<Index> edge_points;
  /// The next level's vertex at each face's centre (the quad split's face
  /// point, the sqrt3 split's first face point); empty for the triangle split.
  std::vector<Index> face_centres;
  /// The next level's faces inside face f: children[child_offsets[f] ..
  /// child_offsets[f + 1]).
  std::vector<Index> child_offsets{0};
  std::vector<Index> children;

  Index vertex_point(Index v) const noexcept { return vertex_points + v; }
  std::span<const Index> points_on(Index e) const noexcept {
    return {edge_points.data() + static_cast<std::size_t>(points_per_edge) * static_cast<std::size_t>(e),
            static_cast<std::size_t>(points_per_edge)};
  }
  std::span<const Index> children_of(Index f) const noexcept {
    return {children.data() + child_offsets[static_cast<std::size_t>(f)],
            static_cast<std::size_t>(child_offsets[static_cast<std::size_t>(f) + 1] -
                                     child_offsets[static_cast<std::size_t>(f)])};
  }
};

/// One step of the quad or triangle split (a composite scheme's level split
/// included).
/// \param parent the level's topology.
/// \param map the split from it to the next level.
/// \return the nesting.
Nesting one_step_nesting(const MeshTopology& parent, const SplitMap& map);

/// Two steps of the sqrt3 split from an even level (on open meshes the first
/// step keeps the boundary, the second trisects it).
/// \param level the level's topology.
/// \param first the split from it to the middle level.
/// \param middle the middle level's topology.
/// \param second the split from the middle level to the next.
/// \param next the next level's faces.
/// \return the nesting.
/// \throws std::logic_error if the splits' numbering is not the one described
///         in src/topology/sqrt3_split.cpp (each face must hold nine faces of
///         the next level).
Nesting two_sqrt3_steps_nesting(const MeshTopology& level, const SplitMap& first, const MeshTopology& middle,
                                const SplitMap& second, const PolygonMesh& next);

/// Two steps of the sqrt2 split on a closed quad mesh: each quad holds the
/// four quads two steps down (the 1-to-4 split), each edge gets its midpoint
/// (the second step's face point of the first step's quad across it), each
/// face its centre (the first step's face point).
/// \param level the level's topology (closed, quads).
/// \param first the split from it to the middle level.
/// \param second the split from the middle level to the next.
/// \param next the next level's faces.
/// \return the nesting.
/// \throws std::logic_error if the splits' numbering is not the one described
///         in src/topology/sqrt2_split.cpp (each face must hold four faces of
///         the next level, each with one centre).
Nesting two_sqrt2_steps_nesting(const MeshTopology& level, const SplitMap& first, const SplitMap& second,
                                const PolygonMesh& next);

}  // namespace subdiv::detail
