#pragma once
/// \file
/// Limit positions and normals of a mesh's vertices.
///
/// Two routes:
/// - Closed forms (Catmull-Clark, Loop, loop-warren: the scheme's
///   `limit_masks`, rules/limit_mask.h): the mesh is refined just enough for
///   the masks to apply (one level where a face has another size than the
///   split's; ceil(s) levels for the largest finite sharpness s, so that
///   semi-sharp edges and vertices have become smooth), at most
///   `max_resolve_levels` and no level over `max_resolve_faces`; a vertex's
///   limit is the limit of its vertex point. Vertices without a closed form
///   there (valence 2, semi-sharp features beyond the caps) take the generic
///   masks when their neighbourhood matches a configuration, else keep their
///   refined position. Darts take the left eigenvectors of their own
///   one-ring matrix (the smooth masks are not their limit: the dart edge's
///   point follows the crease rule), reported as LimitSource::generic.
/// - Generic masks, for every scheme: the left eigenvectors of the local
///   subdivision matrix (eigenvalue 1: the limit position; the subdominant
///   pair: two tangents), computed once per configuration by the analysis
///   and cached, after `isolation_levels` refinement steps. The masks are
///   over the smallest invariant neighbourhood, r face rings (one for
///   Catmull-Clark and Loop, two at the Butterfly schemes' regular
///   vertices). A vertex's neighbourhood is matched to its configuration's
///   ring mesh face by face from the first face (counter-clockwise from the
///   first edge), so within r rings it must look like it: faces of the
///   split's kind around a smooth interior vertex, a boundary vertex, or a
///   corner, the inner vertices' valences and rules the configuration's, and
///   the mesh's own first step there equal to the matrix (so another
///   extraordinary vertex whose rules reach the neighbourhood fails it; the
///   sqrt3 and sqrt2 splits' matrices span two steps, and their rules read
///   nothing the topology does not fix there, so they match the topology
///   alone). A vertex on an interior crease
///   takes the masks of one of its sectors (the first with two or more
///   faces) as a boundary configuration with that sector's faces: each
///   sector evolves as a boundary fan, the crease and boundary rules being
///   the same curve rules. The position reads the curve only; the normal is
///   that sector's. An infinitely sharp corner keeps its position; its
///   tangents are the left eigenvectors of the eigenvalue 1/2 (the two
///   boundary curves; 1/3 over sqrt3's two steps) of the corner
///   configuration with its (first) sector's
///   faces, and under the piecewise-smooth rules its sector angle (the
///   cache is keyed on it); its normal is defined where that pair 1/2 is
///   subdominant (lambda_1 = lambda_2 = 1/2 > |lambda_3|: convex corners,
///   concave ones with the flatness modification), else zero (the standard
///   rules' and the unflattened concave corners, which flip or fold).
///   Vertices that match no
///   canonical neighbourhood (darts, non-manifold vertices, semi-sharp
///   features not yet resolved, corners among them: a corner is kept only
///   where its rule stays, an extraordinary vertex not yet isolated, an
///   interior vertex of two triangles) keep their refined position and are
///   counted. An interior vertex with two quads (valence 2, which the quad
///   split keeps) has the configuration interior k = 2
///   (valence_two_ring_mesh): its limit mask is the left eigenvector of its
///   one-ring matrix; that matrix has 1/4, 1/4 and -1/4 after 1 for
///   Catmull-Clark, no subdominant pair, so no normal.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/refine/refine.h"

namespace subdiv {

/// Which masks limit_positions() prefers.
///
/// The closed forms (the scheme's `limit_masks`: Catmull-Clark, Loop,
/// loop-warren) apply after just enough refinement to resolve faces of
/// another size than the split's and semi-sharp features (capped by
/// LimitOptions::max_resolve_levels and max_resolve_faces). The generic masks
/// are the left eigenvectors of the local subdivision matrix of each vertex's
/// configuration (eigenvalue 1: the position; the subdominant pair: two
/// tangents), computed once per configuration by analyze() and cached, and
/// apply after LimitOptions::isolation_levels steps where the vertex's
/// neighbourhood matches its configuration's ring mesh. Vertices neither
/// route covers keep their refined position.
enum class LimitRoute : std::uint8_t {
  closed_form,  ///< the scheme's closed forms where it has them, else generic
  generic,      ///< the analysis's eigenvector masks
};

/// How limit_positions() computes limits.
struct LimitOptions {
  LimitRoute route = LimitRoute::closed_form;  ///< closed forms first, or generic masks only
  /// Generic route: refinement steps before the masks apply. The sqrt2
  /// split (arity sqrt 2) takes twice as many steps, two per binary level;
  /// the sqrt3 split an even number, the analysis's two-step matrix
  /// starting with a step that does not trisect the boundary.
  int isolation_levels = 2;
  /// Closed-form route: most refinement steps taken to resolve faces and
  /// semi-sharp features (10 covers every finite sharpness: 10 is infinite).
  int max_resolve_levels = 10;
  /// Closed-form route: no step is taken whose mesh would have more faces.
  std::int64_t max_resolve_faces = std::int64_t{1} << 24;
  /// Closed-form route (quad and triangle splits): refine only the faces
  /// around the input vertices and the semi-sharp tags, level by level
  /// (src/analysis/local_refinement.h): the same results bit for bit, in
  /// time and memory that no longer grow fourfold a level. false refines
  /// whole levels (for comparison).
  bool local_levels = true;
  /// Also compute normals and tangents (LimitResult::normals, tangents1,
  /// tangents2).
  bool normals = true;
  /// Boundary interpolation and non-manifold handling, as for refine().
  RefineOptions refine;
};

/// How a vertex's result was obtained.
enum class LimitSource : std::uint8_t {
  closed_form,       ///< the scheme's closed-form limit masks
  generic,           ///< the analysis's eigenvector masks of its configuration
  refined_position,  ///< no mask applied: its refined position (not the limit)
};

/// Limit positions, normals and tangents of a mesh's vertices, and how each
/// was obtained.
struct LimitResult {
  std::vector<Vec3> positions;  ///< one per input vertex
  std::vector<Vec3> normals;    ///< unit normals (empty unless asked; zero where undefined)
  /// With normals asked: the two tangents per vertex (tangent1 x tangent2
  /// along the faces' side; lengths by each formula's convention, for the
  /// generic masks unit masks, at corners the two boundary curves' tangents,
  /// p_first - p and -+(p_last - p)), zero where the vertex kept its refined
  /// position or a corner has no tangent masks. Empty unless asked.
  std::vector<Vec3> tangents1;
  /// The second tangent per vertex, as for `tangents1`.
  std::vector<Vec3> tangents2;
  std::vector<LimitSource> sources;  ///< one per input vertex
  /// Vertices left at their refined position (not the limit).
  Index approximated = 0;
  /// Of `approximated`: vertices with a semi-sharp edge or vertex sharpness
  /// at them or at a neighbour after `levels_refined` steps, which more
  /// steps resolve (ceil(sharpness_left) more make every feature smooth or
  /// infinitely sharp).
  Index semi_sharp = 0;
  /// The largest finite sharpness left after `levels_refined` steps (0: none).
  double sharpness_left = 0.0;
  int levels_refined = 0;  ///< refinement steps taken before the masks
};

/// Why limit_positions() refuses \p scheme whatever the mesh (composite
/// schemes other than the quad split's, such as gcc and midpoint of even
/// degree; the midedge split), or nothing where it covers it.
/// \param scheme The scheme.
/// \return The reason, one sentence; nullopt where limit positions exist.
/// \throws std::bad_alloc if memory runs out.
std::optional<std::string> limit_unavailable(const Scheme& scheme);

/// Limit positions (and normals) of every vertex of \p mesh under \p scheme,
/// by the route `options.route` (see LimitRoute). Vertices that match no
/// mask keep their refined position and are counted in
/// LimitResult::approximated.
/// \param mesh The control mesh.
/// \param scheme The scheme (not one limit_unavailable() refuses).
/// \param options Route, refinement caps, normals, and the refinement rules.
/// \return One position (and, when asked, normal and tangents) per vertex of
///         \p mesh, in its order.
/// \throws InvalidInputError if limit_unavailable() refuses \p scheme, a level or face count in \p options is negative,
///         refinement rejects the mesh or the scheme's parameters (as
///         refine() does: TopologyError, ValidationError, ParameterError), or
///         the analysis cannot read a configuration's matrix.
/// \throws Error if the Schur iteration of an eigenvalue computation does not
///         converge.
/// \throws std::bad_alloc if memory runs out.
LimitResult limit_positions(const PolygonMesh& mesh, const Scheme& scheme, const LimitOptions& options = {});

}  // namespace subdiv
