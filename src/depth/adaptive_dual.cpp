// Adaptive refinement of the dual split (adaptive_dual.h; docs/depth.md).
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

struct DualLevel {
  PolygonMesh mesh;
  std::optional<MeshTopology> topology;
  LimitDistances distances;
  SplitMap map;                  // to the next level
  std::vector<Index> v_face;     // per vertex: its V-face one level down, or kInvalidIndex
  std::vector<Index> v_face_of;  // per V-face one level down (rank): its vertex
  std::vector<char> exists;      // face is in the output's hierarchy
  std::vector<char> split;       // face is replaced by the faces one level down
};

class DualHierarchy {
 public:
  DualHierarchy(const PolygonMesh& mesh, const Scheme& scheme, double eps, const AdaptiveOptions& options)
      : scheme_(scheme), eps_(eps), options_(options) {
    add_level(mesh);
    while (levels_.back().distances.max > eps_) {
      if (static_cast<int>(levels_.size()) > options_.max_level)
        throw InvalidInputError("adaptive refinement: more than " + std::to_string(options_.max_level) +
                                " levels needed for accuracy " + std::to_string(eps_));
      RefineOptions one = options_.depth.refine;
      one.levels = 1;
      one.start_level = options_.depth.refine.start_level + static_cast<int>(levels_.size()) - 1;
      one.on_level = nullptr;
      Hierarchy step = refine_hierarchy(levels_.back().mesh, scheme_, one, KeepLevels::last);
      DualLevel& parent = levels_.back();
      parent.map = std::move(*step.levels.back().map);
      const MeshTopology& t = *parent.topology;
      parent.v_face.assign(static_cast<std::size_t>(t.vertex_count()), kInvalidIndex);
      Index next = t.face_count() + t.edge_count();
      for (Index v = 0; v < t.vertex_count(); ++v)
        if (dual_split_has_v_face(t, v)) {
          parent.v_face[static_cast<std::size_t>(v)] = next++;
          parent.v_face_of.push_back(v);
        }
      add_level(std::move(step.levels.back().mesh));
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
    limit.refine.start_level = options_.depth.refine.start_level + static_cast<int>(levels_.size());
    limit.refine.on_level = nullptr;
    level.distances = resolved_limit_distances(level.mesh, scheme_, limit);
    level.exists.assign(static_cast<std::size_t>(t.face_count()), 0);
    level.split.assign(level.exists.size(), 0);
    levels_.push_back(std::move(level));
  }

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
    next[static_cast<std::size_t>(f)] = 1;  // the F-face
    for (Index c = t.face_first_corner(f); c < t.face_first_corner(f) + t.face_size(f); ++c) {
      const Index e = t.corner_edge(c);
      const auto sides = t.edge_corners(e);
      if (std::all_of(sides.begin(), sides.end(), [&](Index s) { return level.split[static_cast<std::size_t>(t.corner_face(s))] != 0; }))
        next[static_cast<std::size_t>(t.face_count() + e)] = 1;
      const Index v = t.corner_vertex(c);
      const auto around = t.vertex_corners(v);
      if (level.v_face[static_cast<std::size_t>(v)] != kInvalidIndex &&
          std::all_of(around.begin(), around.end(), [&](Index s) { return level.split[static_cast<std::size_t>(t.corner_face(s))] != 0; }))
        next[static_cast<std::size_t>(level.v_face[static_cast<std::size_t>(v)])] = 1;
    }
  }

  // Makes face g of level j exist: the level-(j - 1) faces it is made from
  // are split.
  void ensure_exists(std::size_t j, Index g) {
    if (levels_[j].exists[static_cast<std::size_t>(g)]) return;
    const MeshTopology& t = *levels_[j - 1].topology;
    if (g < t.face_count()) {
      mark_split(j - 1, g);
    } else if (g < t.face_count() + t.edge_count()) {
      for (const Index s : t.edge_corners(g - t.face_count())) mark_split(j - 1, t.corner_face(s));
    } else {
      const Index v = levels_[j - 1].v_face_of[static_cast<std::size_t>(g - t.face_count() - t.edge_count())];
      for (const Index s : t.vertex_corners(v)) mark_split(j - 1, t.corner_face(s));
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
        face = {id_of(lj + 1, level.map.corner_point(t.corner_next(c))), id_of(lj + 1, level.map.corner_point(c)),
                id_of(lj, a), id_of(lj, b)};
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
          run.push_back(id_of(lj + 1, level.map.corner_point(c)));
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
  return out;
}

}  // namespace

AdaptiveResult adaptive_refine_dual(const PolygonMesh& mesh, const Scheme& scheme, double eps,
                                    const AdaptiveOptions& options) {
  return DualHierarchy(mesh, scheme, eps, options).result();
}

}  // namespace subdiv::detail
