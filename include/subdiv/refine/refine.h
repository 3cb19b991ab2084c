#pragma once
/// \file
/// Uniform refinement: the fast path (positions and vertex channels written
/// directly from the masks) and the stencil path (the same masks recorded as
/// tables), level by level. Each level is a complete mesh.

#include <functional>
#include <optional>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/source_lines.h"
#include "subdiv/core/stencil_table.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

/// Which rules apply next to boundaries, creases and corners.
enum class BoundaryRules {
  /// The curve rules on sharp edges and vertices, the smooth rules
  /// elsewhere: OpenSubdiv's rules.
  standard,
  /// Biermann, Levin and Zorin 2000: in addition, the edge points of smooth
  /// edges next to crease, boundary and corner vertices weight their ends
  /// with gamma(theta_k), and concave corners get the flatness modification
  /// (refine/piecewise_smooth.h).
  piecewise_smooth,
};

/// Where the angle alpha of a corner's sectors comes from, for the
/// piecewise-smooth rules, when its tag gives none.
enum class CornerAngles {
  /// pi/2 at convex (and untyped) boundary corners, 3 pi/2 at concave ones.
  fixed,
  /// The angle between the corner's two boundary edges in the control mesh
  /// (2 pi minus it at concave corners).
  measured,
};

/// The rules' name.
/// \param rules the boundary rules.
/// \return "standard" or "piecewise-smooth", a static string.
const char* to_string(BoundaryRules rules) noexcept;
/// The source's name.
/// \param angles where corner angles come from.
/// \return "fixed" or "measured", a static string.
const char* to_string(CornerAngles angles) noexcept;

/// The rule choices: what surface a scheme makes from a mesh. Every command
/// that refines takes the same ones; the analysis reads them too.
struct RuleOptions {
  /// Overrides the mesh's `interpolateboundary` tag; `none` is not supported.
  std::optional<BoundaryInterpolation> boundary;
  /// Refine meshes with non-manifold edges or vertices (and inconsistently
  /// oriented faces), treating those elements as infinitely sharp, as
  /// OpenSubdiv does. Otherwise they are rejected.
  bool allow_non_manifold = false;
  BoundaryRules boundary_rules = BoundaryRules::standard;  ///< the rules next to sharp features
  CornerAngles corner_angles = CornerAngles::fixed;  ///< piecewise-smooth rules: where corner angles come from
  /// The flatness parameter s at concave corners (piecewise-smooth rules):
  /// unset for the default s = 1 - (1/4) / lambda_3, 0 to switch the
  /// modification off, else in (0, 1].
  std::optional<double> flatness;
  /// Overrides the mesh's `creasemethod` tag (uniform or Chaikin creasing of
  /// semi-sharp edges; creasing.h). The refined levels' tags then name this
  /// method, since their crease sharpness was subdivided by it.
  std::optional<CreaseMethod> crease_method;
  /// Overrides the mesh's `smoothtriangles` tag (Catmull-Clark's edge rule
  /// next to triangles, docs/schemes/catmull-clark.md); the refined levels'
  /// tags then name it.
  std::optional<TriangleSubdivision> triangle_subdivision;
  /// Overrides the mesh's face-varying interpolation tag (`t
  /// facevaryinginterpolateboundary`): how face-varying channels are refined
  /// by the schemes that interpolate them smoothly (SchemeTraits::
  /// smooth_face_varying); the refined levels' tags then name it.
  std::optional<FaceVaryingInterpolation> face_varying;
};

/// The boundary interpolation refinement uses on `mesh`: the option's
/// override, else the mesh's `interpolateboundary` tag.
/// \param mesh the mesh (its tags are read).
/// \param options the rule choices.
/// \return the boundary interpolation.
BoundaryInterpolation boundary_of(const PolygonMesh& mesh, const RuleOptions& options) noexcept;
/// The crease method refinement uses on `mesh`: the option's override, else
/// the mesh's `creasemethod` tag.
/// \param mesh the mesh (its tags are read).
/// \param options the rule choices.
/// \return the crease method.
CreaseMethod crease_method_of(const PolygonMesh& mesh, const RuleOptions& options) noexcept;
/// The triangle rule refinement uses on `mesh`: the option's override, else
/// the mesh's `smoothtriangles` tag.
/// \param mesh the mesh (its tags are read).
/// \param options the rule choices.
/// \return the triangle rule.
TriangleSubdivision triangle_subdivision_of(const PolygonMesh& mesh, const RuleOptions& options) noexcept;
/// The face-varying interpolation refinement uses on `mesh`: the option's
/// override, else the mesh's tag.
/// \param mesh the mesh (its tags are read).
/// \param options the rule choices.
/// \return the face-varying interpolation.
FaceVaryingInterpolation face_varying_interpolation_of(const PolygonMesh& mesh, const RuleOptions& options) noexcept;

/// A refinement: the rule choices, and the run controls below, none of
/// which changes the surface made.
struct RefineOptions : RuleOptions {
  int levels = 1;  ///< the uniform steps to take, >= 0
  /// The level the input mesh is at: 0 for a control mesh, k for a mesh
  /// made by k steps of the same scheme. The sqrt3 split alternates its
  /// boundary treatment with the level (sqrt3_step_trisects()), so refining a
  /// level-k mesh by one more step equals refining the control mesh k + 1
  /// steps only when this says k. A hierarchy (hierarchy.h) carries it.
  /// Only a control mesh's non-manifold vertices are sharpened as OpenSubdiv
  /// sharpens its base level's (MeshTopology::is_non_manifold_corner()); the
  /// levels made from it carry that sharpness as corner tags.
  int start_level = 0;
  /// Worker threads; 0 = all available. Results are identical for any count.
  int threads = 0;
  /// Refine the regular faces of schemes that declare a grid rule
  /// (FastPath::regular_grid: Catmull-Clark, bilinear;
  /// FastPath::regular_grid_of: Kobbelt, gcc and midpoint of degree 3, 5 and
  /// 7 with alpha = 1/4, beta = 1/2 at valence 4;
  /// FastPath::regular_triangle_grid and regular_triangle_grid_of: Loop,
  /// Loop-Warren, linear, butterfly, modified-butterfly) as grids,
  /// the remaining levels at once, where the level has only quads (or only
  /// triangles, with at least three levels to go) (refine() and
  /// refine_stencil_table(); docs/refinement.md says where it declines). The
  /// result is the same mesh, numbering, tags and face-varying values
  /// included, with positions, vertex channels and stencil weights equal up
  /// to rounding; false: the masks everywhere, level by level.
  bool regular_grids = true;
  /// Called after each level with its number counted from this call
  /// (1-based) and the level's mesh.
  /// Where the engine takes two steps at once (Scheme::two_steps: 4-8 on a
  /// closed mesh without face-varying channels) the level between them is
  /// never made, and only the second is reported; where the grid path
  /// (regular_grids) takes the remaining levels, only the last is.
  std::function<void(int level, const PolygonMesh& mesh)> on_level;
};

/// Checks that `mesh` can be refined with `scheme` under `options`; the
/// message names the offending element (and, with `lines`, its file and
/// line). Every refinement entry point runs these checks first.
/// \param mesh the mesh to refine.
/// \param scheme the scheme.
/// \param options the rule choices and run controls.
/// \param lines where given, the source lines that errors name.
/// \throws ParameterError if the scheme's parameters are out of range
///   (check_parameters()).
/// \throws ValidationError if the mesh is not valid (bad indices; non-manifold
///   or inconsistently oriented elements unless options.allow_non_manifold).
/// \throws InvalidInputError for negative options.levels or
///   options.start_level, boundary interpolation `none`, malformed face
///   arrays, a tag or option the scheme has no rules for (schemes with a
///   non-primal split and composite schemes: piecewise-smooth rules,
///   non-manifold input, holes, creases and corners, except that sqrt3 takes
///   corners and quasi 4-8 creases and corners), a boundary on a scheme that
///   needs a closed mesh, faces other than the scheme's
///   (triangles, quads), or two triangles on the same three vertices (the
///   triangle, sqrt3 and bisection splits, unless options.allow_non_manifold).
/// \throws std::bad_alloc if memory runs out.
void check_refinable(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                     const SourceLines* lines = nullptr);

/// The mesh after options.levels uniform steps: positions and every vertex
/// channel through the scheme's masks, face-varying channels as
/// face_varying_interpolation_of() says for the schemes with
/// SchemeTraits::smooth_face_varying (linearly within faces otherwise), tags
/// propagated. The mesh's hierarchical edits (hierarchical_edits.h) are
/// applied to each level as it is made where applies_hierarchical_edits()
/// says so and options.start_level is 0; refined levels drop the edit tags.
/// Validates the input first (check_refinable), with
/// `lines` naming the file and lines in its errors. Exceptions thrown by
/// options.on_level propagate.
/// \param mesh the mesh to refine, at level options.start_level.
/// \param scheme the scheme.
/// \param options the rule choices and run controls.
/// \param lines where given, the source lines that errors name.
/// \return the refined mesh.
/// \throws InvalidInputError, ParameterError or ValidationError as
///   check_refinable() does; InvalidInputError also for a malformed
///   hierarchical edit (read_hierarchical_edits()), under the
///   piecewise-smooth rules, for options.flatness outside [0, 1] or a concave
///   corner whose configuration lacks the flatness modification's spectrum,
///   once such a corner is met (check_refinable() does not look at them);
///   and where a position of the result is not finite: finite input near the
///   double range overflows under rules with negative weights (Kobbelt, the
///   Butterfly schemes, large tensions).
/// \throws TopologyError where a split refuses a level (see split_topology():
///   a trisecting sqrt3 step on a triangle with two boundary edges).
/// \throws std::bad_alloc if memory runs out.
PolygonMesh refine(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options = {},
                   const SourceLines* lines = nullptr);

/// The same refinement recorded as stencil tables, one per level made
/// (level i-1 -> level i; one for both of two steps taken at once, see
/// RefineOptions::on_level). `final_level`, if given, receives the last level's mesh with
/// positions evaluated through the tables. The grid path
/// (RefineOptions::regular_grids) is not taken. Tables are linear in the
/// control points: hierarchical edits are not applied.
/// \param mesh the mesh to refine, at level options.start_level.
/// \param scheme the scheme.
/// \param options the rule choices and run controls.
/// \param final_level where given, receives the last level's mesh.
/// \return the tables, coarse first; empty for 0 levels.
/// \throws InvalidInputError, ParameterError, ValidationError or
///   TopologyError as refine() does.
/// \throws std::bad_alloc if memory runs out.
std::vector<StencilTable> refine_stencils(const PolygonMesh& mesh, const Scheme& scheme,
                                          const RefineOptions& options = {}, PolygonMesh* final_level = nullptr);

/// The same refinement as one table, coarse -> level options.levels, built
/// level by level from the composed rows (faster than composing the
/// per-level tables afterwards; the same up to rounding).
/// \param mesh the mesh to refine, at level options.start_level.
/// \param scheme the scheme.
/// \param options the rule choices and run controls.
/// \return the table: a row per vertex of the last level over the vertices
///   of \p mesh; the identity for 0 levels.
/// \throws InvalidInputError, ParameterError, ValidationError or
///   TopologyError as refine() does.
/// \throws std::bad_alloc if memory runs out.
StencilTable refine_stencil_table(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options = {});

/// Composes per-level tables into one: coarse -> last level.
/// \param levels the tables, coarse first, each over the previous one's rows.
/// \return the composed table; an empty table (no rows, no sources) for an
///   empty list.
/// \throws InvalidInputError if a table's source count differs from the
///   previous table's row count.
/// \throws std::bad_alloc if memory runs out.
StencilTable compose(const std::vector<StencilTable>& levels);

}  // namespace subdiv
