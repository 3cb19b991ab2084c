// Tag and face-varying propagation shared by the splits, and the dispatch.

#include "subdiv/topology/split.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "split_detail.h"
#include "subdiv/topology/bisection_split.h"
#include "subdiv/core/error.h"

namespace subdiv {

std::pair<Index, Index> child_faces(const MeshTopology& parent, SplitRule rule, Index f) {
  if (rule == SplitRule::quad) return {parent.face_first_corner(f), parent.face_first_corner(f) + parent.face_size(f)};
  if (rule == SplitRule::dual || rule == SplitRule::midedge || rule == SplitRule::identity) return {f, f + 1};
  if (rule == SplitRule::sqrt3 || rule == SplitRule::sqrt2)
    throw InvalidInputError(std::string(to_string(rule)) + ": child faces belong to the parent's edges, not to its faces");
  return {4 * f, 4 * f + 4};
}

double arity(SplitRule r) noexcept {
  if (r == SplitRule::identity) return 1.0;
  if (r == SplitRule::midedge || r == SplitRule::sqrt2 || r == SplitRule::quasi_4_8) return std::sqrt(2.0);
  if (r == SplitRule::sqrt3) return std::sqrt(3.0);
  return 2.0;
}

const char* to_string(SplitRule r) noexcept {
  switch (r) {
    case SplitRule::quad: return "quad split (QP, arity 2)";
    case SplitRule::triangle: return "triangle split (TP, arity 2)";
    case SplitRule::dual: return "dual split (QD, arity 2)";
    case SplitRule::midedge: return "midedge split (QD, arity sqrt 2)";
    case SplitRule::identity: return "identity (same faces)";
    case SplitRule::quasi_4_8: return "quasi 4-8 bisection (geometric, arity sqrt 2)";
    case SplitRule::sqrt3: return "sqrt3 split (TP, arity sqrt 3)";
    case SplitRule::sqrt2: return "sqrt2 split (QP, arity sqrt 2)";
  }
  return "?";
}

namespace detail {

namespace {

void propagate_corners(const Tags& in, Index vertex_count, const SplitMap& map, Tags& out) {
  for (const CornerTag& c : in.corners) {
    CornerTag t = c;
    t.sharpness = subdivide_sharpness(c.sharpness);
    if (t.sharpness <= 0.0 || c.vertex < 0 || c.vertex >= vertex_count) continue;
    t.vertex = map.vertex_point(c.vertex);
    out.corners.push_back(t);
  }
}

}  // namespace

void propagate_tags(const PolygonMesh& parent, const MeshTopology& topology, const SplitMap& map,
                    std::span<const double> child_end_sharpness, int level, PolygonMesh& child) {
  const Tags& in = parent.tags;
  Tags& out = child.tags;
  out = Tags{};
  out.boundary_interpolation = in.boundary_interpolation;
  out.boundary_interpolation_set = in.boundary_interpolation_set;
  out.face_varying_interpolation = in.face_varying_interpolation;
  out.face_varying_interpolation_set = in.face_varying_interpolation_set;
  out.crease_method = in.crease_method;
  out.crease_method_set = in.crease_method_set;
  out.triangle_subdivision = in.triangle_subdivision;
  out.triangle_subdivision_set = in.triangle_subdivision_set;
  out.face_varying_propagate_corners = in.face_varying_propagate_corners;
  out.face_varying_propagate_corners_set = in.face_varying_propagate_corners_set;
  // Tags no module interprets (hierarchical edits) name the parent's faces,
  // edges and vertices by index; the child's elements are others, so they
  // are dropped (out.other stays empty).
  if (map.rule == SplitRule::sqrt3) {  // vertices are kept, edges are not: corners only
    propagate_corners(in, parent.vertex_count(), map, out);
    return;
  }
  if (map.rule == SplitRule::identity) {  // the same elements: every tag as it is
    out.creases = in.creases;
    out.corners = in.corners;
    out.holes = in.holes;
    return;
  }
  if (!is_primal(map.rule)) return;  // no sharp features there (check_refinable)

  for (const CreaseTag& c : in.creases) {
    const Index e = topology.find_edge(c.v0, c.v1);
    if (e == kInvalidIndex) continue;
    double s0 = subdivide_sharpness(c.sharpness), s1 = s0;  // the halves at c.v0 and c.v1
    if (!child_end_sharpness.empty() && c.sharpness > 0.0 && c.sharpness < kInfiniteSharpness) {
      // Chaikin: each half its own value, unless the edge is infinitely
      // sharp anyway (a boundary), where the tag decays as usual.
      const std::size_t at_v0 = 2 * static_cast<std::size_t>(e) + (topology.edge_vertices(e)[0] == c.v0 ? 0 : 1);
      const std::size_t at_v1 = at_v0 ^ 1;
      if (child_end_sharpness[at_v0] < kInfiniteSharpness) s0 = child_end_sharpness[at_v0];
      if (child_end_sharpness[at_v1] < kInfiniteSharpness) s1 = child_end_sharpness[at_v1];
    }
    if (s0 > 0.0) out.creases.push_back({map.vertex_point(c.v0), map.edge_point(e), s0});
    if (s1 > 0.0) out.creases.push_back({map.edge_point(e), map.vertex_point(c.v1), s1});
  }
  propagate_corners(in, parent.vertex_count(), map, out);
  // The control mesh's non-manifold vertices that OpenSubdiv sharpens are
  // corners for good (its base level's sharpness stays), also where their
  // children no longer look non-manifold.
  if (level == 0)
    for (Index v = 0; v < topology.vertex_count(); ++v)
      if (topology.is_non_manifold_corner(v)) {
        CornerTag corner;
        corner.vertex = map.vertex_point(v);
        out.corners.push_back(corner);
      }
  if (!in.holes.empty()) {
    // Child faces of increasing parents increase: sorted parents give sorted holes.
    std::vector<Index> holes = in.holes;
    std::sort(holes.begin(), holes.end());
    holes.erase(std::unique(holes.begin(), holes.end()), holes.end());
    for (const Index f : holes) {
      if (f < 0 || f >= topology.face_count()) continue;
      const auto [first, last] = child_faces(topology, map.rule, f);
      for (Index cf = first; cf < last; ++cf) out.holes.push_back(cf);
    }
  }
}

void require_edges(const MeshTopology& topology, SplitRule rule) {
  if (is_primal(rule) || !topology.has_coincident_edges()) return;
  for (Index c = 0; c < topology.corner_count(); ++c) {
    const auto ends = topology.edge_vertices(topology.corner_edge(c));
    if (ends[0] == ends[1])
      throw TopologyError("cannot split face " + std::to_string(topology.corner_face(c)) + " by the " +
                          to_string(rule) + ": it repeats a vertex on consecutive corners (a degenerate face)");
  }
}

namespace {

// The key of the half of edge e at the end where corner c's side starts
// (at_start) or ends: keyed by the end vertex, so that the faces on either
// side agree; an edge from a vertex to itself has one side, keyed by it.
Index half_key(const MeshTopology& t, Index c, bool at_start) {
  const Index e = t.corner_edge(c);
  const auto ends = t.edge_vertices(e);
  const Index at = t.corner_vertex(at_start ? c : t.corner_next(c));
  const bool first_half = ends[0] == ends[1] ? at_start : ends[0] == at;
  return 2 * e + (first_half ? 0 : 1);
}

}  // namespace

std::vector<Index> child_edge_keys(const MeshTopology& t, SplitRule rule) {
  if (rule != SplitRule::quad && rule != SplitRule::triangle)
    throw InvalidInputError(std::string("edge keys: the ") + to_string(rule) + " has none");
  const Index nc = t.corner_count();
  // Halves take [0, 2E), edges inside faces 2E + the corner they belong to.
  if (2 * static_cast<std::int64_t>(t.edge_count()) + nc > std::numeric_limits<Index>::max())
    throw InvalidInputError("edge keys: the mesh is too large for them");
  const Index inside = 2 * t.edge_count();
  std::vector<Index> keys;
  if (rule == SplitRule::quad) {
    // Child face c: (vertex point, edge point of c's edge, face point, edge point of the previous edge).
    keys.resize(4 * static_cast<std::size_t>(nc));
    for (Index c = 0; c < nc; ++c) {
      Index* k = keys.data() + 4 * static_cast<std::size_t>(c);
      const Index prev = t.corner_prev(c);
      k[0] = half_key(t, c, true);
      k[1] = inside + c;
      k[2] = inside + prev;
      k[3] = half_key(t, prev, false);
    }
    return keys;
  }
  // Triangle f's children 4f + i = (corner i, its edge's point, the previous
  // edge's point) and the centre (edge points 0, 1, 2); the centre's side j
  // is the inner side of child j + 1.
  keys.resize(4 * static_cast<std::size_t>(nc));
  for (Index f = 0; f < t.face_count(); ++f) {
    Index* k = keys.data() + 12 * static_cast<std::size_t>(f);
    for (Index i = 0; i < 3; ++i) {
      const Index c = 3 * f + i, prev = 3 * f + (i + 2) % 3;
      k[3 * i + 0] = half_key(t, c, true);
      k[3 * i + 1] = inside + c;
      k[3 * i + 2] = half_key(t, prev, false);
      k[9 + i] = inside + 3 * f + (i + 1) % 3;
    }
  }
  return keys;
}

}  // namespace detail

SplitMap split_topology(const PolygonMesh& parent, const MeshTopology& topology, SplitRule rule,
                        PolygonMesh& child, const SplitOptions& options) {
  detail::require_edges(topology, rule);
  if (rule == SplitRule::quasi_4_8) {  // tags and face-varying channels split by the bisection itself
    BisectionMap bisection = bisection_split(parent, topology, child);
    SplitMap map;
    map.rule = rule;
    map.face_points = map.vertex_points = 0;
    map.edge_points = bisection.old_vertex_count;
    map.child_vertex_count = bisection.child_vertex_count();
    map.split_edges = std::move(bisection.split_edges);
    child.vertex_channels.clear();
    return map;
  }
  SplitMap map = rule == SplitRule::quad       ? detail::quad_split(topology, child)
                 : rule == SplitRule::triangle ? detail::triangle_split(topology, child)
                 : rule == SplitRule::dual     ? detail::dual_split(topology, child)
                 : rule == SplitRule::identity ? detail::identity_split(topology, child)
                 : rule == SplitRule::sqrt3    ? detail::sqrt3_split(topology, child, options.level)
                 : rule == SplitRule::sqrt2    ? detail::sqrt2_split(topology, child)
                                               : detail::midedge_split(topology, child);
  detail::propagate_tags(parent, topology, map, options.child_end_sharpness, options.level, child);
  if (rule == SplitRule::sqrt3 && options.boundary == BoundaryInterpolation::edge_and_corner)
    detail::sqrt3_keep_one_face_corners(topology, map, child.tags);
  // Vertex channels are the masks' to fill; face-varying ones split here.
  child.vertex_channels.clear();
  child.face_varying_channels.resize(parent.face_varying_channels.size());
  for (std::size_t i = 0; i < parent.face_varying_channels.size(); ++i) {
    const FaceVaryingChannel& in = parent.face_varying_channels[i];
    FaceVaryingChannel& out = child.face_varying_channels[i];
    if (rule == SplitRule::quad) detail::quad_split_face_varying(topology, in, out);
    else if (rule == SplitRule::triangle) detail::triangle_split_face_varying(topology, in, out);
    else if (rule == SplitRule::dual) detail::dual_split_face_varying(topology, map, child, in, out);
    else if (rule == SplitRule::identity) out = in;
    else if (rule == SplitRule::sqrt3 || rule == SplitRule::sqrt2)
      detail::point_split_face_varying(topology, map, child, in, out);
    else detail::midedge_split_face_varying(topology, child, in, out);
  }
  return map;
}

}  // namespace subdiv
