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

bool is_infinitely_sharp(const LevelCreasing& creasing, Index e) {
  return edge_sharpness_of(creasing, e) >= kInfiniteSharpness;
}

PatchStencil vertex_stencil(Index v) {
  PatchStencil p;
  p.vertex[0] = v;
  p.weight[0] = 1.0;
  p.size = 1;
  return p;
}

/// 2 a - b, terms on the same vertex merged.
PatchStencil reflection(const PatchStencil& a, const PatchStencil& b) {
  PatchStencil r;
  const auto add = [&](Index v, double w) {
    for (int i = 0; i < r.size; ++i) {
      if (r.vertex[static_cast<std::size_t>(i)] == v) {
        r.weight[static_cast<std::size_t>(i)] += w;
        return;
      }
    }
    // At most 4 distinct vertices: a reflection of reflections of a 2 x 2 block.
    r.vertex[static_cast<std::size_t>(r.size)] = v;
    r.weight[static_cast<std::size_t>(r.size)] = w;
    ++r.size;
  };
  for (int i = 0; i < a.size; ++i) add(a.vertex[static_cast<std::size_t>(i)], 2.0 * a.weight[static_cast<std::size_t>(i)]);
  for (int i = 0; i < b.size; ++i) add(b.vertex[static_cast<std::size_t>(i)], -b.weight[static_cast<std::size_t>(i)]);
  return r;
}

/// Whether every face at v is a quad.
bool quads_around(const MeshTopology& topology, Index v) {
  for (const Index c : topology.vertex_corners(v))
    if (topology.face_size(topology.corner_face(c)) != 4) return false;
  return true;
}

/// Whether corner c's vertex is one of bicubic_patch_stencils' corner
/// kinds, given which of the face's sides at it (to the next corner, from
/// the previous one) are sharp.
bool is_patch_corner(const MeshTopology& topology, const LevelCreasing& creasing, Index c, bool next_sharp,
                     bool prev_sharp) {
  const Index v = topology.corner_vertex(c);
  const VertexRule rule = creasing.vertex_rule[static_cast<std::size_t>(v)];
  if (rule != creasing.child_vertex_rule[static_cast<std::size_t>(v)] || !quads_around(topology, v)) return false;
  int sharp = 0;
  for (const Index e : topology.vertex_edges(v)) {
    const double s = edge_sharpness_of(creasing, e);
    if (s > 0.0 && s < kInfiniteSharpness) return false;  // semi-sharp
    sharp += s > 0.0 ? 1 : 0;
  }
  if (!next_sharp && !prev_sharp) return rule == VertexRule::smooth && sharp == 0 && is_regular_interior(topology, v, 4);
  if (next_sharp && prev_sharp) return rule == VertexRule::corner;
  if (rule != VertexRule::crease || sharp != 2) return false;
  const bool boundary = topology.vertex_kind(v) == VertexKind::boundary;
  if (boundary ? topology.vertex_face_count(v) != 2 : !is_regular_interior(topology, v, 4)) return false;
  // The sharp side's continuation through v: the far side at v of the face
  // across the smooth side.
  if (next_sharp) {
    const Index left = topology.corner_across(topology.corner_prev(c));  // at v, across the previous side
    return left != kInvalidIndex && is_infinitely_sharp(creasing, topology.corner_edge(topology.corner_prev(left)));
  }
  const Index below = topology.corner_across(c);  // at the next corner, across the next side
  return below != kInvalidIndex && is_infinitely_sharp(creasing, topology.corner_edge(topology.corner_next(below)));
}

}  // namespace

bool is_regular_patch_corner(const MeshTopology& topology, const LevelCreasing& creasing, Index corner) {
  return topology.face_size(topology.corner_face(corner)) == 4 &&
         is_patch_corner(topology, creasing, corner, is_infinitely_sharp(creasing, topology.corner_edge(corner)),
                         is_infinitely_sharp(creasing, topology.corner_edge(topology.corner_prev(corner))));
}

std::optional<std::array<PatchStencil, 16>> bicubic_patch_stencils(const MeshTopology& topology,
                                                                  const LevelCreasing& creasing, Index corner) {
  const Index face = topology.corner_face(corner);
  if (topology.face_size(face) != 4) return std::nullopt;
  // Corner k at grid point kOrigin[k]; side k runs from corner k to corner
  // k + 1, and kOutward[k] leaves the face across it.
  constexpr std::array<std::array<int, 2>, 4> kOrigin = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  constexpr std::array<std::array<int, 2>, 4> kOutward = {{{0, -1}, {1, 0}, {0, 1}, {-1, 0}}};
  std::array<Index, 4> corners{};
  std::array<bool, 4> sharp{};
  for (std::size_t k = 0; k < 4; ++k) {
    corners[k] = k == 0 ? corner : topology.corner_next(corners[k - 1]);
    sharp[k] = is_infinitely_sharp(creasing, topology.corner_edge(corners[k]));
  }
  for (std::size_t k = 0; k < 4; ++k)
    if (!is_patch_corner(topology, creasing, corners[k], sharp[k], sharp[(k + 3) % 4])) return std::nullopt;

  std::array<std::optional<PatchStencil>, 16> grid;
  const auto at = [&](int i, int j) -> std::optional<PatchStencil>& {
    return grid[static_cast<std::size_t>(grid_index(i, j))];
  };
  for (std::size_t k = 0; k < 4; ++k) at(kOrigin[k][0], kOrigin[k][1]) = vertex_stencil(topology.corner_vertex(corners[k]));
  // Beside each side: across it, or reflected across it.
  for (std::size_t k = 0; k < 4; ++k) {
    const auto [ax, ay] = kOrigin[k];
    const auto [bx, by] = kOrigin[(k + 1) % 4];
    const auto [dx, dy] = kOutward[k];
    if (sharp[k]) {
      at(ax + dx, ay + dy) = reflection(*at(ax, ay), *at(ax - dx, ay - dy));
      at(bx + dx, by + dy) = reflection(*at(bx, by), *at(bx - dx, by - dy));
    } else {
      // The face across runs the side backwards: its corner at b, then a.
      const Index across = topology.corner_across(corners[k]);
      if (across == kInvalidIndex || topology.face_size(topology.corner_face(across)) != 4) return std::nullopt;
      at(ax + dx, ay + dy) = vertex_stencil(topology.corner_vertex(topology.corner_next(topology.corner_next(across))));
      at(bx + dx, by + dy) = vertex_stencil(topology.corner_vertex(topology.corner_prev(across)));
    }
  }
  // Beyond each corner: the diagonal face's far vertex, or a reflection of
  // the points beside the sides across a sharp one.
  for (std::size_t k = 0; k < 4; ++k) {
    const auto [ox, oy] = kOrigin[k];
    const auto [nx, ny] = kOutward[k];            // across the side to the next corner
    const auto [px, py] = kOutward[(k + 3) % 4];  // across the side from the previous one
    if (sharp[k]) {
      at(ox + nx + px, oy + ny + py) = reflection(*at(ox + px, oy + py), *at(ox + px - nx, oy + py - ny));
    } else if (sharp[(k + 3) % 4]) {
      at(ox + nx + px, oy + ny + py) = reflection(*at(ox + nx, oy + ny), *at(ox + nx - px, oy + ny - py));
    } else {
      const auto beyond = points_beyond(topology, corners[k]);
      if (!beyond) return std::nullopt;
      at(ox + nx + px, oy + ny + py) = vertex_stencil((*beyond)[1]);
    }
  }
  std::array<PatchStencil, 16> out;
  std::array<Index, 16> real{};
  std::size_t reals = 0;
  for (std::size_t i = 0; i < 16; ++i) {
    out[i] = *grid[i];
    if (out[i].size == 1) real[reals++] = out[i].vertex[0];
  }
  // A small closed mesh can reach the same vertex twice (a 3 x 3 torus).
  std::sort(real.begin(), real.begin() + static_cast<std::ptrdiff_t>(reals));
  if (std::adjacent_find(real.begin(), real.begin() + static_cast<std::ptrdiff_t>(reals)) !=
      real.begin() + static_cast<std::ptrdiff_t>(reals))
    return std::nullopt;
  return out;
}

std::optional<std::vector<Index>> sector_corners(const MeshTopology& topology, const LevelCreasing& creasing,
                                                 Index corner) {
  const auto stops = [&](Index k) {
    return topology.corner_across(k) == kInvalidIndex || edge_sharpness_of(creasing, topology.corner_edge(k)) > 0.0;
  };
  const Index faces = topology.vertex_face_count(topology.corner_vertex(corner));
  // Back (clockwise, across the edge leaving the vertex) to the first face,
  // then counter-clockwise (across the edge entering it) to the last.
  Index around = corner;
  for (Index steps = 0; !stops(around); around = topology.corner_next(topology.corner_across(around)))
    if (++steps > faces) return std::nullopt;
  std::vector<Index> sector{around};
  while (!stops(topology.corner_prev(around))) {
    around = topology.corner_across(topology.corner_prev(around));
    sector.push_back(around);
    if (static_cast<Index>(sector.size()) > faces) return std::nullopt;
  }
  return sector;
}

bool is_regular_box_spline_corner(const MeshTopology& topology, const LevelCreasing& creasing, Index corner) {
  const Index v = topology.corner_vertex(corner);
  const VertexRule rule = creasing.vertex_rule[static_cast<std::size_t>(v)];
  if (topology.face_size(topology.corner_face(corner)) != 3 || rule != creasing.child_vertex_rule[static_cast<std::size_t>(v)])
    return false;
  for (const Index e : topology.vertex_edges(v)) {
    const double s = edge_sharpness_of(creasing, e);
    if (s > 0.0 && s < kInfiniteSharpness) return false;
  }
  if (rule == VertexRule::smooth) {
    if (!is_regular_interior(topology, v, 6)) return false;
    for (const Index c : topology.vertex_corners(v))
      if (topology.face_size(topology.corner_face(c)) != 3) return false;
    return true;
  }
  // On a straight crease or a boundary: three triangles on the face's side.
  if (rule != VertexRule::crease) return false;
  const auto sector = sector_corners(topology, creasing, corner);
  return sector && sector->size() == 3 && std::all_of(sector->begin(), sector->end(), [&](Index c) {
           return topology.face_size(topology.corner_face(c)) == 3;
         });
}

std::optional<std::array<PatchStencil, 12>> box_spline_patch_stencils(const MeshTopology& topology,
                                                                     const LevelCreasing& creasing, Index corner) {
  if (topology.face_size(topology.corner_face(corner)) != 3) return std::nullopt;
  constexpr std::array<std::array<int, 2>, 3> kOrigin = {{{0, 0}, {1, 0}, {0, 1}}};
  // A corner's six neighbours counter-clockwise from v, in its frame.
  constexpr std::array<std::array<int, 2>, 6> kFan = {{{0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}, {1, 0}}};
  std::array<Index, 12> points{};
  points.fill(kInvalidIndex);
  const auto place = [&](std::array<int, 2> at, Index vertex) {
    const int k = lattice_index(at[0], at[1]);
    if (k < 0) return true;  // beyond the 12
    Index& slot = points[static_cast<std::size_t>(k)];
    if (slot != kInvalidIndex && slot != vertex) return false;
    slot = vertex;
    return true;
  };
  const auto stops = [&](Index c) {
    return topology.corner_across(c) == kInvalidIndex || edge_sharpness_of(creasing, topology.corner_edge(c)) > 0.0;
  };
  // The crease line through a corner on one: its point o, its direction d,
  // and w, the lattice direction 60 degrees from d into the face's side.
  struct Line {
    std::array<int, 2> o, d, w;
  };
  std::optional<Line> line;
  Index c = corner;
  for (std::size_t k = 0; k < 3; ++k, c = topology.corner_next(c)) {
    if (!is_regular_box_spline_corner(topology, creasing, c)) return std::nullopt;
    const Index v = topology.corner_vertex(c);
    // Plain variables: clang 14 cannot capture structured bindings in a lambda.
    const int ox = kOrigin[k][0], oy = kOrigin[k][1];
    const int ux = kOrigin[(k + 1) % 3][0] - ox, uy = kOrigin[(k + 1) % 3][1] - oy;
    const int vx = kOrigin[(k + 2) % 3][0] - ox, vy = kOrigin[(k + 2) % 3][1] - oy;
    const auto direction = [&](std::size_t i) {
      return std::array<int, 2>{kFan[i][0] * ux + kFan[i][1] * vx, kFan[i][0] * uy + kFan[i][1] * vy};
    };
    const auto at = [&](std::size_t i) {
      const auto d = direction(i);
      return std::array<int, 2>{ox + d[0], oy + d[1]};
    };
    if (!place({ox, oy}, v)) return std::nullopt;
    // Counter-clockwise from the face (fan positions 0, 1, ...), across the
    // edge entering v, up to a sharp edge; then clockwise from the face
    // (positions 5, 4, ...) across the edge leaving v.
    std::size_t ccw = 0;
    Index around = c;
    bool closed = false;  // back at the face: a smooth vertex's whole fan
    while (true) {
      if (!place(at(ccw), topology.corner_vertex(topology.corner_prev(around)))) return std::nullopt;
      if (stops(topology.corner_prev(around))) break;
      around = topology.corner_across(topology.corner_prev(around));
      closed = around == c;
      if (closed || ++ccw >= 6) break;
    }
    if (closed) continue;
    if (ccw >= 6) return std::nullopt;
    std::size_t cw = 5;
    around = c;
    if (!place(at(cw), topology.corner_vertex(topology.corner_next(c)))) return std::nullopt;
    while (!stops(around)) {
      around = topology.corner_next(topology.corner_across(around));
      if (--cw <= ccw) return std::nullopt;
      if (!place(at(cw), topology.corner_vertex(topology.corner_next(around)))) return std::nullopt;
    }
    // The sharp edges run to fan positions cw and ccw (opposite: three
    // triangles between); the face's side runs counter-clockwise from cw.
    const Line here{{ox, oy}, direction(cw), direction((cw + 1) % 6)};
    if (line) {
      // One crease line per patch: another corner on it, along it.
      const int ax = here.o[0] - line->o[0], ay = here.o[1] - line->o[1];
      if (ax * line->d[1] - ay * line->d[0] != 0 || here.d[0] * line->d[1] - here.d[1] * line->d[0] != 0)
        return std::nullopt;
    } else {
      line = here;
    }
  }
  std::array<PatchStencil, 12> out;
  for (std::size_t i = 0; i < 12; ++i)
    if (points[i] != kInvalidIndex) out[i] = vertex_stencil(points[i]);
  // Beyond the crease line, one row: x = o + a d - w is the parallelogram
  // reflection p(m1) + p(m2) - p(R x) of R x = o + (a - 1) d + w, with m1 =
  // o + a d and m2 = o + (a - 1) d on the line.
  for (std::size_t i = 0; i < 12; ++i) {
    if (points[i] != kInvalidIndex) continue;
    if (!line) return std::nullopt;
    // x - o = a d + b w, solved in the lattice (d and w a basis, det +-1).
    const int xx = kBoxSplineLattice[i][0] - line->o[0], xy = kBoxSplineLattice[i][1] - line->o[1];
    const int det = line->d[0] * line->w[1] - line->d[1] * line->w[0];
    const int a = (xx * line->w[1] - xy * line->w[0]) / det, b = (line->d[0] * xy - line->d[1] * xx) / det;
    if (b != -1) return std::nullopt;
    const auto point_at = [&](int pa, int pb) {
      return lattice_index(line->o[0] + pa * line->d[0] + pb * line->w[0], line->o[1] + pa * line->d[1] + pb * line->w[1]);
    };
    const int mirror = point_at(a - 1, 1), m1 = point_at(a, 0), m2 = point_at(a - 1, 0);
    if (mirror < 0 || m1 < 0 || m2 < 0) return std::nullopt;
    const Index pm = points[static_cast<std::size_t>(mirror)], p1 = points[static_cast<std::size_t>(m1)],
                p2 = points[static_cast<std::size_t>(m2)];
    if (pm == kInvalidIndex || p1 == kInvalidIndex || p2 == kInvalidIndex) return std::nullopt;
    PatchStencil p;
    p.vertex = {p1, p2, pm, 0};
    p.weight = {1.0, 1.0, -1.0, 0.0};
    p.size = 3;
    out[i] = p;
  }
  std::array<Index, 12> real{};
  std::size_t reals = 0;
  for (std::size_t i = 0; i < 12; ++i)
    if (points[i] != kInvalidIndex) real[reals++] = points[i];
  std::sort(real.begin(), real.begin() + static_cast<std::ptrdiff_t>(reals));
  if (std::adjacent_find(real.begin(), real.begin() + static_cast<std::ptrdiff_t>(reals)) !=
      real.begin() + static_cast<std::ptrdiff_t>(reals))
    return std::nullopt;
  return out;
}

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
