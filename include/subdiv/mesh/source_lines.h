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

/// The prefix of an error about element i of a file: "path:line: ", "path: "
/// when its line is unknown, nothing without lines or a path.
/// `element_lines` picks the kind of element (&SourceLines::face_lines, ...).
inline std::string where(const SourceLines* lines, const std::vector<std::uint32_t> SourceLines::*element_lines,
                         std::size_t i) {
  if (!lines || lines->path.empty()) return std::string();
  const std::uint32_t line = SourceLines::at((*lines).*element_lines, static_cast<Index>(i));
  return lines->path + (line ? ":" + std::to_string(line) : "") + ": ";
}

}  // namespace subdiv
