#pragma once
/// \file
/// Closed-form limit masks of a vertex: its limit position and two tangents
/// as weights over its one-ring, in the layout of OpenSubdiv's Sdc limit
/// masks: a weight on the vertex, one per edge neighbour (ring order), and,
/// for quad schemes, one per face on the face's vertex opposite the centre.
///
/// The ring order is MeshTopology's: counter-clockwise seen from outside,
/// face j between edges j and j + 1 (a boundary vertex: k faces, k + 1
/// edges, edge 0 and edge k on the boundary). Tangents are oriented so that
/// tangent1 x tangent2 points out of the surface (the side the faces are
/// counter-clockwise on); their lengths follow each formula's own convention
/// and are not derivatives in a common parametrisation.

#include <cstdint>
#include <vector>

namespace subdiv {

enum class VertexRule : std::uint8_t;  // rules/scheme.h

/// What the masks depend on: the ring's size and the vertex's rule, on a
/// level where the vertex's faces have the scheme's regular size and its
/// edges are smooth or infinitely sharp.
struct VertexNeighbourhood {
  int edges = 0;      ///< edge neighbours in the ring (k inside, k + 1 on a boundary)
  int faces = 0;      ///< faces around the vertex
  VertexRule rule{};  ///< the vertex's rule on this level
  /// Crease and corner rules: the ring positions of the sharp edges the
  /// masks follow, `sharp[1]` the next sharp edge counter-clockwise from
  /// `sharp[0]`; the faces between them are the sector the masks look at
  /// (on an interior crease, one of its two sides).
  int sharp[2] = {0, 0};

  /// Faces in the sector from sharp[0] counter-clockwise to sharp[1].
  /// \return sharp[1] - sharp[0], or that plus `edges` where the sector
  ///   wraps past ring position 0.
  int sector_faces() const noexcept {
    return sharp[1] > sharp[0] ? sharp[1] - sharp[0] : sharp[1] + edges - sharp[0];
  }
};

/// One limit mask (a position or a tangent) of a vertex, OpenSubdiv's Sdc
/// layout: a weight on the vertex, one per edge neighbour in ring order
/// (MeshTopology's: counter-clockwise, face j between edges j and j + 1),
/// and, for quad schemes, one per face on its vertex opposite the centre.
struct LimitMask {
  double vertex = 0.0;        ///< weight on the vertex itself
  std::vector<double> edges;  ///< one per edge neighbour
  std::vector<double> faces;  ///< quad schemes: one per face (its opposite vertex); else empty

  /// Sizes the mask and sets every weight to 0.
  /// \param edge_count the entries of `edges`, >= 0.
  /// \param face_count the entries of `faces`, >= 0 (0 for triangle schemes).
  /// \throws std::bad_alloc if memory runs out.
  void reset(int edge_count, int face_count) {
    vertex = 0.0;
    edges.assign(static_cast<std::size_t>(edge_count), 0.0);
    faces.assign(static_cast<std::size_t>(face_count), 0.0);
  }
};

/// A vertex's three closed-form limit masks.
struct LimitMasks {
  LimitMask position;  ///< the limit point; its weights sum to 1
  LimitMask tangent1;  ///< the first tangent
  LimitMask tangent2;  ///< the second tangent (tangent1 x tangent2 points out of the surface)
};

/// A scheme's closed-form limit masks; false where it has none for this
/// neighbourhood (the caller then uses the generic eigenvector masks).
using LimitMaskFunction = bool (*)(const VertexNeighbourhood& neighbourhood, LimitMasks& masks);

}  // namespace subdiv
