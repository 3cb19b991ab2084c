#pragma once
/// \file
/// The canonical mesh around one configuration: k sectors of a regular grid
/// (quads for the quad split, triangles for the triangle split) laid out in
/// the plane around the centre vertex at the origin. Sector s spans the rays
/// at angles a s / k and a (s + 1) / k (a = the configuration's sector
/// angle, or a quarter turn per face where a / k would reach pi), and its
/// grid point (i, j) sits at i u_s + j u_(s+1), u_s the unit
/// vector of ray s. Within a sector the layout is linear, so the split's own
/// placement (face centroids, edge midpoints) puts the child of a layout
/// point p at p / 2 (and its descendant n levels down at p / 2^n): that is
/// how analysis identifies a neighbourhood with its image one analysis step
/// (the scheme's period) down.
///
/// An interior vertex with two faces (k = 2, the faces sharing both its
/// edges) has no such layout: two sectors linear in (i, j) would span the
/// same two rays and cover each other. ring_mesh refuses it;
/// valence_two_ring_mesh lays it out otherwise for the quad split and names
/// each vertex's image by its grid point (`image_parent`).

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
  /// The kind of element.
  enum class Kind : std::uint8_t {
    vertex,  ///< a vertex (both grid coordinates even)
    edge,    ///< the midpoint of an edge
    face,    ///< the centre of a quad (quad split)
  };
  Kind kind = Kind::vertex;  ///< the kind of element
  Index a = kInvalidIndex;  ///< the vertex, the edge's first end, or the face
  Index b = kInvalidIndex;  ///< the edge's other end
};

/// The canonical mesh around one configuration (ring_mesh()).
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
/// \param split the split whose layout is made (the quad layout for the
///   quad and sqrt2 splits, the triangle layout for the triangle, sqrt3 and
///   identity splits, the dual layout for the dual and midedge splits).
/// \param configuration the configuration at the centre.
/// \param rings the rings of faces, >= 1.
/// \return the ring mesh.
/// \throws InvalidInputError for the quasi 4-8 bisection, \p rings < 1, too
///   few faces (k < 1; interior: k < 3), a configuration angle outside
///   [0, 2 pi), or, for the dual and midedge splits, a configuration that is
///   not interior.
/// \throws std::bad_alloc if memory runs out.
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
/// \param split the split: SplitRule::quad.
/// \param rings the rings of faces, >= 1.
/// \return the ring mesh, with `linear` false and `image_parent` filled.
/// \throws InvalidInputError for a split other than the quad split, or
///   \p rings < 1.
/// \throws std::bad_alloc if memory runs out.
RingMesh valence_two_ring_mesh(SplitRule split, int rings);

/// The mesh the analysis reads a configuration on: valence_two_ring_mesh
/// for interior k = 2, else ring_mesh.
/// \param split the split whose layout is made.
/// \param configuration the configuration at the centre.
/// \param rings the rings of faces, >= 1.
/// \return the ring mesh.
/// \throws InvalidInputError as ring_mesh() or valence_two_ring_mesh() does.
/// \throws std::bad_alloc if memory runs out.
RingMesh analysis_ring_mesh(SplitRule split, const Configuration& configuration, int rings);

/// A scheme with the split's topology and linear masks: bilinear for the
/// quad split, linear for the triangle split, for the dual split corner points at (v + centroid(f)) / 2, for the
/// midedge split edge midpoints. Refining a
/// layout with it gives the child levels' faces (and, for the primal splits,
/// the child_layout positions). The sqrt3 and sqrt2 splits get their own
/// placements (face centroids, old vertices kept; the sqrt3 split's boundary
/// points at the thirds of their edges); the triangle, identity and quasi
/// 4-8 splits get the linear scheme.
/// \param split the split.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& layout_placement(SplitRule split) noexcept;

/// Positions of the ring mesh's descendants `levels` levels down such that
/// the descendant of layout point p is at p / arity(split)^levels (p / 2^levels
/// for the arity-2 splits, p / 3 two sqrt3 steps down; within a sector the
/// layout is linear): the split's own placement for the primal splits
/// (refined `levels` times); for the dual split, level by level, the corner
/// point of corner v of face f at (v + face_centres[f]) / 2, each child face
/// surrounding its parent element's layout point (an F-face its face's, an
/// E-face the midpoint of its faces' points, a V-face its vertex); for the
/// midedge split (levels = 2 only) the two-step child of a corner placed as
/// the dual split places it. The
/// analysis identifies a neighbourhood with its image `period` steps down
/// by them. The sqrt3 and sqrt2 splits, like the midedge split, are
/// identified after two steps.
/// \param split the split \p ring was laid out for.
/// \param ring a ring mesh of that split with a linear layout.
/// \param levels the levels down, >= 1 (2 for the midedge, sqrt3 and sqrt2
///   splits).
/// \return one position per vertex of the level \p levels down, in the
///   split's numbering.
/// \throws InvalidInputError for \p levels < 1, a level count the midedge,
///   sqrt3 or sqrt2 split does not identify, or a ring whose children do not
///   match its split's numbering; as refine() does for a mesh the placement
///   scheme refuses.
/// \throws std::bad_alloc if memory runs out.
std::vector<Vec3> child_layout(SplitRule split, const RingMesh& ring, int levels = 1);

}  // namespace subdiv
