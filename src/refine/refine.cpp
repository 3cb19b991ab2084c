// The refinement engine: split the topology, then evaluate the scheme's
// masks for every child vertex, either straight into the child's positions
// and vertex channels or into a stencil table. Child vertices are computed
// independently (parallel over ranges; face points before the rest, since
// masks may weight them), each as a fixed-order sum, so results do not
// depend on the thread count.

#include "subdiv/refine/refine.h"
#include "subdiv/refine/hierarchy.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>

#include "subdiv/core/error.h"
#include "subdiv/mesh/validation.h"
#include "face_varying.h"
#include "grid_refine.h"
#include "hierarchical_edits_detail.h"
#include "overflow_check.h"
#include "piecewise_smooth.h"
#include "../core/row_accumulator.h"
#include "../topology/split_detail.h"

namespace subdiv {

BoundaryInterpolation boundary_of(const PolygonMesh& mesh, const RuleOptions& options) noexcept {
  return options.boundary.value_or(mesh.tags.boundary_interpolation);
}

CreaseMethod crease_method_of(const PolygonMesh& mesh, const RuleOptions& options) noexcept {
  return options.crease_method.value_or(mesh.tags.crease_method);
}

TriangleSubdivision triangle_subdivision_of(const PolygonMesh& mesh, const RuleOptions& options) noexcept {
  return options.triangle_subdivision.value_or(mesh.tags.triangle_subdivision);
}

FaceVaryingInterpolation face_varying_interpolation_of(const PolygonMesh& mesh, const RuleOptions& options) noexcept {
  return options.face_varying.value_or(mesh.tags.face_varying_interpolation);
}

namespace {

// LevelView::level_id: unique within the process.
std::uint64_t next_level_id() {
  static std::atomic<std::uint64_t> last{0};
  return ++last;
}

// What the masks of one level see: the parent and its creasing. The parent
// mesh supplies positions, channels and tags; once its topology is derived
// its face arrays are dropped (refine_levels): faces come from the topology.
struct ParentLevel {
  const PolygonMesh& mesh;
  const MeshTopology& topology;
  const LevelCreasing& creasing;
  std::span<const double> sector_angle;  ///< piecewise-smooth rules only
  SchemeParameters parameters;
  int level = 0;  ///< the parent's, 0 for the control mesh
  const SplitMap* level_split = nullptr;  ///< a composite scheme's later steps: its first step's split
  std::span<const char> held = {};
  TriangleSubdivision triangle_subdivision = TriangleSubdivision::catmark;
  // The masks' views, built once per level rather than per child vertex.
  std::uint64_t id = next_level_id();
  LevelView here{topology, creasing.edge_sharpness, 0.0, sector_angle, {}, parameters, level, creasing.vertex_rule,
                 level_split, held, triangle_subdivision, id};
  LevelView below{topology, creasing.edge_sharpness, 1.0, sector_angle, creasing.child_edge_sharpness,  // Chaikin: per edge end
                  parameters, level, creasing.child_vertex_rule, level_split, held, triangle_subdivision, id};
  const LevelView& view() const { return here; }
  const LevelView& child_view() const { return below; }  // one level down
};

// The mask of child vertex i: a face, edge or vertex point by its range, with
// semi-sharp edges and rule transitions blending two masks (creasing.h).
void child_mask(const ParentLevel& parent, const Scheme& scheme, const SplitMap& map, Index i, MaskBuilder& mask) {
  mask.clear();
  const LevelView& view = parent.view();
  // The bisection and the identity step have no semi-sharp transitions to
  // blend: their masks read tags on or off (quasi 4-8) or none.
  if (map.rule == SplitRule::quasi_4_8) {
    if (i < map.edge_points) return scheme.masks.vertex_point(view, i, VertexRule::smooth, mask);
    return scheme.masks.edge_point(view, map.split_edges[static_cast<std::size_t>(i - map.edge_points)],
                                   EdgeRule::smooth, mask);
  }
  if (map.rule == SplitRule::identity)
    return scheme.masks.vertex_point(view, i, parent.creasing.vertex_rule[static_cast<std::size_t>(i)], mask);
  if (map.rule == SplitRule::dual) {
    if (i < map.edge_points) return scheme.masks.corner_point(view, i - map.corner_points, mask);
    const Index boundary = (i - map.edge_points) / 2;
    const Index e = map.boundary_edges[static_cast<std::size_t>(boundary)];
    return scheme.masks.boundary_point(view, e, view.topology.edge_vertices(e)[(i - map.edge_points) % 2], mask);
  }
  if (i < map.edge_points) return scheme.masks.face_point(view, map.point_face(i - map.face_points), mask);
  if (map.rule == SplitRule::sqrt3 && i < map.vertex_points) {  // boundary points, as the dual split's
    const Index boundary = (i - map.edge_points) / 2;
    const Index e = map.boundary_edges[static_cast<std::size_t>(boundary)];
    return scheme.masks.boundary_point(view, e, view.topology.edge_vertices(e)[(i - map.edge_points) % 2], mask);
  }
  if (i < map.vertex_points) {
    const Index e = i - map.edge_points;
    if (edge_sharpness_of(parent.creasing, e) <= 0.0) return scheme.masks.edge_point(view, e, EdgeRule::smooth, mask);
    const double c = edge_crease_weight(parent.creasing, e);  // the crease rule's share: 1, or s
    if (c == 1.0) return scheme.masks.edge_point(view, e, EdgeRule::crease, mask);
    mask.set_scale(1.0 - c);
    scheme.masks.edge_point(view, e, EdgeRule::smooth, mask);
    mask.set_scale(c);
    return scheme.masks.edge_point(view, e, EdgeRule::crease, mask);
  }
  const Index v = i - map.vertex_points;
  const auto vi = static_cast<std::size_t>(v);
  const VertexRule rule = parent.creasing.vertex_rule[vi];
  const VertexRule child_rule = parent.creasing.child_vertex_rule[vi];
  const double w = parent.creasing.parent_rule_weight.empty() ? 1.0 : parent.creasing.parent_rule_weight[vi];
  if (rule == child_rule || w >= 1.0) return scheme.masks.vertex_point(view, v, rule, mask);
  mask.set_scale(1.0 - w);
  scheme.masks.vertex_point(parent.child_view(), v, child_rule, mask);
  if (w <= 0.0) return;
  mask.set_scale(w);
  scheme.masks.vertex_point(view, v, rule, mask);
}

// Runs fn(i, mask) for child vertices [begin, end), in parallel.
template <typename Fn>
void for_each_child_mask(const ParentLevel& parent, const Scheme& scheme, const SplitMap& map, Index begin, Index end,
                         Fn&& fn) {
  tbb::parallel_for(tbb::blocked_range<Index>(begin, end, 2048), [&](const tbb::blocked_range<Index>& range) {
    MaskBuilder mask;
    mask.reserve(64);
    for (Index i = range.begin(); i != range.end(); ++i) {
      child_mask(parent, scheme, map, i, mask);
      fn(i, mask);
    }
  });
}

// Runs range(begin, end) over every child vertex in the masks' order: face
// points first, since edge and vertex masks may weight the new face points
// (MaskBuilder), which must exist by then; or last, where face masks weight
// the new edge points.
template <typename Range>
void in_mask_order(const Scheme& scheme, const SplitMap& map, Range&& range) {
  if (scheme.masks.face_points_read_edge_points) {
    range(map.edge_points, map.child_vertex_count);
    return range(0, map.edge_points);
  }
  range(0, map.edge_points);
  range(map.edge_points, map.child_vertex_count);
}

// for_each_child_mask over every child vertex, in the masks' order.
template <typename Fn>
void for_each_child_mask(const ParentLevel& parent, const Scheme& scheme, const SplitMap& map, Fn&& fn) {
  in_mask_order(scheme, map, [&](Index begin, Index end) { for_each_child_mask(parent, scheme, map, begin, end, fn); });
}

struct Level {
  PolygonMesh child;
  SplitMap map;
  /// Concave corners whose one-ring `fn` modifies after the masks
  /// (piecewise-smooth rules).
  std::vector<detail::FlatnessSite> flatness;
  /// The child's topology, when the level built it already (a composite
  /// scheme's smoothing steps need their quad mesh's).
  std::optional<MeshTopology> child_topology;
};

// One step: the child's faces and tags, then `fn` with the parent level and
// its creasing for the masks.
// `level_split`: for a composite scheme's later steps, the split its first
// step made (LevelView::level_split).
template <typename Fn>
Level refine_step(const PolygonMesh& parent, const MeshTopology& topology, int l, const Scheme& scheme,
                  BoundaryInterpolation boundary, CreaseMethod method, const RefineOptions& options, Fn&& fn,
                  const SplitMap* level_split = nullptr) {
  const LevelCreasing creasing = compute_creasing(parent, topology, boundary, method, l == 0);
  std::vector<double> sector_angle;
  if (options.boundary_rules == BoundaryRules::piecewise_smooth)
    sector_angle = detail::sector_angles(parent, topology, creasing);
  Level level;
  level.map = split_topology(parent, topology, scheme.split, level.child,
                             {.child_end_sharpness = creasing.child_edge_sharpness, .level = l, .boundary = boundary});
  if (level.child.tags.crease_method != method) {  // overridden: the child's tags say how they were made
    level.child.tags.crease_method = method;
    level.child.tags.crease_method_set = true;
  }
  const TriangleSubdivision triangles = triangle_subdivision_of(parent, options);
  if (level.child.tags.triangle_subdivision != triangles) {  // the same for the triangle rule
    level.child.tags.triangle_subdivision = triangles;
    level.child.tags.triangle_subdivision_set = true;
  }
  const FaceVaryingInterpolation face_varying = face_varying_interpolation_of(parent, options);
  if (level.child.tags.face_varying_interpolation != face_varying) {  // and for face-varying channels
    level.child.tags.face_varying_interpolation = face_varying;
    level.child.tags.face_varying_interpolation_set = true;
  }
  level.flatness = detail::flatness_sites(scheme, topology, creasing, sector_angle, level.map, options);
  std::vector<char> held;
  if (scheme.masks.held_vertices) held = scheme.masks.held_vertices(parent, topology, scheme.parameters);
  fn(ParentLevel{parent, topology, creasing, sector_angle, scheme.parameters, l, level_split, held, triangles}, level);
  return level;
}

// One step's evaluation: `fn(view, step, source, level, first)` evaluates
// or records the masks of `step` into `level`, reading values from
// `source`; `first` is false for a composite scheme's later steps, whose
// masks weight the previous step's vertices.
//
// One level of `scheme`: a single step, or a composite scheme's steps in
// turn (Scheme::steps): a split of the level's parent (R, a quad split, or
// quasi 4-8's bisection); smoothing steps, identity splits of its child; A,
// a dual split of the level's parent whose masks weight the smoothed
// vertices. The level's map is the split that numbers its child: the first
// step's, or A's.
template <typename Fn>
Level refine_level(const PolygonMesh& parent, const MeshTopology& topology, int l, const Scheme& scheme,
                   BoundaryInterpolation boundary, CreaseMethod method, const RefineOptions& options, Fn&& fn) {
  if (!scheme.steps)
    return refine_step(parent, topology, l, scheme, boundary, method, options,
                       [&](const ParentLevel& view, Level& level) { fn(view, scheme, parent, level, true); });
  const std::vector<Scheme> steps = scheme.steps(scheme.parameters);
  Level level;
  SplitMap made;                            // the first step's split
  std::optional<MeshTopology> split_child;  // its child's topology
  PolygonMesh source;                       // the previous step's child
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const Scheme& step = steps[i];
    const bool first = i == 0;
    auto evaluate = [&](const PolygonMesh& values) {
      return [&fn, &step, &values, first](const ParentLevel& view, Level& lv) { fn(view, step, values, lv, first); };
    };
    if (first && step.split != SplitRule::identity && step.split != SplitRule::dual) {
      level = refine_step(parent, topology, l, step, boundary, method, options, evaluate(parent));
      made = level.map;
      if (i + 1 < steps.size()) {
        if (step.split == SplitRule::quad) split_child = MeshTopology::from_quad_split(topology, level.child);
        if (!split_child) split_child.emplace(level.child);
      }
    } else if (step.split == SplitRule::identity && split_child) {
      source = std::move(level.child);
      level = refine_step(source, *split_child, l, step, boundary, method, options, evaluate(source), &made);
      level.map = made;
      if (i + 1 == steps.size()) level.child_topology = std::move(split_child);  // the same faces
    } else if (step.split == SplitRule::dual && split_child) {
      source = std::move(level.child);
      level = refine_step(parent, topology, l, step, boundary, method, options, evaluate(source), &made);
    } else {
      throw InvalidInputError(std::string(scheme.name) + ": a composite scheme's steps are a split of the level, " +
                              "then identity splits, then at most one dual split");
    }
  }
  return level;
}

// Whether the engine may take two steps of `scheme` as one level of
// scheme.fast_path.two_steps on this level: its masks read closed manifold levels,
// and face-varying values follow the steps' own splits.
bool takes_two_steps(const Scheme& scheme, const PolygonMesh& mesh, const MeshTopology& topology) {
  if (!scheme.fast_path.two_steps || !mesh.face_varying_channels.empty()) return false;
  for (Index e = 0; e < topology.edge_count(); ++e)
    if (topology.edge_face_count(e) != 2) return false;
  return true;
}

// The levels one after the other, each parent's topology derived from its
// own parent's where the split allows it (a manifold level), built from the
// faces otherwise; `step(parent, topology, l, level_scheme)` refines one
// level with `scheme`, or two with scheme.fast_path.two_steps where they apply.
// `finish(level, topology, remaining)`, where given, may make the remaining
// levels at once (the grid path) and keep what it made; it is asked before
// each level, and refine_levels() returns an empty mesh once it says true.
using Finish = std::function<bool(const PolygonMesh&, const MeshTopology&, int)>;

// The child's topology: derived from the parent's where the split allows
// it; else, for the quad and triangle splits, built from the child's faces
// with the hierarchy's edges (a level's faces alone would merge the halves
// of an edge joining a vertex to itself, or the two edges inside a pair of
// triangles on the same three vertices); nullopt otherwise, for the caller
// to build from the faces.
std::optional<MeshTopology> child_topology(const MeshTopology& parent, const PolygonMesh& child, SplitRule split) {
  std::optional<MeshTopology> derived;
  if (split == SplitRule::quad && !parent.has_coincident_edges()) derived = MeshTopology::from_quad_split(parent, child);
  if (split == SplitRule::triangle && !parent.has_coincident_edges())
    derived = MeshTopology::from_triangle_split(parent, child);
  if (split == SplitRule::sqrt3) derived = MeshTopology::from_sqrt3_split(parent, child);
  if (split == SplitRule::sqrt2) derived = MeshTopology::from_sqrt2_split(parent, child);
  if (!derived && is_primal(split)) derived.emplace(child, detail::child_edge_keys(parent, split));
  return derived;
}

// `edits`, where given, are applied to each level as it is made (the
// control mesh's to its copy).
template <typename Step>
PolygonMesh refine_levels(const PolygonMesh& mesh, MeshTopology coarse_topology, const Scheme& scheme,
                          const RefineOptions& options, Step&& step,
                          const std::function<void(int, const Level&)>& on_child = nullptr,
                          bool every_level = false, const Finish& finish = nullptr,
                          detail::EditFollower* edits = nullptr) {
  // The level being refined: the input itself until a level is made (a
  // copy of it would be the input's size again at the peak), or its copy
  // where the control mesh is edited or corner angles are measured into its
  // tags.
  PolygonMesh current;
  const PolygonMesh* parent = &mesh;
  const bool edit_control = edits && edits->edits_level(0);
  const bool measure = options.boundary_rules == BoundaryRules::piecewise_smooth &&
                       options.corner_angles == CornerAngles::measured;
  if (edit_control || measure) {
    current = mesh;
    parent = &current;
  }
  if (edit_control) edits->apply(0, current);
  if (measure) detail::measure_corner_angles(current, coarse_topology);
  std::optional<MeshTopology> topology = std::move(coarse_topology);
  const int last = options.start_level + options.levels;
  for (int l = options.start_level; l < last;) {
    if (!topology) topology.emplace(*parent);
    if (finish && finish(*parent, *topology, last - l)) return PolygonMesh{};
    const bool twice = !every_level && l + 2 <= last && takes_two_steps(scheme, *parent, *topology);
    const Scheme& level_scheme = twice ? *scheme.fast_path.two_steps : scheme;
    Level level = step(*parent, *topology, l, level_scheme);
    if (edits) {  // on the quad split: one step per level
      edits->descend(*topology, l);
      edits->apply(l + 1, level.child);
    }
    l += twice ? 2 : 1;
    if (l == last) topology.reset();
    else if (level.child_topology) topology = std::move(level.child_topology);
    else topology = child_topology(*topology, level.child, level_scheme.split);
    if (on_child) on_child(l, level);
    current = std::move(level.child);
    parent = &current;
    if (options.on_level) options.on_level(l - options.start_level, current);
    // A derived topology holds a copy of the level's faces, and refinement
    // reads faces only through the topology: drop the mesh's copy, the
    // largest arrays of the level before the last (the final level keeps its
    // faces; it gets no topology).
    if (topology) {
      std::vector<Index>().swap(current.face_offsets);
      std::vector<Index>().swap(current.face_indices);
    }
  }
  return parent == &mesh ? mesh : std::move(current);
}

// The mask applied to positions: parent vertices from `parent`, new face
// and edge points from `child` (already computed).
Vec3 apply_mask(const MaskBuilder& mask, const SplitMap& map, const Vec3* parent, const Vec3* child) {
  Vec3 p;
  const auto vs = mask.vertices();
  const auto ws = mask.weights();
  for (std::size_t j = 0; j < vs.size(); ++j) p += ws[j] * parent[vs[j]];
  const auto fs = mask.face_points();
  const auto fws = mask.face_point_weights();
  for (std::size_t j = 0; j < fs.size(); ++j) p += fws[j] * child[map.face_point(fs[j])];
  const auto es = mask.edge_points();
  const auto ews = mask.edge_point_weights();
  for (std::size_t j = 0; j < es.size(); ++j) p += ews[j] * child[map.edge_point(es[j])];
  return p;
}

// The same for values of k doubles each, added to out.
void apply_mask(const MaskBuilder& mask, const SplitMap& map, const double* parent, const double* child,
                       std::size_t k, double* out) {
  const auto vs = mask.vertices();
  const auto ws = mask.weights();
  for (std::size_t j = 0; j < vs.size(); ++j) {
    const double* src = parent + static_cast<std::size_t>(vs[j]) * k;
    for (std::size_t c = 0; c < k; ++c) out[c] += ws[j] * src[c];
  }
  const auto fs = mask.face_points();
  const auto fws = mask.face_point_weights();
  for (std::size_t j = 0; j < fs.size(); ++j) {
    const double* src = child + static_cast<std::size_t>(map.face_point(fs[j])) * k;
    for (std::size_t c = 0; c < k; ++c) out[c] += fws[j] * src[c];
  }
  const auto es = mask.edge_points();
  const auto ews = mask.edge_point_weights();
  for (std::size_t j = 0; j < es.size(); ++j) {
    const double* src = child + static_cast<std::size_t>(map.edge_point(es[j])) * k;
    for (std::size_t c = 0; c < k; ++c) out[c] += ews[j] * src[c];
  }
}

// The fast path's positions through Scheme::evaluate_point, the masks
// where it declines; in the masks' order of ranges.
void evaluate_points(const PolygonMesh& parent, const Scheme& scheme, const ParentLevel& view, Level& level) {
  const SplitMap& map = level.map;
  std::span<const Vec3> in = parent.positions;
  std::span<Vec3> out = level.child.positions;
  in_mask_order(scheme, map, [&](Index begin, Index end) {
    tbb::parallel_for(tbb::blocked_range<Index>(begin, end, 2048), [&](const tbb::blocked_range<Index>& r) {
      MaskBuilder mask;
      mask.reserve(64);
      for (Index i = r.begin(); i != r.end(); ++i) {
        Vec3& p = out[static_cast<std::size_t>(i)];
        if (scheme.fast_path.point(view.view(), map, i, in, out, p)) continue;
        child_mask(view, scheme, map, i, mask);
        p = apply_mask(mask, map, in.data(), out.data());
      }
    });
  });
}

void evaluate_fast(const PolygonMesh& parent, const Scheme& scheme, const ParentLevel& view, Level& level) {
  PolygonMesh& child = level.child;
  child.vertex_channels.resize(parent.vertex_channels.size());
  for (std::size_t ch = 0; ch < parent.vertex_channels.size(); ++ch) {
    const VertexChannel& in = parent.vertex_channels[ch];
    child.vertex_channels[ch] = {in.name, in.components,
                                 std::vector<double>(static_cast<std::size_t>(level.map.child_vertex_count) *
                                                     static_cast<std::size_t>(in.components))};
  }
  if (parent.vertex_channels.empty() && scheme.fast_path.point && !scheme.fast_path.positions)
    return evaluate_points(parent, scheme, view, level);
  if (scheme.fast_path.positions) {
    scheme.fast_path.positions(view.topology, level.map, parent.positions, child.positions);
    if (parent.vertex_channels.empty()) return;
  }
  for_each_child_mask(view, scheme, level.map, [&](Index i, const MaskBuilder& mask) {
    const auto at = static_cast<std::size_t>(i);
    if (!scheme.fast_path.positions)
      child.positions[at] = apply_mask(mask, level.map, parent.positions.data(), child.positions.data());
    for (std::size_t ch = 0; ch < parent.vertex_channels.size(); ++ch) {
      const auto k = static_cast<std::size_t>(parent.vertex_channels[ch].components);
      double* values = child.vertex_channels[ch].values.data();
      apply_mask(mask, level.map, parent.vertex_channels[ch].values.data(), values, k, values + at * k);
    }
  });
}

// The stencil rows of one level. Parent vertex p contributes row p of
// `composed` (coarse -> parent level) when given, else p itself; a new face
// point contributes its own row, recorded first (or a new edge point its
// row, recorded first where face masks read edge points). Rows come out
// merged and sorted by source.
StencilTable record_stencils(const ParentLevel& view, const Scheme& scheme, const SplitMap& map,
                             const StencilTable* composed) {
  const Index sources = composed ? composed->source_count() : view.topology.vertex_count();
  StencilTable table(sources);
  StencilTable edge_first(sources);  // rows edge_points .. end, where recorded before the face points
  const bool faces_last = scheme.masks.face_points_read_edge_points;
  tbb::enumerable_thread_specific<MaskBuilder> masks;
  auto fill = [&](Index i, detail::RowAccumulator& row) {
    MaskBuilder& mask = masks.local();
    child_mask(view, scheme, map, i, mask);
    const auto vs = mask.vertices();
    const auto ws = mask.weights();
    for (std::size_t j = 0; j < vs.size(); ++j) {
      if (composed) row.add_row(*composed, vs[j], ws[j]);
      else row.add(vs[j], ws[j]);
    }
    for (std::size_t j = 0; j < mask.face_points().size(); ++j)
      row.add_row(table, map.face_point(mask.face_points()[j]), mask.face_point_weights()[j]);
    for (std::size_t j = 0; j < mask.edge_points().size(); ++j)
      row.add_row(edge_first, map.edge_point(mask.edge_points()[j]) - map.edge_points, mask.edge_point_weights()[j]);
  };
  if (!faces_last) {
    detail::append_rows(table, 0, map.edge_points, fill);
    detail::append_rows(table, map.edge_points, map.child_vertex_count, fill);
    return table;
  }
  detail::append_rows(edge_first, map.edge_points, map.child_vertex_count, fill);
  detail::append_rows(table, 0, map.edge_points, fill);
  for (Index r = 0; r < edge_first.row_count(); ++r) table.append_row(edge_first.row_vertices(r), edge_first.row_weights(r));
  return table;
}

// The smooth face-varying refinement of `mesh` by `scheme`, or null where
// its channels are refined linearly (by the split).
std::shared_ptr<detail::FaceVaryingRefiner> face_varying_refiner(const PolygonMesh& mesh, const Scheme& scheme,
                                                                 const RefineOptions& options) {
  const FaceVaryingInterpolation mode = face_varying_interpolation_of(mesh, options);
  if (mesh.face_varying_channels.empty() || !detail::FaceVaryingRefiner::applies(scheme, mode)) return nullptr;
  return std::make_shared<detail::FaceVaryingRefiner>(mode, boundary_of(mesh, options));
}

// refine_levels()'s step for the fast path: each level's positions and
// vertex channels straight from the masks, then the flatness modification;
// face-varying channels smoothly where `face_varying` is given.
auto fast_step(BoundaryInterpolation boundary, CreaseMethod method, const RefineOptions& options,
               std::shared_ptr<detail::FaceVaryingRefiner> face_varying = nullptr) {
  return [boundary, method, &options, face_varying](const PolygonMesh& parent, const MeshTopology& topology, int l,
                                                    const Scheme& level_scheme) {
    return refine_level(parent, topology, l, level_scheme, boundary, method, options,
                        [&face_varying](const ParentLevel& view, const Scheme& step, const PolygonMesh& source,
                                        Level& level, bool) {
                          evaluate_fast(source, step, view, level);
                          detail::apply_flatness(level.flatness, level.child);
                          if (!face_varying) return;
                          const auto mask_of = [&](Index i, MaskBuilder& mask) {
                            child_mask(view, step, level.map, i, mask);
                          };
                          face_varying->refine(source, view.topology, view.creasing, level.map, mask_of, level.child);
                        });
  };
}

template <typename Body>
void run_with_threads(int threads, Body&& body) {
  if (threads > 0) {
    tbb::task_arena arena(threads);
    arena.execute(body);
  } else {
    body();
  }
}

}  // namespace

namespace {

// Whether one of the splits a level of `scheme` makes reads the parent's
// positions (quasi 4-8's bisection): the stencil paths then evaluate every
// level's positions.
bool splits_read_positions(const Scheme& scheme) { return scheme.split == SplitRule::quasi_4_8; }

// The dual, midedge and sqrt3 splits, and composite schemes, have no rules
// for sharp features (sqrt3: but corners; quasi 4-8's bisection: tags on or
// off, which its smoothing holds), holes or non-manifold elements: refuse
// them, naming the tag's line.
void check_no_sharp_features(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                             const SourceLines* lines) {
  const std::string name(scheme.name);
  if (options.boundary_rules == BoundaryRules::piecewise_smooth)
    throw InvalidInputError(name + " has no piecewise-smooth rules; use the standard boundary rules");
  if (options.allow_non_manifold) throw InvalidInputError(name + " cannot refine non-manifold meshes");
  const bool tags_held = scheme.split == SplitRule::quasi_4_8;
  for (std::size_t i = 0; i < mesh.tags.creases.size() && !tags_held; ++i)
    if (mesh.tags.creases[i].sharpness > 0.0)
      throw InvalidInputError(where(lines, &SourceLines::crease_lines, i) + name + " has no crease rules, but edge (" +
                              std::to_string(mesh.tags.creases[i].v0) + ", " + std::to_string(mesh.tags.creases[i].v1) +
                              ") is tagged as a crease");
  // The sqrt3 split keeps the parent's vertices, and with them corner tags.
  for (std::size_t i = 0; i < mesh.tags.corners.size() && scheme.split != SplitRule::sqrt3 && !tags_held; ++i)
    if (mesh.tags.corners[i].sharpness > 0.0)
      throw InvalidInputError(where(lines, &SourceLines::corner_lines, i) + name + " has no corner rules, but vertex " +
                              std::to_string(mesh.tags.corners[i].vertex) + " is tagged as a corner");
  if (!mesh.tags.holes.empty())
    throw InvalidInputError(where(lines, &SourceLines::hole_lines, 0) + name + " has no rules for holes, but face " +
                            std::to_string(mesh.tags.holes[0]) + " is tagged as a hole");
}

/// Two triangles on the same three vertices (a doubled triangle, around an
/// interior vertex of valence 2) are a valid surface, but the triangle, sqrt3
/// and quasi 4-8 splits join their children by two edges between the same
/// pair of new vertices, which a mesh indexed by vertices holds as one
/// non-manifold edge. Refused unless the caller allows non-manifold input,
/// which refines those edges as sharp. Such a pair shares two of its edges.
void check_no_doubled_triangles(const PolygonMesh& mesh, const MeshTopology& topology, const Scheme& scheme,
                                const SourceLines* lines) {
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (mesh.face_size(f) != 3) continue;
    Index across[3];
    for (Index i = 0; i < 3; ++i) {
      const Index c = topology.corner_across(topology.face_first_corner(f) + i);
      across[i] = c == kInvalidIndex ? kInvalidIndex : topology.corner_face(c);
    }
    for (Index i = 0; i < 3; ++i) {
      const Index g = across[i];
      if (g == kInvalidIndex || g == f || mesh.face_size(g) != 3 || (across[(i + 1) % 3] != g && across[(i + 2) % 3] != g))
        continue;
      throw InvalidInputError(where(lines, &SourceLines::face_lines, static_cast<std::size_t>(std::max(f, g))) +
                              std::string(scheme.name) + ": faces " + std::to_string(std::min(f, g)) + " and " +
                              std::to_string(std::max(f, g)) + " are triangles on the same three vertices; the " +
                              to_string(scheme.split) +
                              " would join their children by two edges between the same vertices, a non-manifold "
                              "edge (RuleOptions::allow_non_manifold refines it as a sharp feature; a quad scheme "
                              "such as catmull-clark refines the mesh as it is)");
    }
  }
}

// Everything check_refinable() promises, returning the coarse mesh's
// topology so that refinement does not build it a second time.
MeshTopology check_and_build_topology(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                                      const SourceLines* lines) {
  if (options.levels < 0) throw InvalidInputError("refinement levels must be >= 0, not " + std::to_string(options.levels));
  check_parameters(scheme);
  if (options.start_level < 0)
    throw InvalidInputError("the start level must be >= 0, not " + std::to_string(options.start_level));
  if (boundary_of(mesh, options) == BoundaryInterpolation::none)
    throw InvalidInputError("boundary interpolation 'none' is not supported; use edge-only or edge-and-corner");
  if (!is_primal(scheme.split) || scheme.steps) check_no_sharp_features(mesh, scheme, options, lines);
  if (scheme.steps) {
    // The steps' own checks (degree, weights), and the split they make.
    const std::vector<Scheme> steps = scheme.steps(scheme.parameters);
    const SplitRule made = steps.empty()                                 ? SplitRule::identity
                           : steps.back().split == SplitRule::dual ? SplitRule::dual
                                                                   : steps.front().split;
    if (made != scheme.split)
      throw InvalidInputError(std::string(scheme.name) + ": its steps make a " + to_string(made) +
                              " but the scheme says " + to_string(scheme.split) + " (set the degree with set_degree)");
  }
  const std::string path = lines ? lines->path : std::string();
  try {
    check_face_arrays(mesh);
  } catch (const InvalidInputError&) {
    require_valid(validate(mesh, lines), path);  // names the bad index and its line
    throw;
  }
  MeshTopology topology(mesh);
  ValidationReport report = validate(mesh, topology, lines);
  // Non-manifold elements and flipped faces become sharp features where the
  // caller allows them, and faces repeating a vertex too for the schemes
  // that refine those as OpenSubdiv does; everything else still stops us.
  const bool degenerate_faces = scheme.traits.degenerate_faces && !scheme.steps;
  auto allowed = [degenerate_faces](IssueKind k) {
    return k == IssueKind::non_manifold_edge || k == IssueKind::non_manifold_vertex ||
           k == IssueKind::inconsistent_orientation || (degenerate_faces && k == IssueKind::repeated_vertex);
  };
  if (options.allow_non_manifold) {
    for (std::size_t k = 0; k < report.counts.size(); ++k)
      if (allowed(static_cast<IssueKind>(k))) report.counts[k] = 0;
    std::erase_if(report.issues, [&](const ValidationIssue& i) { return allowed(i.kind); });
  }
  if (!report.ok()) {
    std::size_t fixable = 0;
    for (std::size_t k = 0; k < report.counts.size(); ++k)
      if (allowed(static_cast<IssueKind>(k))) fixable += report.counts[k];
    if (fixable == report.error_count())
      for (auto& issue : report.issues)
        issue.message += issue.kind == IssueKind::repeated_vertex
                             ? " (RuleOptions::allow_non_manifold refines it as OpenSubdiv does)"
                             : " (RuleOptions::allow_non_manifold refines it as a sharp feature)";
    require_valid(report, path);
  }
  if (scheme.traits.needs_closed_mesh)
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      if (topology.vertex_kind(v) == VertexKind::boundary)
        throw InvalidInputError(where(lines, &SourceLines::vertex_lines, static_cast<std::size_t>(v)) +
                                std::string(scheme.name) + " needs a closed mesh, but vertex " + std::to_string(v) +
                                " is on a boundary (it has no boundary rules)");
  // Schemes whose rules read one kind of face refuse the first other face.
  auto require_faces_of = [&](Index sides, const char* kind, const char* remedy) {
    for (Index f = 0; f < mesh.face_count(); ++f)
      if (mesh.face_size(f) != sides)
        throw InvalidInputError(where(lines, &SourceLines::face_lines, static_cast<std::size_t>(f)) +
                                std::string(scheme.name) + " needs a " + kind + " mesh, but face " + std::to_string(f) +
                                " has " + std::to_string(mesh.face_size(f)) + " vertices (" + remedy + ")");
  };
  if (scheme.traits.needs_triangles) require_faces_of(3, "triangle", "triangulate it first: triangulate()");
  const bool splits_faces_by_edge_points =
      scheme.split == SplitRule::triangle || scheme.split == SplitRule::sqrt3 || scheme.split == SplitRule::quasi_4_8;
  if (splits_faces_by_edge_points && !options.allow_non_manifold)
    check_no_doubled_triangles(mesh, topology, scheme, lines);
  if (scheme.traits.needs_quads) require_faces_of(4, "quad", "one bilinear or catmull-clark level first makes every face a quad");
  return topology;
}

// The same with options.threads threads, as the refinement that follows.
MeshTopology checked_topology(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                              const SourceLines* lines) {
  std::optional<MeshTopology> topology;
  run_with_threads(options.threads, [&] { topology.emplace(check_and_build_topology(mesh, scheme, options, lines)); });
  return std::move(*topology);
}

}  // namespace

void check_refinable(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                     const SourceLines* lines) {
  checked_topology(mesh, scheme, options, lines);
}

// The control mesh's hierarchical edits where the scheme applies them
// (refining from the control mesh); null where there are none.
static std::unique_ptr<detail::EditFollower> edit_follower(const PolygonMesh& mesh, const Scheme& scheme,
                                                           const RefineOptions& options) {
  if (options.start_level != 0 || !applies_hierarchical_edits(scheme)) return nullptr;
  HierarchicalEdits edits = read_hierarchical_edits(mesh.tags, mesh);
  if (edits.empty()) return nullptr;
  return std::make_unique<detail::EditFollower>(std::move(edits));
}

PolygonMesh refine(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                   const SourceLines* lines) {
  MeshTopology coarse = checked_topology(mesh, scheme, options, lines);
  const BoundaryInterpolation boundary = boundary_of(mesh, options);
  const CreaseMethod method = crease_method_of(mesh, options);
  std::unique_ptr<detail::EditFollower> edits = edit_follower(mesh, scheme, options);
  const int last = options.start_level + options.levels;
  PolygonMesh result;
  std::optional<PolygonMesh> by_grids;
  Finish as_grids;
  auto face_varying = face_varying_refiner(mesh, scheme, options);
  if (options.regular_grids && !face_varying && (regular_grid_of(scheme) || regular_triangle_grid_of(scheme)))
    as_grids = [&](const PolygonMesh& level, const MeshTopology& topology, int remaining) {
      if (edits && last - remaining < edits->deepest_level()) return false;  // edits to come
      by_grids = detail::refine_as_grids(level, topology, scheme, options, remaining);
      return by_grids.has_value();
    };
  run_with_threads(options.threads, [&] {
    result = refine_levels(mesh, std::move(coarse), scheme, options,
                           fast_step(boundary, method, options, std::move(face_varying)), nullptr, false, as_grids,
                           edits.get());
  });
  if (by_grids) result = std::move(*by_grids);
  run_with_threads(options.threads,
                   [&] { detail::refuse_overflow(result.positions, scheme, options.start_level + options.levels); });
  if (by_grids && options.on_level) options.on_level(options.levels, result);
  return result;
}

Hierarchy refine_hierarchy(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                           KeepLevels keep, const SourceLines* lines) {
  Hierarchy h;
  const int last = options.start_level + options.levels;
  MeshTopology coarse = checked_topology(mesh, scheme, options, lines);
  const BoundaryInterpolation boundary = boundary_of(mesh, options);
  const CreaseMethod method = crease_method_of(mesh, options);
  std::unique_ptr<detail::EditFollower> edits = edit_follower(mesh, scheme, options);
  if (keep == KeepLevels::all) h.levels.push_back({mesh, options.start_level, std::nullopt});
  std::optional<SplitMap> last_map;
  const auto on_child = [&](int l, const Level& level) {
    if (keep == KeepLevels::all) h.levels.push_back({level.child, l, level.map});
    else if (l == last) last_map = level.map;
  };
  PolygonMesh finest;
  run_with_threads(options.threads, [&] {
    finest = refine_levels(mesh, std::move(coarse), scheme, options,
                           fast_step(boundary, method, options, face_varying_refiner(mesh, scheme, options)), on_child,
                           keep == KeepLevels::all, nullptr, edits.get());
  });
  run_with_threads(options.threads, [&] { detail::refuse_overflow(finest.positions, scheme, last); });
  if (keep == KeepLevels::last) h.levels.push_back({std::move(finest), last, std::move(last_map)});
  return h;
}

std::vector<StencilTable> refine_stencils(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                                          PolygonMesh* final_level) {
  MeshTopology coarse = checked_topology(mesh, scheme, options, nullptr);
  const BoundaryInterpolation boundary = boundary_of(mesh, options);
  const CreaseMethod method = crease_method_of(mesh, options);
  std::vector<StencilTable> tables;
  run_with_threads(options.threads, [&] {
    PolygonMesh last = refine_levels(mesh, std::move(coarse), scheme, options,
                                     [&](const PolygonMesh& parent, const MeshTopology& topology, int l, const Scheme& level_scheme) {
      Level level = refine_level(
          parent, topology, l, level_scheme, boundary, method, options,
          [&](const ParentLevel& view, const Scheme& step, const PolygonMesh&, Level& lv, bool first) {
            // A composite scheme's later steps compose onto the level's table.
            if (first) tables.push_back(record_stencils(view, step, lv.map, nullptr));
            else tables.back() = record_stencils(view, step, lv.map, &tables.back());
            detail::apply_flatness(lv.flatness, tables.back());
          });
      if (final_level || splits_read_positions(scheme)) tables.back().apply(parent.positions, level.child.positions);
      return level;
    });
    if (final_level) *final_level = std::move(last);
  });
  return tables;
}

StencilTable refine_stencil_table(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options) {
  MeshTopology coarse = checked_topology(mesh, scheme, options, nullptr);
  const BoundaryInterpolation boundary = boundary_of(mesh, options);
  const CreaseMethod method = crease_method_of(mesh, options);
  std::optional<StencilTable> total;
  Finish as_grids;  // the remaining levels' table by the grid path, composed onto the levels' before
  if (options.regular_grids && (regular_grid_of(scheme) || regular_triangle_grid_of(scheme)))
    as_grids = [&](const PolygonMesh& level, const MeshTopology& topology, int remaining) {
      std::optional<StencilTable> rest = detail::stencils_as_grids(level, topology, scheme, options, remaining);
      if (!rest) return false;
      total = total ? total->then(*rest) : std::move(*rest);
      return true;
    };
  run_with_threads(options.threads, [&] {
    refine_levels(
        mesh, std::move(coarse), scheme, options,
        [&](const PolygonMesh& parent, const MeshTopology& topology, int l, const Scheme& level_scheme) {
          Level level = refine_level(parent, topology, l, level_scheme, boundary, method, options,
                                     [&](const ParentLevel& view, const Scheme& step, const PolygonMesh&, Level& lv,
                                         bool) {
                                       total = record_stencils(view, step, lv.map, total ? &*total : nullptr);
                                       detail::apply_flatness(lv.flatness, *total);
                                     });
          if (splits_read_positions(scheme)) total->apply(mesh.positions, level.child.positions);
          return level;
        },
        nullptr, false, as_grids);
  });
  return total ? std::move(*total) : StencilTable::identity(mesh.vertex_count());
}

const char* to_string(BoundaryRules r) noexcept {
  return r == BoundaryRules::standard ? "standard" : "piecewise-smooth";
}
const char* to_string(CornerAngles a) noexcept { return a == CornerAngles::fixed ? "fixed" : "measured"; }

StencilTable compose(const std::vector<StencilTable>& levels) {
  if (levels.empty()) return StencilTable();
  StencilTable total = levels.front();
  for (std::size_t i = 1; i < levels.size(); ++i) total = total.then(levels[i]);
  return total;
}

}  // namespace subdiv
