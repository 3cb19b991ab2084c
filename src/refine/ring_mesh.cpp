#include "subdiv/refine/ring_mesh.h"

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <tuple>

#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/bilinear.h"
#include "subdiv/rules/linear.h"
#include "subdiv/rules/midedge.h"

namespace subdiv {

double Configuration::sector_angle() const noexcept {
  switch (kind) {
    case Kind::interior: return 2.0 * std::numbers::pi;
    case Kind::boundary: return std::numbers::pi;
    case Kind::corner:
      if (angle > 0.0) return angle;
      return corner == CornerType::concave ? 1.5 * std::numbers::pi : 0.5 * std::numbers::pi;
  }
  return 2.0 * std::numbers::pi;
}

std::string Configuration::name() const {
  const std::string count = " k=" + std::to_string(k);
  switch (kind) {
    case Kind::interior: return "interior" + count;
    case Kind::boundary: return "boundary" + count;
    case Kind::corner: {
      std::string name = std::string(corner == CornerType::concave ? "concave" : "convex") + " corner" + count;
      if (angle > 0.0) name += " alpha=" + std::to_string(static_cast<int>(std::lround(angle * 180.0 / std::numbers::pi))) + "deg";
      return name;
    }
  }
  return count;
}

namespace {

// Grid points are keyed by (sector, i, j). Sector s owns its points with
// j >= 1; a point on ray s (j = 0, i >= 1) belongs to sector s - 1 as
// (0, i), except on the first ray of an open fan. The centre is (0, 0, 0).
// The layout is linear in each sector, or (`polar`, for two sectors around
// a vertex, which no linear layout separates) the point at radius i + j and
// angle a (s + j / (i + j)) / sectors.
class GridPoints {
 public:
  using Key = std::tuple<int, int, int>;

  GridPoints(int sectors, bool closed, double angle, bool polar, PolygonMesh& mesh)
      : sectors_(sectors), closed_(closed), polar_(polar), angle_(angle), mesh_(mesh) {}

  Index at(int s, int i, int j) {
    const Key key = canonical(s, i, j);
    const auto [it, added] = index_.try_emplace(key, mesh_.vertex_count());
    if (added) {
      mesh_.positions.push_back(place(key));
      keys_.push_back(key);
    }
    return it->second;
  }

  /// The vertex at (s, i, j), kInvalidIndex when the mesh has none there.
  Index find(int s, int i, int j) const {
    const auto it = index_.find(canonical(s, i, j));
    return it == index_.end() ? kInvalidIndex : it->second;
  }

  const Key& key(Index v) const { return keys_[static_cast<std::size_t>(v)]; }

 private:
  Key canonical(int s, int i, int j) const {
    if (i == 0 && j == 0) return {0, 0, 0};
    if (j == 0 && (s > 0 || closed_)) return {(s + sectors_ - 1) % sectors_, 0, i};
    return {s, i, j};
  }

  Vec3 place(const Key& key) const {
    const auto [s, i, j] = key;
    if (!polar_) return i * ray(s) + j * ray(s + 1);
    if (i + j == 0) return {};
    const double a = angle_ * (s + static_cast<double>(j) / (i + j)) / sectors_;
    return (i + j) * Vec3{std::cos(a), std::sin(a), 0.0};
  }

  Vec3 ray(int s) const {
    const double a = angle_ * s / sectors_;
    return {std::cos(a), std::sin(a), 0.0};
  }

  int sectors_;
  bool closed_;
  bool polar_;
  double angle_;
  PolygonMesh& mesh_;
  std::map<Key, Index> index_;
  std::vector<Key> keys_;  // per vertex
};

// Per vertex (s, i, j): the element at half its grid point, (i / 2, j / 2)
// in sector s: a vertex, an edge (its ends), or, at the centre of a quad,
// that quad (faces keyed by their corner (s, i, j) nearest the centre).
std::vector<ImageParent> image_parents(const GridPoints& points, SplitRule split, Index vertices,
                                       const std::map<GridPoints::Key, Index>& quads) {
  std::vector<ImageParent> parents;
  for (Index v = 0; v < vertices; ++v) {
    const auto [s, i, j] = points.key(v);
    const auto at = [&, s = s](int a, int b) { return points.find(s, a, b); };
    ImageParent p;
    if (i % 2 == 0 && j % 2 == 0) {
      p = {ImageParent::Kind::vertex, at(i / 2, j / 2)};
    } else if (i % 2 == 0 || j % 2 == 0) {
      p = {ImageParent::Kind::edge, at(i / 2, j / 2), at((i + 1) / 2, (j + 1) / 2)};
    } else if (split == SplitRule::triangle) {  // the diagonal of the grid cell
      p = {ImageParent::Kind::edge, at((i + 1) / 2, (j - 1) / 2), at((i - 1) / 2, (j + 1) / 2)};
    } else {
      const auto it = quads.find({s, (i - 1) / 2, (j - 1) / 2});
      p = {ImageParent::Kind::face, it == quads.end() ? kInvalidIndex : it->second};
    }
    if (p.a == kInvalidIndex || (p.kind == ImageParent::Kind::edge && p.b == kInvalidIndex))
      throw InvalidInputError("ring mesh: no element under a grid point's image");
    parents.push_back(p);
  }
  return parents;
}

// The grid layout of `ring_mesh` (`polar` for interior k = 2).
RingMesh grid_ring_mesh(SplitRule split, const Configuration& configuration, int rings, bool polar) {
  const int k = configuration.k;
  const bool closed = configuration.kind == Configuration::Kind::interior;
  if (rings < 1) throw InvalidInputError("ring mesh: rings must be >= 1, not " + std::to_string(rings));
  if (configuration.angle < 0.0 || configuration.angle >= 2.0 * std::numbers::pi)
    throw InvalidInputError(configuration.name() + ": the corner angle must be in (0, 2 pi)");
  // The layout only identifies vertices (rules never read positions), but a
  // sector must stay a proper wedge: one face spanning pi or more (a single
  // face at a boundary, a concave corner) is laid out with a quarter turn.
  const double angle = polar || configuration.sector_angle() / k < 0.9 * std::numbers::pi
                           ? configuration.sector_angle()
                           : 0.5 * std::numbers::pi * k;
  RingMesh ring;
  GridPoints points(k, closed, angle, polar, ring.mesh);
  std::map<GridPoints::Key, Index> quads;  // the quad split's faces by their corner nearest the centre
  ring.centre = points.at(0, 0, 0);
  for (int s = 0; s < k; ++s) {
    if (split == SplitRule::quad || split == SplitRule::sqrt2) {
      for (int i = 0; i < rings; ++i)
        for (int j = 0; j < rings; ++j) {
          quads.emplace(GridPoints::Key{s, i, j}, ring.mesh.face_count());
          ring.mesh.add_face({points.at(s, i, j), points.at(s, i + 1, j), points.at(s, i + 1, j + 1), points.at(s, i, j + 1)});
        }
    } else {
      for (int i = 0; i < rings; ++i)
        for (int j = 0; i + j < rings; ++j) {
          ring.mesh.add_face({points.at(s, i, j), points.at(s, i + 1, j), points.at(s, i, j + 1)});
          if (i + j + 1 < rings)
            ring.mesh.add_face({points.at(s, i + 1, j), points.at(s, i + 1, j + 1), points.at(s, i, j + 1)});
        }
    }
  }
  if (configuration.kind == Configuration::Kind::corner)
    ring.mesh.tags.corners.push_back(
        {ring.centre, kInfiniteSharpness, configuration.corner, configuration.sector_angle()});
  ring.linear = !polar;
  if (is_primal(split)) ring.image_parent = image_parents(points, split, ring.mesh.vertex_count(), quads);
  return ring;
}

}  // namespace

namespace {

// The dual of the quad layout with one more ring: a vertex per face (at its
// centroid), a face per interior vertex (its faces in ring order).
RingMesh dual_ring_mesh(const Configuration& configuration, int rings) {
  if (configuration.kind != Configuration::Kind::interior)
    throw InvalidInputError(configuration.name() +
                            ": the dual and midedge splits are analysed at extraordinary faces only (interior configurations)");
  if (configuration.k < 3) throw InvalidInputError(configuration.name() + ": an extraordinary face needs k >= 3");
  const RingMesh primal = ring_mesh(SplitRule::quad, configuration, rings + 1);
  const MeshTopology t(primal.mesh);
  RingMesh dual;
  for (Index f = 0; f < t.face_count(); ++f) {
    Vec3 centroid;
    for (const Index v : t.face_vertices(f)) centroid += primal.mesh.positions[static_cast<std::size_t>(v)];
    dual.mesh.positions.push_back((1.0 / t.face_size(f)) * centroid);
  }
  std::vector<Index> face;
  for (Index v = 0; v < t.vertex_count(); ++v) {
    if (t.vertex_kind(v) != VertexKind::interior) continue;
    face.clear();
    for (const Index c : t.vertex_corners(v)) face.push_back(t.corner_face(c));
    if (v == primal.centre) dual.centre_face = dual.mesh.face_count();
    dual.mesh.add_face(face);
    dual.face_centres.push_back(primal.mesh.positions[static_cast<std::size_t>(v)]);
  }
  dual.centre = kInvalidIndex;
  return dual;
}

void dual_placement(const LevelView& level, Index corner, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  const Index f = t.corner_face(corner);
  const double n = t.face_size(f);
  mask.add(t.corner_vertex(corner), 0.5);
  for (const Index v : t.face_vertices(f)) mask.add(v, 0.5 / n);
}

void dual_boundary_placement(const LevelView& level, Index edge, Index vertex, MaskBuilder& mask) {
  mask.add(vertex, 0.75);
  mask.add(level.topology.other_vertex(edge, vertex), 0.25);
}

}  // namespace

const Scheme& layout_placement(SplitRule split) noexcept;

namespace {

// Two midedge steps make a vertex per corner (the point of the first step's
// edge joining the corner's two edge points), a dual split's corner point:
// placed as the dual split places it, at (v + the face's layout point) / 2,
// which is p / 2 for the layout point p it corresponds to. Other vertices
// (at the ring mesh's boundary) keep the midpoint placement.
std::vector<Vec3> midedge_child_layout(const RingMesh& ring, int levels) {
  if (levels != 2)
    throw InvalidInputError("child layout: the midedge split is identified after two steps, not " +
                            std::to_string(levels));
  RefineOptions once;
  once.levels = 1;
  const PolygonMesh first = refine(ring.mesh, layout_placement(SplitRule::midedge), once);
  PolygonMesh second = refine(first, layout_placement(SplitRule::midedge), once);
  const MeshTopology t(ring.mesh), t1(first);
  for (Index c = 0; c < t.corner_count(); ++c) {
    const Index e = t1.find_edge(t.corner_edge(t.corner_prev(c)), t.corner_edge(c));
    if (e == kInvalidIndex) throw InvalidInputError("child layout: a corner's edge points share no edge");
    second.positions[static_cast<std::size_t>(e)] =
        0.5 * (ring.mesh.positions[static_cast<std::size_t>(t.corner_vertex(c))] +
               ring.face_centres[static_cast<std::size_t>(t.corner_face(c))]);
  }
  return second.positions;
}

// The sqrt3 split's linear placement: face centroids, vertices kept,
// boundary points at the thirds of their edges.
void centroid_placement(const LevelView& level, Index f, MaskBuilder& mask) {
  const auto face = level.topology.face_vertices(f);
  for (const Index v : face) mask.add(v, 1.0 / static_cast<double>(face.size()));
}

void kept_placement(const LevelView&, Index v, VertexRule, MaskBuilder& mask) { mask.add(v, 1.0); }

void third_placement(const LevelView& level, Index edge, Index vertex, MaskBuilder& mask) {
  mask.add(vertex, 2.0 / 3.0);
  mask.add(level.topology.other_vertex(edge, vertex), 1.0 / 3.0);
}

// Two sqrt3 steps split every triangle 1-to-9, aligned with it: the layout
// point p's descendant is at p / 3 within a sector. The placement puts the
// first step's face points (centroids of faces, each within a sector) and
// the second step's boundary points (thirds of the old boundary edges) there
// already; the second step's face points belong to the triangles (a,
// point(F), point(G)) of the old edges (a, b) between faces F and G, which
// straddle the ray of a sector boundary, and are placed at (2 a + b) / 3.
std::vector<Vec3> sqrt3_child_layout(const RingMesh& ring, int levels) {
  if (levels != 2)
    throw InvalidInputError("child layout: the sqrt3 split is identified after two steps, not " +
                            std::to_string(levels));
  PolygonMesh first;
  RefineOptions twice;
  twice.levels = 2;
  twice.on_level = [&](int level, const PolygonMesh& mesh) {
    if (level == 1) first = mesh;
  };
  PolygonMesh second = refine(ring.mesh, layout_placement(SplitRule::sqrt3), twice);
  const MeshTopology t0(ring.mesh), t1(first);
  const Index face_points1 = t0.face_count();  // the first step gives every face a point
  Index point = 0;                            // the second step's face points, in face order
  for (Index f = 0; f < t1.face_count(); ++f) {
    bool boundary = false;
    for (Index c = t1.face_first_corner(f); c < t1.face_first_corner(f) + 3; ++c)
      boundary = boundary || t1.is_boundary_edge(t1.corner_edge(c));
    if (boundary) continue;
    Index a = kInvalidIndex, faces[2] = {kInvalidIndex, kInvalidIndex};
    int n = 0;
    for (const Index v : t1.face_vertices(f)) {
      if (v >= face_points1) a = v - face_points1;
      else if (n < 2) faces[n++] = v;
    }
    if (a == kInvalidIndex || n != 2) throw InvalidInputError("child layout: a sqrt3 triangle without one old vertex");
    Index b = kInvalidIndex;
    for (const Index u : t0.face_vertices(faces[0]))
      for (const Index w : t0.face_vertices(faces[1]))
        if (u == w && u != a) b = u;
    if (b == kInvalidIndex) throw InvalidInputError("child layout: a sqrt3 triangle's faces share no edge");
    second.positions[static_cast<std::size_t>(point++)] =
        (1.0 / 3.0) * (2.0 * ring.mesh.positions[static_cast<std::size_t>(a)] + ring.mesh.positions[static_cast<std::size_t>(b)]);
  }
  return second.positions;
}

// Two sqrt2 steps make the quad split of the layout, back in its
// orientation: the layout point p's descendant is at p / 2 within a sector.
// The first step's face points are face centroids (each within a sector);
// the second step's belong to the quads (a, point(G), b, point(F)) of the
// old edges (a, b), which straddle a ray where the edge lies on one, and are
// placed at the edge's midpoint.
std::vector<Vec3> sqrt2_child_layout(const RingMesh& ring, int levels) {
  if (levels != 2)
    throw InvalidInputError("child layout: the sqrt2 split is identified after two steps, not " +
                            std::to_string(levels));
  RefineOptions twice;
  twice.levels = 2;
  PolygonMesh first;
  twice.on_level = [&](int level, const PolygonMesh& mesh) {
    if (level == 1) first = mesh;
  };
  PolygonMesh second = refine(ring.mesh, layout_placement(SplitRule::sqrt2), twice);
  const Index face_points1 = ring.mesh.face_count();
  for (Index f = 0; f < first.face_count(); ++f) {  // second-step face point f
    Vec3 sum;
    int old = 0;
    for (const Index v : first.face(f))
      if (v >= face_points1) {
        sum += ring.mesh.positions[static_cast<std::size_t>(v - face_points1)];
        ++old;
      }
    if (first.face_size(f) == 4 && old == 2) second.positions[static_cast<std::size_t>(f)] = 0.5 * sum;
  }
  return second.positions;
}

}  // namespace

const Scheme& layout_placement(SplitRule split) noexcept {
  static const Scheme sqrt2{.name = "sqrt2-placement",
                            .split = SplitRule::sqrt2,
                            .masks = {.face_point = centroid_placement, .vertex_point = kept_placement}};
  static const Scheme sqrt3{.name = "sqrt3-placement",
                            .split = SplitRule::sqrt3,
                            .traits = {.needs_triangles = true},
                            .masks = {.face_point = centroid_placement,
                                      .vertex_point = kept_placement,
                                      .boundary_point = third_placement}};
  static const Scheme dual{.name = "dual-placement",
                           .split = SplitRule::dual,
                           .masks = {.corner_point = dual_placement, .boundary_point = dual_boundary_placement}};
  static const Scheme midedge = [] {
    Scheme s = midedge_scheme();  // edge midpoints
    s.traits.needs_closed_mesh = false;
    return s;
  }();
  switch (split) {
    case SplitRule::sqrt2: return sqrt2;
    case SplitRule::sqrt3: return sqrt3;
    case SplitRule::dual: return dual;
    case SplitRule::midedge: return midedge;
    case SplitRule::quad: return bilinear_scheme();
    default: return linear_scheme();
  }
}

std::vector<Vec3> child_layout(SplitRule split, const RingMesh& ring, int levels) {
  if (levels < 1) throw InvalidInputError("child layout: levels must be >= 1, not " + std::to_string(levels));
  if (split == SplitRule::midedge) return midedge_child_layout(ring, levels);
  if (split == SplitRule::sqrt3) return sqrt3_child_layout(ring, levels);
  if (split == SplitRule::sqrt2) return sqrt2_child_layout(ring, levels);
  if (split != SplitRule::dual) {
    RefineOptions down;
    down.levels = levels;
    return refine(ring.mesh, layout_placement(split), down).positions;
  }
  // The dual split, one level at a time: each level's faces need the layout
  // points they surround.
  RingMesh level = ring;
  for (int l = 0; l < levels; ++l) {
    RefineOptions once;
    once.levels = 1;
    PolygonMesh child = refine(level.mesh, layout_placement(split), once);
    const MeshTopology t(level.mesh);
    for (Index c = 0; c < t.corner_count(); ++c)  // child vertex c = corner point of corner c
      child.positions[static_cast<std::size_t>(c)] =
          0.5 * (level.mesh.positions[static_cast<std::size_t>(t.corner_vertex(c))] +
                 level.face_centres[static_cast<std::size_t>(t.corner_face(c))]);
    if (l + 1 == levels) return child.positions;
    // Child faces as the dual split numbers them: F-faces, E-faces, V-faces
    // (of vertices that have one).
    RingMesh next;
    next.centre = kInvalidIndex;
    next.centre_face = level.centre_face;  // the centre's F-face
    for (Index f = 0; f < t.face_count(); ++f) next.face_centres.push_back(level.face_centres[static_cast<std::size_t>(f)]);
    for (Index e = 0; e < t.edge_count(); ++e) {
      const auto sides = t.edge_corners(e);
      Vec3 point;
      for (const Index c : sides) point += level.face_centres[static_cast<std::size_t>(t.corner_face(c))];
      next.face_centres.push_back((1.0 / static_cast<double>(sides.size())) * point);
    }
    for (Index v = 0; v < t.vertex_count(); ++v) {
      if (!dual_split_has_v_face(t, v)) continue;
      next.face_centres.push_back(level.mesh.positions[static_cast<std::size_t>(v)]);
    }
    if (static_cast<Index>(next.face_centres.size()) != child.face_count())
      throw InvalidInputError("child layout: the dual split's child faces are not F-, E- and V-faces");
    next.mesh = std::move(child);
    level = std::move(next);
  }
  return {};
}

RingMesh ring_mesh(SplitRule split, const Configuration& configuration, int rings) {
  // Its topology depends on the positions: no canonical ring exists
  // (analysis/quasi_4_8_experiment.h reads its matrices off refined n-gons).
  if (split == SplitRule::quasi_4_8)
    throw InvalidInputError("the quasi 4-8 bisection has no canonical ring meshes (its split depends on geometry)");
  if (split == SplitRule::dual || split == SplitRule::midedge) {  // at extraordinary faces
    if (rings < 1) throw InvalidInputError("ring mesh: rings must be >= 1, not " + std::to_string(rings));
    return dual_ring_mesh(configuration, rings);
  }
  const bool closed = configuration.kind == Configuration::Kind::interior;
  if (configuration.k < (closed ? 3 : 1))
    throw InvalidInputError(configuration.name() + ": needs k >= " + std::string(closed ? "3" : "1") +
                            (closed && configuration.k == 2 ? " for a layout linear in each sector" : ""));
  return grid_ring_mesh(split, configuration, rings, false);
}

RingMesh valence_two_ring_mesh(SplitRule split, int rings) {
  if (split == SplitRule::triangle)
    throw InvalidInputError("interior k=2: two triangles around a vertex share all three edges (the one opposite it "
                            "is non-manifold, or the two are a closed component): no configuration for the triangle split");
  if (split != SplitRule::quad)
    throw InvalidInputError(std::string("interior k=2: a vertex with two faces is analysed for the quad split only, not the ") +
                            to_string(split));
  return grid_ring_mesh(split, {Configuration::Kind::interior, 2}, rings, true);
}

RingMesh analysis_ring_mesh(SplitRule split, const Configuration& configuration, int rings) {
  if (configuration.kind == Configuration::Kind::interior && configuration.k == 2)
    return valence_two_ring_mesh(split, rings);
  return ring_mesh(split, configuration, rings);
}

}  // namespace subdiv
