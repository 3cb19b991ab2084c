#pragma once
/// \file
/// Where each element of a mesh came from in its file, so that validation
/// and tag errors can name the line.

#include <cstdint>
#include <string>
#include <vector>

#include "subdiv/core/types.h"

namespace subdiv {

/// 1-based line numbers (0 = unknown) per element, filled by text readers.
/// Binary readers leave the vectors empty.
struct SourceLines {
  std::string path;                           ///< the file the mesh was read from; empty if none
  std::vector<std::uint32_t> vertex_lines;    ///< parallel to PolygonMesh::positions
  std::vector<std::uint32_t> face_lines;      ///< one per face
  std::vector<std::uint32_t> crease_lines;    ///< parallel to Tags::creases
  std::vector<std::uint32_t> corner_lines;    ///< parallel to Tags::corners
  std::vector<std::uint32_t> hole_lines;      ///< parallel to Tags::holes
  std::vector<std::uint32_t> polyline_lines;  ///< parallel to PolygonMesh::polylines

  /// The line of element \p i, tolerant of missing data.
  /// \param lines one of the per-element vectors.
  /// \param i the element's index; any value.
  /// \return lines[i], or 0 when \p i is outside the vector.
  static std::uint32_t at(const std::vector<std::uint32_t>& lines, Index i) noexcept {
    return i >= 0 && static_cast<std::size_t>(i) < lines.size() ? lines[static_cast<std::size_t>(i)] : 0;
  }
};

/// The prefix of an error about element \p i of a file: "path:line: ", or
/// "path: " when its line is unknown.
/// \param lines where the mesh's elements came from; may be null.
/// \param element_lines picks the kind of element (&SourceLines::face_lines, ...).
/// \param i the element's index.
/// \pre \p element_lines is not null.
/// \return the prefix, or "" when \p lines is null or has no path.
/// \throws std::bad_alloc if memory runs out.
inline std::string where(const SourceLines* lines, const std::vector<std::uint32_t> SourceLines::*element_lines,
                         std::size_t i) {
  if (!lines || lines->path.empty()) return std::string();
  const std::uint32_t line = SourceLines::at((*lines).*element_lines, static_cast<Index>(i));
  return lines->path + (line ? ":" + std::to_string(line) : "") + ": ";
}

}  // namespace subdiv
