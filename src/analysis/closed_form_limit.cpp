#include "closed_form_limit.h"

#include "dart_limit.h"

namespace subdiv::detail {

namespace {

Vec3 apply(const LimitMask& mask, const LimitLevel& level, Index v) {
  const MeshTopology& t = level.topology;
  auto at = [&](Index i) { return level.positions[static_cast<std::size_t>(i)]; };
  Vec3 sum = mask.vertex * at(v);
  const auto edges = t.vertex_edges(v);
  for (std::size_t i = 0; i < mask.edges.size(); ++i) sum += mask.edges[i] * at(t.other_vertex(edges[i], v));
  const auto corners = t.vertex_corners(v);
  for (std::size_t j = 0; j < mask.faces.size(); ++j)
    sum += mask.faces[j] * at(t.corner_vertex(t.corner_next(t.corner_next(corners[j]))));
  return sum;
}

}  // namespace

std::optional<VertexLimit> closed_form_limit(const Scheme& scheme, const LimitLevel& level, Index v,
                                             LimitMasks& scratch) {
  const MeshTopology& t = level.topology;
  const auto vi = static_cast<std::size_t>(v);
  if (!scheme.limit_masks || !t.ring_ordered(v) || level.semi_sharp_vertex[vi]) return std::nullopt;
  const VertexKind kind = t.vertex_kind(v);
  if (kind != VertexKind::interior && kind != VertexKind::boundary) return std::nullopt;
  const VertexRule rule = level.creasing.vertex_rule[vi];
  if (rule != level.creasing.child_vertex_rule[vi]) return std::nullopt;
  const Index face_size = scheme.split == SplitRule::quad ? 4 : 3;
  for (const Index c : t.vertex_corners(v))
    if (t.face_size(t.corner_face(c)) != face_size) return std::nullopt;

  VertexNeighbourhood n;
  n.edges = static_cast<int>(t.vertex_edges(v).size());
  n.faces = static_cast<int>(t.vertex_corners(v).size());
  n.rule = rule;
  // The sharp edges, in ring order: the masks follow the first two. A corner
  // with fewer takes the first two edges, as OpenSubdiv does.
  int sharp_found = 0;
  n.sharp[1] = 1;
  for (int i = 0; i < n.edges; ++i) {
    const double s = edge_sharpness_of(level.creasing, t.vertex_edges(v)[static_cast<std::size_t>(i)]);
    if (s >= kInfiniteSharpness) {
      if (sharp_found < 2) n.sharp[sharp_found] = i;
      ++sharp_found;
    } else if (s > 0.0) {
      return std::nullopt;  // semi-sharp: refine further
    }
  }
  if (rule == VertexRule::corner && sharp_found < 2) {
    n.sharp[0] = 0;
    n.sharp[1] = 1;
  }
  // A dart's masks are its own matrix's eigenvectors (dart_limit.h), not
  // the smooth masks the scheme's closed forms give it.
  const bool dart = rule == VertexRule::dart;
  if (!(dart ? dart_limit_masks(scheme, n, scratch) : scheme.limit_masks(n, scratch))) return std::nullopt;
  return VertexLimit{apply(scratch.position, level, v), apply(scratch.tangent1, level, v),
                     apply(scratch.tangent2, level, v), dart};
}

}  // namespace subdiv::detail
