#include "subdiv/io/mesh_io.h"

#include <algorithm>
#include <cctype>

#include "subdiv/io/file_io.h"
#include "subdiv/core/error.h"
#include "subdiv/io/obj.h"
#include "subdiv/io/off.h"
#include "subdiv/io/ply.h"

namespace subdiv {

FileFormat format_from_path(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") return FileFormat::obj;
  if (ext == ".ply") return FileFormat::ply;
  if (ext == ".off") return FileFormat::off;
  throw InvalidInputError(path.string() + ": unknown mesh format '" + ext +
                          "' (expected .obj, .ply or .off)");
}

const char* to_string(FileFormat f) {
  switch (f) {
    case FileFormat::obj: return "OBJ";
    case FileFormat::ply: return "PLY";
    case FileFormat::off: return "OFF";
  }
  return "?";
}

MeshFile read_mesh(const std::filesystem::path& path) {
  const FileFormat format = format_from_path(path);
  const std::string bytes = read_file(path);
  switch (format) {
    case FileFormat::obj: return parse_obj(bytes, path.string());
    case FileFormat::ply: return parse_ply(bytes, path.string());
    case FileFormat::off: return parse_off(bytes, path.string());
  }
  throw InvalidInputError(path.string() + ": unknown mesh format");
}

std::vector<std::string> write_mesh(const PolygonMesh& mesh, const std::filesystem::path& path,
                                    const WriteOptions& options) {
  const FileFormat format = format_from_path(path);
  check_indices(mesh);
  std::vector<std::string> warnings;
  std::string data;
  switch (format) {
    case FileFormat::obj: data = format_obj(mesh, options, &warnings); break;
    case FileFormat::ply: data = format_ply(mesh, options.ply_encoding, &warnings); break;
    case FileFormat::off: data = format_off(mesh, &warnings); break;
  }
  if (format != FileFormat::obj && !mesh.tags.empty() && options.write_tags)
    warnings.push_back(std::string(to_string(format)) + " has no place for tags (creases, corners, holes): not written");
  if (format != FileFormat::obj && !mesh.polylines.empty())
    warnings.push_back(std::string(to_string(format)) + " has no place for polylines (OBJ 'l' lines): " +
                       std::to_string(mesh.polylines.size()) + " not written");
  write_file_atomically(path, data);
  return warnings;
}

}  // namespace subdiv
