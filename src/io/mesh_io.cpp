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

const char* to_string(FileFormat f) noexcept {
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

namespace {

// `mesh` without the faces tagged as holes (and their face-varying corners);
// the hole tags go with them.
PolygonMesh without_hole_faces(const PolygonMesh& mesh) {
  std::vector<char> hole(static_cast<std::size_t>(mesh.face_count()), 0);
  for (const Index f : mesh.tags.holes)
    if (f >= 0 && f < mesh.face_count()) hole[static_cast<std::size_t>(f)] = 1;
  PolygonMesh out = mesh;
  out.face_offsets = {0};
  out.face_indices.clear();
  out.tags.holes.clear();
  for (FaceVaryingChannel& channel : out.face_varying_channels) channel.indices.clear();
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (hole[static_cast<std::size_t>(f)]) continue;
    out.add_face(mesh.face(f));
    for (std::size_t i = 0; i < mesh.face_varying_channels.size(); ++i) {
      const std::vector<Index>& in = mesh.face_varying_channels[i].indices;
      if (in.size() != mesh.face_indices.size()) continue;  // not per corner: left as the writer finds it
      out.face_varying_channels[i].indices.insert(out.face_varying_channels[i].indices.end(),
                                                   in.begin() + mesh.face_offsets[f], in.begin() + mesh.face_offsets[f + 1]);
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> write_mesh(const PolygonMesh& mesh, const std::filesystem::path& path,
                                    const WriteOptions& options) {
  const FileFormat format = format_from_path(path);
  check_indices(mesh);
  std::vector<std::string> warnings;
  if (format != FileFormat::obj && !mesh.tags.holes.empty() && !options.hole_faces_as_faces) {
    const PolygonMesh kept = without_hole_faces(mesh);
    const Index left_out = mesh.face_count() - kept.face_count();
    warnings.push_back(std::string(to_string(format)) + " has no place for hole tags: " + std::to_string(left_out) +
                       (left_out == 1 ? " hole face" : " hole faces") + " left out");
    std::vector<std::string> rest = write_mesh(kept, path, options);
    warnings.insert(warnings.end(), rest.begin(), rest.end());
    return warnings;
  }
  std::string data;
  switch (format) {
    case FileFormat::obj: data = format_obj(mesh, options, &warnings); break;
    case FileFormat::ply:
      if (!options.write_channels && (!mesh.vertex_channels.empty() || !mesh.face_varying_channels.empty())) {
        PolygonMesh bare = mesh;  // the channels left out, as asked
        bare.vertex_channels.clear();
        bare.face_varying_channels.clear();
        data = format_ply(bare, options.ply_encoding, &warnings, options.threads);
      } else {
        data = format_ply(mesh, options.ply_encoding, &warnings, options.threads);
      }
      break;
    case FileFormat::off: data = format_off(mesh, &warnings, options.threads); break;
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
