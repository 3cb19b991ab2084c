#pragma once
/// \file
/// Reading and writing meshes: OBJ (with OpenSubdiv's tag lines), PLY (ASCII
/// and binary, both endiannesses) and OFF. The format follows the extension.

#include <filesystem>
#include <string>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/source_lines.h"

namespace subdiv {

/// The mesh file formats read and written.
enum class FileFormat {
  obj,  ///< Wavefront OBJ (`.obj`), with OpenSubdiv's tag lines
  ply,  ///< Stanford PLY (`.ply`), ASCII or binary
  off,  ///< Object File Format (`.off`), ASCII
};

/// The format named by the path's extension (case-insensitive).
/// \param path the file's path; only its extension is read.
/// \return the format for `.obj`, `.ply` or `.off`.
/// \throws InvalidInputError for any other extension, or none.
FileFormat format_from_path(const std::filesystem::path& path);
/// The format's name for messages: "OBJ", "PLY" or "OFF".
/// \param format the format.
/// \return a static string; "?" for a value outside the enumeration.
const char* to_string(FileFormat format) noexcept;

/// What a reader returns: the mesh, where its elements came from, and notes
/// about content that was read but not kept (dropped channels, unknown
/// keywords).
struct MeshFile {
  PolygonMesh mesh;                   ///< the mesh as read
  SourceLines lines;                  ///< the file's path and each element's line (no lines for binary files)
  std::vector<std::string> warnings;  ///< one line per note, without the file's path
};

/// Reads a mesh; the format follows the extension (format_from_path()).
/// A parsed mesh may still be invalid for subdivision: run validate() on it.
/// \param path the file to read.
/// \return the mesh, its source lines and the reader's notes.
/// \throws InvalidInputError when the extension names no supported format.
/// \throws IoError when the file cannot be read.
/// \throws ParseError (naming file and line) when its contents are
///         malformed: bad numbers, truncation, zero or out-of-range indices,
///         impossible header counts.
/// \throws std::bad_alloc if memory runs out.
MeshFile read_mesh(const std::filesystem::path& path);

/// How a PLY file stores its elements.
enum class PlyEncoding {
  binary_little_endian,  ///< binary, least significant byte first
  binary_big_endian,     ///< binary, most significant byte first
  ascii,                 ///< text, one element per line
};

/// What write_mesh() (and format_obj()) write, and how.
struct WriteOptions {
  PlyEncoding ply_encoding = PlyEncoding::binary_little_endian;  ///< PLY only
  bool write_tags = true;      ///< OBJ tag lines (the other formats have no place for tags)
  /// OBJ and PLY: the channels each has a place for (OBJ: UVs, normals and
  /// colours; PLY: normals, UVs and colours); false writes none.
  bool write_channels = true;
  /// PLY and OFF have no place for hole tags: faces tagged as holes are left
  /// out (they are not part of the surface), with a note, unless this asks
  /// to write them as ordinary faces. OBJ keeps them, with their tags.
  bool hole_faces_as_faces = false;
  /// Worker threads formatting text (OBJ, ASCII PLY, OFF); 0: all cores.
  /// The bytes written are the same for every count.
  int threads = 0;
};

/// Writes a mesh in the format its extension names (format_from_path()),
/// to a temporary file next to \p path renamed into place
/// (write_file_atomically()), so a failure never leaves a truncated file.
/// \param mesh the mesh to write.
/// \param path the file to write; its directory must exist.
/// \param options what to write and how.
/// \return notes about data the format cannot hold (dropped channels, tags,
///         hole faces, polylines), one line each.
/// \throws InvalidInputError when the extension names no supported format,
///         the mesh fails check_indices(), or (OBJ) a raw tag's name or
///         string is empty or holds white space.
/// \throws IoError when the file cannot be written.
/// \throws std::bad_alloc if memory runs out.
std::vector<std::string> write_mesh(const PolygonMesh& mesh, const std::filesystem::path& path,
                                    const WriteOptions& options = {});

}  // namespace subdiv
