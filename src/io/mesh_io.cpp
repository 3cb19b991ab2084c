#include "subdiv/io/mesh_io.h"

#include <algorithm>
#include <cctype>

#include "subdiv/io/file_io.h"
#include "subdiv/core/error.h"
#include "subdiv/io/gltf.h"
#include "subdiv/io/obj.h"
#include "subdiv/io/off.h"
#include "subdiv/io/ply.h"
#include "subdiv/io/stl.h"

namespace subdiv {

FileFormat format_from_path(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") return FileFormat::obj;
  if (ext == ".ply") return FileFormat::ply;
  if (ext == ".off") return FileFormat::off;
  if (ext == ".gltf") return FileFormat::gltf;
  if (ext == ".glb") return FileFormat::glb;
  if (ext == ".stl") return FileFormat::stl;
  throw InvalidInputError(path.string() + ": unknown mesh format '" + ext +
                          "' (expected .obj, .ply, .off, .gltf, .glb or .stl)");
}

const char* to_string(FileFormat f) noexcept {
  switch (f) {
    case FileFormat::obj: return "OBJ";
    case FileFormat::ply: return "PLY";
    case FileFormat::off: return "OFF";
    case FileFormat::gltf: return "glTF";
    case FileFormat::glb: return "GLB";
    case FileFormat::stl: return "STL";
  }
  return "?";
}

MeshFile read_mesh(const std::filesystem::path& path, const ReadOptions& options) {
  const FileFormat format = format_from_path(path);
  const std::string bytes = read_file(path);
  switch (format) {
    case FileFormat::obj: return parse_obj(bytes, path.string());
    case FileFormat::ply: return parse_ply(bytes, path.string());
    case FileFormat::off: return parse_off(bytes, path.string());
    case FileFormat::gltf: return parse_gltf(bytes, path.string(), false, options);
    case FileFormat::glb: return parse_gltf(bytes, path.string(), true, options);
    case FileFormat::stl: return parse_stl(bytes, path.string(), options);
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
  const bool keeps_tags = format == FileFormat::obj || format == FileFormat::gltf || format == FileFormat::glb;
  if (!keeps_tags && !mesh.tags.holes.empty() && !options.hole_faces_as_faces) {
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
    case FileFormat::gltf:
    case FileFormat::glb:
      if (!options.write_tags || !options.write_channels) {
        PolygonMesh bare = mesh;  // what was asked to be left out, left out
        if (!options.write_tags) bare.tags = {};
        if (!options.write_channels) {
          bare.vertex_channels.clear();
          bare.face_varying_channels.clear();
        }
        data = format_gltf(bare, format == FileFormat::glb, &warnings);
      } else {
        data = format_gltf(mesh, format == FileFormat::glb, &warnings);
      }
      break;
    case FileFormat::stl: data = format_stl(mesh, options.stl_encoding, &warnings); break;
  }
  if (!keeps_tags && !mesh.tags.empty() && options.write_tags)
    warnings.push_back(std::string(to_string(format)) + " has no place for tags (creases, corners, holes): not written");
  if (format != FileFormat::obj && !mesh.polylines.empty())
    warnings.push_back(std::string(to_string(format)) + " has no place for polylines (OBJ 'l' lines): " +
                       std::to_string(mesh.polylines.size()) + " not written");
  write_file_atomically(path, data);
  return warnings;
}

}  // namespace subdiv
