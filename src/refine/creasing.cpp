#include "subdiv/refine/creasing.h"

#include "../core/large_buffers.h"

#include <algorithm>
#include <atomic>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace subdiv {

void subdivide_sharpness_around_vertex(CreaseMethod method, std::span<const double> parent,
                                       std::span<double> child) noexcept {
  const std::size_t n = parent.size();
  if (method == CreaseMethod::uniform || n < 2) {
    for (std::size_t i = 0; i < n; ++i) child[i] = subdivide_sharpness(parent[i]);
    return;
  }
  // Chaikin (Sdc::Crease): only semi-sharp edges enter the mean, in the same
  // arithmetic as OpenSubdiv's (the sum minus the edge's own sharpness).
  double sum = 0.0;
  int semi_sharp = 0;
  for (const double s : parent)
    if (s > 0.0 && s < kInfiniteSharpness) {
      sum += s;
      ++semi_sharp;
    }
  for (std::size_t i = 0; i < n; ++i) {
    const double s = parent[i];
    if (s <= 0.0 || s >= kInfiniteSharpness || semi_sharp == 1) {
      child[i] = subdivide_sharpness(s);
    } else {
      const double others = (sum - s) / static_cast<double>(semi_sharp - 1);
      const double c = 0.75 * s + 0.25 * others - 1.0;
      child[i] = c > 0.0 ? c : 0.0;
    }
  }
}

VertexRule vertex_rule_for(double vertex_sharpness, int sharp_edge_count) noexcept {
  if (vertex_sharpness > 0.0) return VertexRule::corner;
  switch (sharp_edge_count) {
    case 0: return VertexRule::smooth;
    case 1: return VertexRule::dart;
    case 2: return VertexRule::crease;
    default: return VertexRule::corner;
  }
}

namespace {

// The sharpness vertex v's rule sees: its tag, or infinite where the vertex
// cannot be smooth (isolated; a non-manifold vertex that is not a crease; a
// one-face boundary vertex in edge-and-corner mode).
double effective_vertex_sharpness(const MeshTopology& topo, BoundaryInterpolation boundary, Index v, double tagged,
                                  const LevelCreasing& out) {
  const VertexKind kind = topo.vertex_kind(v);
  if (kind == VertexKind::isolated) return kInfiniteSharpness;
  if (!topo.ring_ordered(v)) {
    int infinitely_sharp = 0;
    for (const Index e : topo.vertex_edges(v)) infinitely_sharp += edge_sharpness_of(out, e) >= kInfiniteSharpness;
    if (infinitely_sharp != 2) return kInfiniteSharpness;
  }
  if (boundary == BoundaryInterpolation::edge_and_corner && kind == VertexKind::boundary &&
      topo.vertex_face_count(v) == 1)
    return kInfiniteSharpness;
  return tagged;
}

// Where edge e's child at vertex v sits in LevelCreasing::child_edge_sharpness.
std::size_t child_slot(const MeshTopology& topo, Index e, Index v) {
  return 2 * static_cast<std::size_t>(e) + (topo.edge_vertices(e)[0] == v ? 0 : 1);
}

// Chaikin: the children at v of v's edges, written to their slots (each
// slot belongs to one vertex, so vertices may run in parallel).
void subdivide_edges_at_vertex(const MeshTopology& topo, Index v, std::vector<double>& parent,
                               std::vector<double>& child, LevelCreasing& out) {
  const auto edges = topo.vertex_edges(v);
  parent.resize(edges.size());
  child.resize(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) parent[i] = edge_sharpness_of(out, edges[i]);
  subdivide_sharpness_around_vertex(CreaseMethod::chaikin, parent, child);
  for (std::size_t i = 0; i < edges.size(); ++i) out.child_edge_sharpness[child_slot(topo, edges[i], v)] = child[i];
}

// The rules of vertex v now and one level down; true when they differ. One
// level down an edge stays sharp at v when its child there is sharp: when its
// sharpness exceeds 1 (uniform), or per child_edge_sharpness (Chaikin,
// PerEnd; a template argument, so that the uniform loop stays as lean).
template <bool PerEnd>
bool classify_vertex(const MeshTopology& topo, BoundaryInterpolation boundary, Index v, double tagged,
                     LevelCreasing& out) {
  int sharp = 0, child_sharp = 0;
  for (const Index e : topo.vertex_edges(v)) {
    const double s = edge_sharpness_of(out, e);
    sharp += s > 0.0;
    if constexpr (PerEnd) child_sharp += out.child_edge_sharpness[child_slot(topo, e, v)] > 0.0;
    else child_sharp += s > 1.0;
  }
  const double vs = effective_vertex_sharpness(topo, boundary, v, tagged, out);
  const auto vi = static_cast<std::size_t>(v);
  out.vertex_rule[vi] = vertex_rule_for(vs, sharp);
  out.child_vertex_rule[vi] = vertex_rule_for(subdivide_sharpness(vs), child_sharp);
  return out.vertex_rule[vi] != out.child_vertex_rule[vi];
}

// The weight of the parent's rule at a vertex whose rule changes
// (Sdc::Crease::ComputeFractionalWeightAtVertex): the mean sharpness of
// what stops being sharp at v, at most 1. With Chaikin creasing an edge of
// sharpness above 1 can stop being sharp at v (its child there decays to 0).
double parent_rule_weight_at(const MeshTopology& topo, BoundaryInterpolation boundary, Index v, double tagged,
                             const LevelCreasing& out) {
  return decay_weight(topo, out, v, effective_vertex_sharpness(topo, boundary, v, tagged, out), topo.vertex_edges(v));
}

}  // namespace

double decay_weight(const MeshTopology& topo, const LevelCreasing& creasing, Index v, double vertex_sharpness,
                    std::span<const Index> edges) noexcept {
  int transitions = 0;
  double sum = 0.0;
  if (vertex_sharpness > 0.0 && subdivide_sharpness(vertex_sharpness) <= 0.0) {
    ++transitions;
    sum += vertex_sharpness;
  }
  for (const Index e : edges) {
    const double s = edge_sharpness_of(creasing, e);
    if (s > 0.0 && child_sharpness_of(creasing, e, topo.edge_vertices(e)[0] == v ? 0 : 1) <= 0.0) {
      ++transitions;  // sharp now, smooth one level down
      sum += s;
    }
  }
  return transitions > 0 ? std::min(1.0, sum / transitions) : 0.0;
}

std::vector<double> vertex_sharpness(const PolygonMesh& mesh, const MeshTopology& topo, BoundaryInterpolation boundary,
                                     const LevelCreasing& creasing) {
  std::vector<double> tagged(static_cast<std::size_t>(topo.vertex_count()), 0.0);
  for (const CornerTag& c : mesh.tags.corners)
    if (c.vertex >= 0 && c.vertex < topo.vertex_count())
      tagged[static_cast<std::size_t>(c.vertex)] = std::max(tagged[static_cast<std::size_t>(c.vertex)], c.sharpness);
  for (Index v = 0; v < topo.vertex_count(); ++v) {
    const auto vi = static_cast<std::size_t>(v);
    tagged[vi] = effective_vertex_sharpness(topo, boundary, v, tagged[vi], creasing);
  }
  return tagged;
}

LevelCreasing compute_creasing(const PolygonMesh& mesh, const MeshTopology& topo, BoundaryInterpolation boundary,
                               CreaseMethod method, bool control_level) {
  const auto ne = static_cast<std::size_t>(topo.edge_count());
  const auto nv = static_cast<std::size_t>(topo.vertex_count());
  LevelCreasing out;

  detail::assign_large(out.edge_sharpness, ne, 0.0);
  for (const CreaseTag& c : mesh.tags.creases) {
    const Index e = topo.find_edge(c.v0, c.v1);
    if (e != kInvalidIndex) out.edge_sharpness[static_cast<std::size_t>(e)] = std::max(out.edge_sharpness[static_cast<std::size_t>(e)], c.sharpness);
  }
  std::atomic<bool> any_sharp = !mesh.tags.creases.empty();
  // A flipped edge leaves the ring of the vertex its sides both run to
  // unordered (the walk finds a neighbour running the same way): with every
  // ring ordered there is none to look for.
  const bool may_have_flipped = !topo.all_rings_ordered();
  tbb::parallel_for(tbb::blocked_range<Index>(0, topo.edge_count(), 8192), [&](const tbb::blocked_range<Index>& r) {
    for (Index e = r.begin(); e != r.end(); ++e)
      if (topo.edge_face_count(e) != 2 || (may_have_flipped && topo.is_flipped_edge(e))) {
        out.edge_sharpness[static_cast<std::size_t>(e)] = kInfiniteSharpness;
        any_sharp = true;
      }
  });
  if (!any_sharp) std::vector<double>().swap(out.edge_sharpness);

  std::vector<double> vertex_sharpness;  // tagged corners; empty without any
  if (!mesh.tags.corners.empty()) detail::assign_large(vertex_sharpness, nv, 0.0);
  for (const CornerTag& c : mesh.tags.corners)
    if (c.vertex >= 0 && static_cast<std::size_t>(c.vertex) < nv)
      vertex_sharpness[static_cast<std::size_t>(c.vertex)] = std::max(vertex_sharpness[static_cast<std::size_t>(c.vertex)], c.sharpness);
  // The control mesh's non-manifold vertices that OpenSubdiv sharpens count as tagged corners.
  auto tagged = [&](Index v) {
    if (control_level && topo.is_non_manifold_corner(v)) return kInfiniteSharpness;
    return vertex_sharpness.empty() ? 0.0 : vertex_sharpness[static_cast<std::size_t>(v)];
  };

  // Chaikin's per-end child sharpness, only where it can differ from the
  // uniform rule: some edge is semi-sharp.
  const bool chaikin = method == CreaseMethod::chaikin && !out.edge_sharpness.empty() &&
                       std::any_of(out.edge_sharpness.begin(), out.edge_sharpness.end(),
                                   [](double s) { return s > 0.0 && s < kInfiniteSharpness; });
  if (chaikin) detail::assign_large(out.child_edge_sharpness, 2 * ne, 0.0);

  detail::assign_large(out.vertex_rule, nv);
  detail::assign_large(out.child_vertex_rule, nv);
  // Every vertex writes only its own entries (its rules, its ends of its
  // edges): parallel loops. Blend weights are stored only when some vertex's
  // rule changes (semi-sharp features).
  std::atomic<bool> any_change = false;
  if (chaikin) {
    tbb::parallel_for(tbb::blocked_range<Index>(0, topo.vertex_count(), 4096), [&](const tbb::blocked_range<Index>& r) {
      std::vector<double> parent, child;  // per-vertex buffers
      for (Index v = r.begin(); v != r.end(); ++v) {
        subdivide_edges_at_vertex(topo, v, parent, child, out);
        if (classify_vertex<true>(topo, boundary, v, tagged(v), out)) any_change = true;
      }
    });
  } else {
    tbb::parallel_for(tbb::blocked_range<Index>(0, topo.vertex_count(), 4096), [&](const tbb::blocked_range<Index>& r) {
      for (Index v = r.begin(); v != r.end(); ++v)
        if (classify_vertex<false>(topo, boundary, v, tagged(v), out)) any_change = true;
    });
  }
  if (!any_change) return out;
  detail::assign_large(out.parent_rule_weight, nv, 1.0);
  tbb::parallel_for(tbb::blocked_range<Index>(0, topo.vertex_count(), 4096), [&](const tbb::blocked_range<Index>& r) {
    for (Index v = r.begin(); v != r.end(); ++v) {
      const auto vi = static_cast<std::size_t>(v);
      if (out.vertex_rule[vi] != out.child_vertex_rule[vi])
        out.parent_rule_weight[vi] = parent_rule_weight_at(topo, boundary, v, tagged(v), out);
    }
  });
  return out;
}

}  // namespace subdiv
