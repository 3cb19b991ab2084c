#pragma once
// A regular face's patch for the grid path (grid_refine.h): its 4 x 4
// control points, its share of the points it shares with its neighbours,
// and the scheme's tensor stencil (RegularGrid) applied to its grid.

#include <array>
#include <cstddef>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/rules/scheme.h"
#include "grid_numbering.h"

namespace subdiv::detail {

// The 16 control points of face f's bicubic patch, row-major from (-1, -1)
// to (2, 2) in the face's frame (corners at (0, 0), (1, 0), (1, 1), (0, 1));
// false unless every corner is an interior vertex with four quads around it
// and the 16 points are distinct.
bool gather_patch(const MeshTopology& t, Index f, std::array<Index, 16>& patch);

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

Ownership ownership_of(const MeshTopology& t, Index f, int n);

/// weights[x][i]: the weight of control point i (at -1, 0, 1, 2 along a
/// line) in the point at x = 0 .. n of a patch refined `levels` times along
/// the line (n = 2^levels): the line's rows of the patch's stencils.
std::vector<std::array<double, 4>> line_weights(const RegularGrid& rule, int levels);

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
  std::vector<Index> index;        // the final vertex number of each grid point
  std::vector<Index> local_index;  // faces of the masks' mesh: the point's number in its refinement

  void size_for(int n, int width) {
    const auto side = static_cast<std::size_t>(n + 3);
    const std::size_t doubles = side * side * static_cast<std::size_t>(width);
    if (grid.size() >= doubles) return;
    grid.resize(doubles);
    rows.resize(doubles);
    refined.resize(doubles);
    index.resize(static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1));
    local_index.resize(index.size());
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

}  // namespace subdiv::detail
