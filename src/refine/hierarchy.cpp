#include "subdiv/refine/hierarchy.h"

#include <string>

#include "subdiv/core/error.h"

namespace subdiv {

ChildOrigin origin_of(const SplitMap& map, Index child) {
  if (child < 0 || child >= map.child_vertex_count)
    throw InvalidInputError("child vertex " + std::to_string(child) + " is outside the split's " +
                            std::to_string(map.child_vertex_count) + " vertices");
  using Kind = ChildOrigin::Kind;
  switch (map.rule) {
    case SplitRule::dual:
      if (child < map.edge_points) return {Kind::corner, child - map.corner_points};
      return {Kind::boundary_point, map.boundary_edges[static_cast<std::size_t>((child - map.edge_points) / 2)]};
    case SplitRule::sqrt3:
      if (child >= map.vertex_points) return {Kind::vertex, child - map.vertex_points};
      if (child >= map.edge_points)
        return {Kind::boundary_point, map.boundary_edges[static_cast<std::size_t>((child - map.edge_points) / 2)]};
      return {Kind::face, map.point_face(child - map.face_points)};
    case SplitRule::triangle:
    case SplitRule::midedge:
      // [edge points | vertex points] (the midedge split has no vertex points).
      if (child < map.vertex_points) return {Kind::edge, child - map.edge_points};
      return {Kind::vertex, child - map.vertex_points};
    case SplitRule::quad:
    case SplitRule::sqrt2:
      // [face points | edge points | vertex points] (sqrt2: no edge points).
      if (child < map.edge_points) return {Kind::face, child - map.face_points};
      if (child < map.vertex_points) return {Kind::edge, child - map.edge_points};
      return {Kind::vertex, child - map.vertex_points};
    case SplitRule::identity:
      return {Kind::vertex, child - map.vertex_points};
    case SplitRule::quasi_4_8:
      // [vertex points | split points, one per split edge].
      if (child < map.edge_points) return {Kind::vertex, child};
      return {Kind::edge, map.split_edges[static_cast<std::size_t>(child - map.edge_points)]};
  }
  throw InvalidInputError(std::string("the ") + to_string(map.rule) + " split records no child origins");
}

void refine_further(Hierarchy& hierarchy, const Scheme& scheme, int levels, const RefineOptions& options,
                    KeepLevels keep) {
  if (hierarchy.levels.empty()) throw InvalidInputError("refine_further: the hierarchy has no level");
  RefineOptions more = options;
  more.levels = levels;
  more.start_level = hierarchy.finest().level;
  Hierarchy next = refine_hierarchy(hierarchy.finest().mesh, scheme, more, keep);
  if (keep == KeepLevels::last) {
    hierarchy = std::move(next);
    return;
  }
  for (std::size_t i = 1; i < next.levels.size(); ++i) hierarchy.levels.push_back(std::move(next.levels[i]));
}

}  // namespace subdiv
