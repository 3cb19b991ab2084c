#pragma once
/// \file
/// Reading and writing meshes: OBJ (with OpenSubdiv's tag lines), PLY (ASCII
/// and binary, both endiannesses), OFF, glTF 2.0 (`.gltf` and `.glb`) and STL
/// (ASCII and binary). The format follows the extension.

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
  gltf,  ///< glTF 2.0 as JSON (`.gltf`), buffers embedded or beside it
  glb,   ///< glTF 2.0 binary container (`.glb`)
  stl,   ///< STereoLithography (`.stl`), ASCII or binary: triangles only
};

/// The format named by the path's extension (case-insensitive).
/// \param path the file's path; only its extension is read.
/// \return the format for `.obj`, `.ply`, `.off`, `.gltf`, `.glb` or `.stl`.
/// \throws InvalidInputError for any other extension, or none.
FileFormat format_from_path(const std::filesystem::path& path);
/// The format's name for messages: "OBJ", "PLY", "OFF", "glTF", "GLB" or "STL".
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

/// How read_mesh() reads the formats that store triangle soups or split
/// vertices at attribute seams.
struct ReadOptions {
  /// STL, and glTF files that subdiv did not write: a corner whose position
  /// differs from an earlier vertex's by at most this much in every
  /// coordinate joins that vertex (the earliest such, which keeps its
  /// position). 0 merges equal positions only; a negative value keeps every
  /// file vertex apart (STL: three per triangle).
  double weld_tolerance = 0.0;
};

/// Reads a mesh; the format follows the extension (format_from_path()).
/// A parsed mesh may still be invalid for subdivision: run validate() on it.
/// \param path the file to read.
/// \param options how STL and glTF vertices are welded.
/// \return the mesh, its source lines and the reader's notes.
/// \throws InvalidInputError when the extension names no supported format.
/// \throws IoError when the file cannot be read.
/// \throws ParseError (naming file and line) when its contents are
///         malformed: bad numbers, truncation, zero or out-of-range indices,
///         impossible header counts.
/// \throws std::bad_alloc if memory runs out.
MeshFile read_mesh(const std::filesystem::path& path, const ReadOptions& options = {});

/// How a PLY file stores its elements.
enum class PlyEncoding {
  binary_little_endian,  ///< binary, least significant byte first
  binary_big_endian,     ///< binary, most significant byte first
  ascii,                 ///< text, one element per line
};

/// How an STL file stores its triangles.
enum class StlEncoding {
  binary,  ///< 80-byte header, count, 50 bytes per triangle (float32)
  ascii,   ///< `solid` ... `endsolid` text, positions to full double precision
};

/// What write_mesh() (and format_obj()) write, and how.
struct WriteOptions {
  PlyEncoding ply_encoding = PlyEncoding::binary_little_endian;  ///< PLY only
  StlEncoding stl_encoding = StlEncoding::binary;                ///< STL only
  bool write_tags = true;      ///< OBJ tag lines and glTF's extras (the other formats have no place for tags)
  /// OBJ, PLY and glTF: the channels each has a place for (OBJ: UVs, normals
  /// and colours; PLY: normals, UVs and colours; glTF: one to four
  /// components); false writes none.
  bool write_channels = true;
  /// PLY, OFF and STL have no place for hole tags: faces tagged as holes are
  /// left out (they are not part of the surface), with a note, unless this
  /// asks to write them as ordinary faces. OBJ and glTF keep them, with
  /// their tags.
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
