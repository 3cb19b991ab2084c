// The regular triangle's patch: gathering its control points, its share of
// shared points, and its points' weights.

#include "triangle_patch.h"

#include <algorithm>

namespace subdiv::detail {

namespace {

constexpr int kDirection[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};  // counter-clockwise
constexpr int kCorner[3][2] = {{0, 0}, {1, 0}, {0, 1}};

}  // namespace

bool gather_triangle_patch(const MeshTopology& t, Index f, std::array<Index, 16>& patch) {
  patch.fill(kInvalidIndex);
  if (t.face_size(f) != 3) return false;
  const Index first = t.face_first_corner(f);
  const Index corner_vertex[3] = {t.corner_vertex(first), t.corner_vertex(first + 1), t.corner_vertex(first + 2)};
  for (int k = 0; k < 3; ++k) {
    const Index v = corner_vertex[k];
    if (t.vertex_kind(v) != VertexKind::interior || t.valence(v) != 6 || t.vertex_face_count(v) != 6 ||
        !t.ring_ordered(v))
      return false;
    // The ring's edges in order (the level's faces are all triangles, so
    // consecutive ring vertices bound a face at v): find the next corner,
    // and the direction in which the previous one follows it.
    const auto ring = t.vertex_edges(v);
    auto ring_vertex = [&](int j) { return t.other_vertex(ring[static_cast<std::size_t>(((j % 6) + 6) % 6)], v); };
    int start = 0;
    while (start < 6 && ring_vertex(start) != corner_vertex[(k + 1) % 3]) ++start;
    if (start == 6) return false;
    const Index previous = corner_vertex[(k + 2) % 3];
    const int step = ring_vertex(start + 1) == previous ? 1 : ring_vertex(start - 1) == previous ? -1 : 0;
    if (step == 0) return false;
    // Corner k's next corner lies in direction 2k (towards (1, 0), then
    // (-1, 1), then (0, -1)), the ring turning counter-clockwise from it.
    for (int turn = 0; turn < 6; ++turn) {
      const int d = (2 * k + turn) % 6;
      const int i = kCorner[k][0] + kDirection[d][0], j = kCorner[k][1] + kDirection[d][1];
      const Index vertex = ring_vertex(start + step * turn);
      Index& slot = patch[static_cast<std::size_t>((i + 1) + 4 * (j + 1))];
      if (slot != kInvalidIndex && slot != vertex) return false;
      slot = vertex;
    }
  }
  std::array<Index, 16> sorted = patch;
  std::sort(sorted.begin(), sorted.end());
  // Four slots stay empty (kInvalidIndex, which sorts first); the 12 others distinct.
  return sorted[3] == kInvalidIndex && sorted[4] != kInvalidIndex &&
         std::adjacent_find(sorted.begin() + 4, sorted.end()) == sorted.end();
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

std::vector<std::array<double, 16>> triangle_point_weights(const RegularTriangleGrid& rule, int levels) {
  // Refine the 16 slots' unit impulses together: 16 values per point.
  const int n = 1 << levels;
  Scratch s;
  s.size_for(n, 16);
  std::fill(s.grid.begin(), s.grid.end(), 0.0);
  for (std::size_t k = 0; k < 16; ++k) s.grid[k * 16 + k] = 1.0;
  refine_triangle_patch<16>(rule, levels, 16, s);
  std::vector<std::array<double, 16>> weights(static_cast<std::size_t>((n + 1) * (n + 1)));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i + j <= n; ++i)
      std::copy_n(s.grid.data() + ((i + 1) + (n + 3) * (j + 1)) * 16, 16,
                  weights[static_cast<std::size_t>(i + (n + 1) * j)].begin());
  return weights;
}

}  // namespace subdiv::detail
