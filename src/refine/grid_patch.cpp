// The regular patch of a face: gathering its control points, its share of
// shared points, and the stencil's weights along a grid line.

#include "grid_patch.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <type_traits>

namespace subdiv::detail {

namespace {

// A quad placed on the patch's grid: its corner `origin` at (x, y), the
// next corners counter-clockwise at (x + 1, y), (x + 1, y + 1), (x, y + 1).
struct PlacedQuad {
  Index origin;  // a corner of the topology
  int x, y;
};

// The quad across one side of `q`, placed; nullopt at a boundary or where
// the neighbour is not a quad. On a consistently oriented mesh the corner
// across a side runs it the other way, which fixes the neighbour's frame.
std::optional<PlacedQuad> step(const MeshTopology& t, const PlacedQuad& q, int dx, int dy) {
  const Index c0 = q.origin, c1 = t.corner_next(c0), c2 = t.corner_next(c1), c3 = t.corner_next(c2);
  // The side crossed: +x is c1's edge, +y c2's, -x c3's, -y c0's.
  const Index side = dx > 0 ? c1 : dy > 0 ? c2 : dx < 0 ? c3 : c0;
  const Index d = t.corner_across(side);
  if (d == kInvalidIndex || t.face_size(t.corner_face(d)) != 4 || t.corner_vertex(d) != t.corner_vertex(t.corner_next(side)))
    return std::nullopt;
  // d sits at the crossed side's far end, seen from q; the neighbour's
  // origin is the corner that lands on its own (0, 0).
  const Index origin = dx > 0 ? t.corner_next(d) : dy > 0 ? d : dx < 0 ? t.corner_prev(d) : t.corner_next(t.corner_next(d));
  return PlacedQuad{origin, q.x + dx, q.y + dy};
}

bool regular_vertex(const MeshTopology& t, Index v, const std::vector<char>& sharp) {
  return t.vertex_kind(v) == VertexKind::interior && t.valence(v) == 4 && t.vertex_face_count(v) == 4 &&
         sharp[static_cast<std::size_t>(v)] == 0;
}

// kRingSlots[k][m]: at reach 1, the slots of the points that the m-th quad
// counter-clockwise around the face's corner k (m = 1, 2, 3; the face is
// m = 0) adds: its corner after k's, the one opposite, the one before.
constexpr auto kRingSlots = [] {
  constexpr int kCornerAt[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  constexpr int kDirection[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};  // counter-clockwise
  std::array<std::array<std::array<int, 3>, 4>, 4> slots{};
  auto slot = [](int x, int y) { return (y + 1) * 4 + (x + 1); };
  for (int k = 0; k < 4; ++k)
    for (int m = 1; m < 4; ++m) {
      const int* a = kDirection[(k + m) % 4];  // corner k's next corner lies in direction k
      const int* b = kDirection[(k + m + 1) % 4];
      const int x = kCornerAt[k][0], y = kCornerAt[k][1];
      slots[static_cast<std::size_t>(k)][static_cast<std::size_t>(m)] = {
          slot(x + a[0], y + a[1]), slot(x + a[0] + b[0], y + a[1] + b[1]), slot(x + b[0], y + b[1])};
    }
  return slots;
}();

// gather_patch() at reach 1, read from the corners' ordered rings of four
// quads rather than walked quad by quad: the quads around a regular corner
// follow one another counter-clockwise in vertex_corners().
bool gather_ring_patch(const MeshTopology& t, Index f, const std::vector<char>& sharp, std::span<Index> patch) {
  std::fill(patch.begin(), patch.begin() + 16, kInvalidIndex);
  const Index first = t.face_first_corner(f);
  constexpr int kCornerSlot[4] = {5, 6, 10, 9};
  for (int k = 0; k < 4; ++k) {
    const Index v = t.corner_vertex(first + k);
    if (!regular_vertex(t, v, sharp) || !t.ring_ordered(v)) return false;
    patch[static_cast<std::size_t>(kCornerSlot[k])] = v;
  }
  bool disagree = false;
  for (int k = 0; k < 4; ++k) {
    const Index c = first + k;
    const auto ring = t.vertex_corners(t.corner_vertex(c));
    std::size_t j = 0;
    while (j < 4 && ring[j] != c) ++j;
    if (j == 4) return false;
    for (std::size_t m = 1; m < 4; ++m) {
      const Index around = ring[(j + m) % 4];
      if (t.face_size(t.corner_face(around)) != 4) return false;
      const Index next = t.corner_next(around);
      const std::array<Index, 3> points = {t.corner_vertex(next), t.corner_vertex(t.corner_next(next)),
                                           t.corner_vertex(t.corner_prev(around))};
      const auto& slots = kRingSlots[static_cast<std::size_t>(k)][m];
      for (std::size_t i = 0; i < 3; ++i) {
        Index& at = patch[static_cast<std::size_t>(slots[i])];
        disagree |= at != kInvalidIndex && at != points[i];
        at = points[i];
      }
    }
  }
  if (disagree) return false;
  std::array<Index, 16> points;
  std::copy_n(patch.begin(), 16, points.begin());
  return set_and_distinct(points);
}

}  // namespace

bool gather_patch(const MeshTopology& t, Index f, int reach, const std::vector<char>& sharp, std::span<Index> patch) {
  if (reach == 1 && t.face_size(f) == 4) return gather_ring_patch(t, f, sharp, patch);
  const int side = patch_side(reach);
  std::fill(patch.begin(), patch.end(), kInvalidIndex);
  auto place = [&](const PlacedQuad& q) {
    Index c = q.origin;
    static constexpr int kAt[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto& at : kAt) {
      const Index v = t.corner_vertex(c);
      Index& slot = patch[static_cast<std::size_t>((q.y + at[1] + reach) * side + q.x + at[0] + reach)];
      if (slot != kInvalidIndex && slot != v) return false;
      slot = v;
      c = t.corner_next(c);
    }
    return true;
  };
  if (t.face_size(f) != 4) return false;
  // The column of faces through f, up and down, then each column face's row
  // left and right: every face of the (2r + 1)^2 block placed once.
  std::array<PlacedQuad, 2 * kMaxPatchReach + 1> column;
  column[static_cast<std::size_t>(reach)] = {t.face_first_corner(f), 0, 0};
  for (const int dy : {1, -1})
    for (int y = dy; std::abs(y) <= reach; y += dy) {
      const std::optional<PlacedQuad> q = step(t, column[static_cast<std::size_t>(reach + y - dy)], 0, dy);
      if (!q) return false;
      column[static_cast<std::size_t>(reach + y)] = *q;
    }
  for (int y = -reach; y <= reach; ++y) {
    const PlacedQuad& middle = column[static_cast<std::size_t>(reach + y)];
    if (!place(middle)) return false;
    for (const int dx : {1, -1}) {
      PlacedQuad q = middle;
      for (int x = 1; x <= reach; ++x) {
        const std::optional<PlacedQuad> next = step(t, q, dx, 0);
        if (!next || !place(*next)) return false;
        q = *next;
      }
    }
  }
  const auto points = static_cast<std::size_t>(side * side);
  auto distinct = [&]<std::size_t N>(std::integral_constant<std::size_t, N>) {
    std::array<Index, N> copy;
    std::copy_n(patch.begin(), N, copy.begin());
    return set_and_distinct(copy);
  };
  const bool ok = reach == 1   ? distinct(std::integral_constant<std::size_t, 16>{})
                  : reach == 2 ? distinct(std::integral_constant<std::size_t, 36>{})
                               : distinct(std::integral_constant<std::size_t, 64>{});
  if (!ok) return false;
  // Reach 1 (Catmull-Clark's rules): the corners' rings are all the rules
  // read. Wider stencils read their neighbours' lines too: every point.
  if (reach == 1) {
    for (const int at : {side + 1, side + 2, 2 * side + 2, 2 * side + 1})
      if (!regular_vertex(t, patch[static_cast<std::size_t>(at)], sharp)) return false;
    return true;
  }
  for (std::size_t i = 0; i < points; ++i)
    if (!regular_vertex(t, patch[i], sharp)) return false;
  return true;
}

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

std::vector<double> line_weights(const RegularGrid& rule, int levels) {
  const int n = 1 << levels, reach = rule.patch_reach(), side = patch_side(reach);
  std::vector<double> weights(static_cast<std::size_t>((n + 1) * side));
  // Refine each control point's unit impulse along the line, as refine_line
  // refines values (one double per point).
  std::vector<double> line, finer;
  for (int i = 0; i < side; ++i) {
    line.assign(static_cast<std::size_t>(side), 0.0);
    line[static_cast<std::size_t>(i)] = 1.0;
    int m = side;
    for (int l = 0; l < levels; ++l) {
      finer.resize(static_cast<std::size_t>(2 * m - 2 * reach - 1));
      if (reach == 1) refine_line<1, 1>(rule, line.data(), 1, m, finer.data(), 1, 1);
      else if (reach == 2) refine_line<1, 2>(rule, line.data(), 1, m, finer.data(), 1, 1);
      else refine_line<1, 3>(rule, line.data(), 1, m, finer.data(), 1, 1);
      line.swap(finer);
      m = 2 * m - 2 * reach - 1;
    }
    for (int x = 0; x <= n; ++x)
      weights[static_cast<std::size_t>(x * side + i)] = line[static_cast<std::size_t>(x + reach)];
  }
  return weights;
}

}  // namespace subdiv::detail
