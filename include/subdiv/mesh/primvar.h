#pragma once
/// \file
/// Data channels ("primvars") that ride along with a mesh and that refinement
/// carries to every level: UVs, colours, normals, anything with N components.

#include <string>
#include <vector>

#include "subdiv/core/types.h"

namespace subdiv {

/// One value of `components` doubles per mesh vertex, interpolated with the
/// same weights as the positions.
struct VertexChannel {
  std::string name;            ///< identifies the channel ("uv", "color", "normal", ...)
  int components = 0;          ///< doubles per value (> 0 in a valid channel)
  std::vector<double> values;  ///< size = vertex_count * components

  /// Number of whole values stored.
  /// \return values.size() / components, or 0 when components <= 0.
  Index value_count() const noexcept {
    return components > 0 ? static_cast<Index>(values.size() / static_cast<std::size_t>(components)) : 0;
  }
};

/// Face-varying data: a pool of values and, for every face corner (parallel to
/// PolygonMesh::face_indices), the index of its value. Corners that meet at a
/// vertex may use different values (UV seams).
struct FaceVaryingChannel {
  std::string name;             ///< identifies the channel ("uv", "normal", ...)
  int components = 0;           ///< doubles per value (> 0 in a valid channel)
  std::vector<double> values;   ///< size = value_count * components
  std::vector<Index> indices;   ///< one per face corner, each in [0, value_count())

  /// Number of whole values in the pool.
  /// \return values.size() / components, or 0 when components <= 0.
  Index value_count() const noexcept {
    return components > 0 ? static_cast<Index>(values.size() / static_cast<std::size_t>(components)) : 0;
  }
};

}  // namespace subdiv
