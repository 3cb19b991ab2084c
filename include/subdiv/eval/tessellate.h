#pragma once
/// \file
/// A uniform tessellation of the limit surface: every ptex face sampled on a
/// regular grid through LimitEvaluator, points on shared edges and corners
/// made once, so the result is watertight (a closed control mesh gives a
/// closed tessellation).

#include "subdiv/eval/limit_evaluator.h"
#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv {

/// The tessellation of \p mesh's limit surface at `rate` segments per edge.
///
/// A Catmull-Clark quad becomes rate x rate quads, a Loop triangle rate^2
/// triangles; a Catmull-Clark n-gon's sub-faces (its ptex faces) take
/// rate / 2 each, so that each of its edges has `rate` segments too, which
/// needs an even rate. The vertices are the limit points, with their limit
/// normals as the face-varying channel "normal" (indexed like the faces).
/// \param mesh the control mesh \p evaluator was made from.
/// \param evaluator its evaluator.
/// \param rate segments per edge, in [1, 4096].
/// \return the tessellation: the control mesh's vertices first (their limit
///   points), then the points inside edges, then those inside faces.
/// \throws InvalidInputError for a rate outside [1, 4096], an odd rate where
///   the mesh has Catmull-Clark n-gons, a mesh whose ptex faces are not the
///   evaluator's, or a result beyond the index range.
/// \throws std::bad_alloc if memory runs out.
PolygonMesh tessellate(const PolygonMesh& mesh, const LimitEvaluator& evaluator, int rate);

}  // namespace subdiv
