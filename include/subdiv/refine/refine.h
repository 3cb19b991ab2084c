#pragma once
// Uniform refinement: the fast path (positions and vertex channels written
// directly from the masks) and the stencil path (the same masks recorded as
// tables), level by level. Each level is a complete mesh.

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

const char* to_string(BoundaryRules);
const char* to_string(CornerAngles);

/// The rule choices: what surface a scheme makes from a mesh. Every command
/// that refines takes the same ones; the analysis reads them too.
struct RuleOptions {
  /// Overrides the mesh's `interpolateboundary` tag; `none` is not supported.
  std::optional<BoundaryInterpolation> boundary;
  /// Refine meshes with non-manifold edges or vertices (and inconsistently
  /// oriented faces), treating those elements as infinitely sharp, as
  /// OpenSubdiv does. Otherwise they are rejected.
  bool allow_non_manifold = false;
  BoundaryRules boundary_rules = BoundaryRules::standard;
  CornerAngles corner_angles = CornerAngles::fixed;
  /// The flatness parameter s at concave corners (piecewise-smooth rules):
  /// unset for the default s = 1 - (1/4) / lambda_3, 0 to switch the
  /// modification off.
  std::optional<double> flatness;
  /// Overrides the mesh's `creasemethod` tag (uniform or Chaikin creasing of
  /// semi-sharp edges; creasing.h). The refined levels' tags then name this
  /// method, since their crease sharpness was subdivided by it.
  std::optional<CreaseMethod> crease_method;
};

/// The boundary interpolation refinement uses on `mesh`: the option's
/// override, else the mesh's `interpolateboundary` tag.
BoundaryInterpolation boundary_of(const PolygonMesh& mesh, const RuleOptions& options);
/// The crease method refinement uses on `mesh`: the option's override, else
/// the mesh's `creasemethod` tag.
CreaseMethod crease_method_of(const PolygonMesh& mesh, const RuleOptions& options);

/// A refinement: the rule choices, and the run controls below, none of
/// which changes the surface made.
struct RefineOptions : RuleOptions {
  int levels = 1;
  /// The level the input mesh is at: 0 for a control mesh, k for a mesh
  /// made by k steps of the same scheme. The sqrt3 split alternates its
  /// boundary treatment with the level (sqrt3_step_trisects()), so refining a
  /// level-k mesh by one more step equals refining the control mesh k + 1
  /// steps only when this says k. A hierarchy (hierarchy.h) carries it.
  int start_level = 0;
  /// Worker threads; 0 = all available. Results are identical for any count.
  int threads = 0;
  /// Refine the regular faces of schemes that declare a grid rule
  /// (FastPath::regular_grid: Catmull-Clark, bilinear;
  /// FastPath::regular_triangle_grid: Loop, Loop-Warren, linear) as grids,
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

/// Throws (ValidationError, InvalidInputError) unless `mesh` can be refined
/// with `scheme` under `options`; the message names the offending element.
void check_refinable(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                     const SourceLines* lines = nullptr);

/// The mesh after options.levels uniform steps: positions and every vertex
/// channel through the scheme's masks, face-varying channels linearly within
/// faces, tags propagated. Validates the input first (check_refinable), with
/// `lines` naming the file and lines in its errors.
PolygonMesh refine(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options = {},
                   const SourceLines* lines = nullptr);

/// The same refinement recorded as stencil tables, one per level made
/// (level i-1 -> level i; one for both of two steps taken at once, see
/// RefineOptions::on_level). `final_level`, if given, receives the last level's mesh with
/// positions evaluated through the tables.
std::vector<StencilTable> refine_stencils(const PolygonMesh& mesh, const Scheme& scheme,
                                          const RefineOptions& options = {}, PolygonMesh* final_level = nullptr);

/// The same refinement as one table, coarse -> level options.levels, built
/// level by level from the composed rows (faster than composing the
/// per-level tables afterwards; the same up to rounding).
StencilTable refine_stencil_table(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options = {});

/// Composes per-level tables into one: coarse -> last level.
StencilTable compose(const std::vector<StencilTable>& levels);

}  // namespace subdiv
