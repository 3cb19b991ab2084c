#include "subdiv/refine/subdivision_matrix.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "subdiv/refine/ring_mesh.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"

namespace subdiv {

namespace {

constexpr double kLayoutTolerance = 1e-9;

// The vertices of the faces within `rings` face rings of the centre (a
// vertex, or the dual split's centre face, whose vertices are ring 0), with
// their ring numbers (-1 outside).
std::vector<int> face_rings(const MeshTopology& topology, const RingMesh& mesh, int rings) {
  if (mesh.centre_face != kInvalidIndex) return vertex_rings(topology, topology.face_vertices(mesh.centre_face), rings);
  const Index centre[] = {mesh.centre};
  return vertex_rings(topology, centre, rings);
}

// The vertex of `points` (among `candidates`) at p, or -1.
Index vertex_at(const std::vector<Vec3>& points, const std::vector<Index>& candidates, Vec3 p) {
  for (const Index v : candidates)
    if (norm(points[static_cast<std::size_t>(v)] - p) < kLayoutTolerance) return v;
  return kInvalidIndex;
}

// The child of `parent` in the quad split's numbering [face points | edge
// points | vertex points] or the triangle split's [edge points | vertex
// points].
Index image_child(const MeshTopology& t, SplitRule split, const ImageParent& parent) {
  const Index faces = split == SplitRule::quad ? t.face_count() : 0;
  switch (parent.kind) {
    case ImageParent::Kind::face: return parent.a;
    case ImageParent::Kind::edge: {
      const Index e = t.find_edge(parent.a, parent.b);
      return e == kInvalidIndex ? kInvalidIndex : faces + e;
    }
    case ImageParent::Kind::vertex: return faces + t.edge_count() + parent.a;
  }
  return kInvalidIndex;
}

double angle_of(Vec3 p) {
  const double a = std::atan2(p.y, p.x);
  return a < -kLayoutTolerance ? a + 2.0 * std::numbers::pi : std::max(a, 0.0);
}

}  // namespace

std::vector<int> vertex_rings(const MeshTopology& topology, std::span<const Index> centre, int rings) {
  std::vector<int> ring(static_cast<std::size_t>(topology.vertex_count()), -1);
  std::vector<Index> frontier(centre.begin(), centre.end());
  for (const Index v : frontier) ring[static_cast<std::size_t>(v)] = 0;
  for (int r = 1; r <= rings; ++r) {
    std::vector<Index> next;
    for (const Index v : frontier)
      for (const Index c : topology.vertex_corners(v))
        for (const Index w : topology.face_vertices(topology.corner_face(c)))
          if (ring[static_cast<std::size_t>(w)] < 0) {
            ring[static_cast<std::size_t>(w)] = r;
            next.push_back(w);
          }
    frontier = std::move(next);
  }
  return ring;
}

LocalSubdivisionMatrix local_subdivision_matrix(const Scheme& scheme, const Configuration& configuration, int rings,
                                                const RefineOptions& rules) {
  if (rings < 1) throw InvalidInputError("subdivision matrix: rings must be >= 1, not " + std::to_string(rings));
  const RingMesh ring = analysis_ring_mesh(scheme.split, configuration, ring_mesh_size(rings));
  const MeshTopology topology(ring.mesh);
  const std::vector<int> ring_number = face_rings(topology, ring, rings);

  // The neighbourhood, ordered by ring, then angle, then distance.
  std::vector<Index> coarse;
  for (Index v = 0; v < ring.mesh.vertex_count(); ++v)
    if (ring_number[static_cast<std::size_t>(v)] >= 0) coarse.push_back(v);
  const auto& positions = ring.mesh.positions;
  std::sort(coarse.begin(), coarse.end(), [&](Index a, Index b) {
    const Vec3 pa = positions[static_cast<std::size_t>(a)], pb = positions[static_cast<std::size_t>(b)];
    const int ra = ring_number[static_cast<std::size_t>(a)], rb = ring_number[static_cast<std::size_t>(b)];
    if (ra != rb) return ra < rb;
    const double aa = angle_of(pa), ab = angle_of(pb);
    if (std::fabs(aa - ab) > kLayoutTolerance) return aa < ab;
    return norm(pa) < norm(pb);
  });
  std::vector<int> column(static_cast<std::size_t>(ring.mesh.vertex_count()), -1);
  for (std::size_t b = 0; b < coarse.size(); ++b) column[static_cast<std::size_t>(coarse[b])] = static_cast<int>(b);

  // One analysis step (the scheme's period: that many refinement steps,
  // composed) as a stencil table, and the split's own linear placement as
  // many levels down to find where each neighbourhood vertex went.
  if (scheme.traits.period < 1)
    throw InvalidInputError(std::string(scheme.name) + ": period must be >= 1, not " + std::to_string(scheme.traits.period));
  RefineOptions once = rules;
  once.levels = scheme.traits.period;
  once.on_level = nullptr;
  Scheme open = scheme;  // the ring mesh's outer boundary lies outside the neighbourhood
  open.traits.needs_closed_mesh = false;
  const StencilTable table = refine_stencil_table(ring.mesh, open, once);
  // A layout that is not linear (interior k = 2) names the images by the
  // split's numbering instead, one step down.
  if (!ring.linear && scheme.traits.period != 1)
    throw InvalidInputError(std::string(scheme.name) + ": " + configuration.name() +
                            " is analysed one refinement step at a time, not over a period of " +
                            std::to_string(scheme.traits.period));
  const std::vector<Vec3> layout_child = ring.linear ? child_layout(scheme.split, ring, scheme.traits.period) : std::vector<Vec3>{};
  const double shrink = std::pow(arity(scheme.split), -scheme.traits.period);
  std::vector<Index> all_child(layout_child.size());
  std::iota(all_child.begin(), all_child.end(), 0);
  const auto image_of = [&](Index v) {
    if (ring.linear) return vertex_at(layout_child, all_child, shrink * positions[static_cast<std::size_t>(v)]);
    return image_child(topology, scheme.split, ring.image_parent[static_cast<std::size_t>(v)]);
  };

  LocalSubdivisionMatrix m;
  m.configuration = configuration;
  m.rules = once;
  m.rings = rings;
  m.period = scheme.traits.period;
  const auto n = static_cast<Eigen::Index>(coarse.size());
  m.S = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index a = 0; a < n; ++a) {
    const Vec3 p = positions[static_cast<std::size_t>(coarse[static_cast<std::size_t>(a)])];
    m.layout.push_back(p);
    m.ring_of.push_back(ring_number[static_cast<std::size_t>(coarse[static_cast<std::size_t>(a)])]);
    const Index child = image_of(coarse[static_cast<std::size_t>(a)]);
    if (child == kInvalidIndex) throw InvalidInputError(configuration.name() + ": no child vertex at a neighbourhood point");
    const auto vertices = table.row_vertices(child);
    const auto weights = table.row_weights(child);
    for (std::size_t e = 0; e < vertices.size(); ++e) {
      const int b = column[static_cast<std::size_t>(vertices[e])];
      if (b >= 0) {
        m.S(a, b) += weights[e];
      } else if (weights[e] != 0.0 && m.invariant) {
        m.invariant = false;
        m.invariance_note = "neighbourhood vertex " + std::to_string(a) + " (ring " + std::to_string(m.ring_of.back()) +
                            ") one step down uses a vertex outside the " + std::to_string(rings) + "-ring";
      }
    }
  }
  if (configuration.kind == Configuration::Kind::interior) {
    const double turn = 2.0 * std::numbers::pi / configuration.k;
    const double c = std::cos(turn), s = std::sin(turn);
    std::vector<Index> indices(coarse.size());
    std::iota(indices.begin(), indices.end(), 0);
    for (const Vec3& p : m.layout) {
      const Index image = vertex_at(m.layout, indices, {c * p.x - s * p.y, s * p.x + c * p.y, 0.0});
      if (image == kInvalidIndex) throw InvalidInputError(configuration.name() + ": layout is not rotationally symmetric");
      m.rotate.push_back(image);
    }
  }
  return m;
}

LocalSubdivisionMatrix invariant_subdivision_matrix(const Scheme& scheme, const Configuration& configuration,
                                                    int max_rings, const RefineOptions& rules) {
  LocalSubdivisionMatrix m;
  for (int rings = 1; rings <= std::max(max_rings, scheme.traits.analysis_rings); ++rings) {
    m = local_subdivision_matrix(scheme, configuration, rings, rules);
    if (m.invariant) return m;
  }
  return m;
}

}  // namespace subdiv
