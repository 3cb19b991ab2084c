// The regular patch of a face: gathering its control points, its share of
// shared points, and the stencil's weights along a grid line.

#include "grid_patch.h"

#include <algorithm>
#include <utility>

namespace subdiv::detail {

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

std::vector<std::array<double, 4>> line_weights(const RegularGrid& rule, int levels) {
  const int n = 1 << levels;
  std::vector<std::array<double, 4>> weights(static_cast<std::size_t>(n + 1));
  // Refine each control point's unit impulse along the line, as refine_line
  // refines values (one double per point).
  std::vector<double> line, finer;
  for (int i = 0; i < 4; ++i) {
    line.assign(4, 0.0);
    line[static_cast<std::size_t>(i)] = 1.0;
    int m = 4;
    for (int l = 0; l < levels; ++l) {
      finer.resize(static_cast<std::size_t>(2 * m - 3));
      refine_line<1>(rule, line.data(), 1, m, finer.data(), 1, 1);
      line.swap(finer);
      m = 2 * m - 3;
    }
    for (int x = 0; x <= n; ++x) weights[static_cast<std::size_t>(x)][static_cast<std::size_t>(i)] = line[static_cast<std::size_t>(x + 1)];
  }
  return weights;
}

}  // namespace subdiv::detail
