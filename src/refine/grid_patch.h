#pragma once
// A regular face's patch for the grid path (grid_refine.h): its control
// points (4 x 4 for Catmull-Clark, up to 8 x 8), its share of the points it
// shares with its neighbours, and the scheme's tensor stencil (RegularGrid)
// applied to its grid.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/rules/scheme.h"
#include "grid_numbering.h"

namespace subdiv::detail {

// The largest patch reach (RegularGrid::patch_reach()) and its control points.
constexpr int kMaxPatchReach = 3;
constexpr int kMaxPatchPoints = (2 * kMaxPatchReach + 2) * (2 * kMaxPatchReach + 2);

// Control points per side of a patch of reach r: from -r to r + 1.
constexpr int patch_side(int reach) { return 2 * reach + 2; }

// Whether a patch's N points are all set (not kInvalidIndex) and distinct,
// by a small open-addressing set: cheaper than sorting or comparing every
// pair of a few dozen points.
template <std::size_t N>
bool set_and_distinct(const std::array<Index, N>& points) {
  constexpr std::size_t kSlots = std::bit_ceil(2 * N);
  constexpr int kShift = 32 - std::countr_zero(kSlots);
  std::array<Index, kSlots> seen;
  seen.fill(kInvalidIndex);
  for (const Index p : points) {
    if (p == kInvalidIndex) return false;
    // Fibonacci hashing: the product's high bits.
    std::size_t h = (static_cast<std::uint32_t>(p) * 2654435769u) >> kShift;
    while (seen[h] != kInvalidIndex) {
      if (seen[h] == p) return false;
      h = (h + 1) & (kSlots - 1);
    }
    seen[h] = p;
  }
  return true;
}

// The (2r + 2)^2 control points of face f's patch of reach r, row-major
// from (-r, -r) to (r + 1, r + 1) in the face's frame (corners at (0, 0),
// (1, 0), (1, 1), (0, 1)), walked face by face across the quads around f;
// false unless the walk finds quads with consistent corners and distinct
// points, and the points the rule reads are regular: at reach 1 the corners
// (interior, four quads around), beyond it every point, none sharp.
bool gather_patch(const MeshTopology& t, Index f, int reach, const std::vector<char>& sharp, std::span<Index> patch);

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

/// weights[x * side + i]: the weight of control point i (at -r .. r + 1
/// along a line, side = 2r + 2 of them) in the point at x = 0 .. n of a
/// patch refined `levels` times along the line (n = 2^levels): the line's
/// rows of the patch's stencils.
std::vector<double> line_weights(const RegularGrid& rule, int levels);

// One step of the tensor stencil along a line of m points (`in_stride`
// points apart), the line's points from -r to n + r for reach r = kReach,
// making those from -r to 2n + r: 2m - 2r - 1 points (`out_stride` apart).
// A point is `width` doubles (kWidth where known at compile time, 0
// otherwise). Reach 1 reads one point each side (the even rule's middle
// three weights, the odd rule's middle two), reach 2 reads the odd rule's
// four, reach 3 every weight.
// Only the points t_begin <= t < t_end are made (all of them by default).
template <int kWidth, int kReach>
void refine_line(const RegularGrid& rule, const double* in, std::ptrdiff_t in_stride, int m, double* out,
                 std::ptrdiff_t out_stride, int width, int t_begin = 0, int t_end = -1) {
  constexpr int kEven = kReach == 3 ? 2 : 1;  // even points read i - kEven .. i + kEven
  constexpr int kOdd = kReach == 1 ? 1 : 2;   // odd points read i - kOdd + 1 .. i + kOdd
  const std::ptrdiff_t w = kWidth > 0 ? kWidth : width;
  const std::ptrdiff_t is = in_stride * w, os = out_stride * w;
  const int fine = t_end >= 0 ? t_end : 2 * m - 2 * kReach - 1;
  for (int t = t_begin; t < fine; ++t) {
    // Fine point t is at position p = t - r, coarse point j at j - r: an
    // even p = 2i reads coarse points from i - kEven, at j = (t + r) / 2 -
    // kEven; an odd p = 2i + 1 from i - kOdd + 1, at j = (t + r - 1) / 2 -
    // kOdd + 1 (t + r >= 1, so the halving is exact and cheap).
    const auto half = static_cast<unsigned>(t + kReach) / 2u;
    double* o = out + t * os;
    if ((t + kReach) % 2 == 0) {
      const double* a = in + (static_cast<int>(half) - kEven) * is;
      const double* k = rule.even.data() + 2 - kEven;
      for (std::ptrdiff_t j = 0; j < w; ++j) {
        double sum = k[0] * a[j];
        for (int q = 1; q <= 2 * kEven; ++q) sum += k[q] * a[q * is + j];
        o[j] = sum;
      }
    } else {
      const double* a = in + (static_cast<int>(half) - kOdd + 1) * is;
      const double* k = rule.odd.data() + 2 - kOdd;
      for (std::ptrdiff_t j = 0; j < w; ++j) {
        double sum = k[0] * a[j];
        for (int q = 1; q < 2 * kOdd; ++q) sum += k[q] * a[q * is + j];
        o[j] = sum;
      }
    }
  }
}

// A thread's working arrays, sized once for the final level's grid.
struct Scratch {
  std::vector<double> grid, rows, refined;
  std::vector<Index> index;        // the final vertex number of each grid point
  std::vector<Index> local_index;  // faces of the masks' mesh: the point's number in its refinement

  void size_for(int n, int width, int reach = 1) {
    const auto side = static_cast<std::size_t>(n + 2 * reach + 1);
    const std::size_t doubles = side * side * static_cast<std::size_t>(width);
    if (grid.size() < doubles) {
      grid.resize(doubles);
      rows.resize(doubles);
      refined.resize(doubles);
    }
    const std::size_t points = static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1);
    if (index.size() < points) {
      index.resize(points);
      local_index.resize(points);
    }
  }
};

// Refines the (2r + 2)^2 control values in scratch.grid `levels` times, r =
// kReach: the (n + 2r + 1)^2 grid of the patch's points from -r to n + r, in
// scratch.grid, of which the last level makes only the face's own, 0 .. n
// (no later level reads the others).
template <int kWidth, int kReach>
void refine_patch(const RegularGrid& rule, int levels, int width, Scratch& s) {
  int m = patch_side(kReach);
  for (int l = 0; l < levels; ++l) {
    const int fine = 2 * m - 2 * kReach - 1;
    const bool last = l + 1 == levels;
    const int begin = last ? kReach : 0, end = last ? fine - kReach : fine;
    for (int r = 0; r < m; ++r)
      refine_line<kWidth, kReach>(rule, s.grid.data() + r * m * width, 1, m, s.rows.data() + r * fine * width, 1, width,
                                  begin, end);
    for (int col = begin; col < end; ++col)
      refine_line<kWidth, kReach>(rule, s.rows.data() + col * width, fine, m, s.refined.data() + col * width, fine,
                                  width, begin, end);
    s.grid.swap(s.refined);
    m = fine;
  }
}

}  // namespace subdiv::detail
