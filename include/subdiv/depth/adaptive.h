#pragma once
/// \file
/// Adaptive refinement to an accuracy: refine only where control vertices are
/// further than eps from their limit positions, and join the levels without
/// cracks ("A priori computation of the subdivision depth", section 3.1,
/// static and mobile vertices; docs/depth.md, "Adaptive refinement").
///
/// The output is a conforming mesh whose faces are faces of the uniform
/// levels (leaves of the face hierarchy) and, where a leaf meets finer
/// neighbours, a transition triangulation of the leaf. Every output vertex is
/// a vertex of some uniform level, at that level's position: its distance to
/// its limit is exactly what uniform refinement gives there.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "subdiv/depth/depth.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

/// How adaptive_refine() refines.
struct AdaptiveOptions {
  DepthOptions depth;  ///< the refinement rules
  /// Deepest level refined; the refinement stops earlier once every leaf's
  /// corners are within eps. Throws InvalidInputError if that takes more.
  int max_level = 12;  ///< in levels of AdaptiveResult::steps_per_level steps
};

/// Where an output vertex comes from: vertex `index` of uniform level `level`
/// (of AdaptiveResult::steps_per_level refinement steps each).
struct AdaptiveVertexSource {
  int level = 0;    ///< the uniform level (0: the control mesh)
  Index index = 0;  ///< the vertex's index in that level
};

/// The conforming adaptive mesh, where each vertex comes from, and how it
/// compares with uniform refinement.
struct AdaptiveResult {
  PolygonMesh mesh;  ///< conforming; faces of the uniform levels and transition faces
  std::vector<AdaptiveVertexSource> sources;  ///< one per output vertex
  std::vector<double> distances;              ///< each output vertex's distance to its limit
  /// Output vertices whose limit is only approximated (limit_positions()
  /// matched no configuration after four isolation levels): their
  /// `distances` are to that approximation, and eps is not established there.
  Index approximated = 0;
  /// Uniform levels (`steps_per_level` steps each) after which every vertex
  /// is within eps (measured), and the face count there: what adaptive
  /// refinement is compared with.
  int uniform_depth = 0;
  std::int64_t uniform_faces = 0;  ///< faces of the uniform mesh at `uniform_depth`
  int leaves_per_level_max = 0;  ///< deepest level with a leaf face
  std::int64_t transition_faces = 0;  ///< output faces that are not uniform faces
  /// Refinement steps per level of the hierarchy walked:
  /// adaptive_steps_per_level() (2 for 4-8 and the sqrt3 split).
  int steps_per_level = 1;
  /// What eps bounds: every vertex's distance to its limit, or (interpolating
  /// schemes, whose vertices are all on the limit) the faces' linear surface
  /// against the limit, through their next level's displacements.
  DepthMeasure measure = DepthMeasure::vertex_to_limit;
  /// Interpolating schemes: the largest distance of a leaf's next-level
  /// vertices (its edge points and face point) from its linear surface, at
  /// most `displacement_threshold`; 0 otherwise.
  double largest_displacement = 0.0;
  /// Interpolating schemes: eps (1 - r), r the depth bound's rate (the
  /// displacements still to come then add up to at most eps); 0 otherwise.
  double displacement_threshold = 0.0;
};

/// Loop (the paper's four face cases, with a leaf met by finer neighbours
/// split into 2, 3 or 4 triangles) and Catmull-Clark (a leaf met by finer
/// neighbours is fanned from its face point: quads at corners whose two
/// edges are split, triangles elsewhere). Any scheme in the registry works
/// the same way by its split; the sqrt3 split in levels of two steps (its
/// faces nest 1-to-9, a leaf met by finer neighbours is fanned from its
/// centre); 4-8 by its two-step quad split (the same surface), in levels of
/// two steps; the sqrt2 split's interpolating scheme likewise (its faces nest
/// 1-to-4). The dual split (Doo-Sabin; gcc and midpoint of even degree) and
/// midedge (in levels of two steps, a dual split) on closed manifold meshes:
/// a face one level down exists where the faces it is made from are split,
/// joined by half E-faces and fan polygons.
/// Interpolating schemes (the Butterflies, Kobbelt's, interpolatory
/// sqrt3, interpolating sqrt2), whose vertices are all on the limit, split a
/// face while a vertex the next level makes in it lies further than
/// eps (1 - r) from its linear surface, r the depth bound's rate
/// (AdaptiveResult::measure). Throws as refine() does, and for meshes with
/// hole tags (no rule here keeps a hole open). The result carries positions
/// and faces only: no channels and no tags.
/// \param mesh The control mesh.
/// \param scheme The scheme (quad or triangle split; a composite scheme's
///        level split; the sqrt3 split; 4-8).
/// \param eps The accuracy: the largest vertex-to-limit distance allowed at
///        a leaf's corners (mesh units), positive.
/// \param options The refinement rules and the deepest level.
/// \return The conforming mesh with its vertices' sources and distances.
/// \throws InvalidInputError if \p eps is not positive, adaptive_unavailable()
///         gives a reason, the mesh has hole tags, more than
///         `options.max_level` levels are needed, refinement rejects the mesh
///         (as refine() does), limit positions fail (as limit_positions()
///         does), an interpolating scheme's depth bound fails (as
///         depth_bound() does), an open sqrt3 mesh starts at an odd level,
///         or a dual-split mesh is open or not manifold.
/// \throws Error if the Schur iteration of an eigenvalue computation does not
///         converge.
/// \throws std::bad_alloc if memory runs out.
AdaptiveResult adaptive_refine(const PolygonMesh& mesh, const Scheme& scheme, double eps,
                               const AdaptiveOptions& options = {});

/// Refinement steps per level of the hierarchy adaptive_refine() walks: 2
/// for 4-8 (its two-step quad split), the sqrt3 and sqrt2 splits (whose
/// faces nest after two steps) and midedge (whose two steps are a dual
/// split), 1 otherwise.
/// \param scheme The scheme.
/// \return 1 or 2.
int adaptive_steps_per_level(const Scheme& scheme) noexcept;

/// Why adaptive_refine() refuses \p scheme whatever the mesh (schemes
/// without limit positions, approximating schemes of the sqrt2 split other
/// than 4-8), or nothing where it covers it.
/// \param scheme The scheme.
/// \param options The refinement rules the scheme is analysed under.
/// \return The reason, one sentence; nullopt where adaptive refinement applies.
/// \throws InvalidInputError if the analysis of the scheme's regular
///         interior configuration fails (see interpolates_with_wide_masks()).
/// \throws Error if the Schur iteration of an eigenvalue computation does not
///         converge.
/// \throws std::bad_alloc if memory runs out.
std::optional<std::string> adaptive_unavailable(const Scheme& scheme, const AdaptiveOptions& options = {});

}  // namespace subdiv
