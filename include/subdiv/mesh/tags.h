#pragma once
/// \file
/// Sharpness tags and subdivision options attached to a mesh, as the survey
/// (Zorin, section 3.2) and OpenSubdiv (Sdc::Options, crease/corner/hole tags)
/// use them.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "subdiv/core/types.h"

namespace subdiv {

/// A tagged edge. sharpness >= kInfiniteSharpness is an infinitely sharp
/// crease; 0 < sharpness < kInfiniteSharpness is semi-sharp (fractional).
struct CreaseTag {
  Index v0 = kInvalidIndex;               ///< one end of the edge (a vertex index)
  Index v1 = kInvalidIndex;               ///< the other end; the order of v0 and v1 does not matter
  double sharpness = kInfiniteSharpness;  ///< finite and >= 0 in a valid tag
  /// Member-wise equality.
  /// \param a first tag.
  /// \param b second tag.
  /// \return whether the vertices (in the same order) and sharpness are equal.
  friend bool operator==(const CreaseTag& a, const CreaseTag& b) = default;
};

/// A crease or corner sharpness one level down (OpenSubdiv's uniform rule,
/// Sdc::Crease::SubdivideUniformSharpness): infinite stays infinite, a
/// semi-sharp one loses 1, down to 0 (smooth).
/// \param s the sharpness at this level.
/// \return the sharpness at the next level: \p s if s >= kInfiniteSharpness,
///         else max(s - 1, 0).
inline double subdivide_sharpness(double s) noexcept {
  if (s >= kInfiniteSharpness) return s;
  return s > 1.0 ? s - 1.0 : 0.0;
}

/// Whether a corner's sector is convex (angle < pi) or concave (angle > pi).
/// Unspecified leaves the choice to the scheme's rules (OpenSubdiv semantics).
enum class CornerType {
  unspecified,  ///< the scheme's rules decide
  convex,       ///< the sector's angle is below pi
  concave,      ///< the sector's angle is above pi
};

/// A tagged vertex. The sharpness follows OpenSubdiv (infinite = a corner the
/// limit surface interpolates); type and angle feed the piecewise-smooth
/// corner rules (Biermann, Levin and Zorin 2000).
struct CornerTag {
  Index vertex = kInvalidIndex;               ///< the tagged vertex
  double sharpness = kInfiniteSharpness;      ///< finite and >= 0 in a valid tag
  CornerType type = CornerType::unspecified;  ///< convex or concave sector, or left to the rules
  std::optional<double> angle;  ///< radians, in (0, 2 pi)
  /// Member-wise equality.
  /// \param a first tag.
  /// \param b second tag.
  /// \return whether every member is equal.
  friend bool operator==(const CornerTag& a, const CornerTag& b) = default;
};

/// OpenSubdiv's vertex boundary interpolation (Sdc::Options::VtxBoundaryInterpolation).
enum class BoundaryInterpolation {
  none,             ///< no boundary interpolation (VTX_BOUNDARY_NONE); refinement rejects it
  edge_only,        ///< boundary edges are infinitely sharp creases (VTX_BOUNDARY_EDGE_ONLY)
  edge_and_corner,  ///< also, boundary vertices with one face are infinitely sharp corners (VTX_BOUNDARY_EDGE_AND_CORNER)
};

/// OpenSubdiv's face-varying linear interpolation (Sdc::Options::FVarLinearInterpolation).
enum class FaceVaryingInterpolation {
  none,           ///< smooth everywhere (FVAR_LINEAR_NONE)
  corners_only,   ///< linear at corners only (FVAR_LINEAR_CORNERS_ONLY)
  corners_plus1,  ///< corners, plus junctions of three or more regions (FVAR_LINEAR_CORNERS_PLUS1)
  corners_plus2,  ///< corners_plus1, plus sharpened darts and concave corners (FVAR_LINEAR_CORNERS_PLUS2)
  boundaries,     ///< linear along every face-varying boundary (FVAR_LINEAR_BOUNDARIES)
  all,            ///< linear everywhere (FVAR_LINEAR_ALL)
};

/// Every FaceVaryingInterpolation, in declaration order.
inline constexpr FaceVaryingInterpolation kFaceVaryingInterpolations[] = {
    FaceVaryingInterpolation::none,          FaceVaryingInterpolation::corners_only,
    FaceVaryingInterpolation::corners_plus1, FaceVaryingInterpolation::corners_plus2,
    FaceVaryingInterpolation::boundaries,    FaceVaryingInterpolation::all,
};

/// OpenSubdiv's creasing method for semi-sharp creases.
enum class CreaseMethod {
  uniform,  ///< every level subtracts 1 from the sharpness (CREASE_UNIFORM)
  chaikin,  ///< Chaikin's rule averages sharpness along the crease (CREASE_CHAIKIN)
};

/// OpenSubdiv's Catmull-Clark triangle rule.
enum class TriangleSubdivision {
  catmark,  ///< Catmull-Clark's own rule on triangles too (TRI_SUB_CATMARK)
  smooth,   ///< the modified, smoother weights for triangles (TRI_SUB_SMOOTH)
};

/// A tag line kept verbatim: hierarchical edits (read by
/// read_hierarchical_edits() and applied by refinement where the scheme
/// takes them) and tags no module interprets. Written back unchanged with the
/// same mesh (`subdiv convert`); refinement drops them from the refined
/// levels, whose faces and vertices their indices do not name.
struct RawTag {
  std::string name;                  ///< the tag's name (`vertexedit`, ...)
  std::vector<long long> ints;       ///< its integer arguments, in order
  std::vector<double> floats;        ///< its floating-point arguments, in order
  std::vector<std::string> strings;  ///< its string arguments, in order
  /// Member-wise equality.
  /// \param a first tag.
  /// \param b second tag.
  /// \return whether every member is equal.
  friend bool operator==(const RawTag& a, const RawTag& b) = default;
};

/// Everything a mesh carries besides geometry and data channels: sharpness
/// tags, holes, subdivision options and uninterpreted tag lines.
struct Tags {
  std::vector<CreaseTag> creases;  ///< tagged edges
  std::vector<CornerTag> corners;  ///< tagged vertices
  std::vector<Index> holes;  ///< face indices
  /// How boundary vertices and edges are interpolated (refinement rejects
  /// BoundaryInterpolation::none).
  BoundaryInterpolation boundary_interpolation = BoundaryInterpolation::edge_and_corner;
  /// OpenSubdiv's face-varying interpolation option: how the schemes with
  /// SchemeTraits::smooth_face_varying refine face-varying channels (the
  /// others refine them linearly); kept and written back.
  FaceVaryingInterpolation face_varying_interpolation = FaceVaryingInterpolation::all;
  /// How semi-sharp creases lose sharpness from level to level.
  CreaseMethod crease_method = CreaseMethod::uniform;
  /// OpenSubdiv's Catmull-Clark triangle rule option; kept and written back,
  /// not read by the refinement rules.
  TriangleSubdivision triangle_subdivision = TriangleSubdivision::catmark;
  /// OpenSubdiv's face-varying "propagate corners" option; kept and written
  /// back, not read by refinement.
  bool face_varying_propagate_corners = false;
  /// True for each option that a file or the user set explicitly, so writers
  /// only emit what was given.
  bool boundary_interpolation_set = false;
  bool face_varying_interpolation_set = false;          ///< face_varying_interpolation was given explicitly
  bool crease_method_set = false;                       ///< crease_method was given explicitly
  bool triangle_subdivision_set = false;                ///< triangle_subdivision was given explicitly
  bool face_varying_propagate_corners_set = false;      ///< face_varying_propagate_corners was given explicitly
  std::vector<RawTag> other;  ///< tag lines kept verbatim, in file order

  /// Whether there is nothing to write: no tags and no option set explicitly.
  /// Option values that were not set (the defaults) do not count.
  /// \return true when there are no creases, corners, holes or raw tags and
  ///         no `*_set` flag is true.
  bool empty() const noexcept {
    return creases.empty() && corners.empty() && holes.empty() && other.empty() &&
           !boundary_interpolation_set && !face_varying_interpolation_set &&
           !crease_method_set && !triangle_subdivision_set && !face_varying_propagate_corners_set;
  }
  /// Member-wise equality (tag order matters).
  /// \param a first set of tags.
  /// \param b second set of tags.
  /// \return whether every member is equal.
  friend bool operator==(const Tags& a, const Tags& b) = default;
};

/// The option's name for messages: "none", "edge-only" or "edge-and-corner".
/// \param b the option.
/// \return a static string; "?" for a value outside the enumeration.
const char* to_string(BoundaryInterpolation b) noexcept;
/// The option's name for messages: "none", "corners-only", "corners-plus1",
/// "corners-plus2", "boundaries" or "all".
/// \param f the option.
/// \return a static string; "?" for a value outside the enumeration.
const char* to_string(FaceVaryingInterpolation f) noexcept;
/// The method's name: "uniform" or "chaikin".
/// \param c the method.
/// \return a static string.
const char* to_string(CreaseMethod c) noexcept;
/// The crease method with this name (to_string's, case-sensitive).
/// \param name the name to look up.
/// \return the method, or nullopt when no method has that name.
std::optional<CreaseMethod> crease_method_named(std::string_view name) noexcept;
/// Every crease method's name, in declaration order.
/// \return {"uniform", "chaikin"}.
/// \throws std::bad_alloc if memory runs out.
std::vector<std::string> crease_method_names();
/// The rule's name: "catmark" or "smooth".
/// \param t the rule.
/// \return a static string.
const char* to_string(TriangleSubdivision t) noexcept;
/// The corner type's name: "unspecified", "convex" or "concave".
/// \param t the corner type.
/// \return a static string; "?" for a value outside the enumeration.
const char* to_string(CornerType t) noexcept;

}  // namespace subdiv
