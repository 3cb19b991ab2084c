// Adaptive refinement over the uniform face hierarchy (docs/depth.md,
// "Adaptive refinement"). Levels are refined uniformly (the paper's adaptive
// scheme saves faces, not computation: it measures distances at every
// level), then a set of leaf faces is chosen and joined without cracks.
// A level is one step of the quad and triangle splits, or two of the sqrt3
// and sqrt2 splits, whose faces nest after two (depth/adaptive_nesting.h);
// the dual and midedge splits have no face hierarchy and their own
// construction (depth/adaptive_dual.h).

#include "subdiv/depth/adaptive.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "depth/adaptive_dual.h"
#include "depth/adaptive_nesting.h"
#include "depth/nested_linear_surface.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/rules/bilinear.h"
#include "subdiv/rules/linear.h"

namespace subdiv {

namespace {

struct Level {
  PolygonMesh mesh;
  std::optional<MeshTopology> topology;
  std::vector<double> distance;
  std::vector<char> approximated;  // the vertex's limit is only approximated: distance to that
  // Interpolating schemes: each vertex's distance from the parent level's
  // linear surface at its parameter (0 for old vertices and the control mesh).
  std::vector<double> displacement;
  detail::Nesting link;         // in the next level
  std::vector<char> exists;     // face is in the hierarchy (its parent was split)
  std::vector<char> split;      // face is replaced by its children
  std::vector<char> edge_split; // edge gets its edge point in the output
};

class LeafHierarchy {
 public:
  // `displacement_threshold`: set for interpolating schemes, whose faces are
  // refined by their next level's displacements instead of their vertices'
  // distances (every vertex is on the limit).
  LeafHierarchy(const PolygonMesh& mesh, const Scheme& scheme, double eps, const AdaptiveOptions& options,
                std::optional<double> displacement_threshold = std::nullopt)
      : scheme_(scheme),
        eps_(eps),
        options_(options),
        steps_(adaptive_steps_per_level(scheme)),
        threshold_(displacement_threshold) {
    add_level(mesh, {});
    // Uniform levels until every vertex is within eps (interpolating schemes:
    // every new vertex within the threshold of its parent's surface, and one
    // level more, which the last faces' displacements are read from): no face
    // of the last level is ever split.
    while (needs_another_level()) {
      if (static_cast<int>(levels_.size()) > options_.max_level)
        throw InvalidInputError("adaptive refinement: more than " + std::to_string(options_.max_level) +
                                " levels needed for accuracy " + std::to_string(eps_));
      RefineOptions period = options_.depth.refine;
      period.levels = steps_;
      period.start_level = step_number(levels_.size() - 1);
      period.on_level = nullptr;
      // The splits' own maps link the levels (hierarchy.h).
      Hierarchy steps = refine_hierarchy(levels_.back().mesh, scheme_, period, steps_ == 1 ? KeepLevels::last : KeepLevels::all);
      Level& parent = levels_.back();
      if (steps_ == 1) {
        parent.link = detail::one_step_nesting(*parent.topology, *steps.levels.back().map);
      } else if (scheme_.split == SplitRule::sqrt2) {
        parent.link = detail::two_sqrt2_steps_nesting(*parent.topology, *steps.levels[1].map, *steps.levels[2].map,
                                                      steps.levels[2].mesh);
      } else {
        const MeshTopology middle(steps.levels[1].mesh);
        parent.link = detail::two_sqrt3_steps_nesting(*parent.topology, *steps.levels[1].map, middle,
                                                      *steps.levels[2].map, steps.levels[2].mesh);
      }
      std::vector<double> displacement;
      if (threshold_) displacement = displacements(parent.mesh, steps.levels.back().mesh);
      add_level(std::move(steps.levels.back().mesh), std::move(displacement));
    }
    levels_.front().exists.assign(levels_.front().exists.size(), 1);
    choose_leaves();
  }

  AdaptiveResult result() const;

 private:
  // The refinement step number of hierarchy level j (the sqrt3 split's
  // boundary steps alternate with it).
  int step_number(std::size_t j) const { return options_.depth.refine.start_level + steps_ * static_cast<int>(j); }

  bool needs_another_level() {
    if (!threshold_) return max_distance(levels_.back()) > eps_;
    const std::size_t last = levels_.size() - 1;
    if (!settled_ && last > 0 &&
        std::all_of(levels_.back().displacement.begin(), levels_.back().displacement.end(),
                    [&](double d) { return d <= *threshold_; }))
      settled_ = last;
    return !settled_ || last < *settled_ + 1;
  }

  // Each vertex of `child` (the next level below `parent`) against the
  // parent's linear surface there: the linear or bilinear scheme's
  // refinement numbers its vertices alike, and so does the sqrt3 split's
  // nested surface over two steps (depth/nested_linear_surface.h).
  std::vector<double> displacements(const PolygonMesh& parent, const PolygonMesh& child) const {
    RefineOptions one = options_.depth.refine;
    one.levels = 1;
    one.start_level = step_number(levels_.size() - 1);
    one.on_level = nullptr;
    const PolygonMesh flat =
        scheme_.split == SplitRule::sqrt3 || scheme_.split == SplitRule::sqrt2
            ? detail::nested_linear_refinement(parent, one.start_level, scheme_.split)
            : refine(parent, scheme_.split == SplitRule::quad ? bilinear_scheme() : linear_scheme(), one);
    if (flat.face_indices != child.face_indices)
      throw std::logic_error("adaptive refinement: the linear surface's refinement numbers the level differently");
    std::vector<double> out(child.positions.size());
    for (std::size_t v = 0; v < out.size(); ++v) out[v] = norm(child.positions[v] - flat.positions[v]);
    return out;
  }

  void add_level(PolygonMesh mesh, std::vector<double> displacement) {
    Level level;
    level.mesh = std::move(mesh);
    level.topology.emplace(level.mesh);
    if (threshold_) {
      // Every vertex of an interpolating scheme is on the limit.
      level.displacement = displacement.empty() ? std::vector<double>(level.mesh.positions.size(), 0.0)
                                                : std::move(displacement);
      level.distance.assign(level.mesh.positions.size(), 0.0);
      level.approximated.assign(level.mesh.positions.size(), 0);
      level.exists.assign(static_cast<std::size_t>(level.topology->face_count()), 0);
      level.split.assign(level.exists.size(), 0);
      level.edge_split.assign(static_cast<std::size_t>(level.topology->edge_count()), 0);
      levels_.push_back(std::move(level));
      return;
    }
    LimitOptions limit;
    limit.normals = false;
    limit.refine = options_.depth.refine;
    limit.refine.start_level = step_number(levels_.size());
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

  // Interpolating schemes: the largest displacement of the next level's
  // vertices made inside face f of level j or on its edges.
  double displacement_inside(std::size_t j, Index f) const {
    const Level& level = levels_[j];
    const Level& next = levels_[j + 1];
    const MeshTopology& t = *level.topology;
    double worst = 0.0;
    for (Index c = t.face_first_corner(f); c < t.face_first_corner(f) + t.face_size(f); ++c)
      for (const Index p : level.link.points_on(t.corner_edge(c)))
        worst = std::max(worst, next.displacement[static_cast<std::size_t>(p)]);
    if (!level.link.face_centres.empty())
      worst = std::max(worst, next.displacement[static_cast<std::size_t>(level.link.face_centres[static_cast<std::size_t>(f)])]);
    return worst;
  }

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
  // point whose pieces of the edge the next level splits again (a T-junction).
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
    if (threshold_ && displacement_inside(j, f) > *threshold_) return true;
    if (split_edges == 0) return false;
    const auto far = [&](Index child_vertex) { return mobile(next, child_vertex); };
    for (Index c = t.face_first_corner(f); c < t.face_first_corner(f) + t.face_size(f); ++c) {
      const Index v = t.corner_vertex(c);
      if (mobile(level, v) && far(level.link.vertex_point(v))) return true;
      const Index e = t.corner_edge(c);
      if (!level.edge_split[static_cast<std::size_t>(e)]) continue;
      const std::span<const Index> points = level.link.points_on(e);
      if (std::any_of(points.begin(), points.end(), far)) return true;
      const auto [a, b] = t.edge_vertices(e);
      Index from = level.link.vertex_point(a);
      for (std::size_t k = 0; k <= points.size(); ++k) {
        const Index to = k < points.size() ? points[k] : level.link.vertex_point(b);
        const Index piece = next.topology->find_edge(from, to);
        if (piece != kInvalidIndex && next.edge_split[static_cast<std::size_t>(piece)]) return true;
        from = to;
      }
    }
    return !level.link.face_centres.empty() && far(level.link.face_centres[static_cast<std::size_t>(f)]);
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
          for (const Index child : level.link.children_of(f)) levels_[j + 1].exists[static_cast<std::size_t>(child)] = 1;
          changed = true;
        }
      }
    }
  }

  const Scheme& scheme_;
  double eps_;
  AdaptiveOptions options_;
  int steps_;  // refinement steps per level: adaptive_steps_per_level()
  std::optional<double> threshold_;  // interpolating schemes' displacement threshold
  std::optional<std::size_t> settled_;  // interpolating: the first level whose displacements are all within it
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
    while (v.level > 0 && v.index >= levels_[static_cast<std::size_t>(v.level - 1)].link.vertex_points) {
      v.index -= levels_[static_cast<std::size_t>(v.level - 1)].link.vertex_points;
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
      if (threshold_ && j + 1 < levels_.size())
        out.largest_displacement = std::max(out.largest_displacement, displacement_inside(j, f));
      const Index n = t.face_size(f);
      const Index first = t.face_first_corner(f);
      // Corners (a mobile corner at its vertex point one level down) and
      // the points of split edges, from corner i towards corner i + 1.
      std::vector<LevelVertex> corner(static_cast<std::size_t>(n));
      std::vector<std::vector<LevelVertex>> along(static_cast<std::size_t>(n));
      int split_edges = 0;
      for (Index i = 0; i < n; ++i) {
        const Index v = t.corner_vertex(first + i);
        corner[static_cast<std::size_t>(i)] =
            mobile(level, v) ? LevelVertex{lj + 1, level.link.vertex_point(v)} : LevelVertex{lj, v};
        const Index e = t.corner_edge(first + i);
        if (level.edge_split[static_cast<std::size_t>(e)]) {
          std::vector<LevelVertex>& points = along[static_cast<std::size_t>(i)];
          for (const Index p : level.link.points_on(e)) points.push_back({lj + 1, p});
          if (t.edge_vertices(e)[0] != v) std::reverse(points.begin(), points.end());
          ++split_edges;
        }
      }
      const auto v = [&](Index i) { return corner[static_cast<std::size_t>(i % n)]; };
      const auto m = [&](Index i) { return along[static_cast<std::size_t>(i % n)].front(); };
      const auto has_mid = [&](Index i) { return !along[static_cast<std::size_t>(i % n)].empty(); };
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
      const LevelVertex centre{lj + 1, level.link.face_centres[fi]};
      if (scheme_.split == SplitRule::sqrt3) {
        // Two sqrt3 steps (designed here): fan from the centre over the
        // corners and the thirds of the split edges.
        std::vector<LevelVertex> rim;
        for (Index i = 0; i < n; ++i) {
          rim.push_back(v(i));
          rim.insert(rim.end(), along[static_cast<std::size_t>(i)].begin(), along[static_cast<std::size_t>(i)].end());
        }
        for (std::size_t k = 0; k < rim.size(); ++k) emit({centre, rim[k], rim[(k + 1) % rim.size()]}, true);
        continue;
      }
      // Quad split: fan from the face point; a corner whose two edges are
      // split keeps its child quad.
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
      at.index = levels_[static_cast<std::size_t>(at.level)].link.vertex_point(at.index);
      ++at.level;
    }
    const Level& level = levels_[static_cast<std::size_t>(at.level)];
    out.sources[id] = {at.level, at.index};
    out.mesh.positions[id] = level.mesh.positions[static_cast<std::size_t>(at.index)];
    out.distances[id] = level.distance[static_cast<std::size_t>(at.index)];
    out.approximated += level.approximated[static_cast<std::size_t>(at.index)];
  }
  // Uniform refinement to the same accuracy: the last level (interpolating
  // schemes: the level before the first whose displacements are all within
  // the threshold).
  const std::size_t uniform = threshold_ ? *settled_ - 1 : levels_.size() - 1;
  out.uniform_depth = static_cast<int>(uniform);
  out.uniform_faces = levels_[uniform].mesh.face_count();
  out.steps_per_level = steps_;
  if (threshold_) {
    out.measure = DepthMeasure::surface_to_limit;
    out.displacement_threshold = *threshold_;
  }
  return out;
}

}  // namespace

int adaptive_steps_per_level(const Scheme& scheme) noexcept {
  return scheme.fast_path.two_steps || scheme.split == SplitRule::sqrt3 || scheme.split == SplitRule::sqrt2 ||
                 scheme.split == SplitRule::midedge
             ? 2
             : 1;
}

std::optional<std::string> adaptive_unavailable(const Scheme& scheme, const AdaptiveOptions& options) {
  if (scheme.fast_path.two_steps) return adaptive_unavailable(*scheme.fast_path.two_steps, options);
  if (const auto reason = limit_unavailable(scheme)) return "no adaptive refinement without limit positions, and " + *reason;
  if (scheme.split == SplitRule::sqrt2 && !interpolates_with_wide_masks(scheme, options.depth))
    return "adaptive refinement of an approximating scheme of the sqrt2 split walks its two-step quad split, "
           "which only 4-8 declares (Scheme::fast_path.two_steps)";
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
    result.steps_per_level = adaptive_steps_per_level(scheme);
    return result;
  }
  if (scheme.split == SplitRule::dual || scheme.split == SplitRule::midedge)
    return detail::adaptive_refine_dual(mesh, scheme, eps, options);
  if (interpolates_with_wide_masks(scheme, options.depth)) {
    // Every vertex is on the limit: faces are refined until their next
    // level's vertices lie within eps (1 - r) of their linear surface, r the
    // depth bound's rate, so that the displacements still to come add up to
    // at most eps (docs/depth.md, "Adaptive refinement").
    const DepthBound bound = depth_bound(mesh, scheme, options.depth);
    double rate = 0.0;
    for (const DepthTerm& term : bound.terms) rate = std::max(rate, term.rate);
    return LeafHierarchy(mesh, scheme, eps, options, eps * (1.0 - rate)).result();
  }
  return LeafHierarchy(mesh, scheme, eps, options).result();
}

}  // namespace subdiv
