#include "input_mesh.h"

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "output_checks.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/refine/hierarchical_edits.h"

namespace subdiv::cli {

void triangulate_if_asked(const Scheme& scheme, bool triangulate, MeshFile& file) {
  if (!triangulate || !scheme.traits.needs_triangles) return;
  file.mesh = subdiv::triangulate(file.mesh);
  file.lines.face_lines.clear();
  file.lines.hole_lines.clear();
}

void warn_dropped_tags(const std::string& path, const PolygonMesh& mesh, const Scheme* scheme, int levels) {
  const bool edits_apply = scheme && applies_hierarchical_edits(*scheme);
  std::vector<std::pair<std::string, int>> kinds;  // in the file's order
  std::size_t dropped = 0, too_deep = 0;
  for (std::size_t i = 0; i < mesh.tags.other.size(); ++i) {
    const RawTag& t = mesh.tags.other[i];
    if (edits_apply && is_hierarchical_edit(t)) {
      int level = 0;
      try {
        level = hierarchical_edit_level(t, i + 1, mesh);
      } catch (const InvalidInputError& e) {
        throw InvalidInputError(path + ": " + e.what());
      }
      if (level <= levels) continue;
      ++too_deep;
    }
    ++dropped;
    auto it = std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.first == t.name; });
    if (it == kinds.end()) kinds.emplace_back(t.name, 1);
    else ++it->second;
  }
  if (dropped == 0) return;
  std::string list;
  for (const auto& [name, count] : kinds) list += (list.empty() ? "" : ", ") + std::to_string(count) + " " + name;
  const std::string why = too_deep == dropped
                              ? fmt::format("their edits lie below the {} levels made", levels)
                              : "their indices name the input's faces and vertices";
  warnf("subdiv: warning: %s: %zu tags not applied dropped from the refined mesh (%s): %s\n", path.c_str(), dropped,
        list.c_str(), why.c_str());
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
