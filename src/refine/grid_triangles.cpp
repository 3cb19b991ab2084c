// The grid path of triangle-split schemes (grid_triangles.h).

#include "grid_triangles.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"
#include "grid_common.h"
#include "triangle_numbering.h"
#include "triangle_patch.h"

namespace subdiv::detail {

namespace {

// The tags of the last level: the level's options, and its crease, corner
// and hole tags carried down as split_topology() carries them one level at
// a time with uniform creasing (each crease's halves at the ends' vertex
// points; a hole's faces in a row).
Tags last_level_tags(const PolygonMesh& level, const MeshTopology& t, const TriangleNumbering& numbering) {
  Tags out = tag_options(level.tags);
  struct Crease {
    Index v0, v1, edge;
    double sharpness;
  };
  std::vector<Crease> creases;
  for (const CreaseTag& c : level.tags.creases) {
    const bool valid = c.v0 >= 0 && c.v1 >= 0 && c.v0 < t.vertex_count() && c.v1 < t.vertex_count();
    const Index e = valid ? t.find_edge(c.v0, c.v1) : kInvalidIndex;
    if (e != kInvalidIndex) creases.push_back({c.v0, c.v1, e, c.sharpness});
  }
  std::vector<CornerTag> corners;
  for (const CornerTag& c : level.tags.corners)
    if (c.vertex >= 0 && c.vertex < t.vertex_count()) corners.push_back(c);
  for (int depth = 0; depth < numbering.levels(); ++depth) {
    const auto vertex_point = static_cast<Index>(numbering.edges(depth));
    // The halves' own numbers are needed only where another split follows.
    const TriangleLevel* split = depth < numbering.derived_levels() && depth + 1 < numbering.levels()
                                     ? &numbering.level(depth) : nullptr;
    std::vector<Crease> next;
    for (const Crease& c : creases) {
      const double s = subdivide_sharpness(c.sharpness);
      if (s <= 0.0) continue;
      const Index e = c.edge;  // its point's number
      next.push_back({vertex_point + c.v0, e, split ? split->half(c.edge, c.v0, c.v1) : kInvalidIndex, s});
      next.push_back({e, vertex_point + c.v1, split ? split->half(c.edge, c.v1, c.v0) : kInvalidIndex, s});
    }
    creases.swap(next);
    for (CornerTag& c : corners) {
      c.sharpness = subdivide_sharpness(c.sharpness);
      c.vertex += vertex_point;
    }
    std::erase_if(corners, [](const CornerTag& c) { return c.sharpness <= 0.0; });
  }
  for (const Crease& c : creases) out.creases.push_back({c.v0, c.v1, c.sharpness});
  out.corners = std::move(corners);
  std::vector<Index> holes = level.tags.holes;
  std::sort(holes.begin(), holes.end());
  holes.erase(std::unique(holes.begin(), holes.end()), holes.end());
  const auto per_face = static_cast<Index>(numbering.faces(numbering.levels()) / numbering.faces(0));
  for (const Index f : holes)
    if (f >= 0 && f < t.face_count())
      for (Index i = 0; i < per_face; ++i) out.holes.push_back(f * per_face + i);
  return out;
}

// Face-varying channels follow the triangle split linearly within each
// face (triangle_split_face_varying()): a face's new values are the
// midpoints of its edges, made with the same arithmetic, numbered [the
// level's values | one per corner]. Each new value belongs to one face.
struct FaceVaryingLevels {
  std::vector<std::int64_t> faces;  // of the levels before the last
  std::vector<Index> values;        // the value count of each level
};

FaceVaryingLevels face_varying_levels(const FaceVaryingChannel& channel, const TriangleNumbering& numbering) {
  FaceVaryingLevels levels{{}, {channel.value_count()}};
  for (int depth = 0; depth < numbering.levels(); ++depth) {
    levels.faces.push_back(numbering.faces(depth));
    levels.values.push_back(levels.values.back() + static_cast<Index>(3 * numbering.faces(depth)));
  }
  return levels;
}

// The values and last-level indices of face `face` of the level at `depth`,
// whose corners hold values `ids`, and of its descendants.
void split_face_varying(const FaceVaryingLevels& levels, Index face, const std::array<Index, 3>& ids, std::size_t depth,
                        FaceVaryingChannel& out) {
  if (depth == levels.faces.size()) {
    std::copy(ids.begin(), ids.end(), out.indices.begin() + 3 * static_cast<std::ptrdiff_t>(face));
    return;
  }
  const auto k = static_cast<std::size_t>(out.components);
  const Index first = levels.values[depth] + 3 * face;  // the midpoints of the edges leaving corners 0, 1, 2
  auto value = [&](Index i) { return out.values.data() + static_cast<std::size_t>(i) * k; };
  for (std::size_t c = 0; c < 3; ++c) {
    const double* a = value(ids[c]);
    const double* b = value(ids[(c + 1) % 3]);
    double* mid = value(first + static_cast<Index>(c));
    for (std::size_t j = 0; j < k; ++j) mid[j] = 0.5 * (a[j] + b[j]);
  }
  for (Index c = 0; c < 3; ++c)
    split_face_varying(levels, 4 * face + c, {ids[static_cast<std::size_t>(c)], first + c, first + (c + 2) % 3},
                       depth + 1, out);
  split_face_varying(levels, 4 * face + 3, {first, first + 1, first + 2}, depth + 1, out);
}

// What the positions and the stencils share: the numbering, which faces
// are regular, and the masks' mesh of the others.
struct TrianglePlan {
  const MeshTopology& topology;
  TriangleNumbering numbering;
  RegularTriangleGrid rule;
  int reach = 1;  // the patch's steps beyond the triangle
  int levels = 0;
  int n = 0;           // grid intervals per face side: 2^levels
  Index per_face = 0;  // final faces per face: 4^levels
  std::vector<char> regular_vertex = {};  // per vertex (regular_triangle_vertices())
  std::vector<char> regular = {};         // per face, once known (regular_faces())
  MasksMesh local = {};                   // the others', once known (take_others())
  RefineOptions by_masks = {};

  std::size_t slots() const { return static_cast<std::size_t>(triangle_slots(reach)); }
  // Face f's control points, and whether it is regular. Gathered where
  // needed rather than kept: a level's patches are more indices than its
  // faces.
  bool patch(Index f, std::span<Index> points) const {
    return gather_triangle_patch(topology, f, reach, regular_vertex, points);
  }
  std::int64_t last_faces() const { return numbering.faces(levels); }
  std::int64_t last_vertices() const { return numbering.vertices(levels); }
};

// The plan, without its faces' regularity; nullopt where the grid path does
// not apply, or where most faces have a corner where the rules are not the
// regular ones (the masks are then faster).
std::optional<TrianglePlan> plan_triangles(const PolygonMesh& level, const MeshTopology& t, const Scheme& scheme,
                                           const RefineOptions& options, int levels) {
  const std::optional<RegularTriangleGrid> rule = regular_triangle_grid_of(scheme);
  if (!rule || scheme.split != SplitRule::triangle || scheme.steps || !covers_level(level, t, options, levels, 3) ||
      t.face_count() == 0)
    return std::nullopt;
  std::optional<TriangleLevel> start = triangle_level(t);
  if (!start) return std::nullopt;
  // Refused where the last level overflows the index type.
  std::int64_t faces = t.face_count(), edges = t.edge_count(), vertices = t.vertex_count();
  for (int l = 0; l < levels; ++l) {
    vertices += edges;
    edges = 2 * edges + 3 * faces;
    faces *= 4;
  }
  constexpr auto kMax = static_cast<std::int64_t>(std::numeric_limits<Index>::max());
  if (3 * faces > kMax || edges > kMax || vertices > kMax) return std::nullopt;
  std::vector<char> regular_vertex = regular_triangle_vertices(t, sharp_vertices(level, t));
  Index irregular = 0;
  for (Index f = 0; f < t.face_count(); ++f)
    for (const Index v : t.face_vertices(f))
      if (!regular_vertex[static_cast<std::size_t>(v)]) {
        ++irregular;
        break;
      }
  if (2 * irregular > t.face_count()) return std::nullopt;
  const Index nf = t.face_count();
  return TrianglePlan{.topology = t,
                      .numbering = TriangleNumbering(std::move(*start), levels),
                      .rule = *rule,
                      .reach = rule->patch_reach(),
                      .levels = levels,
                      .n = 1 << levels,
                      .per_face = static_cast<Index>(faces / nf),
                      .regular_vertex = std::move(regular_vertex),
                      .regular = {},
                      .local = MasksMesh{},
                      .by_masks = masks_options(options, levels)};
}

// Every face's regularity, by gathering its patch.
std::vector<char> regular_faces(const TrianglePlan& plan) {
  std::vector<char> regular(static_cast<std::size_t>(plan.topology.face_count()));
  tbb::parallel_for(tbb::blocked_range<Index>(0, plan.topology.face_count(), 4096),
                    [&](const tbb::blocked_range<Index>& range) {
                      std::array<Index, kMaxTriangleSlots> patch;
                      for (Index f = range.begin(); f != range.end(); ++f)
                        regular[static_cast<std::size_t>(f)] = plan.patch(f, {patch.data(), plan.slots()});
                    });
  return regular;
}

// Sets the plan's faces' regularity and the masks' mesh of the others;
// false where that mesh would hold most faces (the masks are then faster).
bool take_others(TrianglePlan& plan, const PolygonMesh& level, std::vector<char> regular) {
  // The masks' mesh keeps its artificial boundary beyond what the faces'
  // points read: one ring for Loop's rules. Where edge points read wings
  // two steps out, one ring changes the points of
  // tests/refine/grid_butterfly_test.cpp's meshes; two give the masks'
  // values there, and three keep a ring of margin.
  std::optional<MasksMesh> local = masks_mesh(level, plan.topology, regular, plan.reach == 1 ? 1 : 3);
  if (!local) return false;
  plan.regular = std::move(regular);
  plan.local = std::move(*local);
  return true;
}

// Walks face f's final faces (on_face(sub-face) for each) and records, for
// each point of its grid, its final vertex number (s.index) and, for a face
// of the masks' mesh, the point's number in that mesh's refinement, whose
// faces are `local_faces` (s.local_index; none: f is taken as regular).
template <typename OnFace>
void walk_face(const TrianglePlan& plan, Index f, std::span<const Index> local_faces, Scratch& s, OnFace&& on_face) {
  const bool grid = local_faces.empty() || plan.regular[static_cast<std::size_t>(f)] != 0;
  const int stride = plan.n + 1;
  const Index local_first = grid ? 0 : plan.local.face_in_mesh[static_cast<std::size_t>(f)] * plan.per_face;
  plan.numbering.for_each_final_face(f, [&](const SubTriangle& sub) {
    on_face(sub);
    const auto mine = static_cast<std::size_t>(local_first + (sub.face - f * plan.per_face)) * 3;
    for (std::size_t c = 0; c < 3; ++c) {
      const auto at = static_cast<std::size_t>(sub.at[c].y * stride + sub.at[c].x);
      s.index[at] = sub.vertex[c];
      if (!grid) s.local_index[at] = local_faces[mine + c];
    }
  });
}

// Calls fn(x, y, at) for each point of face f's grid that f owns, `at` its
// place in the scratch index arrays.
template <typename Fn>
void for_each_owned_point(const TrianglePlan& plan, Index f, Fn&& fn) {
  const TriangleOwnership own = triangle_ownership_of(plan.topology, f, plan.n);
  for (int y = 0; y <= plan.n; ++y)
    for (int x = 0; x + y <= plan.n; ++x)
      if (own.owns({x, y})) fn(x, y, static_cast<std::size_t>(y * (plan.n + 1) + x));
}

}  // namespace

std::optional<PolygonMesh> refine_triangles_as_grids(const PolygonMesh& level, const MeshTopology& t,
                                                     const Scheme& scheme, const RefineOptions& options, int levels) {
  std::optional<TrianglePlan> plan = plan_triangles(level, t, scheme, options, levels);
  if (!plan) return std::nullopt;
  PolygonMesh out = sized_result(level, options, last_level_tags(level, t, plan->numbering), plan->last_vertices(),
                                 plan->last_faces(), 3);
  std::vector<FaceVaryingLevels> face_varying;
  for (const FaceVaryingChannel& in : level.face_varying_channels) {
    face_varying.push_back(face_varying_levels(in, plan->numbering));
    FaceVaryingChannel& channel = out.face_varying_channels.emplace_back();
    channel.name = in.name;
    channel.components = in.components;
    assign_large(channel.values, static_cast<std::size_t>(face_varying.back().values.back()) *
                                     static_cast<std::size_t>(in.components));
    std::copy(in.values.begin(), in.values.end(), channel.values.begin());
    assign_large(channel.indices, 3 * static_cast<std::size_t>(plan->last_faces()));
  }
  const RegularTriangleGrid& rule = plan->rule;
  const PointValues values(level);
  const int width = values.width, n = plan->n, reach = plan->reach, side = n + 2 * reach + 1;
  auto refine_grid = [&](Scratch& s) {
    if (reach == 1) width == 3 ? refine_triangle_patch<3, 1>(rule, levels, width, s) : refine_triangle_patch<0, 1>(rule, levels, width, s);
    else width == 3 ? refine_triangle_patch<3, 2>(rule, levels, width, s) : refine_triangle_patch<0, 2>(rule, levels, width, s);
  };
  // Shallow grids make only the points their face owns, each straight from
  // the control points: with two levels a face owns about 8 of its grid's
  // 15 points, which level by level take 33 with the margin.
  const std::optional<TrianglePointRows> rows =
      levels <= kDirectTriangleLevels ? std::optional<TrianglePointRows>(std::in_place, rule, levels) : std::nullopt;
  auto owned_points_directly = [&](Index f, Scratch& s) {
    for_each_owned_point(*plan, f, [&](int, int, std::size_t at) {
      const int* slot = rows->slots.data();
      const double* weight = rows->weights.data();
      const int begin = rows->offsets[at], end = rows->offsets[at + 1];
      if (width == 3) {
        double x = 0.0, y = 0.0, z = 0.0;
        for (int e = begin; e < end; ++e) {
          const double* p = s.grid.data() + 3 * slot[e];
          x += weight[e] * p[0], y += weight[e] * p[1], z += weight[e] * p[2];
        }
        out.positions[static_cast<std::size_t>(s.index[at])] = {x, y, z};
        return;
      }
      double* value = s.refined.data();
      std::fill_n(value, width, 0.0);
      for (int e = begin; e < end; ++e)
        for (int c = 0; c < width; ++c) value[c] += weight[e] * s.grid[static_cast<std::size_t>(slot[e] * width + c)];
      scatter(value, s.index[at], out);
    });
  };

  // Every face's final faces and face-varying values, and the points of the
  // regular faces, whose patches are gathered here, once: the faces whose
  // gathering fails are the masks'.
  std::vector<char> regular(static_cast<std::size_t>(t.face_count()));
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(tbb::blocked_range<Index>(0, t.face_count(), 64), [&](const tbb::blocked_range<Index>& range) {
    Scratch& s = scratch.local();
    s.size_for(n, width, reach);
    for (Index f = range.begin(); f != range.end(); ++f) {
      walk_face(*plan, f, {}, s, [&](const SubTriangle& sub) {
        const auto at = static_cast<std::size_t>(sub.face) * 3;
        out.face_offsets[static_cast<std::size_t>(sub.face)] = sub.face * 3;
        std::copy(sub.vertex.begin(), sub.vertex.end(), out.face_indices.begin() + static_cast<std::ptrdiff_t>(at));
      });
      for (std::size_t ch = 0; ch < face_varying.size(); ++ch) {
        const auto corners = level.face_varying_channels[ch].indices.begin() + 3 * static_cast<std::ptrdiff_t>(f);
        split_face_varying(face_varying[ch], f, {corners[0], corners[1], corners[2]}, 0, out.face_varying_channels[ch]);
      }
      std::array<Index, kMaxTriangleSlots> patch;
      if (!plan->patch(f, {patch.data(), plan->slots()})) continue;
      regular[static_cast<std::size_t>(f)] = 1;
      for (std::size_t i = 0; i < plan->slots(); ++i)
        if (patch[i] != kInvalidIndex) values.gather(patch[i], s.grid.data() + i * static_cast<std::size_t>(width));
      if (rows) {
        owned_points_directly(f, s);
        continue;
      }
      refine_grid(s);
      for_each_owned_point(*plan, f, [&](int x, int y, std::size_t at) {
        scatter(s.grid.data() + static_cast<std::size_t>(((y + reach) * side + x + reach) * width), s.index[at], out);
      });
    }
  });
  out.face_offsets.back() = static_cast<Index>(3 * plan->last_faces());

  // The other faces' points, from the masks' refinement of the small mesh
  // around them.
  if (std::all_of(regular.begin(), regular.end(), [](char r) { return r != 0; })) return out;
  if (!take_others(*plan, level, std::move(regular))) return std::nullopt;
  const PolygonMesh local_refined = refine(plan->local.mesh, scheme, plan->by_masks);
  tbb::parallel_for(tbb::blocked_range<Index>(0, t.face_count(), 64), [&](const tbb::blocked_range<Index>& range) {
    Scratch& s = scratch.local();
    s.size_for(n, width, reach);
    for (Index f = range.begin(); f != range.end(); ++f) {
      if (plan->regular[static_cast<std::size_t>(f)]) continue;
      walk_face(*plan, f, local_refined.face_indices, s, [](const SubTriangle&) {});
      for_each_owned_point(*plan, f, [&](int, int, std::size_t at) {
        copy_point(local_refined, s.local_index[at], s.index[at], out);
      });
    }
  });
  return out;
}

std::optional<StencilTable> triangle_stencils_as_grids(const PolygonMesh& level, const MeshTopology& t,
                                                       const Scheme& scheme, const RefineOptions& options, int levels) {
  std::optional<TrianglePlan> plan = plan_triangles(level, t, scheme, options, levels);
  if (!plan || !take_others(*plan, level, regular_faces(*plan))) return std::nullopt;
  // The masks' mesh: its last level's faces (to place its points) and its table.
  PolygonMesh local_refined;
  StencilTable local_table;
  if (plan->local.mesh.face_count() > 0) {
    local_refined = refine(plan->local.mesh, scheme, plan->by_masks);
    local_table = refine_stencil_table(plan->local.mesh, scheme, plan->by_masks);
  }
  const TrianglePointRows weights(plan->rule, levels);

  // Each vertex's row size, from its owning face; then the rows in place.
  const auto rows = static_cast<std::size_t>(plan->last_vertices());
  std::vector<Index> offsets;
  assign_large(offsets, rows + 1, 0);
  tbb::enumerable_thread_specific<Scratch> scratch;
  auto for_each_face = [&](auto&& body) {
    tbb::parallel_for(tbb::blocked_range<Index>(0, t.face_count(), 64), [&](const tbb::blocked_range<Index>& range) {
      Scratch& s = scratch.local();
      s.size_for(plan->n, 1);
      for (Index f = range.begin(); f != range.end(); ++f) {
        walk_face(*plan, f, local_refined.face_indices, s, [](const SubTriangle&) {});
        body(f, s);
      }
    });
  };
  for_each_face([&](Index f, const Scratch& s) {
    const bool grid = plan->regular[static_cast<std::size_t>(f)] != 0;
    for_each_owned_point(*plan, f, [&](int, int, std::size_t at) {
      const Index size = grid ? weights.offsets[at + 1] - weights.offsets[at]
                              : static_cast<Index>(local_table.row_vertices(s.local_index[at]).size());
      offsets[static_cast<std::size_t>(s.index[at]) + 1] = size;
    });
  });
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  if (offsets.back() < 0 || static_cast<std::int64_t>(offsets.back()) > std::numeric_limits<Index>::max())
    return std::nullopt;
  std::vector<Index> sources;
  std::vector<double> row_weights;
  assign_large(sources, static_cast<std::size_t>(offsets.back()));
  assign_large(row_weights, static_cast<std::size_t>(offsets.back()));
  for_each_face([&](Index f, const Scratch& s) {
    const bool grid = plan->regular[static_cast<std::size_t>(f)] != 0;
    std::array<Index, kMaxTriangleSlots> patch;
    if (grid) plan->patch(f, {patch.data(), plan->slots()});
    std::array<std::pair<Index, double>, kMaxTriangleSlots> entries;
    std::vector<std::pair<Index, double>> mapped;  // a masks' row over the level's vertices
    for_each_owned_point(*plan, f, [&](int, int, std::size_t at) {
      std::span<std::pair<Index, double>> row;
      if (grid) {
        std::size_t count = 0;
        for (int e = weights.offsets[at]; e < weights.offsets[at + 1]; ++e)
          entries[count++] = {patch[static_cast<std::size_t>(weights.slots[static_cast<std::size_t>(e)])],
                              weights.weights[static_cast<std::size_t>(e)]};
        row = {entries.data(), count};
      } else {
        const auto vs = local_table.row_vertices(s.local_index[at]);
        const auto ws = local_table.row_weights(s.local_index[at]);
        mapped.clear();
        for (std::size_t k = 0; k < vs.size(); ++k)
          mapped.emplace_back(plan->local.level_vertex[static_cast<std::size_t>(vs[k])], ws[k]);
        row = mapped;
      }
      std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      auto out = static_cast<std::size_t>(offsets[static_cast<std::size_t>(s.index[at])]);
      for (const auto& [vertex, w] : row) {
        sources[out] = vertex;
        row_weights[out++] = w;
      }
    });
  });
  return StencilTable::from_rows(t.vertex_count(), std::move(offsets), std::move(sources), std::move(row_weights));
}

}  // namespace subdiv::detail
