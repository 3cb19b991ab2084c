#pragma once
/// \file
/// The nearest point of the limit surface to given points in space.

#include <span>
#include <vector>

#include "subdiv/eval/limit_evaluator.h"
#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv {

/// A point of the limit surface nearest to a query point.
struct ClosestPoint {
  SurfaceLocation location;  ///< where on the surface (ptex face, u, v)
  Vec3 position;             ///< the surface point
  double distance = 0.0;     ///< its distance to the query point
};

/// For each point, the nearest point of the limit surface found by a local
/// search: the surface is sampled on tessellate()'s grid at `samples_per_edge`,
/// and from the samples nearest the query point (those within 1.5 times the
/// nearest one's distance, at most 16 ptex faces) a Newton iteration on the
/// squared distance, kept inside each ptex face, converges to a local
/// minimum; the nearest of those is returned. It is the global nearest point
/// unless a closer part of the surface passes between samples unseen (the
/// finer the sampling, the smaller that gap).
/// \param mesh the control mesh \p evaluator was made from.
/// \param evaluator its evaluator.
/// \param points the query points (finite).
/// \param samples_per_edge the sampling rate, even, in [2, 64].
/// \return one result per point, in order; parallel over the calling
///   thread's task arena, the same for any thread count.
/// \throws InvalidInputError for a non-finite point (naming it), a rate
///   outside [2, 64] or odd, or as tessellate() does.
/// \throws std::bad_alloc if memory runs out.
std::vector<ClosestPoint> closest_points(const PolygonMesh& mesh, const LimitEvaluator& evaluator,
                                         std::span<const Vec3> points, int samples_per_edge = 8);

}  // namespace subdiv
