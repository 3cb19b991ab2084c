#pragma once
// Sharpness tags and subdivision options attached to a mesh, as the survey
// (Zorin, section 3.2) and OpenSubdiv (Sdc::Options, crease/corner/hole tags)
// use them.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "subdiv/core/types.h"

namespace subdiv {

/// A tagged edge. sharpness >= kInfiniteSharpness is an infinitely sharp
/// crease; 0 < sharpness < kInfiniteSharpness is semi-sharp (fractional).
struct CreaseTag {
  Index v0 = kInvalidIndex;
  Index v1 = kInvalidIndex;
  double sharpness = kInfiniteSharpness;
  friend bool operator==(const CreaseTag&, const CreaseTag&) = default;
};

/// A crease or corner sharpness one level down (OpenSubdiv's uniform rule,
/// Sdc::Crease::SubdivideUniformSharpness): infinite stays infinite, a
/// semi-sharp one loses 1, down to 0 (smooth).
inline double subdivide_sharpness(double s) {
  if (s >= kInfiniteSharpness) return s;
  return s > 1.0 ? s - 1.0 : 0.0;
}

/// Whether a corner's sector is convex (angle < pi) or concave (angle > pi).
/// Unspecified leaves the choice to the scheme's rules (OpenSubdiv semantics).
enum class CornerType { unspecified, convex, concave };

/// A tagged vertex. The sharpness follows OpenSubdiv (infinite = a corner the
/// limit surface interpolates); type and angle feed the piecewise-smooth
/// corner rules (Biermann, Levin and Zorin 2000).
struct CornerTag {
  Index vertex = kInvalidIndex;
  double sharpness = kInfiniteSharpness;
  CornerType type = CornerType::unspecified;
  std::optional<double> angle;  ///< radians, in (0, 2 pi)
  friend bool operator==(const CornerTag&, const CornerTag&) = default;
};

/// OpenSubdiv's vertex boundary interpolation (Sdc::Options::VtxBoundaryInterpolation).
enum class BoundaryInterpolation { none, edge_only, edge_and_corner };

/// OpenSubdiv's face-varying linear interpolation (Sdc::Options::FVarLinearInterpolation).
enum class FaceVaryingInterpolation {
  none, corners_only, corners_plus1, corners_plus2, boundaries, all
};

/// OpenSubdiv's creasing method for semi-sharp creases.
enum class CreaseMethod { uniform, chaikin };

/// OpenSubdiv's Catmull-Clark triangle rule.
enum class TriangleSubdivision { catmark, smooth };

/// A tag line kept verbatim because no module interprets it yet
/// (hierarchical edits, future extensions). Written back unchanged with the
/// same mesh (`subdiv convert`); refinement drops them from the refined
/// levels, whose faces and vertices their indices do not name.
struct RawTag {
  std::string name;
  std::vector<long long> ints;
  std::vector<double> floats;
  std::vector<std::string> strings;
  friend bool operator==(const RawTag&, const RawTag&) = default;
};

struct Tags {
  std::vector<CreaseTag> creases;
  std::vector<CornerTag> corners;
  std::vector<Index> holes;  ///< face indices
  BoundaryInterpolation boundary_interpolation = BoundaryInterpolation::edge_and_corner;
  FaceVaryingInterpolation face_varying_interpolation = FaceVaryingInterpolation::all;
  CreaseMethod crease_method = CreaseMethod::uniform;
  TriangleSubdivision triangle_subdivision = TriangleSubdivision::catmark;
  bool face_varying_propagate_corners = false;
  /// True for each option that a file or the user set explicitly, so writers
  /// only emit what was given.
  bool boundary_interpolation_set = false;
  bool face_varying_interpolation_set = false;
  bool crease_method_set = false;
  bool triangle_subdivision_set = false;
  bool face_varying_propagate_corners_set = false;
  std::vector<RawTag> other;

  bool empty() const {
    return creases.empty() && corners.empty() && holes.empty() && other.empty() &&
           !boundary_interpolation_set && !face_varying_interpolation_set &&
           !crease_method_set && !triangle_subdivision_set && !face_varying_propagate_corners_set;
  }
  friend bool operator==(const Tags&, const Tags&) = default;
};

const char* to_string(BoundaryInterpolation);
const char* to_string(FaceVaryingInterpolation);
const char* to_string(CreaseMethod);
/// The crease method with this name (to_string's), or nullopt.
std::optional<CreaseMethod> crease_method_named(std::string_view name);
/// Every crease method's name, in declaration order.
std::vector<std::string> crease_method_names();
const char* to_string(TriangleSubdivision);
const char* to_string(CornerType);

}  // namespace subdiv
