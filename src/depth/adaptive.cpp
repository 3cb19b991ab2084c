// Adaptive refinement over the uniform face hierarchy (docs/depth.md,
// "Adaptive refinement"). Levels are refined uniformly (the paper's adaptive
// scheme saves faces, not computation: it measures distances at every
// level), then a set of leaf faces is chosen and joined without cracks.

#include "subdiv/depth/adaptive.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>
#include <string>
#include <unordered_map>

#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/hierarchy.h"

namespace subdiv {

namespace {

struct Level {
  PolygonMesh mesh;
  std::optional<MeshTopology> topology;
  std::vector<double> distance;
  std::vector<char> approximated;  // the vertex's limit is only approximated: distance to that
  SplitMap map;                 // to the next level
  std::vector<char> exists;     // face is in the hierarchy (its parent was split)
  std::vector<char> split;      // face is replaced by its children
  std::vector<char> edge_split; // edge gets its edge point in the output
};

class LeafHierarchy {
 public:
  LeafHierarchy(const PolygonMesh& mesh, const Scheme& scheme, double eps, const AdaptiveOptions& options)
      : scheme_(scheme), eps_(eps), options_(options) {
    add_level(mesh);
    // Uniform levels until every vertex is within eps: no face of the last
    // level is ever split.
    while (max_distance(levels_.back()) > eps_) {
      if (static_cast<int>(levels_.size()) > options_.max_level)
        throw InvalidInputError("adaptive refinement: more than " + std::to_string(options_.max_level) +
                                " levels needed for accuracy " + std::to_string(eps_));
      RefineOptions one = options_.depth.refine;
      one.levels = 1;
      one.start_level = static_cast<int>(levels_.size()) - 1;
      one.on_level = nullptr;
      // The split's own map links the levels (hierarchy.h).
      Hierarchy step = refine_hierarchy(levels_.back().mesh, scheme_, one, KeepLevels::last);
      levels_.back().map = std::move(*step.levels.back().map);
      add_level(std::move(step.levels.back().mesh));
    }
    levels_.front().exists.assign(levels_.front().exists.size(), 1);
    choose_leaves();
  }

  AdaptiveResult result() const;

 private:
  void add_level(PolygonMesh mesh) {
    Level level;
    level.mesh = std::move(mesh);
    level.topology.emplace(level.mesh);
    LimitOptions limit;
    limit.normals = false;
    limit.refine = options_.depth.refine;
    limit.refine.on_level = nullptr;
    LimitDistances distances = resolved_limit_distances(level.mesh, scheme_, limit);
    level.distance = std::move(distances.distances);
    level.approximated = std::move(distances.approximated_vertices);
    level.exists.assign(static_cast<std::size_t>(level.topology->face_count()), 0);
    level.split.assign(level.exists.size(), 0);
    level.edge_split.assign(static_cast<std::size_t>(level.topology->edge_count()), 0);
    levels_.push_back(std::move(level));
  }

  static double max_distance(const Level& level) {
    double worst = 0.0;
    for (const double d : level.distance) worst = std::max(worst, d);
    return worst;
  }

  bool mobile(const Level& level, Index v) const { return level.distance[static_cast<std::size_t>(v)] > eps_; }

  // The paper's rule: an edge is split when an end is mobile; and every
  // edge of a split face is split.
  void mark_edges(Level& level) const {
    std::fill(level.edge_split.begin(), level.edge_split.end(), 0);
    const MeshTopology& t = *level.topology;
    for (Index f = 0; f < t.face_count(); ++f) {
      if (!level.exists[static_cast<std::size_t>(f)]) continue;
      const bool split = level.split[static_cast<std::size_t>(f)];
      for (Index c = t.face_first_corner(f); c < t.face_first_corner(f) + t.face_size(f); ++c)
        if (split || mobile(level, t.corner_vertex(c)) || mobile(level, t.corner_vertex(t.corner_next(c))))
          level.edge_split[static_cast<std::size_t>(t.corner_edge(c))] = 1;
    }
  }

  // Whether leaf face f of level j must be split instead: two or more mobile
  // corners (the paper's cases c and d), every edge split, or a transition
  // that would use a vertex further than eps from its limit, or an edge
  // point whose half-edges the next level splits again (a T-junction).
  bool must_split(std::size_t j, Index f) const {
    const Level& level = levels_[j];
    const Level& next = levels_[j + 1];
    const MeshTopology& t = *level.topology;
    int mobile_corners = 0;
    int split_edges = 0;
    for (Index c = t.face_first_corner(f); c < t.face_first_corner(f) + t.face_size(f); ++c) {
      mobile_corners += mobile(level, t.corner_vertex(c)) ? 1 : 0;
      split_edges += level.edge_split[static_cast<std::size_t>(t.corner_edge(c))] ? 1 : 0;
    }
    if (mobile_corners >= 2 || split_edges == t.face_size(f)) return true;
    if (split_edges == 0) return false;
    const auto far = [&](Index child_vertex) { return mobile(next, child_vertex); };
    for (Index c = t.face_first_corner(f); c < t.face_first_corner(f) + t.face_size(f); ++c) {
      const Index v = t.corner_vertex(c);
      if (mobile(level, v) && far(level.map.vertex_point(v))) return true;
      const Index e = t.corner_edge(c);
      if (!level.edge_split[static_cast<std::size_t>(e)]) continue;
      const Index mid = level.map.edge_point(e);
      if (far(mid)) return true;
      for (const Index end : {v, t.corner_vertex(t.corner_next(c))}) {
        const Index half = next.topology->find_edge(level.map.vertex_point(end), mid);
        if (half != kInvalidIndex && next.edge_split[static_cast<std::size_t>(half)]) return true;
      }
    }
    return scheme_.split == SplitRule::quad && far(level.map.face_point(f));
  }

  // The smallest fixed point: splits are only ever added, so this ends.
  void choose_leaves() {
    for (bool changed = true; changed;) {
      changed = false;
      for (Level& level : levels_) mark_edges(level);
      for (std::size_t j = 0; j + 1 < levels_.size(); ++j) {
        Level& level = levels_[j];
        const MeshTopology& t = *level.topology;
        for (Index f = 0; f < t.face_count(); ++f) {
          const auto fi = static_cast<std::size_t>(f);
          if (!level.exists[fi] || level.split[fi] || !must_split(j, f)) continue;
          level.split[fi] = 1;
          const auto [first, last] = child_faces(t, scheme_.split, f);
          for (Index child = first; child < last; ++child) levels_[j + 1].exists[static_cast<std::size_t>(child)] = 1;
          changed = true;
        }
      }
    }
  }

  const Scheme& scheme_;
  double eps_;
  AdaptiveOptions options_;
  std::vector<Level> levels_;
};

// A vertex of the output, named by a level and an index there.
struct LevelVertex {
  int level;
  Index index;
};

AdaptiveResult LeafHierarchy::result() const {
  // Follow vertex points down to the level where the vertex appeared: that
  // names it whatever level a face refers to it at; its position is taken
  // at the deepest level any face refers to it.
  const auto origin = [&](LevelVertex v) {
    while (v.level > 0 && v.index >= levels_[static_cast<std::size_t>(v.level - 1)].map.vertex_points) {
      v.index -= levels_[static_cast<std::size_t>(v.level - 1)].map.vertex_points;
      --v.level;
    }
    return v;
  };
  std::unordered_map<std::uint64_t, Index> ids;
  std::vector<LevelVertex> origins;
  std::vector<int> deepest;
  AdaptiveResult out;
  std::vector<Index> face;
  const auto emit = [&](const std::vector<LevelVertex>& corners, bool transition) {
    face.clear();
    for (const LevelVertex corner : corners) {
      const LevelVertex o = origin(corner);
      const std::uint64_t key = (static_cast<std::uint64_t>(o.level) << 32) | static_cast<std::uint32_t>(o.index);
      const auto [it, added] = ids.emplace(key, static_cast<Index>(origins.size()));
      if (added) {
        origins.push_back(o);
        deepest.push_back(corner.level);
      }
      deepest[static_cast<std::size_t>(it->second)] = std::max(deepest[static_cast<std::size_t>(it->second)], corner.level);
      face.push_back(it->second);
    }
    out.mesh.add_face(face);
    if (transition) ++out.transition_faces;
  };

  for (std::size_t j = 0; j < levels_.size(); ++j) {
    const Level& level = levels_[j];
    const MeshTopology& t = *level.topology;
    const int lj = static_cast<int>(j);
    for (Index f = 0; f < t.face_count(); ++f) {
      const auto fi = static_cast<std::size_t>(f);
      if (!level.exists[fi] || level.split[fi]) continue;
      out.leaves_per_level_max = std::max(out.leaves_per_level_max, lj);
      const Index n = t.face_size(f);
      const Index first = t.face_first_corner(f);
      // Corners (a mobile corner at its vertex point one level down) and
      // the edge points of split edges.
      std::vector<LevelVertex> corner(static_cast<std::size_t>(n));
      std::vector<std::optional<LevelVertex>> mid(static_cast<std::size_t>(n));
      int split_edges = 0;
      for (Index i = 0; i < n; ++i) {
        const Index v = t.corner_vertex(first + i);
        corner[static_cast<std::size_t>(i)] =
            mobile(level, v) ? LevelVertex{lj + 1, level.map.vertex_point(v)} : LevelVertex{lj, v};
        const Index e = t.corner_edge(first + i);
        if (level.edge_split[static_cast<std::size_t>(e)]) {
          mid[static_cast<std::size_t>(i)] = LevelVertex{lj + 1, level.map.edge_point(e)};
          ++split_edges;
        }
      }
      const auto v = [&](Index i) { return corner[static_cast<std::size_t>(i % n)]; };
      const auto m = [&](Index i) { return *mid[static_cast<std::size_t>(i % n)]; };
      const auto has_mid = [&](Index i) { return mid[static_cast<std::size_t>(i % n)].has_value(); };
      if (split_edges == 0) {
        emit(corner, false);
        continue;
      }
      if (scheme_.split == SplitRule::triangle) {
        // The paper's Figure 9 cases: one split edge (a neighbour was split)
        // halves the triangle; two (one mobile corner) cut that corner off
        // and halve the rest.
        Index i = 0;
        if (split_edges == 1) {
          while (!has_mid(i)) ++i;
          emit({v(i), m(i), v(i + 2)}, true);
          emit({m(i), v(i + 1), v(i + 2)}, true);
        } else {
          while (has_mid(i)) ++i;  // the unsplit edge v(i) v(i+1)
          emit({m(i + 1), v(i + 2), m(i + 2)}, true);
          emit({v(i), v(i + 1), m(i + 1)}, true);
          emit({v(i), m(i + 1), m(i + 2)}, true);
        }
        continue;
      }
      // Quad split: fan from the face point; a corner whose two edges are
      // split keeps its child quad.
      const LevelVertex centre{lj + 1, level.map.face_point(f)};
      for (Index i = 0; i < n; ++i) {
        const bool before = has_mid(i + n - 1);
        const bool after = has_mid(i);
        if (before && after) {
          emit({centre, m(i + n - 1), v(i), m(i)}, true);
          continue;
        }
        if (before) emit({centre, m(i + n - 1), v(i)}, true);
        if (after) emit({centre, v(i), m(i)}, true);
        else emit({centre, v(i), v(i + 1)}, true);
      }
    }
  }

  out.sources.resize(origins.size());
  out.distances.resize(origins.size());
  out.mesh.positions.resize(origins.size());
  for (std::size_t id = 0; id < origins.size(); ++id) {
    LevelVertex at = origins[id];
    while (at.level < deepest[id]) {
      at.index = levels_[static_cast<std::size_t>(at.level)].map.vertex_point(at.index);
      ++at.level;
    }
    const Level& level = levels_[static_cast<std::size_t>(at.level)];
    out.sources[id] = {at.level, at.index};
    out.mesh.positions[id] = level.mesh.positions[static_cast<std::size_t>(at.index)];
    out.distances[id] = level.distance[static_cast<std::size_t>(at.index)];
    out.approximated += level.approximated[static_cast<std::size_t>(at.index)];
  }
  out.uniform_depth = static_cast<int>(levels_.size()) - 1;
  out.uniform_faces = levels_.back().mesh.face_count();
  return out;
}

}  // namespace

std::optional<std::string> adaptive_unavailable(const Scheme& scheme, const AdaptiveOptions& options) {
  if (scheme.fast_path.two_steps) return adaptive_unavailable(*scheme.fast_path.two_steps, options);
  if (const auto reason = limit_unavailable(scheme)) return "no adaptive refinement without limit positions, and " + *reason;
  if (!is_primal(scheme.split))
    return "adaptive refinement walks the face hierarchy of the quad and triangle splits, whose child faces nest in "
           "their parents; the other splits' child faces straddle parent faces and need transition rules of their "
           "own (such as Kobbelt's for sqrt3), not implemented";
  if (interpolates_with_wide_masks(scheme, options.depth))
    return "no adaptive refinement for an interpolating scheme: its vertices are on the limit surface at every "
           "level, so their distance to it says nothing about the faces in between";
  return std::nullopt;
}

AdaptiveResult adaptive_refine(const PolygonMesh& mesh, const Scheme& scheme, double eps,
                               const AdaptiveOptions& options) {
  if (!(eps > 0.0)) throw InvalidInputError("accuracy must be a positive number");
  if (const auto reason = adaptive_unavailable(scheme, options))
    throw InvalidInputError(std::string(scheme.name) + ": " + *reason);
  if (!mesh.tags.holes.empty())
    throw InvalidInputError("face " + std::to_string(mesh.tags.holes.front()) +
                            " is tagged as a hole, and adaptive refinement has no rule for holes (it would fill them)");
  // 4-8: two of its steps are a quad split (Scheme::fast_path.two_steps), the
  // same surface, whose face hierarchy is walked in levels of two steps.
  if (scheme.fast_path.two_steps) {
    AdaptiveResult result = LeafHierarchy(mesh, *scheme.fast_path.two_steps, eps, options).result();
    result.steps_per_level = 2;
    return result;
  }
  return LeafHierarchy(mesh, scheme, eps, options).result();
}

}  // namespace subdiv
