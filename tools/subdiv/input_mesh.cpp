#include "input_mesh.h"

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

#include "output_checks.h"
#include "subdiv/mesh/triangulate.h"

namespace subdiv::cli {

void triangulate_if_asked(const Scheme& scheme, bool triangulate, MeshFile& file) {
  if (!triangulate || !scheme.traits.needs_triangles) return;
  file.mesh = subdiv::triangulate(file.mesh);
  file.lines.face_lines.clear();
  file.lines.hole_lines.clear();
}

void warn_dropped_tags(const std::string& path, const Tags& tags) {
  if (tags.other.empty()) return;
  std::vector<std::pair<std::string, int>> kinds;  // in the file's order
  for (const RawTag& t : tags.other) {
    auto it = std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.first == t.name; });
    if (it == kinds.end()) kinds.emplace_back(t.name, 1);
    else ++it->second;
  }
  std::string list;
  for (const auto& [name, count] : kinds) list += (list.empty() ? "" : ", ") + std::to_string(count) + " " + name;
  warnf(
               "subdiv: warning: %s: %zu tags not interpreted dropped from the refined mesh (%s): their indices name "
               "the input's faces and vertices\n",
               path.c_str(), tags.other.size(), list.c_str());
}

void drop_input_normals(const std::string& path, PolygonMesh& mesh) {
  const auto is_normal = [](const auto& channel) { return channel.name == "normal"; };
  const std::size_t dropped = std::erase_if(mesh.vertex_channels, is_normal) +
                              std::erase_if(mesh.face_varying_channels, is_normal);
  if (dropped == 0) return;
  warnf(
               "subdiv: warning: %s: input normals dropped: refinement would interpolate them as data, not follow "
               "the refined surface ('subdiv limit --normals' writes the limit surface's)\n",
               path.c_str());
}

}  // namespace subdiv::cli
