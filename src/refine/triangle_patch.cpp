// The regular triangle's patch: gathering its control points, its share of
// shared points, and its points' weights.

#include "triangle_patch.h"

#include <algorithm>

namespace subdiv::detail {

namespace {

constexpr int kDirection[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};  // counter-clockwise
constexpr int kCorner[3][2] = {{0, 0}, {1, 0}, {0, 1}};

bool regular_vertex(const MeshTopology& t, Index v, const std::vector<char>& sharp) {
  return t.vertex_kind(v) == VertexKind::interior && t.valence(v) == 6 && t.vertex_face_count(v) == 6 &&
         t.ring_ordered(v) && sharp[static_cast<std::size_t>(v)] == 0;
}

// Places the ring of the regular vertex v at (vi, vj) into the patch, given
// two of its neighbours already placed: the ring runs one way or the other
// from the first, which the second decides. False where they disagree.
bool place_ring(const MeshTopology& t, Index v, int vi, int vj, int reach, std::span<Index> patch) {
  const int side = 2 * reach + 2;
  auto slot = [&](int i, int j) -> Index& { return patch[static_cast<std::size_t>((i + reach) + side * (j + reach))]; };
  const auto ring = t.vertex_edges(v);
  auto ring_vertex = [&](int k) { return t.other_vertex(ring[static_cast<std::size_t>(((k % 6) + 6) % 6)], v); };
  int known[2], found = 0;  // directions whose neighbour is placed
  for (int d = 0; d < 6 && found < 2; ++d) {
    const int i = vi + kDirection[d][0], j = vj + kDirection[d][1];
    if (in_hexagon(i, j, 1, reach) && slot(i, j) != kInvalidIndex) known[found++] = d;
  }
  if (found < 2) return false;
  const Index first = slot(vi + kDirection[known[0]][0], vj + kDirection[known[0]][1]);
  const Index second = slot(vi + kDirection[known[1]][0], vj + kDirection[known[1]][1]);
  int start = 0;
  while (start < 6 && ring_vertex(start) != first) ++start;
  if (start == 6) return false;
  const int apart = known[1] - known[0];
  const int step = ring_vertex(start + apart) == second ? 1 : ring_vertex(start - apart) == second ? -1 : 0;
  if (step == 0) return false;
  for (int turn = 0; turn < 6; ++turn) {
    const int d = (known[0] + turn) % 6;
    const int i = vi + kDirection[d][0], j = vj + kDirection[d][1];
    if (!in_hexagon(i, j, 1, reach)) continue;
    const Index vertex = ring_vertex(start + step * turn);
    Index& at = slot(i, j);
    if (at != kInvalidIndex && at != vertex) return false;
    at = vertex;
  }
  return true;
}

}  // namespace

bool gather_triangle_patch(const MeshTopology& t, Index f, int reach, const std::vector<char>& sharp,
                           std::span<Index> patch) {
  std::fill(patch.begin(), patch.end(), kInvalidIndex);
  if (t.face_size(f) != 3) return false;
  const int side = 2 * reach + 2;
  auto slot = [&](int i, int j) -> Index& { return patch[static_cast<std::size_t>((i + reach) + side * (j + reach))]; };
  const Index first = t.face_first_corner(f);
  for (int k = 0; k < 3; ++k) {
    const Index v = t.corner_vertex(first + k);
    if (!regular_vertex(t, v, sharp)) return false;
    slot(kCorner[k][0], kCorner[k][1]) = v;
  }
  // The corners' rings (each corner knows the other two), then, at reach
  // 2, the rings of the points they placed, which must be regular too.
  for (int k = 0; k < 3; ++k)
    if (!place_ring(t, t.corner_vertex(first + k), kCorner[k][0], kCorner[k][1], reach, patch)) return false;
  if (reach == 2)
    for (int j = -1; j <= 2; ++j)
      for (int i = -1; i + j <= 2; ++i) {
        if (!in_hexagon(i, j, 1, 1) || (i >= 0 && j >= 0 && i + j <= 1)) continue;  // the first ring only
        const Index v = slot(i, j);
        if (v == kInvalidIndex || !regular_vertex(t, v, sharp) || !place_ring(t, v, i, j, reach, patch)) return false;
      }
  // Every slot of the hexagon set, with distinct points.
  std::array<Index, kMaxTriangleSlots> points{};
  std::size_t count = 0;
  for (int j = -reach; j <= 1 + reach; ++j)
    for (int i = -reach; i <= 1 + reach; ++i)
      if (in_hexagon(i, j, 1, reach)) {
        if (slot(i, j) == kInvalidIndex) return false;
        points[count++] = slot(i, j);
      }
  std::sort(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(count));
  return std::adjacent_find(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(count)) ==
         points.begin() + static_cast<std::ptrdiff_t>(count);
}

TriangleOwnership triangle_ownership_of(const MeshTopology& t, Index f, int n) {
  TriangleOwnership o;
  o.n = n;
  const Index first = t.face_first_corner(f);
  for (int c = 0; c < 3; ++c) {
    o.corner[c] = t.corner_face(t.vertex_corners(t.corner_vertex(first + c)).front()) == f;
    o.edge[c] = t.corner_face(t.edge_corners(t.corner_edge(first + c)).front()) == f;
  }
  return o;
}

std::vector<double> triangle_point_weights(const RegularTriangleGrid& rule, int levels) {
  // Refine the slots' unit impulses together: one value per slot and point.
  const int n = 1 << levels, reach = rule.patch_reach(), slots = triangle_slots(reach);
  const auto k = static_cast<std::size_t>(slots);
  Scratch s;
  s.size_for(n, slots, reach);
  std::fill(s.grid.begin(), s.grid.end(), 0.0);
  for (std::size_t i = 0; i < k; ++i) s.grid[i * k + i] = 1.0;
  if (reach == 1) refine_triangle_patch<0, 1>(rule, levels, slots, s);
  else refine_triangle_patch<0, 2>(rule, levels, slots, s);
  std::vector<double> weights(static_cast<std::size_t>((n + 1) * (n + 1)) * k);
  const int side = n + 2 * reach + 1;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i + j <= n; ++i)
      std::copy_n(s.grid.data() + static_cast<std::size_t>((i + reach) + side * (j + reach)) * k, k,
                  weights.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(i + (n + 1) * j) * k));
  return weights;
}

}  // namespace subdiv::detail
