// Quasi 4-8 bisection (Velho, Algorithm 1); the order and numbering are
// documented in subdiv/topology/bisection_split.h.

#include "subdiv/topology/bisection_split.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "subdiv/core/error.h"

namespace subdiv {

std::vector<Index> bisection_edge_order(const MeshTopology& topology, std::span<const Vec3> positions,
                                        double tie_tolerance) {
  const Index edges = topology.edge_count();
  std::vector<double> length(static_cast<std::size_t>(edges));
  for (Index e = 0; e < edges; ++e) {
    const auto [a, b] = topology.edge_vertices(e);
    length[static_cast<std::size_t>(e)] =
        norm(positions[static_cast<std::size_t>(a)] - positions[static_cast<std::size_t>(b)]);
  }
  // Radial key: an edge's first appearance in the walk over the vertices'
  // counter-clockwise rings.
  std::vector<Index> radial(static_cast<std::size_t>(edges), kInvalidIndex);
  Index position = 0;
  for (Index v = 0; v < topology.vertex_count(); ++v)
    for (const Index e : topology.vertex_edges(v)) {
      if (radial[static_cast<std::size_t>(e)] == kInvalidIndex) radial[static_cast<std::size_t>(e)] = position;
      ++position;
    }
  std::vector<Index> order(static_cast<std::size_t>(edges));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](Index x, Index y) {
    const double lx = length[static_cast<std::size_t>(x)], ly = length[static_cast<std::size_t>(y)];
    if (lx != ly) return lx > ly;
    return radial[static_cast<std::size_t>(x)] < radial[static_cast<std::size_t>(y)];
  });
  // Tie classes, each then taken in radial order.
  for (std::size_t first = 0; first < order.size();) {
    const double floor = (1.0 - tie_tolerance) * length[static_cast<std::size_t>(order[first])];
    std::size_t last = first + 1;
    while (last < order.size() && length[static_cast<std::size_t>(order[last])] >= floor) ++last;
    std::sort(
        order.begin() + static_cast<std::ptrdiff_t>(first), order.begin() + static_cast<std::ptrdiff_t>(last),
        [&](Index x, Index y) { return radial[static_cast<std::size_t>(x)] < radial[static_cast<std::size_t>(y)]; });
    first = last;
  }
  return order;
}

std::vector<char> bisection_split_edges(const MeshTopology& topology, std::span<const Vec3> positions,
                                        double tie_tolerance) {
  std::vector<char> marked(static_cast<std::size_t>(topology.edge_count()), 0);
  std::vector<char> split(marked.size(), 0);
  for (const Index e : bisection_edge_order(topology, positions, tie_tolerance)) {
    if (marked[static_cast<std::size_t>(e)]) continue;
    split[static_cast<std::size_t>(e)] = 1;
    for (const Index side : topology.edge_corners(e)) {  // mark_cluster(e)
      const Index f = topology.corner_face(side);
      const Index first = topology.face_first_corner(f);
      for (Index c = first; c < first + topology.face_size(f); ++c)
        marked[static_cast<std::size_t>(topology.corner_edge(c))] = 1;
    }
  }
  return split;
}

namespace {

// Face-varying values: corners copied, the split point of a bisected face
// gets one new value, the mean of its split edge's two corner values there.
struct FaceVaryingSplit {
  const FaceVaryingChannel& in;
  FaceVaryingChannel& out;
  std::size_t k;
  Index midpoint_value(Index ca, Index cb) {
    const Index value = out.value_count();
    const double* a = in.values.data() + static_cast<std::size_t>(in.indices[static_cast<std::size_t>(ca)]) * k;
    const double* b = in.values.data() + static_cast<std::size_t>(in.indices[static_cast<std::size_t>(cb)]) * k;
    for (std::size_t j = 0; j < k; ++j) out.values.push_back(0.5 * (a[j] + b[j]));
    return value;
  }
};

}  // namespace

BisectionMap bisection_split(const PolygonMesh& parent, const MeshTopology& topology, PolygonMesh& child,
                             double tie_tolerance) {
  for (Index f = 0; f < topology.face_count(); ++f)
    if (topology.face_size(f) != 3)
      throw TopologyError("quasi 4-8 bisection needs triangles, but face " + std::to_string(f) + " has " +
                          std::to_string(topology.face_size(f)) + " vertices");
  for (Index c = 0; c < topology.corner_count(); ++c)
    if (topology.corner_vertex(c) == topology.corner_vertex(topology.corner_next(c)))
      throw TopologyError("cannot split face " + std::to_string(topology.corner_face(c)) +
                          ": it repeats a vertex on consecutive corners (a degenerate face)");
  const std::vector<char> split = bisection_split_edges(topology, parent.positions, tie_tolerance);

  BisectionMap map;
  map.old_vertex_count = topology.vertex_count();
  std::vector<Index> split_point(split.size(), kInvalidIndex);
  for (Index e = 0; e < topology.edge_count(); ++e)
    if (split[static_cast<std::size_t>(e)]) {
      split_point[static_cast<std::size_t>(e)] = map.old_vertex_count + static_cast<Index>(map.split_edges.size());
      map.split_edges.push_back(e);
    }

  child = PolygonMesh{};
  child.positions.assign(parent.positions.begin(), parent.positions.end());
  child.positions.resize(static_cast<std::size_t>(map.child_vertex_count()));
  for (std::size_t i = 0; i < map.split_edges.size(); ++i) {
    const auto [a, b] = topology.edge_vertices(map.split_edges[i]);
    child.positions[static_cast<std::size_t>(map.old_vertex_count) + i] =
        0.5 * (parent.positions[static_cast<std::size_t>(a)] + parent.positions[static_cast<std::size_t>(b)]);
  }

  std::vector<FaceVaryingSplit> channels;
  child.face_varying_channels.resize(parent.face_varying_channels.size());
  for (std::size_t i = 0; i < parent.face_varying_channels.size(); ++i) {
    const FaceVaryingChannel& in = parent.face_varying_channels[i];
    child.face_varying_channels[i] = {in.name, in.components, in.values, {}};
    channels.push_back({in, child.face_varying_channels[i], static_cast<std::size_t>(in.components)});
  }

  for (Index f = 0; f < topology.face_count(); ++f) {
    const Index c0 = topology.face_first_corner(f);
    Index at = kInvalidIndex;  // the corner whose outgoing edge is split
    for (Index c = c0; c < c0 + 3; ++c)
      if (split[static_cast<std::size_t>(topology.corner_edge(c))]) {
        if (at != kInvalidIndex)
          throw TopologyError("quasi 4-8 bisection: face " + std::to_string(f) + " has two split edges");
        at = c;
      }
    if (at == kInvalidIndex) {
      child.add_face(topology.face_vertices(f));
      for (FaceVaryingSplit& ch : channels)
        for (Index c = c0; c < c0 + 3; ++c) ch.out.indices.push_back(ch.in.indices[static_cast<std::size_t>(c)]);
      continue;
    }
    const Index cb = topology.corner_next(at), cc = topology.corner_next(cb);
    const Index a = topology.corner_vertex(at), b = topology.corner_vertex(cb), c = topology.corner_vertex(cc);
    const Index s = split_point[static_cast<std::size_t>(topology.corner_edge(at))];
    child.add_face({a, s, c});
    child.add_face({s, b, c});
    for (FaceVaryingSplit& ch : channels) {
      const Index m = ch.midpoint_value(at, cb);
      const auto value = [&](Index corner) { return ch.in.indices[static_cast<std::size_t>(corner)]; };
      for (const Index x : {value(at), m, value(cc), m, value(cb), value(cc)}) ch.out.indices.push_back(x);
    }
  }

  // Tags: the halves of a split crease stay tagged; vertex numbers are kept.
  child.tags = parent.tags;
  child.tags.creases.clear();
  child.tags.other.clear();  // uninterpreted tags index the parent's faces (propagate_tags)
  for (const CreaseTag& t : parent.tags.creases) {
    const Index e = topology.find_edge(t.v0, t.v1);
    const Index s = e == kInvalidIndex ? kInvalidIndex : split_point[static_cast<std::size_t>(e)];
    if (s == kInvalidIndex) {
      child.tags.creases.push_back(t);
      continue;
    }
    child.tags.creases.push_back({t.v0, s, t.sharpness});
    child.tags.creases.push_back({s, t.v1, t.sharpness});
  }
  return map;
}

}  // namespace subdiv
