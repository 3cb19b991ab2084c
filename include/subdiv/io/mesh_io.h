#pragma once
// Reading and writing meshes: OBJ (with OpenSubdiv's tag lines), PLY (ASCII
// and binary, both endiannesses) and OFF. The format follows the extension.

#include <filesystem>
#include <string>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/source_lines.h"

namespace subdiv {

enum class FileFormat { obj, ply, off };

/// The format named by the path's extension (case-insensitive); throws
/// InvalidInputError for any other extension.
FileFormat format_from_path(const std::filesystem::path& path);
const char* to_string(FileFormat);

/// What a reader returns: the mesh, where its elements came from, and notes
/// about content that was read but not kept (dropped channels, unknown
/// keywords).
struct MeshFile {
  PolygonMesh mesh;
  SourceLines lines;
  std::vector<std::string> warnings;
};

/// Reads a mesh. Throws IoError when the file cannot be read and ParseError
/// (naming file and line) when its contents are malformed: bad numbers,
/// truncation, zero or out-of-range indices, impossible header counts. A
/// parsed mesh may still be invalid for subdivision: run validate() on it.
MeshFile read_mesh(const std::filesystem::path& path);

enum class PlyEncoding { binary_little_endian, binary_big_endian, ascii };

struct WriteOptions {
  PlyEncoding ply_encoding = PlyEncoding::binary_little_endian;
  bool write_tags = true;      ///< OBJ tag lines
  bool write_channels = true;  ///< UVs, normals, colours where the format has a place for them
  /// PLY and OFF have no place for hole tags: faces tagged as holes are left
  /// out (they are not part of the surface), with a note, unless this asks
  /// to write them as ordinary faces. OBJ keeps them, with their tags.
  bool hole_faces_as_faces = false;
  /// Worker threads formatting text (OBJ, ASCII PLY, OFF); 0: all cores.
  /// The bytes written are the same for every count.
  int threads = 0;
};

/// Writes a mesh to a temporary file next to `path` and renames it into
/// place, so a failure never leaves a truncated file. Returns notes about
/// data the format cannot hold (dropped channels, tags, hole faces,
/// polylines).
std::vector<std::string> write_mesh(const PolygonMesh& mesh, const std::filesystem::path& path,
                                    const WriteOptions& options = {});

}  // namespace subdiv
