// The regular triangle's patch: gathering its control points, its share of
// shared points, and its points' weights.

#include "triangle_patch.h"

#include <algorithm>
#include <array>
#include <utility>

namespace subdiv::detail {

namespace {

constexpr int kDirection[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};  // counter-clockwise
constexpr int kCorner[3][2] = {{0, 0}, {1, 0}, {0, 1}};

bool regular_vertex(Index v, const std::vector<char>& regular) { return regular[static_cast<std::size_t>(v)] != 0; }

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

// The direction of corner k's next corner, seen from corner k.
constexpr int kNextDirection[3] = {0, 2, 4};

// kRingSlots[r][k][d]: at reach r, the slot of corner k's neighbour in
// direction kNextDirection[k] + d.
constexpr auto kRingSlots = [] {
  std::array<std::array<std::array<int, 6>, 3>, kMaxTriangleReach + 1> slots{};
  for (int r = 1; r <= kMaxTriangleReach; ++r)
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 6; ++d) {
        const int direction = (kNextDirection[k] + d) % 6;
        const int i = kCorner[k][0] + kDirection[direction][0], j = kCorner[k][1] + kDirection[direction][1];
        slots[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)][static_cast<std::size_t>(d)] =
            (i + r) + (2 * r + 2) * (j + r);
      }
  return slots;
}();

// kNewDirections[k]: the directions d (from kNextDirection[k]) of corner
// k's ring that no corner before it places: the others are the corners
// themselves and, shared by two corners, the vertex opposite each edge,
// which both read from the same face across that edge.
constexpr std::array<std::pair<std::size_t, std::size_t>, 3> kNewDirections = {{{2, 6}, {3, 6}, {3, 5}}};

// Places the rings of the triangle's corners, read from their ordered
// corners: around a regular vertex, face j + 1 of vertex_corners() follows
// face j counter-clockwise, so the next corner of its corner lies one
// direction further. Reads the corner arrays only, unlike place_ring(),
// which searches the ring's edges. At reach 1 each point is read once (the
// rings of ordered regular vertices agree where they overlap); at reach 2,
// where place_ring() follows, every ring point is placed and checked.
bool place_corner_rings(const MeshTopology& t, Index first, int reach, std::span<Index> patch) {
  bool disagree = false;
  for (std::size_t k = 0; k < 3; ++k) {
    const Index c = first + static_cast<Index>(k);
    const auto ring = t.vertex_corners(t.corner_vertex(c));
    std::size_t j = 0;
    while (j < 6 && ring[j] != c) ++j;
    if (j == 6) return false;
    const auto& slot = kRingSlots[static_cast<std::size_t>(reach)][k];
    const auto [begin, end] = reach == 1 ? kNewDirections[k] : std::pair<std::size_t, std::size_t>{0, 6};
    for (std::size_t d = begin; d < end; ++d) {
      const Index vertex = t.corner_vertex(t.corner_next(ring[j + d < 6 ? j + d : j + d - 6]));
      Index& at = patch[static_cast<std::size_t>(slot[d])];
      disagree |= at != kInvalidIndex && at != vertex;
      at = vertex;
    }
  }
  return !disagree;
}

// The N points of a patch's hexagon slots.
template <std::size_t N>
std::array<Index, N> hexagon_points(std::span<const Index> patch, std::span<const int> slots) {
  std::array<Index, N> points;
  for (std::size_t a = 0; a < N; ++a) points[a] = patch[static_cast<std::size_t>(slots[a])];
  return points;
}

}  // namespace

std::vector<char> regular_triangle_vertices(const MeshTopology& t, const std::vector<char>& sharp) {
  std::vector<char> regular(static_cast<std::size_t>(t.vertex_count()));
  for (Index v = 0; v < t.vertex_count(); ++v)
    regular[static_cast<std::size_t>(v)] = t.vertex_kind(v) == VertexKind::interior && t.valence(v) == 6 &&
                                           t.vertex_face_count(v) == 6 && t.ring_ordered(v) &&
                                           sharp[static_cast<std::size_t>(v)] == 0;
  return regular;
}

bool gather_triangle_patch(const MeshTopology& t, Index f, int reach, const std::vector<char>& regular,
                           std::span<Index> patch) {
  std::fill(patch.begin(), patch.end(), kInvalidIndex);
  if (t.face_size(f) != 3) return false;
  const int side = 2 * reach + 2;
  auto slot = [&](int i, int j) -> Index& { return patch[static_cast<std::size_t>((i + reach) + side * (j + reach))]; };
  const Index first = t.face_first_corner(f);
  for (int k = 0; k < 3; ++k) {
    const Index v = t.corner_vertex(first + k);
    if (!regular_vertex(v, regular)) return false;
    slot(kCorner[k][0], kCorner[k][1]) = v;
  }
  // The corners' rings, then, at reach 2, the rings of the points they
  // placed, which must be regular too.
  if (!place_corner_rings(t, first, reach, patch)) return false;
  if (reach == 2)
    for (int j = -1; j <= 2; ++j)
      for (int i = -1; i + j <= 2; ++i) {
        if (!in_hexagon(i, j, 1, 1) || (i >= 0 && j >= 0 && i + j <= 1)) continue;  // the first ring only
        const Index v = slot(i, j);
        if (v == kInvalidIndex || !regular_vertex(v, regular) || !place_ring(t, v, i, j, reach, patch)) return false;
      }
  // Every slot of the hexagon set, with distinct points.
  const std::span<const int> slots = hexagon_slots(reach);
  return reach == 1 ? set_and_distinct(hexagon_points<12>(patch, slots))
                    : set_and_distinct(hexagon_points<27>(patch, slots));
}

std::span<const int> hexagon_slots(int reach) {
  static const auto table = [] {
    std::array<std::vector<int>, kMaxTriangleReach + 1> slots;
    for (int r = 1; r <= kMaxTriangleReach; ++r)
      for (int j = -r; j <= 1 + r; ++j)
        for (int i = -r; i <= 1 + r; ++i)
          if (in_hexagon(i, j, 1, r)) slots[static_cast<std::size_t>(r)].push_back((i + r) + (2 * r + 2) * (j + r));
    return slots;
  }();
  return table[static_cast<std::size_t>(reach)];
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

TrianglePointRows::TrianglePointRows(const RegularTriangleGrid& rule, int levels) {
  const std::vector<double> all = triangle_point_weights(rule, levels);
  const auto k = static_cast<std::size_t>(triangle_slots(rule.patch_reach()));
  offsets.push_back(0);
  for (std::size_t point = 0; point < all.size() / k; ++point) {
    for (std::size_t slot = 0; slot < k; ++slot)
      if (all[point * k + slot] != 0.0) {
        slots.push_back(static_cast<int>(slot));
        weights.push_back(all[point * k + slot]);
      }
    offsets.push_back(static_cast<int>(slots.size()));
  }
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
