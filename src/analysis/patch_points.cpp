#include "analysis/patch_points.h"

#include <algorithm>

namespace subdiv {
namespace {

/// The three grid points beyond one corner of the patch's face, in that
/// corner's frame (u toward the face's next corner, v toward its previous
/// one): (0, -1), (-1, -1) and (-1, 0). Walks across the corner's edge into
/// the face below, then across that face's edge leaving the corner into the
/// diagonal face. Empty where a face on the way is not a quad or an edge has
/// no other side.
std::optional<std::array<Index, 3>> points_beyond(const MeshTopology& topology, Index corner) {
  const Index below = topology.corner_across(corner);  // at the face's next corner, in the face below
  if (below == kInvalidIndex || topology.face_size(topology.corner_face(below)) != 4) return std::nullopt;
  const Index at_corner = topology.corner_next(below);
  const Index diagonal = topology.corner_across(at_corner);  // at grid point (0, -1), in the diagonal face
  if (diagonal == kInvalidIndex || topology.face_size(topology.corner_face(diagonal)) != 4) return std::nullopt;
  return std::array<Index, 3>{topology.corner_vertex(topology.corner_next(at_corner)),
                              topology.corner_vertex(topology.corner_prev(diagonal)),
                              topology.corner_vertex(topology.corner_next(topology.corner_next(diagonal)))};
}

constexpr Index grid_index(int i, int j) { return (i + 1) + 4 * (j + 1); }

}  // namespace

std::optional<std::array<Index, 16>> bicubic_patch_points(const MeshTopology& topology, Index corner) {
  const Index face = topology.corner_face(corner);
  if (topology.face_size(face) != 4) return std::nullopt;
  // Corner k of the face, counted from `corner`, sits at grid point
  // kOrigin[k]; its frame's u and v axes are the first frame's turned k
  // quarter turns.
  constexpr std::array<std::array<int, 2>, 4> kOrigin = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  constexpr std::array<std::array<int, 2>, 4> kAxisU = {{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
  std::array<Index, 16> points{};
  points.fill(kInvalidIndex);
  Index c = corner;
  for (std::size_t k = 0; k < 4; ++k, c = topology.corner_next(c)) {
    const Index v = topology.corner_vertex(c);
    if (topology.vertex_kind(v) != VertexKind::interior || topology.vertex_face_count(v) != 4 ||
        topology.valence(v) != 4) {
      return std::nullopt;
    }
    const auto beyond = points_beyond(topology, c);
    if (!beyond) return std::nullopt;
    const auto [ox, oy] = kOrigin[k];
    const auto [ux, uy] = kAxisU[k];
    const int vx = -uy, vy = ux;  // v is u turned a quarter turn
    const auto place = [&](int a, int b, Index vertex) {
      points[static_cast<std::size_t>(grid_index(ox + a * ux + b * vx, oy + a * uy + b * vy))] = vertex;
    };
    place(0, 0, v);
    place(0, -1, (*beyond)[0]);
    place(-1, -1, (*beyond)[1]);
    place(-1, 0, (*beyond)[2]);
  }
  // A small closed mesh can reach the same vertex twice (a 3 x 3 torus).
  std::array<Index, 16> sorted = points;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return std::nullopt;
  return points;
}

}  // namespace subdiv
