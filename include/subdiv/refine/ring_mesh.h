#pragma once
// The canonical mesh around one configuration: k sectors of a regular grid
// (quads for the quad split, triangles for the triangle split) laid out in
// the plane around the centre vertex at the origin. Sector s spans the rays
// at angles a s / k and a (s + 1) / k (a = the configuration's sector
// angle, or a quarter turn per face where a / k would reach pi), and its
// grid point (i, j) sits at i u_s + j u_(s+1), u_s the unit
// vector of ray s. Within a sector the layout is linear, so the split's own
// placement (face centroids, edge midpoints) puts the child of a layout
// point p at p / 2 (and its descendant n levels down at p / 2^n): that is
// how analysis identifies a neighbourhood with its image one analysis step
// (the scheme's period) down.
//
// An interior vertex with two faces (k = 2, the faces sharing both its
// edges) has no such layout: two sectors linear in (i, j) would span the
// same two rays and cover each other. ring_mesh refuses it;
// valence_two_ring_mesh lays it out otherwise for the quad split and names
// each vertex's image by its grid point (`image_parent`).

#include <cstdint>
#include <vector>

#include "subdiv/refine/configuration.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/rules/scheme.h"
#include "subdiv/topology/split.h"

namespace subdiv {

/// The element of a ring mesh under a vertex's image one quad or triangle
/// split down: grid point (s, i, j) halved is a vertex (i, j even), the
/// midpoint of an edge (one odd; the triangle split: both odd, the grid
/// cell's diagonal), or the centre of a quad (both odd, quad split). Its
/// child in the split's numbering is the image.
struct ImageParent {
  enum class Kind : std::uint8_t { vertex, edge, face };
  Kind kind = Kind::vertex;
  Index a = kInvalidIndex;  ///< the vertex, the edge's first end, or the face
  Index b = kInvalidIndex;  ///< the edge's other end
};

struct RingMesh {
  PolygonMesh mesh;  ///< positions are the planar layout
  Index centre = 0;  ///< the centre vertex (primal splits)
  /// Dual split: the centre is a face, the k-gon at the origin, and `centre`
  /// is kInvalidIndex.
  Index centre_face = kInvalidIndex;
  /// Dual split: per face, the layout point it surrounds (the vertex of the
  /// quad layout it is dual to; not its centroid where a face straddles two
  /// sectors).
  std::vector<Vec3> face_centres;
  /// The layout is linear in each sector (child_layout finds descendants).
  bool linear = true;
  /// Quad and triangle splits: per vertex, the element whose child one step
  /// down is the vertex's image, the element at half its grid point
  /// (ImageParent). Empty for the other splits.
  std::vector<ImageParent> image_parent;
};

/// The configuration's mesh with `rings` rings of faces around the centre.
/// Corners carry an infinitely sharp corner tag of the configuration's type
/// and angle on the centre. Throws InvalidInputError for k < 1 (interior:
/// k < 3; k = 2 is valence_two_ring_mesh's), rings < 1, or a split without
/// a grid layout.
///
/// For the dual and midedge splits the configuration is an extraordinary face: "interior
/// k" is a k-gon surrounded by `rings` rings of quads, laid out as the dual
/// of the quad layout around a vertex of valence k (a vertex at each face
/// centroid of that layout, a face around each of its interior vertices).
/// Only interior configurations have a dual layout.
RingMesh ring_mesh(SplitRule split, const Configuration& configuration, int rings);

/// Interior k = 2 for the quad split: two sectors of the grid around the
/// centre, point (s, i, j) at radius i + j and angle pi (s + j / (i + j)).
/// Planar, one to one and turned onto itself by a half turn (the rotation
/// of the configuration), but not linear in a sector: `linear` is false,
/// child_layout does not apply, and the image of a vertex one step down is
/// the child of its `image_parent`. Throws InvalidInputError for rings < 1
/// and other splits: two triangles around a vertex share all three edges
/// (the one opposite it is non-manifold), and the other splits' layouts are
/// linear.
RingMesh valence_two_ring_mesh(SplitRule split, int rings);

/// The mesh the analysis reads a configuration on: valence_two_ring_mesh
/// for interior k = 2, else ring_mesh.
RingMesh analysis_ring_mesh(SplitRule split, const Configuration& configuration, int rings);

/// A scheme with the split's topology and linear masks: bilinear, linear,
/// for the dual split corner points at (v + centroid(f)) / 2, for the
/// midedge split edge midpoints. Refining a
/// layout with it gives the child levels' faces (and, for the primal splits,
/// the child_layout positions).
const Scheme& layout_placement(SplitRule split);

/// Positions of the ring mesh's descendants `levels` levels down such that
/// the descendant of layout point p is at p / 2^levels (within a sector the
/// layout is linear): the split's own placement for the primal splits
/// (refined `levels` times); for the dual split, level by level, the corner
/// point of corner v of face f at (v + face_centres[f]) / 2, each child face
/// surrounding its parent element's layout point (an F-face its face's, an
/// E-face the midpoint of its faces' points, a V-face its vertex); for the
/// midedge split (levels = 2 only) the two-step child of a corner placed as
/// the dual split places it. The
/// analysis identifies a neighbourhood with its image `period` steps down
/// by them. Throws InvalidInputError for levels < 1.
std::vector<Vec3> child_layout(SplitRule split, const RingMesh& ring, int levels = 1);

}  // namespace subdiv
