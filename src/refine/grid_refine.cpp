// The grid path (grid_refine.h): regular faces as tensor-product grids
// (grid_patch.h), the others by the masks on a small mesh around them, and
// the result's numbering by index arithmetic (grid_numbering.h).

#include "grid_refine.h"

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
#include "grid_numbering.h"
#include "grid_patch.h"
#include "grid_triangles.h"

namespace subdiv::detail {

namespace {

// The tags of the level `counts.size()` quad splits below `level`: its
// options, and its crease, corner and hole tags carried down as
// split_topology() carries them one level at a time with uniform creasing
// (each crease's halves at the ends' vertex points, each numbered by index
// arithmetic; a hole's faces in a row).
Tags last_level_tags(const PolygonMesh& level, const MeshTopology& t, std::span<const LevelCounts> counts) {
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
  for (const LevelCounts& at : counts) {
    const auto edge_point = static_cast<Index>(at.faces), vertex_point = static_cast<Index>(at.faces + at.edges);
    const auto halves = static_cast<Index>(4 * at.faces);
    std::vector<Crease> next;
    for (const Crease& c : creases) {
      const double s = subdivide_sharpness(c.sharpness);
      if (s <= 0.0) continue;
      const Index e = edge_point + c.edge;
      next.push_back({vertex_point + c.v0, e, halves + 2 * c.edge + (c.v0 < c.v1 ? 0 : 1), s});
      next.push_back({e, vertex_point + c.v1, halves + 2 * c.edge + (c.v1 < c.v0 ? 0 : 1), s});
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
  std::int64_t per_face = 1;
  for (std::size_t l = 0; l < counts.size(); ++l) per_face *= 4;
  for (const Index f : holes)
    if (f >= 0 && f < t.face_count())
      for (std::int64_t i = 0; i < per_face; ++i) out.holes.push_back(static_cast<Index>(f * per_face + i));
  return out;
}

// Face-varying channels follow the quad split linearly within each face
// (quad_split_face_varying()): a face's new values are the midpoints of its
// edges and its centroid, made with the same arithmetic in the same order,
// numbered [the level's values | one per corner | one per face]. Each new
// value belongs to one face, so faces fill theirs independently.
struct FaceVaryingLevels {
  std::span<const LevelCounts> counts;  // of the levels before the last
  std::vector<Index> values;            // the value count of each level
};

FaceVaryingLevels face_varying_levels(const FaceVaryingChannel& channel, std::span<const LevelCounts> counts) {
  FaceVaryingLevels levels{counts, {channel.value_count()}};
  for (const LevelCounts& at : counts) levels.values.push_back(levels.values.back() + static_cast<Index>(5 * at.faces));
  return levels;
}

// The values and last-level indices of face `face` of the level at `depth`,
// whose corners hold values `ids`, and of its descendants.
void split_face_varying(const FaceVaryingLevels& levels, Index face, const std::array<Index, 4>& ids,
                        std::size_t depth, FaceVaryingChannel& out) {
  if (depth == levels.counts.size()) {
    std::copy(ids.begin(), ids.end(), out.indices.begin() + 4 * static_cast<std::ptrdiff_t>(face));
    return;
  }
  const auto k = static_cast<std::size_t>(out.components);
  const Index first = levels.values[depth], corners = static_cast<Index>(4 * levels.counts[depth].faces);
  auto value = [&](Index i) { return out.values.data() + static_cast<std::size_t>(i) * k; };
  const Index centroid = first + corners + face;
  double* m = value(centroid);
  std::fill(m, m + k, 0.0);
  for (int c = 0; c < 4; ++c) {
    const double* a = value(ids[static_cast<std::size_t>(c)]);
    const double* b = value(ids[static_cast<std::size_t>((c + 1) % 4)]);
    double* mid = value(first + 4 * face + c);
    for (std::size_t j = 0; j < k; ++j) mid[j] = 0.5 * (a[j] + b[j]);
    for (std::size_t j = 0; j < k; ++j) m[j] += a[j] / 4;
  }
  for (Index c = 0; c < 4; ++c) {
    const std::array<Index, 4> child{ids[static_cast<std::size_t>(c)], first + 4 * face + c, centroid,
                                     first + 4 * face + (c + 3) % 4};
    split_face_varying(levels, 4 * face + c, child, depth + 1, out);
  }
}

// What the positions and the stencils of the grid path share: the levels'
// counts, which faces are regular, and the masks' mesh of the others.
struct GridPlan {
  const MeshTopology& topology;
  RegularGrid rule;
  int reach = 1;                    // the patch's points beyond the face on each side
  int side = 4;                     // control points per patch side: 2 reach + 2
  int levels = 0;
  int n = 0;                        // grid intervals per face side: 2^levels
  Index per_face = 0;               // final faces per face: 4^levels
  std::vector<LevelCounts> counts = {};  // of the levels before the last
  LevelCounts last = {};
  std::vector<char> sharp = {};     // per vertex (sharp_vertices())
  bool manifold = false;            // whether the masks' mesh must not pinch
  std::vector<char> regular = {};   // per face, once known (regular_faces())
  MasksMesh local = {};             // the others', once known (take_others())
  RefineOptions by_masks = {};      // for the masks' mesh

  std::size_t patch_size() const { return static_cast<std::size_t>(side * side); }
  // Face f's control points, and whether it is regular: a patch of the
  // stencil's reach with no sharp point where the rules read. Gathered where
  // needed rather than kept: a level's patches are more indices than its faces.
  bool patch(Index f, std::span<Index> points) const { return gather_patch(topology, f, reach, sharp, points); }
};

// The plan, without its faces' regularity; nullopt where the grid path does
// not apply, or where most faces have a corner where the rules are not the
// regular ones (the masks are then faster).
std::optional<GridPlan> plan_grids(const PolygonMesh& level, const MeshTopology& t, const Scheme& scheme,
                                   const RefineOptions& options, int levels) {
  const std::optional<RegularGrid> rule = regular_grid_of(scheme);
  if (!rule || scheme.split != SplitRule::quad || !covers_level(level, t, options, levels, 4)) return std::nullopt;
  const Index nf = t.face_count();
  if (nf == 0) return std::nullopt;  // nothing to plan; the masks return the empty mesh
  const int reach = rule->patch_reach();
  GridPlan plan{.topology = t, .rule = *rule, .reach = reach, .side = patch_side(reach), .levels = levels,
                .n = 1 << levels};
  plan.counts.push_back({nf, t.edge_count(), t.vertex_count()});
  for (int l = 0; l < levels; ++l) plan.counts.push_back(plan.counts.back().child());
  plan.last = plan.counts.back();
  plan.counts.pop_back();
  // Refused where the last level overflows the index type.
  constexpr auto kMax = static_cast<std::int64_t>(std::numeric_limits<Index>::max());
  if (4 * plan.last.faces > kMax || plan.last.vertices > kMax) return std::nullopt;
  plan.per_face = static_cast<Index>(plan.last.faces / nf);
  plan.sharp = sharp_vertices(level, t);
  Index irregular = 0;
  for (Index f = 0; f < nf; ++f)
    for (const Index v : t.face_vertices(f))
      if (t.vertex_kind(v) != VertexKind::interior || t.valence(v) != 4 || plan.sharp[static_cast<std::size_t>(v)]) {
        ++irregular;
        break;
      }
  if (2 * irregular > nf) return std::nullopt;
  // Composite schemes refine manifold meshes only: their masks' mesh must
  // not pinch.
  plan.manifold = scheme.steps != nullptr;
  plan.by_masks = masks_options(options, levels);
  if (plan.manifold) plan.by_masks.allow_non_manifold = false;
  return plan;
}

// Every face's regularity, by gathering its patch.
std::vector<char> regular_faces(const GridPlan& plan) {
  std::vector<char> regular(static_cast<std::size_t>(plan.topology.face_count()));
  tbb::parallel_for(tbb::blocked_range<Index>(0, plan.topology.face_count(), 4096),
                    [&](const tbb::blocked_range<Index>& range) {
                      std::array<Index, kMaxPatchPoints> patch;
                      for (Index f = range.begin(); f != range.end(); ++f)
                        regular[static_cast<std::size_t>(f)] = plan.patch(f, {patch.data(), plan.patch_size()});
                    });
  return regular;
}

// Sets the plan's faces' regularity and the masks' mesh of the others;
// false where that mesh would hold most faces (the masks are then faster).
bool take_others(GridPlan& plan, const PolygonMesh& level, std::vector<char> regular) {
  // The masks' mesh keeps its artificial boundary beyond what the faces'
  // points read. Catmull-Clark's read the faces around their corners (one
  // ring); a composite scheme's, one ring per smoothing step (its reach);
  // Kobbelt's face points read new edge points on lines one face further
  // out, whose rules see those lines' vertices (reach 2, three rings; with
  // two, the open grid of tests/refine/grid_wide_stencil_test.cpp differs).
  std::optional<MasksMesh> local =
      masks_mesh(level, plan.topology, regular, plan.reach == 1 ? 1 : plan.reach + 1, plan.manifold);
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
void walk_face(const GridPlan& plan, Index f, std::span<const Index> local_faces, Scratch& s, OnFace&& on_face) {
  const bool grid = local_faces.empty() || plan.regular[static_cast<std::size_t>(f)] != 0;
  const int stride = plan.n + 1;
  const Index local_first = grid ? 0 : plan.local.face_in_mesh[static_cast<std::size_t>(f)] * plan.per_face;
  auto emit = [&](const SubFace& sub) {
    on_face(sub);
    const auto mine = static_cast<std::size_t>(local_first + (sub.face - f * plan.per_face)) * 4;
    for (std::size_t c = 0; c < 4; ++c) {
      const auto at = static_cast<std::size_t>(sub.at[c].y * stride + sub.at[c].x);
      s.index[at] = sub.vertex[c];
      if (!grid) s.local_index[at] = local_faces[mine + c];
    }
  };
  for_each_final_face(root_of(plan.topology, f, plan.n), 0, plan.counts, emit);
}

// Calls fn(x, y, at) for each point of face f's grid that f owns, `at` its
// place in the scratch index arrays.
template <typename Fn>
void for_each_owned_point(const GridPlan& plan, Index f, Fn&& fn) {
  const Ownership own = ownership_of(plan.topology, f, plan.n);
  for (int y = 0; y <= plan.n; ++y)
    for (int x = 0; x <= plan.n; ++x)
      if (own.owns({x, y})) fn(x, y, static_cast<std::size_t>(y * (plan.n + 1) + x));
}

}  // namespace

std::optional<PolygonMesh> refine_as_grids(const PolygonMesh& level, const MeshTopology& t, const Scheme& scheme,
                                           const RefineOptions& options, int levels) {
  if (scheme.split == SplitRule::triangle)
    return levels >= kMinTriangleGridLevels ? refine_triangles_as_grids(level, t, scheme, options, levels) : std::nullopt;
  std::optional<GridPlan> plan = plan_grids(level, t, scheme, options, levels);
  if (!plan) return std::nullopt;
  PolygonMesh out = sized_result(level, options, last_level_tags(level, t, plan->counts), plan->last.vertices,
                                 plan->last.faces, 4);
  std::vector<FaceVaryingLevels> face_varying;
  for (std::size_t ch = 0; ch < level.face_varying_channels.size(); ++ch) {
    const FaceVaryingChannel& in = level.face_varying_channels[ch];
    face_varying.push_back(face_varying_levels(in, plan->counts));
    FaceVaryingChannel& channel = out.face_varying_channels.emplace_back();
    channel.name = in.name;
    channel.components = in.components;
    assign_large(channel.values, static_cast<std::size_t>(face_varying.back().values.back()) *
                                     static_cast<std::size_t>(in.components));
    std::copy(in.values.begin(), in.values.end(), channel.values.begin());
    assign_large(channel.indices, 4 * static_cast<std::size_t>(plan->last.faces));
  }
  const RegularGrid& rule = plan->rule;
  const PointValues values(level);
  const int width = values.width, n = plan->n, reach = plan->reach, side = n + 2 * reach + 1;
  auto refine_grid = [&](Scratch& s) {
    if (reach == 1) width == 3 ? refine_patch<3, 1>(rule, levels, width, s) : refine_patch<0, 1>(rule, levels, width, s);
    else if (reach == 2) width == 3 ? refine_patch<3, 2>(rule, levels, width, s) : refine_patch<0, 2>(rule, levels, width, s);
    else width == 3 ? refine_patch<3, 3>(rule, levels, width, s) : refine_patch<0, 3>(rule, levels, width, s);
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
      walk_face(*plan, f, {}, s, [&](const SubFace& sub) {
        const auto at = static_cast<std::size_t>(sub.face) * 4;
        out.face_offsets[static_cast<std::size_t>(sub.face)] = sub.face * 4;
        std::copy(sub.vertex.begin(), sub.vertex.end(), out.face_indices.begin() + static_cast<std::ptrdiff_t>(at));
      });
      for (std::size_t ch = 0; ch < face_varying.size(); ++ch) {
        const auto corners = level.face_varying_channels[ch].indices.begin() + 4 * static_cast<std::ptrdiff_t>(f);
        split_face_varying(face_varying[ch], f, {corners[0], corners[1], corners[2], corners[3]}, 0,
                           out.face_varying_channels[ch]);
      }
      std::array<Index, kMaxPatchPoints> patch;
      if (!plan->patch(f, {patch.data(), plan->patch_size()})) continue;
      regular[static_cast<std::size_t>(f)] = 1;
      for (std::size_t i = 0; i < plan->patch_size(); ++i)
        values.gather(patch[i], s.grid.data() + i * static_cast<std::size_t>(width));
      refine_grid(s);
      for_each_owned_point(*plan, f, [&](int x, int y, std::size_t at) {
        scatter(s.grid.data() + static_cast<std::size_t>(((y + reach) * side + x + reach) * width), s.index[at], out);
      });
    }
  });
  out.face_offsets.back() = static_cast<Index>(4 * plan->last.faces);

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
      walk_face(*plan, f, local_refined.face_indices, s, [](const SubFace&) {});
      for_each_owned_point(*plan, f, [&](int, int, std::size_t at) {
        copy_point(local_refined, s.local_index[at], s.index[at], out);
      });
    }
  });
  return out;
}

std::optional<StencilTable> stencils_as_grids(const PolygonMesh& level, const MeshTopology& t, const Scheme& scheme,
                                              const RefineOptions& options, int levels) {
  if (scheme.split == SplitRule::triangle)
    return levels >= kMinTriangleGridLevels ? triangle_stencils_as_grids(level, t, scheme, options, levels)
                                            : std::nullopt;
  std::optional<GridPlan> plan = plan_grids(level, t, scheme, options, levels);
  if (!plan || !take_others(*plan, level, regular_faces(*plan))) return std::nullopt;
  // The masks' mesh: its last level's faces (to place its points) and its table.
  PolygonMesh local_refined;
  StencilTable local_table;
  if (plan->local.mesh.face_count() > 0) {
    local_refined = refine(plan->local.mesh, scheme, plan->by_masks);
    local_table = refine_stencil_table(plan->local.mesh, scheme, plan->by_masks);
  }
  // A regular point's row, the same for every face: the nonzero products of
  // the line weights, on control point side j + i, made once per grid point.
  const std::vector<double> weights = line_weights(plan->rule, levels);
  const auto side = static_cast<std::size_t>(plan->side);
  const auto points = static_cast<std::size_t>(plan->n + 1);
  std::vector<std::size_t> entry_offsets{0};
  std::vector<std::pair<std::size_t, double>> point_entries;
  for (std::size_t y = 0; y < points; ++y)
    for (std::size_t x = 0; x < points; ++x) {
      for (std::size_t j = 0; j < side; ++j)
        for (std::size_t i = 0; i < side; ++i) {
          const double w = weights[x * side + i] * weights[y * side + j];
          if (w != 0.0) point_entries.emplace_back(side * j + i, w);
        }
      entry_offsets.push_back(point_entries.size());
    }
  auto regular_entries = [&](int x, int y) {
    const std::size_t at = static_cast<std::size_t>(y) * points + static_cast<std::size_t>(x);
    return std::span<const std::pair<std::size_t, double>>(point_entries.data() + entry_offsets[at],
                                                           entry_offsets[at + 1] - entry_offsets[at]);
  };

  // Each vertex's row size, from its owning face; then the rows in place.
  const auto rows = static_cast<std::size_t>(plan->last.vertices);
  std::vector<Index> offsets;
  assign_large(offsets, rows + 1, 0);
  tbb::enumerable_thread_specific<Scratch> scratch;
  auto for_each_face = [&](auto&& body) {
    tbb::parallel_for(tbb::blocked_range<Index>(0, t.face_count(), 64), [&](const tbb::blocked_range<Index>& range) {
      Scratch& s = scratch.local();
      s.size_for(plan->n, 1);
      for (Index f = range.begin(); f != range.end(); ++f) {
        walk_face(*plan, f, local_refined.face_indices, s, [](const SubFace&) {});
        body(f, s);
      }
    });
  };
  for_each_face([&](Index f, const Scratch& s) {
    const bool grid = plan->regular[static_cast<std::size_t>(f)] != 0;
    for_each_owned_point(*plan, f, [&](int x, int y, std::size_t at) {
      const std::size_t size =
          grid ? regular_entries(x, y).size() : local_table.row_vertices(s.local_index[at]).size();
      offsets[static_cast<std::size_t>(s.index[at]) + 1] = static_cast<Index>(size);
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
    std::array<Index, kMaxPatchPoints> patch;
    if (grid) plan->patch(f, {patch.data(), plan->patch_size()});
    std::array<std::pair<Index, double>, kMaxPatchPoints> entries;
    for_each_owned_point(*plan, f, [&](int x, int y, std::size_t at) {
      std::size_t count = 0;
      if (grid)
        for (const auto& [k, w] : regular_entries(x, y)) entries[count++] = {patch[k], w};
      const auto vs = grid ? std::span<const Index>() : local_table.row_vertices(s.local_index[at]);
      const auto ws = grid ? std::span<const double>() : local_table.row_weights(s.local_index[at]);
      std::vector<std::pair<Index, double>> mapped;  // a masks' row over the level's vertices
      for (std::size_t k = 0; k < vs.size(); ++k)
        mapped.emplace_back(plan->local.level_vertex[static_cast<std::size_t>(vs[k])], ws[k]);
      const std::span<std::pair<Index, double>> row =
          grid ? std::span<std::pair<Index, double>>(entries.data(), count) : std::span<std::pair<Index, double>>(mapped);
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
