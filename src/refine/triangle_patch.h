#pragma once
// A regular triangle's patch for the grid path (grid_refine.h) on the
// triangular lattice: its control points (12 within one step of the
// triangle, 27 within two for stencils with wings), its share of the points
// it shares with its neighbours, and the scheme's three-direction stencil
// (RegularTriangleGrid) applied to its grid.
//
// Points are in axial coordinates (i, j): the face's corners at (0, 0),
// (1, 0), (0, 1), a point's six neighbours at (i, j) + (1, 0), (0, 1),
// (-1, 1), (-1, 0), (0, -1), (1, -1), counter-clockwise. A grid of n
// intervals per side and reach r holds the points within r steps of the
// triangle (i, j >= 0, i + j <= n) in an (n + 2r + 1)^2 array at
// (i + r) + (n + 2r + 1)(j + r): the hexagon i, j >= -r, i + j >= -r,
// i, j <= n + r, i + j <= n + r. One step of the stencil makes the next
// grid's hexagon from this one's.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/rules/scheme.h"
#include "grid_numbering.h"
#include "grid_patch.h"

namespace subdiv::detail {

// The slots of a patch of reach r: the hexagon of n = 1 in a (2r + 2)^2
// array (12 of 16 used at reach 1, 27 of 36 at reach 2).
constexpr int kMaxTriangleReach = 2;
constexpr int kMaxTriangleSlots = (2 * kMaxTriangleReach + 2) * (2 * kMaxTriangleReach + 2);
constexpr int triangle_slots(int reach) { return (2 * reach + 2) * (2 * reach + 2); }

// Whether (i, j) lies in the hexagon of a grid of n intervals and reach r.
inline bool in_hexagon(int i, int j, int n, int r = 1) {
  return i >= -r && j >= -r && i + j >= -r && i <= n + r && j <= n + r && i + j <= n + r;
}

// The slots of the hexagon of n = 1 and reach r, in row order (12 at reach
// 1, 27 at reach 2).
std::span<const int> hexagon_slots(int reach);

// Per vertex: whether the regular rules apply at it: an interior vertex
// with six triangles around in an ordered ring, not sharp (`sharp`:
// sharp_vertices()).
std::vector<char> regular_triangle_vertices(const MeshTopology& t, const std::vector<char>& sharp);

// The control points of triangle f's patch of reach r (the hexagon of n =
// 1) at (i + r) + (2r + 2)(j + r), the other slots kInvalidIndex; false
// unless the points the rules read are `regular` vertices
// (regular_triangle_vertices(): the corners at reach 1; at reach 2 the
// corners and their rings, whose rings place the second step), and the
// points are distinct.
bool gather_triangle_patch(const MeshTopology& t, Index f, int reach, const std::vector<char>& regular,
                           std::span<Index> patch);

// Face f's share of the shared points: a corner vertex belongs to the face
// of its first corner, an edge's inner points to the face of its first side.
struct TriangleOwnership {
  std::array<bool, 3> corner{}, edge{};
  int n = 0;
  bool owns(GridPoint p) const {
    if (p.y == 0) return p.x == 0 ? corner[0] : p.x == n ? corner[1] : edge[0];
    if (p.x == 0) return p.y == n ? corner[2] : edge[2];
    if (p.x + p.y == n) return edge[1];
    return true;
  }
};

TriangleOwnership triangle_ownership_of(const MeshTopology& t, Index f, int n);

// Refines the control values in s.grid (width doubles each, at their slots
// of the (2r + 2)^2 array, r = kReach) `levels` times: the hexagon of n =
// 2^levels in s.grid, of which the last level makes only the triangle's
// own points (no later level reads the others). kWidth: width where known
// at compile time, 0 otherwise.
template <int kWidth, int kReach>
void refine_triangle_patch(const RegularTriangleGrid& rule, int levels, int width, Scratch& s) {
  constexpr int r = kReach;
  const std::ptrdiff_t w = kWidth > 0 ? kWidth : width;
  int n = 1;
  for (int l = 0; l < levels; ++l) {
    const int m = 2 * n;
    const std::ptrdiff_t in_side = n + 2 * r + 1, out_side = m + 2 * r + 1;
    const double* in = s.grid.data();
    auto at = [&](int i, int j) { return in + ((i + r) + in_side * (j + r)) * w; };
    const int beyond = l + 1 == levels ? 0 : r;  // how far past the triangle this level's points reach
    for (int y = -beyond; y <= m + beyond; ++y) {
      double* row = s.refined.data() + out_side * (y + r) * w;
      for (int x = std::max(-beyond, -beyond - y); x <= std::min(m + beyond, m + beyond - y); ++x) {
        double* o = row + (x + r) * w;
        if (x % 2 == 0 && y % 2 == 0) {  // a vertex point
          const int i = x / 2, j = y / 2;
          const double *p = at(i, j), *a = at(i + 1, j), *b = at(i, j + 1), *c = at(i - 1, j + 1), *d = at(i - 1, j),
                       *e = at(i, j - 1), *f = at(i + 1, j - 1);
          for (std::ptrdiff_t k = 0; k < w; ++k)
            o[k] = rule.centre * p[k] + rule.ring * (a[k] + b[k] + c[k] + d[k] + e[k] + f[k]);
          continue;
        }
        // An edge point: the edge's ends a, b and the vertices c, d opposite.
        if constexpr (kReach == 1) {  // the hot path of Loop's grids: pointers straight away
          const double *a, *b, *c, *d;
          if (y % 2 == 0) {  // along (1, 0)
            const int i = (x - 1) / 2, j = y / 2;
            a = at(i, j), b = at(i + 1, j), c = at(i, j + 1), d = at(i + 1, j - 1);
          } else if (x % 2 == 0) {  // along (0, 1)
            const int i = x / 2, j = (y - 1) / 2;
            a = at(i, j), b = at(i, j + 1), c = at(i + 1, j), d = at(i - 1, j + 1);
          } else {  // along (1, -1)
            const int i = (x - 1) / 2, j = (y + 1) / 2;
            a = at(i, j), b = at(i + 1, j - 1), c = at(i + 1, j), d = at(i, j - 1);
          }
          for (std::ptrdiff_t k = 0; k < w; ++k) o[k] = rule.near * (a[k] + b[k]) + rule.far * (c[k] + d[k]);
          continue;
        }
        // The same as axial coordinates, for the wings.
        int ai, aj, bi, bj, ci, cj, di, dj;
        if (y % 2 == 0) {  // along (1, 0)
          ai = (x - 1) / 2, aj = y / 2, bi = ai + 1, bj = aj, ci = ai, cj = aj + 1, di = ai + 1, dj = aj - 1;
        } else if (x % 2 == 0) {  // along (0, 1)
          ai = x / 2, aj = (y - 1) / 2, bi = ai, bj = aj + 1, ci = ai + 1, cj = aj, di = ai - 1, dj = aj + 1;
        } else {  // along (1, -1)
          ai = (x - 1) / 2, aj = (y + 1) / 2, bi = ai + 1, bj = aj - 1, ci = ai + 1, cj = aj, di = ai, dj = aj - 1;
        }
        const double *a = at(ai, aj), *b = at(bi, bj), *c = at(ci, cj), *d = at(di, dj);
        // The wings: across (b, c), (a, c), (b, d) and (a, d), each the
        // parallelogram's fourth point.
        const double *e1 = at(bi + ci - ai, bj + cj - aj), *e2 = at(ai + ci - bi, aj + cj - bj),
                     *e3 = at(bi + di - ai, bj + dj - aj), *e4 = at(ai + di - bi, aj + dj - bj);
        for (std::ptrdiff_t k = 0; k < w; ++k)
          o[k] = rule.near * (a[k] + b[k]) + rule.far * (c[k] + d[k]) + rule.wing * (e1[k] + e2[k] + e3[k] + e4[k]);
      }
    }
    s.grid.swap(s.refined);
    n = m;
  }
}

// weights[(i + (n + 1) j) * slots + k]: the weight of control slot k (of
// the (2r + 2)^2 array, slots of them) in the point (i, j) of the triangle
// refined `levels` times.
std::vector<double> triangle_point_weights(const RegularTriangleGrid& rule, int levels);

// The same without the zero weights: point (i, j)'s weights are
// weights[offsets[p] .. offsets[p + 1]) on slots[...] alike, p = i + (n + 1) j.
struct TrianglePointRows {
  std::vector<int> offsets, slots;
  std::vector<double> weights;
  TrianglePointRows(const RegularTriangleGrid& rule, int levels);
};

}  // namespace subdiv::detail
