#include "subdiv/refine/creasing.h"

#include "../core/large_buffers.h"

#include <algorithm>
#include <atomic>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace subdiv {

double subdivide_sharpness(double s) {
  if (s >= kInfiniteSharpness) return s;
  return s > 1.0 ? s - 1.0 : 0.0;
}

VertexRule vertex_rule_for(double vertex_sharpness, int sharp_edge_count) {
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

// The rules of vertex v now and one level down; true when they differ. One
// level down an edge stays sharp when its sharpness exceeds 1.
bool classify_vertex(const MeshTopology& topo, BoundaryInterpolation boundary, Index v, double tagged,
                     LevelCreasing& out) {
  int sharp = 0, child_sharp = 0;
  for (const Index e : topo.vertex_edges(v)) {
    const double s = edge_sharpness_of(out, e);
    sharp += s > 0.0;
    child_sharp += s > 1.0;
  }
  const double vs = effective_vertex_sharpness(topo, boundary, v, tagged, out);
  const auto vi = static_cast<std::size_t>(v);
  out.vertex_rule[vi] = vertex_rule_for(vs, sharp);
  out.child_vertex_rule[vi] = vertex_rule_for(subdivide_sharpness(vs), child_sharp);
  return out.vertex_rule[vi] != out.child_vertex_rule[vi];
}

// The weight of the parent's rule at a vertex whose rule changes
// (Sdc::Crease::ComputeFractionalWeightAtVertex): the mean sharpness of
// what stops being sharp, at most 1.
double parent_rule_weight_at(const MeshTopology& topo, BoundaryInterpolation boundary, Index v, double tagged,
                             const LevelCreasing& out) {
  const double vs = effective_vertex_sharpness(topo, boundary, v, tagged, out);
  int transitions = 0;
  double sum = 0.0;
  if (vs > 0.0 && subdivide_sharpness(vs) <= 0.0) {
    ++transitions;
    sum += vs;
  }
  for (const Index e : topo.vertex_edges(v)) {
    const double s = edge_sharpness_of(out, e);
    if (s > 0.0 && s <= 1.0) {  // sharp now, smooth one level down
      ++transitions;
      sum += s;
    }
  }
  return transitions > 0 ? std::min(1.0, sum / transitions) : 0.0;
}

}  // namespace

LevelCreasing compute_creasing(const PolygonMesh& mesh, const MeshTopology& topo, BoundaryInterpolation boundary) {
  const auto ne = static_cast<std::size_t>(topo.edge_count());
  const auto nv = static_cast<std::size_t>(topo.vertex_count());
  LevelCreasing out;

  detail::assign_large(out.edge_sharpness, ne, 0.0);
  for (const CreaseTag& c : mesh.tags.creases) {
    const Index e = topo.find_edge(c.v0, c.v1);
    if (e != kInvalidIndex) out.edge_sharpness[static_cast<std::size_t>(e)] = std::max(out.edge_sharpness[static_cast<std::size_t>(e)], c.sharpness);
  }
  std::atomic<bool> any_sharp = !mesh.tags.creases.empty();
  tbb::parallel_for(tbb::blocked_range<Index>(0, topo.edge_count(), 8192), [&](const tbb::blocked_range<Index>& r) {
    for (Index e = r.begin(); e != r.end(); ++e)
      if (topo.edge_face_count(e) != 2 || topo.is_flipped_edge(e)) {
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
  auto tagged = [&](Index v) { return vertex_sharpness.empty() ? 0.0 : vertex_sharpness[static_cast<std::size_t>(v)]; };

  detail::assign_large(out.vertex_rule, nv);
  detail::assign_large(out.child_vertex_rule, nv);
  // Every vertex writes only its own entries: parallel loops. Blend weights
  // are stored only when some vertex's rule changes (semi-sharp features).
  std::atomic<bool> any_change = false;
  tbb::parallel_for(tbb::blocked_range<Index>(0, topo.vertex_count(), 4096), [&](const tbb::blocked_range<Index>& r) {
    for (Index v = r.begin(); v != r.end(); ++v)
      if (classify_vertex(topo, boundary, v, tagged(v), out)) any_change = true;
  });
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
