// The paper's bounds, with the formulas re-derived where the extracted text
// is garbled (docs/depth.md has the derivations).

#include "subdiv/depth/depth_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/ring_mesh.h"

namespace subdiv {

namespace {

// No sensible input needs more; a larger answer means a rate close to 1.
constexpr int kMaxDepth = 64;

}  // namespace

const char* to_string(DepthMeasure m) noexcept {
  return m == DepthMeasure::vertex_to_limit ? "vertex-to-limit" : "surface-to-limit";
}

double DepthBound::at(int level) const noexcept {
  if (level < start) return std::numeric_limits<double>::infinity();
  double worst = 0.0;
  for (const DepthTerm& term : terms)
    worst = std::max(worst, term.amplitude * std::pow(term.rate, level - start));
  return worst;
}

int DepthBound::depth_for(double eps) const {
  if (!(eps > 0.0) || !std::isfinite(eps)) throw InvalidInputError("accuracy must be a positive number");
  for (const DepthTerm& term : terms)
    if (!(term.rate >= 0.0 && term.rate < 1.0) || !std::isfinite(term.amplitude))
      throw InvalidInputError(scheme + ": no depth bound: " + term.what + " does not contract (rate " +
                              std::to_string(term.rate) + ")");
  for (int level = start; level <= start + kMaxDepth; ++level)
    if (at(level) <= eps) return level;
  throw InvalidInputError(scheme + ": more than " + std::to_string(kMaxDepth) + " steps needed for accuracy " +
                          std::to_string(eps));
}

double loop_contraction(const Scheme& scheme, int valence) {
  // Paper, proof of Theorem 3: n P' - sum of the new neighbours
  // = (5/8 - n beta)(n P - sum of the old neighbours) for the vertex point
  // P' and the edge points around it. With Loop's masks (vertex point
  // (1 - n beta) P + beta sum Q, edge point 3/8 on each end, 1/8 on each
  // opposite vertex) the factor is the vertex mask's weight on P less the
  // edge mask's weight on P: read off the scheme's own masks at an interior
  // vertex of valence n, so no weight is restated here.
  const RingMesh ring = ring_mesh(SplitRule::triangle, {Configuration::Kind::interior, valence, CornerType::convex}, 1);
  const MeshTopology t(ring.mesh);
  const LevelView view{t, {}, 0.0, {}, {}, scheme.parameters};
  auto weight_on = [](const MaskBuilder& mask, Index v) {
    double w = 0.0;
    for (std::size_t i = 0; i < mask.vertices().size(); ++i)
      if (mask.vertices()[i] == v) w += mask.weights()[i];
    return w;
  };
  MaskBuilder vertex_mask, edge_mask;
  scheme.masks.vertex_point(view, ring.centre, VertexRule::smooth, vertex_mask);
  scheme.masks.edge_point(view, t.vertex_edges(ring.centre)[0], EdgeRule::smooth, edge_mask);
  return weight_on(vertex_mask, ring.centre) - weight_on(edge_mask, ring.centre);
}

DepthBound loop_paper_bound(const Scheme& scheme, double max_limit_distance, int max_valence) {
  // Refinement creates valence-6 vertices, so n is at least 6 (paper,
  // discussion of Figure 12); 5/8 - n beta grows with n.
  const int n = std::max(6, max_valence);
  return {"",
          "paper",
          0,
          {{"largest control-vertex-to-limit distance, contracted by 5/8 - n beta at n = " + std::to_string(n) +
                " (paper, Theorem 3)",
            max_limit_distance, loop_contraction(scheme, n)}}};
}

DepthBound cheng_catmull_clark_bound(double max_second_difference, int start) {
  return {"",
          "paper",
          start,
          {{"(1/3) x largest second difference, contracted by 1/4 (Cheng; paper, Theorem 2)",
            max_second_difference / 3.0, 0.25}}};
}

DepthBound doo_sabin_bound(double max_second_difference, int start) {
  return {"",
          "paper",
          start,
          {{"(1/4) x largest second difference after " + std::to_string(start) +
                (start == 1 ? " step" : " steps") + ", contracted by 1/4 (paper, Theorem 5)",
            max_second_difference / 4.0, 0.25}}};
}

}  // namespace subdiv
