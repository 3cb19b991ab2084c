#pragma once
/// \file
/// glTF 2.0, as JSON (`.gltf`) or in the binary container (`.glb`), through
/// TinyGLTF. glTF stores triangles over vertices split wherever an attribute
/// differs (UV seams); subdiv keeps what glTF has no field for — the
/// polygons, the vertices before splitting, and the tags — in the
/// primitive's `extras.subdiv` (docs/file-formats.md), and reads it back
/// from there.

#include <string>
#include <string_view>
#include <vector>

#include "subdiv/io/mesh_io.h"

namespace subdiv {

/// Parses glTF 2.0. Every triangle primitive (modes TRIANGLES,
/// TRIANGLE_STRIP and TRIANGLE_FAN) of the default scene's nodes is read,
/// placed by its node's transform; all of them form one mesh. Points and
/// lines are left out with a note. When the file holds one primitive with
/// subdiv's extras, the polygons, vertices and tags come from them; otherwise
/// vertices are welded by position (ReadOptions::weld_tolerance), faces are
/// triangles (with a note that quad schemes need the polygons of an OBJ, PLY
/// or OFF file), and TEXCOORD_0, COLOR_0 and NORMAL become face-varying
/// channels "uv", "color" and "normal".
/// \param bytes the file's contents.
/// \param path names the source in errors; its directory resolves buffers
///        stored in separate files.
/// \param binary whether \p bytes is a `.glb` container.
/// \param options the welding tolerance.
/// \return the mesh, no source lines, and notes.
/// \throws ParseError naming \p path when the file is not glTF 2.0 or an
///         accessor, buffer view or index is out of range or malformed.
/// \throws std::bad_alloc if memory runs out.
MeshFile parse_gltf(std::string_view bytes, const std::string& path, bool binary, const ReadOptions& options = {});

/// Serialises a mesh as glTF 2.0 with its buffer embedded: one scene, one
/// node, one mesh, one triangle primitive (polygons split into fans from
/// their first corner). Positions are float32 with their bounds; vertex and
/// face-varying channels become attributes (TEXCOORD_0 for a two-component
/// "uv", COLOR_0 for a three- or four-component "color", NORMAL for a
/// three-component "normal", `_NAME` for any other of one to four
/// components). The polygons, the original vertices (when face-varying
/// channels split them) and the tags go to `extras.subdiv`.
/// \param mesh the mesh to write.
/// \param binary `.glb` when true, `.gltf` JSON (buffer as a data URI) else.
/// \param warnings receives notes: polygons stored as triangles for other
///        programs, channels and polylines not written; may be null.
/// \return the file's bytes.
/// \throws InvalidInputError if the mesh fails check_face_arrays() or is too
///         large for glTF's 32-bit sizes.
/// \throws std::bad_alloc if memory runs out.
std::string format_gltf(const PolygonMesh& mesh, bool binary, std::vector<std::string>* warnings = nullptr);

}  // namespace subdiv
