#include "subdiv/mesh/tags.h"

namespace subdiv {

const char* to_string(BoundaryInterpolation b) noexcept {
  switch (b) {
    case BoundaryInterpolation::none: return "none";
    case BoundaryInterpolation::edge_only: return "edge-only";
    case BoundaryInterpolation::edge_and_corner: return "edge-and-corner";
  }
  return "?";
}

const char* to_string(FaceVaryingInterpolation f) noexcept {
  switch (f) {
    case FaceVaryingInterpolation::none: return "none";
    case FaceVaryingInterpolation::corners_only: return "corners-only";
    case FaceVaryingInterpolation::corners_plus1: return "corners-plus1";
    case FaceVaryingInterpolation::corners_plus2: return "corners-plus2";
    case FaceVaryingInterpolation::boundaries: return "boundaries";
    case FaceVaryingInterpolation::all: return "all";
  }
  return "?";
}

const char* to_string(CreaseMethod c) noexcept {
  return c == CreaseMethod::uniform ? "uniform" : "chaikin";
}

std::optional<CreaseMethod> crease_method_named(std::string_view name) noexcept {
  for (const CreaseMethod c : {CreaseMethod::uniform, CreaseMethod::chaikin})
    if (name == to_string(c)) return c;
  return std::nullopt;
}

std::vector<std::string> crease_method_names() {
  return {to_string(CreaseMethod::uniform), to_string(CreaseMethod::chaikin)};
}

const char* to_string(TriangleSubdivision t) noexcept {
  return t == TriangleSubdivision::catmark ? "catmark" : "smooth";
}

const char* to_string(CornerType t) noexcept {
  switch (t) {
    case CornerType::unspecified: return "unspecified";
    case CornerType::convex: return "convex";
    case CornerType::concave: return "concave";
  }
  return "?";
}

}  // namespace subdiv
