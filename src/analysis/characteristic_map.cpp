#include "subdiv/analysis/characteristic_map.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "subdiv/refine/ring_mesh.h"
#include "subdiv/core/error.h"
#include "subdiv/refine/refine.h"

namespace subdiv {

namespace {

double cross_z(Vec3 a, Vec3 b) { return a.x * b.y - a.y * b.x; }

// +1 or -1 when every corner turns that way, 0 otherwise (folded or
// degenerate). `scale` sets what counts as zero.
int face_orientation(const std::vector<Vec3>& p, std::span<const Index> face, double scale) {
  int sign = 0;
  const std::size_t n = face.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a = p[static_cast<std::size_t>(face[i])];
    const Vec3 next = p[static_cast<std::size_t>(face[(i + 1) % n])];
    const Vec3 prev = p[static_cast<std::size_t>(face[(i + n - 1) % n])];
    const double c = cross_z(next - a, prev - a);
    const int s = c > 1e-12 * scale ? 1 : c < -1e-12 * scale ? -1 : 0;
    if (s == 0 || (sign != 0 && s != sign)) return 0;
    sign = s;
  }
  return sign;
}

// Whether segments ab and cd share a point (touching counts); collinear
// segments share one only if their extents overlap. eps: what counts as 0
// for the cross products.
bool segments_meet(Vec3 a, Vec3 b, Vec3 c, Vec3 d, double eps) {
  auto side = [eps](double v) { return v > eps ? 1 : v < -eps ? -1 : 0; };
  const int d1 = side(cross_z(b - a, c - a)), d2 = side(cross_z(b - a, d - a));
  const int d3 = side(cross_z(d - c, a - c)), d4 = side(cross_z(d - c, b - c));
  if (d1 == 0 && d2 == 0) {  // collinear: compare extents along the line
    const Vec3 u = b - a;
    const double t0 = dot(c - a, u), t1 = dot(d - a, u), len = dot(u, u);
    return std::max(t0, t1) >= -eps && std::min(t0, t1) <= len + eps;
  }
  return d1 * d2 <= 0 && d3 * d4 <= 0;
}

// The outline of `mesh` (edges with one face) as one closed loop of
// vertices, or empty when it is not a single loop.
std::vector<Index> single_outline(const PolygonMesh& mesh) {
  std::map<std::pair<Index, Index>, int> directed;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t i = 0; i < face.size(); ++i) ++directed[{face[i], face[(i + 1) % face.size()]}];
  }
  std::map<Index, Index> next;
  for (const auto& [edge, count] : directed)
    if (!directed.contains({edge.second, edge.first})) {
      if (next.contains(edge.first)) return {};
      next[edge.first] = edge.second;
    }
  if (next.empty()) return {};
  std::vector<Index> loop{next.begin()->first};
  while (loop.size() <= next.size()) {
    const auto it = next.find(loop.back());
    if (it == next.end()) return {};
    if (it->second == loop.front()) break;
    loop.push_back(it->second);
  }
  return loop.size() == next.size() ? loop : std::vector<Index>{};
}

// Keeps the faces of the image joined to the centre across edges. Away from
// the centre the valid region can have islands (sqrt3: small patches around
// outer neighbourhood vertices, whose few descendants depend on the
// neighbourhood alone); the criterion is about the map around the centre.
void keep_centre_component(CharacteristicMap& map, const PolygonMesh& layout, const std::vector<Index>& kept) {
  Index centre = kInvalidIndex;
  for (Index v = 0; v < layout.vertex_count() && centre == kInvalidIndex; ++v)
    if (norm(layout.positions[static_cast<std::size_t>(v)]) < 1e-12) centre = kept[static_cast<std::size_t>(v)];
  if (centre == kInvalidIndex) return;
  const Index nf = map.image.face_count();
  std::map<std::pair<Index, Index>, std::vector<Index>> edge_faces;
  for (Index f = 0; f < nf; ++f) {
    const auto face = map.image.face(f);
    for (std::size_t i = 0; i < face.size(); ++i) {
      const Index a = face[i], b = face[(i + 1) % face.size()];
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  }
  std::vector<char> reached(static_cast<std::size_t>(nf), 0);
  std::vector<Index> stack;
  for (Index f = 0; f < nf; ++f) {
    const auto face = map.image.face(f);
    if (std::find(face.begin(), face.end(), centre) != face.end()) {
      reached[static_cast<std::size_t>(f)] = 1;
      stack.push_back(f);
    }
  }
  while (!stack.empty()) {
    const Index f = stack.back();
    stack.pop_back();
    const auto face = map.image.face(f);
    for (std::size_t i = 0; i < face.size(); ++i) {
      const Index a = face[i], b = face[(i + 1) % face.size()];
      for (const Index g : edge_faces[{std::min(a, b), std::max(a, b)}])
        if (!reached[static_cast<std::size_t>(g)]) {
          reached[static_cast<std::size_t>(g)] = 1;
          stack.push_back(g);
        }
    }
  }
  if (std::count(reached.begin(), reached.end(), 1) == nf) return;
  PolygonMesh image;
  image.positions = map.image.positions;
  std::vector<int> sector, orientation;
  for (Index f = 0; f < nf; ++f) {
    if (!reached[static_cast<std::size_t>(f)]) continue;
    const auto face = map.image.face(f);
    image.add_face(std::vector<Index>(face.begin(), face.end()));
    sector.push_back(map.face_sector[static_cast<std::size_t>(f)]);
    orientation.push_back(map.face_orientation[static_cast<std::size_t>(f)]);
  }
  map.image = std::move(image);
  map.face_sector = std::move(sector);
  map.face_orientation = std::move(orientation);
}

}  // namespace

CharacteristicMap characteristic_map(const Scheme& scheme, const LocalSubdivisionMatrix& matrix,
                                     const Eigen::VectorXd& x, const Eigen::VectorXd& y, int levels) {
  const auto n = static_cast<std::size_t>(matrix.S.rows());
  if (static_cast<std::size_t>(x.size()) != n || static_cast<std::size_t>(y.size()) != n)
    throw InvalidInputError("characteristic map: eigenvectors do not match the matrix");
  if (levels < 1) throw InvalidInputError("characteristic map: levels must be >= 1");

  // The same ring mesh the matrix was read from; neighbourhood vertices found
  // by their layout positions.
  const RingMesh ring = ring_mesh(scheme.split, matrix.configuration, ring_mesh_size(matrix.rings));
  std::vector<char> in_neighbourhood(static_cast<std::size_t>(ring.mesh.vertex_count()), 0);
  PolygonMesh control = ring.mesh;
  for (Vec3& p : control.positions) p = Vec3{};
  for (std::size_t a = 0; a < n; ++a) {
    Index found = kInvalidIndex;
    for (Index v = 0; v < ring.mesh.vertex_count() && found == kInvalidIndex; ++v)
      if (norm(ring.mesh.positions[static_cast<std::size_t>(v)] - matrix.layout[a]) < 1e-9) found = v;
    if (found == kInvalidIndex) throw InvalidInputError("characteristic map: the matrix's layout is not the ring's");
    in_neighbourhood[static_cast<std::size_t>(found)] = 1;
    control.positions[static_cast<std::size_t>(found)] = {x[static_cast<Eigen::Index>(a)], y[static_cast<Eigen::Index>(a)], 0.0};
  }

  // Level by level: the per-level tables are the masks themselves, much
  // smaller than one composed table. A child vertex is valid when every
  // parent its mask uses is.
  // `levels` analysis steps: the scheme's period refinement steps each.
  const int steps = levels * matrix.period;
  RefineOptions options = matrix.rules;
  options.levels = steps;
  Scheme open = scheme;  // the ring mesh's outer boundary lies outside the neighbourhood
  open.traits.needs_closed_mesh = false;
  const std::vector<StencilTable> tables = refine_stencils(ring.mesh, open, options);
  const Scheme& placement = layout_placement(scheme.split);
  RefineOptions linear;
  linear.levels = steps;
  const PolygonMesh layout = refine(ring.mesh, placement, linear);
  std::vector<Vec3> points = control.positions;
  std::vector<char> valid = in_neighbourhood;
  for (const StencilTable& table : tables) {
    std::vector<Vec3> next(static_cast<std::size_t>(table.row_count()));
    table.apply(points, next);
    std::vector<char> next_valid(next.size(), 1);
    for (Index r = 0; r < table.row_count(); ++r) {
      const auto vertices = table.row_vertices(r);
      const auto weights = table.row_weights(r);
      for (std::size_t e = 0; e < vertices.size(); ++e)
        if (weights[e] != 0.0 && !valid[static_cast<std::size_t>(vertices[e])]) next_valid[static_cast<std::size_t>(r)] = 0;
    }
    points = std::move(next);
    valid = std::move(next_valid);
  }

  // The valid vertices, renumbered.
  std::vector<Index> kept(points.size(), kInvalidIndex);
  CharacteristicMap map;
  map.levels = levels;  // analysis steps
  for (std::size_t r = 0; r < points.size(); ++r) {
    if (!valid[r]) continue;
    kept[r] = map.image.vertex_count();
    map.image.positions.push_back(points[r]);
  }
  double scale = 0.0;
  for (const Vec3& p : map.image.positions) scale = std::max(scale, dot(p, p));

  const int k = matrix.configuration.k;
  const double wedge = matrix.configuration.sector_angle() / k;
  std::vector<Index> face;
  for (Index f = 0; f < layout.face_count(); ++f) {
    face.clear();
    Vec3 centroid;
    for (const Index v : layout.face(f)) {
      face.push_back(kept[static_cast<std::size_t>(v)]);
      centroid += layout.positions[static_cast<std::size_t>(v)];
    }
    if (std::find(face.begin(), face.end(), kInvalidIndex) != face.end()) continue;
    map.image.add_face(face);
    double angle = std::atan2(centroid.y, centroid.x);
    if (angle < 0) angle += 2.0 * std::numbers::pi;
    map.face_sector.push_back(std::min(k - 1, static_cast<int>(angle / wedge)));
    map.face_orientation.push_back(face_orientation(map.image.positions, map.image.face(map.image.face_count() - 1), scale));
  }
  if (map.image.face_count() == 0) {
    map.note = "no face of the ring depends on the neighbourhood alone";
    return map;
  }
  keep_centre_component(map, layout, kept);

  // Faces against the majority orientation, or degenerate, make it irregular.
  const auto positive = std::count(map.face_orientation.begin(), map.face_orientation.end(), 1);
  const auto negative = std::count(map.face_orientation.begin(), map.face_orientation.end(), -1);
  map.regular = map.image.face_count() == std::max(positive, negative);
  if (!map.regular) {
    map.note = std::to_string(std::min(positive, negative)) + " of " + std::to_string(map.image.face_count()) +
               " faces of the refined map are reversed and " +
               std::to_string(map.image.face_count() - positive - negative) +
               " folded or degenerate (the Jacobian is not of one sign)";
    return map;
  }
  const std::vector<Index> outline = single_outline(map.image);
  if (outline.empty()) {
    map.note = "the image's outline is not a single loop";
    return map;
  }
  const std::size_t m = outline.size();
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 2; j < m; ++j) {
      if (i == 0 && j + 1 == m) continue;  // adjacent across the loop's start
      const Vec3 a = map.image.positions[static_cast<std::size_t>(outline[i])];
      const Vec3 b = map.image.positions[static_cast<std::size_t>(outline[(i + 1) % m])];
      const Vec3 c = map.image.positions[static_cast<std::size_t>(outline[j])];
      const Vec3 d = map.image.positions[static_cast<std::size_t>(outline[(j + 1) % m])];
      if (segments_meet(a, b, c, d, 1e-12 * scale)) {
        map.note = "the image's outline crosses itself: the map overlaps itself";
        return map;
      }
    }
  map.injective = true;
  return map;
}

}  // namespace subdiv
