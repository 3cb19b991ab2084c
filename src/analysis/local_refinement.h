#pragma once
// Refinement confined to where the closed-form limits look (limit.cpp).
//
// The closed forms read a vertex's vertex point after `levels` steps and
// its few rings there. Deep levels (semi-sharp creases of sharpness 8 on
// a mesh of 800 faces: 13 million faces) are mostly far from every vertex
// followed, so after each step the level is cut down to the faces within
// kCropRings face rings of the followed vertices. A child vertex reads its
// parent element's faces and the rules of that element's vertices, so a
// level cut to R rings refines exactly, bit for bit, the child vertices
// within about 2 (R - 1) - 1 child rings: R = 3 keeps R rings exact from
// level to level; kCropRings = 4 leaves a ring to spare, and the closed
// forms (and the generic masks' one-ring matches) read two rings.
//
// The sharpness left after the last level is read off every semi-sharp
// tag: the ends of semi-sharp edges and semi-sharp corners keep their
// one-ring faces, which is what the tags' next level reads (Chaikin
// creasing averages the sharpness of the edges at an end).

#include <vector>

#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv::detail {

/// Face rings kept around each followed vertex.
inline constexpr int kCropRings = 4;

/// The faces of `mesh` within `rings` face rings of
/// `followed` (ring 0: those vertices; ring r: the vertices of the faces
/// at ring r - 1) or within one ring of a semi-sharp tag, as a mesh of
/// their own: faces, vertices and tags in their order in `mesh`, with
/// positions and tags only (no channels or polylines). `followed` is
/// renumbered into the cut mesh.
PolygonMesh crop_around(const PolygonMesh& mesh, std::vector<Index>& followed, int rings);

}  // namespace subdiv::detail
