#pragma once
// A regular triangle's patch for the grid path (grid_refine.h) on the
// triangular lattice: its 12 control points, its share of the points it
// shares with its neighbours, and the scheme's three-direction stencil
// (RegularTriangleGrid) applied to its grid.
//
// Points are in axial coordinates (i, j): the face's corners at (0, 0),
// (1, 0), (0, 1), a point's six neighbours at (i, j) + (1, 0), (0, 1),
// (-1, 1), (-1, 0), (0, -1), (1, -1), counter-clockwise. A grid of n
// intervals per side holds the points within one step of the triangle
// (i, j >= 0, i + j <= n) in an (n + 3)^2 array at (i + 1) + (n + 3)(j + 1):
// the hexagon i, j >= -1, i + j >= -1, i, j <= n + 1, i + j <= n + 1. One
// step of the stencil makes the next grid's hexagon from this one's.

#include <array>
#include <cstddef>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/rules/scheme.h"
#include "grid_numbering.h"
#include "grid_patch.h"

namespace subdiv::detail {

// Whether (i, j) lies in the hexagon of a grid of n intervals.
inline bool in_hexagon(int i, int j, int n) {
  return i >= -1 && j >= -1 && i + j >= -1 && i <= n + 1 && j <= n + 1 && i + j <= n + 1;
}

// The 12 control points of triangle f's patch (the hexagon of n = 1) at
// (i + 1) + 4 (j + 1), the four other slots kInvalidIndex; false unless
// every corner is an interior vertex with six triangles around it and the
// 12 points are distinct.
bool gather_triangle_patch(const MeshTopology& t, Index f, std::array<Index, 16>& patch);

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

// Refines the 12 control values in s.grid (width doubles each, at their
// slots of the 4 x 4 array) `levels` times: the hexagon of n = 2^levels in
// s.grid. kWidth: width where known at compile time, 0 otherwise.
template <int kWidth>
void refine_triangle_patch(const RegularTriangleGrid& rule, int levels, int width, Scratch& s) {
  const std::ptrdiff_t w = kWidth > 0 ? kWidth : width;
  int n = 1;
  for (int l = 0; l < levels; ++l) {
    const int m = 2 * n;
    const std::ptrdiff_t in_side = n + 3, out_side = m + 3;
    const double* in = s.grid.data();
    auto at = [&](int i, int j) { return in + ((i + 1) + in_side * (j + 1)) * w; };
    for (int y = -1; y <= m + 1; ++y) {
      double* row = s.refined.data() + out_side * (y + 1) * w;
      for (int x = std::max(-1, -1 - y); x <= std::min(m + 1, m + 1 - y); ++x) {
        double* o = row + (x + 1) * w;
        if (x % 2 == 0 && y % 2 == 0) {  // a vertex point
          const int i = x / 2, j = y / 2;
          const double *p = at(i, j), *a = at(i + 1, j), *b = at(i, j + 1), *c = at(i - 1, j + 1), *d = at(i - 1, j),
                       *e = at(i, j - 1), *f = at(i + 1, j - 1);
          for (std::ptrdiff_t k = 0; k < w; ++k)
            o[k] = rule.centre * p[k] + rule.ring * (a[k] + b[k] + c[k] + d[k] + e[k] + f[k]);
          continue;
        }
        // An edge point: the edge's ends a, b and the vertices c, d opposite.
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
      }
    }
    s.grid.swap(s.refined);
    n = m;
  }
}

// weights[i + (n + 1) j][k]: the weight of control slot k (of the 4 x 4
// array) in the point (i, j) of the triangle refined `levels` times.
std::vector<std::array<double, 16>> triangle_point_weights(const RegularTriangleGrid& rule, int levels);

}  // namespace subdiv::detail
