#pragma once
// subdiv's extras in a glTF primitive, `extras.subdiv`: what glTF has no
// field for (docs/file-formats.md).
//
//   version       1
//   polygons      the size of each polygon, in order; polygon i is the fan
//                 of its size - 2 triangles, from its first corner
//   vertex_count  the mesh's vertex count
//   vertices      (when face-varying channels split vertices) the mesh
//                 vertex of each glTF vertex
//   channels      [{attribute, name, face_varying}]: the channel each
//                 attribute holds
//   tags          the mesh's tags as OBJ tag lines (`t crease 2/1/0 ...`)

namespace subdiv::gltf_extras {

inline constexpr const char* kKey = "subdiv";
inline constexpr const char* kVersionKey = "version";
inline constexpr int kVersion = 1;
inline constexpr const char* kPolygonsKey = "polygons";
inline constexpr const char* kVertexCountKey = "vertex_count";
inline constexpr const char* kVerticesKey = "vertices";
inline constexpr const char* kChannelsKey = "channels";
inline constexpr const char* kTagsKey = "tags";

}  // namespace subdiv::gltf_extras
