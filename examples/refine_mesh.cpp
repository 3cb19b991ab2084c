// Refines a mesh with a scheme chosen by name and writes the result. Creases,
// corners and holes tagged in the file (OBJ `t` lines) are refined by the
// scheme's sharp rules and kept in the output.
//
//   refine_mesh data/meshes/l_shape.obj catmull-clark 2 l_shape2.obj

#include <charconv>
#include <cstdio>
#include <cstring>

#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

int main(int argc, char** argv) {
  int levels = 0;
  if (argc != 5 || std::from_chars(argv[3], argv[3] + std::strlen(argv[3]), levels).ec != std::errc()) {
    std::fprintf(stderr, "usage: refine_mesh MESH SCHEME LEVELS OUTPUT\n");
    return 1;
  }
  const subdiv::Scheme* scheme = subdiv::find_scheme(argv[2]);
  if (scheme == nullptr) {
    std::fprintf(stderr, "unknown scheme '%s' (`subdiv schemes` lists them)\n", argv[2]);
    return 1;
  }
  try {
    const subdiv::MeshFile file = subdiv::read_mesh(argv[1]);  // ParseError names file and line
    subdiv::RefineOptions options;
    options.levels = levels;
    // Validates first: a mesh the scheme cannot take throws, naming the element.
    const subdiv::PolygonMesh refined = subdiv::refine(file.mesh, *scheme, options, &file.lines);
    subdiv::write_mesh(refined, argv[4]);  // temporary file, then rename: never a truncated output
    std::printf("%s: %d faces -> %d faces (%s, %d levels), %zu creases and %zu corners tagged\n", argv[4],
                file.mesh.face_count(), refined.face_count(), argv[2], levels, refined.tags.creases.size(),
                refined.tags.corners.size());
  } catch (const subdiv::Error& e) {
    std::fprintf(stderr, "refine_mesh: %s\n", e.what());
    return 1;
  }
  return 0;
}
