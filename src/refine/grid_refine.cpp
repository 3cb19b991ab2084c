// The grid path (grid_refine.h): regular faces as tensor-product grids,
// the others by the masks on a small mesh around them, and the result's
// numbering by index arithmetic.

#include "grid_refine.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"

namespace subdiv::detail {

namespace {

// The element counts of an all-quad level, and of its quad split.
struct LevelCounts {
  std::int64_t faces = 0, edges = 0, vertices = 0;
  LevelCounts child() const { return {4 * faces, 2 * edges + 4 * faces, faces + edges + vertices}; }
};

// A point of a starting face's grid at the final level: x along its first
// edge, y from its first corner towards its last, both in 0 .. n.
struct GridPoint {
  int x, y;
};

GridPoint midpoint(GridPoint a, GridPoint b) { return {(a.x + b.x) / 2, (a.y + b.y) / 2}; }

// A face of some level inside one starting face: its number, its vertices,
// its edges (edge c runs from vertex c to vertex c + 1) and where its
// corners lie on the starting face's final grid. No member initializers:
// four are made per split, and zeroing them first costs more than the split.
struct SubFace {
  Index face;
  std::array<Index, 4> vertex, edge;
  std::array<GridPoint, 4> at;
};

// The four children of `s` in the quad split of its level (`level` its
// counts), numbered as split_topology() and MeshTopology::from_quad_split()
// number them: child face c = corner c = [vertex point of vertex c, edge
// point of edge c, face point, edge point of edge c - 1]; child vertices
// [face points | edge points | vertex points]; child edges [the interior
// edges (face point, edge point), 4 per face in the order of their parent
// edges' numbers | the halves of each parent edge, the one at its smaller
// vertex first].
// Without `edges`, the children's edges are left unset (the last level's
// faces need none).
template <bool edges>
void split_sub_face(const SubFace& s, const LevelCounts& level, std::array<SubFace, 4>& children) {
  const auto edge_point = static_cast<Index>(level.faces);
  const auto vertex_point = static_cast<Index>(level.faces + level.edges);
  const auto halves = static_cast<Index>(4 * level.faces);
  auto interior = [&](Index e) {
    Index rank = 0;
    for (const Index other : s.edge) rank += other < e;
    return 4 * s.face + rank;
  };
  auto half = [&](Index e, Index end, Index other_end) { return halves + 2 * e + (end < other_end ? 0 : 1); };
  const GridPoint centre = midpoint(s.at[0], s.at[2]);
  for (int c = 0; c < 4; ++c) {
    const int next = (c + 1) % 4, prev = (c + 3) % 4;
    SubFace& child = children[static_cast<std::size_t>(c)];
    child.face = 4 * s.face + c;
    child.vertex = {vertex_point + s.vertex[c], edge_point + s.edge[c], s.face, edge_point + s.edge[prev]};
    if constexpr (edges)
      child.edge = {half(s.edge[c], s.vertex[c], s.vertex[next]), interior(s.edge[c]), interior(s.edge[prev]),
                    half(s.edge[prev], s.vertex[c], s.vertex[prev])};
    else
      child.edge = {kInvalidIndex, kInvalidIndex, kInvalidIndex, kInvalidIndex};
    child.at = {s.at[c], midpoint(s.at[c], s.at[next]), centre, midpoint(s.at[prev], s.at[c])};
  }
}

// Calls emit(sub-face) for each face of the last level inside `s`, in
// increasing order; counts[j] are the counts of the level at depth j.
template <typename Emit>
void for_each_final_face(const SubFace& s, std::size_t depth, std::span<const LevelCounts> counts, Emit& emit) {
  if (depth == counts.size()) return emit(s);
  std::array<SubFace, 4> children;
  if (depth + 1 == counts.size()) {
    split_sub_face<false>(s, counts[depth], children);
    for (const SubFace& child : children) emit(child);
    return;
  }
  split_sub_face<true>(s, counts[depth], children);
  for (const SubFace& child : children) for_each_final_face(child, depth + 1, counts, emit);
}

// A starting face as the root of its sub-faces, its corners at the grid's
// corners (0, 0), (n, 0), (n, n), (0, n).
SubFace root_of(const MeshTopology& t, Index f, int n) {
  SubFace s;
  s.face = f;
  const Index first = t.face_first_corner(f);
  for (int c = 0; c < 4; ++c) {
    s.vertex[c] = t.corner_vertex(first + c);
    s.edge[c] = t.corner_edge(first + c);
  }
  s.at = {GridPoint{0, 0}, GridPoint{n, 0}, GridPoint{n, n}, GridPoint{0, n}};
  return s;
}

// The 16 control points of face f's bicubic patch, row-major from (-1, -1)
// to (2, 2) in the face's frame (corners at (0, 0), (1, 0), (1, 1), (0, 1));
// false unless every corner is an interior vertex with four quads around it
// and the 16 points are distinct.
bool gather_patch(const MeshTopology& t, Index f, std::array<Index, 16>& patch) {
  static constexpr int kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  patch.fill(kInvalidIndex);
  const Index first = t.face_first_corner(f);
  for (int c = 0; c < 4; ++c) {
    const Index v = t.corner_vertex(first + c);
    if (t.vertex_kind(v) != VertexKind::interior || t.valence(v) != 4 || t.vertex_face_count(v) != 4) return false;
    // The frame of the corner: x towards the next corner, y towards the previous.
    int x[2] = {kCorner[(c + 1) % 4][0] - kCorner[c][0], kCorner[(c + 1) % 4][1] - kCorner[c][1]};
    int y[2] = {kCorner[(c + 3) % 4][0] - kCorner[c][0], kCorner[(c + 3) % 4][1] - kCorner[c][1]};
    Index corner = first + c;
    for (int turn = 0; turn < 4; ++turn) {
      if (t.face_size(t.corner_face(corner)) != 4) return false;
      const Index next = t.corner_next(corner), prev = t.corner_prev(corner);
      const std::pair<Index, std::array<int, 2>> points[3] = {
          {t.corner_vertex(next), {1, 0}}, {t.corner_vertex(t.corner_next(next)), {1, 1}}, {t.corner_vertex(prev), {0, 1}}};
      for (const auto& [vertex, along] : points) {
        const int px = kCorner[c][0] + along[0] * x[0] + along[1] * y[0];
        const int py = kCorner[c][1] + along[0] * x[1] + along[1] * y[1];
        Index& slot = patch[static_cast<std::size_t>((py + 1) * 4 + px + 1)];
        if (slot != kInvalidIndex && slot != vertex) return false;
        slot = vertex;
      }
      // The next face around v, across the edge towards `prev`; its frame
      // is this one turned a quarter.
      corner = t.corner_across(prev);
      if (corner == kInvalidIndex || t.corner_vertex(corner) != v) return false;
      std::swap(x, y);
      y[0] = -y[0];
      y[1] = -y[1];
    }
    if (corner != first + c) return false;
  }
  std::array<Index, 16> sorted = patch;
  std::sort(sorted.begin(), sorted.end());
  return sorted.front() != kInvalidIndex && std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

// Face f's share of the shared points: a corner vertex belongs to the face
// of its first corner, an edge's inner points to the face of its first side.
struct Ownership {
  std::array<bool, 4> corner{}, edge{};
  int n = 0;
  bool owns(GridPoint p) const {
    if (p.y == 0) return p.x == 0 ? corner[0] : p.x == n ? corner[1] : edge[0];
    if (p.y == n) return p.x == n ? corner[2] : p.x == 0 ? corner[3] : edge[2];
    if (p.x == n) return edge[1];
    if (p.x == 0) return edge[3];
    return true;
  }
};

Ownership ownership_of(const MeshTopology& t, Index f, int n) {
  Ownership o;
  o.n = n;
  const Index first = t.face_first_corner(f);
  for (int c = 0; c < 4; ++c) {
    o.corner[c] = t.corner_face(t.vertex_corners(t.corner_vertex(first + c)).front()) == f;
    o.edge[c] = t.corner_face(t.edge_corners(t.corner_edge(first + c)).front()) == f;
  }
  return o;
}

// One step of the tensor stencil along a line of m points (`in_stride`
// points apart), making 2m - 3 points (`out_stride` apart): the line's points
// from -1 to n + 1 become those from -1 to 2n + 1. A point is `width`
// doubles (kWidth where known at compile time, 0 otherwise).
template <int kWidth>
void refine_line(const RegularGrid& rule, const double* in, std::ptrdiff_t in_stride, int m, double* out,
                 std::ptrdiff_t out_stride, int width) {
  const std::ptrdiff_t w = kWidth > 0 ? kWidth : width;
  const std::ptrdiff_t is = in_stride * w, os = out_stride * w;
  const int fine = 2 * m - 3;
  for (int t = 0; t < fine; ++t) {
    const double* a = in + (t / 2) * is;
    double* o = out + t * os;
    if (t % 2 == 0) {
      for (std::ptrdiff_t j = 0; j < w; ++j) o[j] = rule.odd[0] * a[j] + rule.odd[1] * a[is + j];
    } else {
      for (std::ptrdiff_t j = 0; j < w; ++j)
        o[j] = rule.even[0] * a[j] + rule.even[1] * a[is + j] + rule.even[2] * a[2 * is + j];
    }
  }
}

// A thread's working arrays, sized once for the final level's grid.
struct Scratch {
  std::vector<double> grid, rows, refined;
  std::vector<Index> index;  // the final vertex number of each grid point

  void size_for(int n, int width) {
    const auto side = static_cast<std::size_t>(n + 3);
    const std::size_t doubles = side * side * static_cast<std::size_t>(width);
    if (grid.size() >= doubles) return;
    grid.resize(doubles);
    rows.resize(doubles);
    refined.resize(doubles);
    index.resize(static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1));
  }
};

// Refines the 4 x 4 control values in scratch.grid `levels` times: the
// (n + 3)^2 grid of the patch's points from -1 to n + 1, in scratch.grid.
template <int kWidth>
void refine_patch(const RegularGrid& rule, int levels, int width, Scratch& s) {
  int m = 4;
  for (int l = 0; l < levels; ++l) {
    const int fine = 2 * m - 3;
    for (int r = 0; r < m; ++r)
      refine_line<kWidth>(rule, s.grid.data() + r * m * width, 1, m, s.rows.data() + r * fine * width, 1, width);
    for (int col = 0; col < fine; ++col)
      refine_line<kWidth>(rule, s.rows.data() + col * width, fine, m, s.refined.data() + col * width, fine, width);
    s.grid.swap(s.refined);
    m = fine;
  }
}

// The values refined per point: the position, then each vertex channel's.
struct PointValues {
  const PolygonMesh& mesh;
  int width = 3;

  explicit PointValues(const PolygonMesh& m) : mesh(m) {
    for (const VertexChannel& c : mesh.vertex_channels) width += c.components;
  }
  void gather(Index v, double* out) const {
    const Vec3& p = mesh.positions[static_cast<std::size_t>(v)];
    out[0] = p.x, out[1] = p.y, out[2] = p.z;
    out += 3;
    for (const VertexChannel& c : mesh.vertex_channels) {
      const auto k = static_cast<std::size_t>(c.components);
      std::copy_n(c.values.data() + static_cast<std::size_t>(v) * k, k, out);
      out += k;
    }
  }
};

// Writes one point's values (position, then channels) to vertex v of `out`.
void scatter(const double* values, Index v, PolygonMesh& out) {
  out.positions[static_cast<std::size_t>(v)] = {values[0], values[1], values[2]};
  values += 3;
  for (VertexChannel& c : out.vertex_channels) {
    const auto k = static_cast<std::size_t>(c.components);
    std::copy_n(values, k, c.values.data() + static_cast<std::size_t>(v) * k);
    values += k;
  }
}

// Copies vertex `from` of `in` (position and channels) to vertex `to` of `out`.
void copy_point(const PolygonMesh& in, Index from, Index to, PolygonMesh& out) {
  out.positions[static_cast<std::size_t>(to)] = in.positions[static_cast<std::size_t>(from)];
  for (std::size_t ch = 0; ch < out.vertex_channels.size(); ++ch) {
    const auto k = static_cast<std::size_t>(out.vertex_channels[ch].components);
    std::copy_n(in.vertex_channels[ch].values.data() + static_cast<std::size_t>(from) * k, k,
                out.vertex_channels[ch].values.data() + static_cast<std::size_t>(to) * k);
  }
}

constexpr int kMaxGridLevels = 8;

// The tags of a level made from `parent`: its options without its element
// tags (the callers refuse sharp ones) and without tags no module reads,
// which name the parent's elements.
Tags child_tags(const Tags& parent) {
  Tags tags = parent;
  tags.creases.clear();
  tags.corners.clear();
  tags.holes.clear();
  tags.other.clear();
  return tags;
}

// Whether the grid path covers these levels (grid_refine.h), before looking
// at which faces are regular.
bool covers(const PolygonMesh& level, const MeshTopology& t, const Scheme& scheme, const RefineOptions& options,
            int levels) {
  // Deeper runs take their first levels by the masks, while the mesh is
  // small, so that a face's grid stays within a few megabytes.
  if (!scheme.fast_path.regular_grid || scheme.split != SplitRule::quad || scheme.steps || levels < 1 ||
      levels > kMaxGridLevels)
    return false;
  if (options.boundary_rules != BoundaryRules::standard || options.allow_non_manifold) return false;
  if (!level.face_varying_channels.empty()) return false;
  for (const VertexChannel& c : level.vertex_channels)
    if (c.components <= 0 || c.values.size() != level.positions.size() * static_cast<std::size_t>(c.components))
      return false;
  if (!level.tags.creases.empty() || !level.tags.corners.empty() || !level.tags.holes.empty()) return false;
  for (Index f = 0; f < t.face_count(); ++f)
    if (t.face_size(f) != 4) return false;
  for (Index v = 0; v < t.vertex_count(); ++v)
    if (t.vertex_kind(v) == VertexKind::isolated) return false;
  return true;
}

// The faces that are not regular patches and those sharing a vertex with
// them, as a mesh of their own for the masks (its artificial boundary
// changes only points outside the faces taken from it), with the number
// each face has there (kInvalidIndex for faces not in it).
struct MasksMesh {
  PolygonMesh mesh;
  std::vector<Index> face_in_mesh;
};

// nullopt where it would hold more than half the faces.
std::optional<MasksMesh> masks_mesh(const PolygonMesh& level, const MeshTopology& t, const std::vector<char>& regular) {
  const Index nf = t.face_count();
  std::vector<char> near(static_cast<std::size_t>(t.vertex_count()));
  for (Index f = 0; f < nf; ++f)
    if (!regular[static_cast<std::size_t>(f)])
      for (const Index v : t.face_vertices(f)) near[static_cast<std::size_t>(v)] = 1;
  MasksMesh local;
  local.face_in_mesh.assign(static_cast<std::size_t>(nf), kInvalidIndex);
  std::vector<Index> vertex_in_mesh(static_cast<std::size_t>(t.vertex_count()), kInvalidIndex);
  PolygonMesh& mesh = local.mesh;
  mesh.tags = child_tags(level.tags);
  for (const VertexChannel& c : level.vertex_channels) mesh.vertex_channels.push_back({c.name, c.components, {}});
  for (Index f = 0; f < nf; ++f) {
    const auto vertices = t.face_vertices(f);
    if (std::none_of(vertices.begin(), vertices.end(), [&](Index v) { return near[static_cast<std::size_t>(v)] != 0; }))
      continue;
    if (2 * (mesh.face_count() + 1) > nf) return std::nullopt;
    std::array<Index, 4> face;
    for (std::size_t c = 0; c < 4; ++c) {
      const auto v = static_cast<std::size_t>(vertices[c]);
      if (vertex_in_mesh[v] == kInvalidIndex) {
        vertex_in_mesh[v] = mesh.vertex_count();
        mesh.positions.push_back(level.positions[v]);
        for (std::size_t ch = 0; ch < level.vertex_channels.size(); ++ch) {
          const VertexChannel& in = level.vertex_channels[ch];
          const auto k = static_cast<std::size_t>(in.components);
          mesh.vertex_channels[ch].values.insert(mesh.vertex_channels[ch].values.end(), in.values.begin() + v * k,
                                                 in.values.begin() + (v + 1) * k);
        }
      }
      face[c] = vertex_in_mesh[v];
    }
    local.face_in_mesh[static_cast<std::size_t>(f)] = mesh.add_face(face);
  }
  return local;
}

// The result's arrays, sized, and its tags: the level's options, with the
// crease method refinement used (as the masks' levels name it).
PolygonMesh sized_result(const PolygonMesh& level, const RefineOptions& options, const LevelCounts& counts) {
  PolygonMesh out;
  out.tags = child_tags(level.tags);
  const CreaseMethod method = options.crease_method.value_or(level.tags.crease_method);
  if (out.tags.crease_method != method) {
    out.tags.crease_method = method;
    out.tags.crease_method_set = true;
  }
  assign_large(out.positions, static_cast<std::size_t>(counts.vertices));
  assign_large(out.face_offsets, static_cast<std::size_t>(counts.faces) + 1);
  assign_large(out.face_indices, 4 * static_cast<std::size_t>(counts.faces));
  for (const VertexChannel& c : level.vertex_channels) {
    out.vertex_channels.push_back({c.name, c.components, {}});
    assign_large(out.vertex_channels.back().values,
                 static_cast<std::size_t>(counts.vertices) * static_cast<std::size_t>(c.components));
  }
  return out;
}

}  // namespace

std::optional<PolygonMesh> refine_as_grids(const PolygonMesh& level, const MeshTopology& t, const Scheme& scheme,
                                           const RefineOptions& options, int levels) {
  if (!covers(level, t, scheme, options, levels)) return std::nullopt;
  const Index nf = t.face_count();

  // The levels' counts, refused where the last one overflows the index type.
  std::vector<LevelCounts> counts{{nf, t.edge_count(), t.vertex_count()}};
  for (int l = 0; l < levels; ++l) counts.push_back(counts.back().child());
  const LevelCounts final_counts = counts.back();
  counts.pop_back();
  constexpr auto kMax = static_cast<std::int64_t>(std::numeric_limits<Index>::max());
  if (4 * final_counts.faces > kMax || final_counts.vertices > kMax) return std::nullopt;

  std::vector<char> regular(static_cast<std::size_t>(nf));
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 4096), [&](const tbb::blocked_range<Index>& range) {
    std::array<Index, 16> patch;
    for (Index f = range.begin(); f != range.end(); ++f) regular[static_cast<std::size_t>(f)] = gather_patch(t, f, patch);
  });
  std::optional<MasksMesh> local = masks_mesh(level, t, regular);
  if (!local) return std::nullopt;  // mostly irregular: the masks first
  PolygonMesh local_refined;
  if (local->mesh.face_count() > 0) {
    RefineOptions by_masks = options;
    by_masks.levels = levels;
    by_masks.regular_grids = false;
    by_masks.on_level = nullptr;
    by_masks.allow_non_manifold = true;  // its rim may pinch; the points taken lie inside
    local_refined = refine(local->mesh, scheme, by_masks);
  }

  PolygonMesh out = sized_result(level, options, final_counts);
  const RegularGrid& rule = *scheme.fast_path.regular_grid;
  const PointValues values(level);
  const int width = values.width, n = 1 << levels, side = n + 3;
  const auto per_face = static_cast<Index>(final_counts.faces / nf);  // 4^levels
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 64), [&](const tbb::blocked_range<Index>& range) {
    Scratch& s = scratch.local();
    s.size_for(n, width);
    std::array<Index, 16> patch;
    for (Index f = range.begin(); f != range.end(); ++f) {
      const Ownership own = ownership_of(t, f, n);
      const bool grid = regular[static_cast<std::size_t>(f)] != 0;
      // Faces, and where each vertex lies on the grid; the masks' points of
      // the other faces straight from their mesh.
      const Index local_first = grid ? 0 : local->face_in_mesh[static_cast<std::size_t>(f)] * per_face;
      auto emit = [&](const SubFace& sub) {
        const auto at = static_cast<std::size_t>(sub.face) * 4;
        out.face_offsets[static_cast<std::size_t>(sub.face)] = sub.face * 4;
        for (std::size_t c = 0; c < 4; ++c) {
          out.face_indices[at + c] = sub.vertex[c];
          if (grid) {
            s.index[static_cast<std::size_t>(sub.at[c].y * (n + 1) + sub.at[c].x)] = sub.vertex[c];
          } else if (own.owns(sub.at[c])) {
            const auto mine = static_cast<std::size_t>(local_first + (sub.face - f * per_face)) * 4 + c;
            copy_point(local_refined, local_refined.face_indices[mine], sub.vertex[c], out);
          }
        }
      };
      for_each_final_face(root_of(t, f, n), 0, counts, emit);
      if (!grid) continue;
      gather_patch(t, f, patch);
      for (std::size_t i = 0; i < 16; ++i) values.gather(patch[i], s.grid.data() + i * static_cast<std::size_t>(width));
      if (width == 3) refine_patch<3>(rule, levels, width, s);
      else refine_patch<0>(rule, levels, width, s);
      for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
          if (own.owns({x, y}))
            scatter(s.grid.data() + static_cast<std::size_t>(((y + 1) * side + x + 1) * width),
                    s.index[static_cast<std::size_t>(y * (n + 1) + x)], out);
    }
  });
  out.face_offsets.back() = static_cast<Index>(4 * final_counts.faces);
  return out;
}

}  // namespace subdiv::detail
