#pragma once
// Where each element of a mesh came from in its file, so that validation
// and tag errors can name the line.

#include <cstdint>
#include <string>
#include <vector>

#include "subdiv/core/types.h"

namespace subdiv {

/// 1-based line numbers (0 = unknown) per element, filled by text readers.
/// Binary readers leave the vectors empty.
struct SourceLines {
  std::string path;
  std::vector<std::uint32_t> vertex_lines;
  std::vector<std::uint32_t> face_lines;
  std::vector<std::uint32_t> crease_lines;    ///< parallel to Tags::creases
  std::vector<std::uint32_t> corner_lines;    ///< parallel to Tags::corners
  std::vector<std::uint32_t> hole_lines;      ///< parallel to Tags::holes
  std::vector<std::uint32_t> polyline_lines;  ///< parallel to PolygonMesh::polylines

  static std::uint32_t at(const std::vector<std::uint32_t>& lines, Index i) {
    return i >= 0 && static_cast<std::size_t>(i) < lines.size() ? lines[static_cast<std::size_t>(i)] : 0;
  }
};

}  // namespace subdiv
