// Adaptive refinement of the dual split, and of midedge in levels of two
// steps, which make a dual split (adaptive_dual.h; docs/depth.md).
//
// Levels are refined uniformly until every vertex is within eps of its
// limit, as for the other splits. A level-(j + 1) face exists where the
// level-j faces it is made from are split: an F-face where its face is, an
// E-face where both faces of its edge are, a V-face where every face around
// its vertex is. A face is split when one of its corners is further than eps
// from its limit, and only where every face around its vertices exists at its
// level (the balance rule: a split face's neighbours are faces of its own
// level, so the transitions below only meet faces of two adjacent levels).
// Transitions, designed here, between a split face f and a leaf g of level j:
//   across their edge (a, b): half of the E-face, the quad of f's two corner
//     points at a and b and the vertices a and b themselves;
//   at a vertex v whose faces are partly split: for each run of consecutive
//     split faces around v, the polygon of v and their corner points at v
//     (a run of one face needs none: its two half E-faces meet).
// Every output vertex is a vertex of a uniform level at that level's position.

#include "depth/adaptive_dual.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/hierarchy.h"

namespace subdiv::detail {

namespace {

// What a level's elements make one level down: the F-face of each face, the
// E-face of each edge, the V-face of each vertex (kInvalidIndex: none), the
// corner point of each corner; and, per face one level down, what made it.
struct DualLink {
  enum class Maker : std::uint8_t { face, edge, vertex };
  std::vector<Index> f_face, e_face, v_face, corner_point;
  std::vector<std::pair<Maker, Index>> made_by;
};

// One dual split.
DualLink dual_split_link(const MeshTopology& t, const SplitMap& map, Index child_faces) {
  DualLink link;
  link.made_by.assign(static_cast<std::size_t>(child_faces), {DualLink::Maker::face, kInvalidIndex});
  for (Index f = 0; f < t.face_count(); ++f) {
    link.f_face.push_back(f);
    link.made_by[static_cast<std::size_t>(f)] = {DualLink::Maker::face, f};
  }
  for (Index e = 0; e < t.edge_count(); ++e) {
    link.e_face.push_back(t.face_count() + e);
    link.made_by[static_cast<std::size_t>(t.face_count() + e)] = {DualLink::Maker::edge, e};
  }
  Index next = t.face_count() + t.edge_count();
  for (Index v = 0; v < t.vertex_count(); ++v) {
    link.v_face.push_back(dual_split_has_v_face(t, v) ? next : kInvalidIndex);
    if (link.v_face.back() != kInvalidIndex) link.made_by[static_cast<std::size_t>(next++)] = {DualLink::Maker::vertex, v};
  }
  for (Index c = 0; c < t.corner_count(); ++c) link.corner_point.push_back(map.corner_point(c));
  return link;
}

// Two midedge steps (src/topology/midedge_split.cpp): the first makes a
// vertex per edge and faces [F-faces | V-faces]; the second a vertex per
// edge of that level (one per corner of this one) and faces [F-faces of its
// faces | V-faces of its vertices]. So this level's face f, vertex v and
// edge e make faces f, (F-face of V-face of v) and (V-face of vertex e).
DualLink two_midedge_steps_link(const MeshTopology& t, const MeshTopology& middle, Index child_faces) {
  DualLink link;
  link.made_by.assign(static_cast<std::size_t>(child_faces), {DualLink::Maker::face, kInvalidIndex});
  for (Index f = 0; f < t.face_count(); ++f) {
    link.f_face.push_back(f);
    link.made_by[static_cast<std::size_t>(f)] = {DualLink::Maker::face, f};
  }
  Index middle_face = t.face_count();
  for (Index v = 0; v < t.vertex_count(); ++v) {
    link.v_face.push_back(t.vertex_face_count(v) > 0 ? middle_face++ : kInvalidIndex);
    if (link.v_face.back() != kInvalidIndex)
      link.made_by[static_cast<std::size_t>(link.v_face.back())] = {DualLink::Maker::vertex, v};
  }
  if (middle_face != middle.face_count()) throw std::logic_error("two midedge steps: the middle faces do not follow");
  for (Index e = 0; e < t.edge_count(); ++e) {  // middle vertex e has faces: its V-face follows the middle faces
    link.e_face.push_back(middle.face_count() + e);
    link.made_by[static_cast<std::size_t>(middle.face_count() + e)] = {DualLink::Maker::edge, e};
  }
  for (Index c = 0; c < t.corner_count(); ++c) {
    const Index point = middle.find_edge(t.corner_edge(t.corner_prev(c)), t.corner_edge(c));
    if (point == kInvalidIndex) throw std::logic_error("two midedge steps: a corner has no middle edge");
    link.corner_point.push_back(point);
  }
  return link;
}

struct DualLevel {
  PolygonMesh mesh;
  std::optional<MeshTopology> topology;
  LimitDistances distances;
  DualLink link;             // to the next level
  std::vector<char> exists;  // face is in the output's hierarchy
  std::vector<char> split;   // face is replaced by the faces one level down
};

class DualHierarchy {
 public:
  DualHierarchy(const PolygonMesh& mesh, const Scheme& scheme, double eps, const AdaptiveOptions& options)
      : scheme_(scheme), eps_(eps), options_(options), steps_(scheme.split == SplitRule::midedge ? 2 : 1) {
    add_level(mesh);
    while (levels_.back().distances.max > eps_) {
      if (static_cast<int>(levels_.size()) > options_.max_level)
        throw InvalidInputError("adaptive refinement: more than " + std::to_string(options_.max_level) +
                                " levels needed for accuracy " + std::to_string(eps_));
      RefineOptions period = options_.depth.refine;
      period.levels = steps_;
      period.start_level = step_number(levels_.size() - 1);
      period.on_level = nullptr;
      Hierarchy steps = refine_hierarchy(levels_.back().mesh, scheme_, period, steps_ == 1 ? KeepLevels::last : KeepLevels::all);
      DualLevel& parent = levels_.back();
      const Index child_faces = steps.levels.back().mesh.face_count();
      parent.link = steps_ == 1 ? dual_split_link(*parent.topology, *steps.levels.back().map, child_faces)
                                : two_midedge_steps_link(*parent.topology, MeshTopology(steps.levels[1].mesh), child_faces);
      add_level(std::move(steps.levels.back().mesh));
    }
    levels_.front().exists.assign(levels_.front().exists.size(), 1);
    choose_leaves();
  }

  AdaptiveResult result() const;

 private:
  void add_level(PolygonMesh mesh) {
    DualLevel level;
    level.mesh = std::move(mesh);
    level.topology.emplace(level.mesh);
    const MeshTopology& t = *level.topology;
    if (!t.boundary_loops().empty() || !t.all_rings_ordered())
      throw InvalidInputError(std::string(scheme_.name) +
                              ": adaptive refinement of the dual split covers closed manifold meshes (every vertex "
                              "with one ordered ring of faces)");
    LimitOptions limit;
    limit.normals = false;
    limit.refine = options_.depth.refine;
    limit.refine.start_level = step_number(levels_.size());
    limit.refine.on_level = nullptr;
    level.distances = resolved_limit_distances(level.mesh, scheme_, limit);
    level.exists.assign(static_cast<std::size_t>(t.face_count()), 0);
    level.split.assign(level.exists.size(), 0);
    levels_.push_back(std::move(level));
  }

  // The refinement step number of hierarchy level j.
  int step_number(std::size_t j) const { return options_.depth.refine.start_level + steps_ * static_cast<int>(j); }

  bool mobile(const DualLevel& level, Index v) const {
    return level.distances.distances[static_cast<std::size_t>(v)] > eps_;
  }

  template <typename Visit>
  static void faces_around_vertices(const MeshTopology& t, Index f, Visit&& visit) {
    for (const Index v : t.face_vertices(f))
      for (const Index c : t.vertex_corners(v)) visit(t.corner_face(c));
  }

  // Marks face f of level j split, after making every face around its
  // vertices exist (the balance rule), and makes the faces one level down
  // exist whose level-j faces are now all split.
  void mark_split(std::size_t j, Index f) {
    DualLevel& level = levels_[j];
    if (level.split[static_cast<std::size_t>(f)]) return;
    const MeshTopology& t = *level.topology;
    faces_around_vertices(t, f, [&](Index g) { ensure_exists(j, g); });
    level.split[static_cast<std::size_t>(f)] = 1;
    changed_ = true;
    std::vector<char>& next = levels_[j + 1].exists;
    const DualLink& link = level.link;
    next[static_cast<std::size_t>(link.f_face[static_cast<std::size_t>(f)])] = 1;
    const auto all_split = [&](std::span<const Index> corners) {
      return std::all_of(corners.begin(), corners.end(),
                         [&](Index s) { return level.split[static_cast<std::size_t>(t.corner_face(s))] != 0; });
    };
    for (Index c = t.face_first_corner(f); c < t.face_first_corner(f) + t.face_size(f); ++c) {
      const Index e = t.corner_edge(c);
      if (all_split(t.edge_corners(e))) next[static_cast<std::size_t>(link.e_face[static_cast<std::size_t>(e)])] = 1;
      const Index v = t.corner_vertex(c);
      const Index v_face = link.v_face[static_cast<std::size_t>(v)];
      if (v_face != kInvalidIndex && all_split(t.vertex_corners(v))) next[static_cast<std::size_t>(v_face)] = 1;
    }
  }

  // Makes face g of level j exist: the level-(j - 1) faces it is made from
  // are split.
  void ensure_exists(std::size_t j, Index g) {
    if (levels_[j].exists[static_cast<std::size_t>(g)]) return;
    const MeshTopology& t = *levels_[j - 1].topology;
    const auto [maker, element] = levels_[j - 1].link.made_by[static_cast<std::size_t>(g)];
    switch (maker) {
      case DualLink::Maker::face:
        mark_split(j - 1, element);
        break;
      case DualLink::Maker::edge:
        for (const Index s : t.edge_corners(element)) mark_split(j - 1, t.corner_face(s));
        break;
      case DualLink::Maker::vertex:
        for (const Index s : t.vertex_corners(element)) mark_split(j - 1, t.corner_face(s));
        break;
    }
  }

  void choose_leaves() {
    for (changed_ = true; changed_;) {
      changed_ = false;
      for (std::size_t j = 0; j + 1 < levels_.size(); ++j) {
        const MeshTopology& t = *levels_[j].topology;
        for (Index f = 0; f < t.face_count(); ++f) {
          const DualLevel& level = levels_[j];
          if (!level.exists[static_cast<std::size_t>(f)] || level.split[static_cast<std::size_t>(f)]) continue;
          const auto corners = t.face_vertices(f);
          if (std::any_of(corners.begin(), corners.end(), [&](Index v) { return mobile(level, v); })) mark_split(j, f);
        }
      }
    }
  }

  const Scheme& scheme_;
  double eps_;
  AdaptiveOptions options_;
  int steps_;  // refinement steps per level: 2 for the midedge split, whose two steps are a dual split
  bool changed_ = false;
  std::vector<DualLevel> levels_;
};

AdaptiveResult DualHierarchy::result() const {
  AdaptiveResult out;
  std::unordered_map<std::uint64_t, Index> ids;
  std::vector<std::pair<int, Index>> origins;
  std::set<std::pair<Index, Index>> directed;  // the transitions' directed edges so far
  std::vector<Index> face;
  const auto id_of = [&](int level, Index v) {
    const std::uint64_t key = (static_cast<std::uint64_t>(level) << 32) | static_cast<std::uint32_t>(v);
    const auto [it, added] = ids.emplace(key, static_cast<Index>(origins.size()));
    if (added) origins.emplace_back(level, v);
    return it->second;
  };
  const auto emit = [&](bool transition) {
    out.mesh.add_face(face);
    if (!transition) return;
    ++out.transition_faces;
    for (std::size_t i = 0; i < face.size(); ++i) directed.emplace(face[i], face[(i + 1) % face.size()]);
  };

  for (std::size_t j = 0; j < levels_.size(); ++j) {
    const DualLevel& level = levels_[j];
    const MeshTopology& t = *level.topology;
    const int lj = static_cast<int>(j);
    for (Index f = 0; f < t.face_count(); ++f) {
      if (!level.exists[static_cast<std::size_t>(f)] || level.split[static_cast<std::size_t>(f)]) continue;
      out.leaves_per_level_max = std::max(out.leaves_per_level_max, lj);
      face.clear();
      for (const Index v : t.face_vertices(f)) face.push_back(id_of(lj, v));
      emit(false);
    }
    if (j + 1 == levels_.size()) continue;
    const auto is_split = [&](Index g) { return level.split[static_cast<std::size_t>(g)] != 0; };
    // Half E-faces: split f, leaf g across edge (a, b), a -> b in f.
    for (Index f = 0; f < t.face_count(); ++f) {
      if (!is_split(f)) continue;
      for (Index c = t.face_first_corner(f); c < t.face_first_corner(f) + t.face_size(f); ++c) {
        const Index across = t.corner_across(c);
        if (across == kInvalidIndex || is_split(t.corner_face(across))) continue;
        const Index a = t.corner_vertex(c), b = t.corner_vertex(t.corner_next(c));
        const std::vector<Index>& point = level.link.corner_point;
        face = {id_of(lj + 1, point[static_cast<std::size_t>(t.corner_next(c))]),
                id_of(lj + 1, point[static_cast<std::size_t>(c)]), id_of(lj, a), id_of(lj, b)};
        emit(true);
      }
    }
    // Fan polygons: runs of two or more split faces around a vertex with a leaf.
    for (Index v = 0; v < t.vertex_count(); ++v) {
      const auto ring = t.vertex_corners(v);
      const auto leaf = std::find_if(ring.begin(), ring.end(), [&](Index c) { return !is_split(t.corner_face(c)); });
      if (leaf == ring.end() || std::none_of(ring.begin(), ring.end(), [&](Index c) { return is_split(t.corner_face(c)); }))
        continue;
      const std::size_t k = ring.size(), start = static_cast<std::size_t>(leaf - ring.begin());
      std::vector<Index> run;
      for (std::size_t step = 1; step <= k; ++step) {
        const Index c = ring[(start + step) % k];
        if (is_split(t.corner_face(c))) {
          run.push_back(id_of(lj + 1, level.link.corner_point[static_cast<std::size_t>(c)]));
          continue;
        }
        if (run.size() >= 2) {
          face = {id_of(lj, v)};
          face.insert(face.end(), run.begin(), run.end());
          // Orient it against the half E-faces it meets.
          if (directed.count({face[0], face[1]}) || directed.count({face.back(), face[0]}))
            std::reverse(face.begin() + 1, face.end());
          emit(true);
        }
        run.clear();
      }
    }
  }

  out.sources.resize(origins.size());
  out.distances.resize(origins.size());
  out.mesh.positions.resize(origins.size());
  for (std::size_t id = 0; id < origins.size(); ++id) {
    const auto [lj, v] = origins[id];
    const DualLevel& level = levels_[static_cast<std::size_t>(lj)];
    out.sources[id] = {lj, v};
    out.mesh.positions[id] = level.mesh.positions[static_cast<std::size_t>(v)];
    out.distances[id] = level.distances.distances[static_cast<std::size_t>(v)];
    out.approximated += level.distances.approximated_vertices.empty()
                            ? 0
                            : level.distances.approximated_vertices[static_cast<std::size_t>(v)];
  }
  out.uniform_depth = static_cast<int>(levels_.size()) - 1;
  out.uniform_faces = levels_.back().mesh.face_count();
  out.steps_per_level = steps_;
  return out;
}

}  // namespace

AdaptiveResult adaptive_refine_dual(const PolygonMesh& mesh, const Scheme& scheme, double eps,
                                    const AdaptiveOptions& options) {
  return DualHierarchy(mesh, scheme, eps, options).result();
}

}  // namespace subdiv::detail
