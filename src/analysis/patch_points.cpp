#include "analysis/patch_points.h"

#include <algorithm>

#include "analysis/patch_basis.h"

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

/// An interior vertex with `faces` faces and as many edges.
bool is_regular_interior(const MeshTopology& topology, Index v, Index faces) {
  return topology.vertex_kind(v) == VertexKind::interior && topology.vertex_face_count(v) == faces &&
         topology.valence(v) == faces;
}

constexpr Index grid_index(int i, int j) { return (i + 1) + 4 * (j + 1); }

/// The index of lattice point (a, b) in kBoxSplineLattice, -1 if absent.
int lattice_index(int a, int b) {
  for (std::size_t k = 0; k < kBoxSplineLattice.size(); ++k) {
    if (kBoxSplineLattice[k][0] == a && kBoxSplineLattice[k][1] == b) return static_cast<int>(k);
  }
  return -1;
}

template <std::size_t N>
bool all_distinct(std::array<Index, N> points) {
  std::sort(points.begin(), points.end());
  return std::adjacent_find(points.begin(), points.end()) == points.end();
}

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
    if (!is_regular_interior(topology, v, 4)) return std::nullopt;
    const auto beyond = points_beyond(topology, c);
    if (!beyond) return std::nullopt;
    // Plain variables: clang 14 cannot capture structured bindings in a lambda.
    const int ox = kOrigin[k][0], oy = kOrigin[k][1];
    const int ux = kAxisU[k][0], uy = kAxisU[k][1];
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
  if (!all_distinct(points)) return std::nullopt;
  return points;
}

std::optional<std::array<Index, 12>> box_spline_patch_points(const MeshTopology& topology, Index corner) {
  if (topology.face_size(topology.corner_face(corner)) != 3) return std::nullopt;
  // Corner k of the face, counted from `corner`, sits at kOrigin[k]; in its
  // frame u points to the next corner and v to the previous one.
  constexpr std::array<std::array<int, 2>, 3> kOrigin = {{{0, 0}, {1, 0}, {0, 1}}};
  // A corner's six neighbours counter-clockwise from v, in its frame.
  constexpr std::array<std::array<int, 2>, 6> kFan = {{{0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}, {1, 0}}};
  std::array<Index, 12> points{};
  points.fill(kInvalidIndex);
  const auto place = [&](int a, int b, Index vertex) {
    const int k = lattice_index(a, b);
    if (k < 0) return false;
    Index& slot = points[static_cast<std::size_t>(k)];
    if (slot != kInvalidIndex && slot != vertex) return false;
    slot = vertex;
    return true;
  };
  Index c = corner;
  for (std::size_t k = 0; k < 3; ++k, c = topology.corner_next(c)) {
    const Index v = topology.corner_vertex(c);
    if (!is_regular_interior(topology, v, 6)) return std::nullopt;
    const auto [ox, oy] = kOrigin[k];
    const auto [nx, ny] = kOrigin[(k + 1) % 3];
    const auto [px, py] = kOrigin[(k + 2) % 3];
    const int ux = nx - ox, uy = ny - oy, vx = px - ox, vy = py - oy;
    if (!place(ox, oy, v)) return std::nullopt;
    // Around the vertex, face by face: each step crosses the edge into the
    // corner's previous vertex.
    Index around = c;
    for (const auto& [a, b] : kFan) {
      if (topology.face_size(topology.corner_face(around)) != 3) return std::nullopt;
      if (!place(ox + a * ux + b * vx, oy + a * uy + b * vy, topology.corner_vertex(topology.corner_prev(around)))) {
        return std::nullopt;
      }
      around = topology.corner_across(topology.corner_prev(around));
      if (around == kInvalidIndex) return std::nullopt;
    }
    if (around != c) return std::nullopt;
  }
  if (!all_distinct(points)) return std::nullopt;
  return points;
}

}  // namespace subdiv
