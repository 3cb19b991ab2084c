// Doo-Sabin: all of its weights (D. Doo, M. Sabin, "Behaviour of recursive
// division surfaces near extraordinary points", Computer-Aided Design 10(6),
// 1978; the mask as Zorin's survey gives it, section 4.1 and Fig. 9).
//
// Interior: the new vertex of corner i of a k-gon is sum_j alpha_|j-i| v_j,
//   alpha_0 = 1/4 + 5/(4k),  alpha_i = (3 + 2 cos(2 i pi / k)) / (4k).
// Its discrete Fourier transform is 1 at frequency 0, 1/2 at +-1 and 1/4 at
// every other frequency: the spectrum of the map from a face's vertices to
// its child face's, whatever k (checked in tests/rules/doo_sabin_test.cpp).
// For k = 4 the mask is 9/16, 3/16, 1/16, 3/16, the biquadratic B-spline's.
//
// Boundary: Doo's construction (the survey, section 4.1) replicates each
// boundary edge (a, b) into the degenerate quad (a, b, b, a) outside it. That
// quad's corner points are 3/4 a + 1/4 b and 1/4 a + 3/4 b, the dual split's
// boundary points; faces at the boundary keep the interior mask. The child
// boundary polygon is then the Chaikin refinement of the parent's, so the
// boundary limit is the quadratic B-spline of the boundary polygon (corners
// are cut, as in Doo's construction). Creases, corner tags and holes have no
// Doo-Sabin rule and are refused (refine.cpp).

#include "subdiv/rules/doo_sabin.h"

#include <array>
#include <cmath>
#include <numbers>

#include "subdiv/curves/curve_scheme.h"

namespace subdiv {

double doo_sabin_weight(int k, int i) noexcept {
  const double interior = (3.0 + 2.0 * std::cos(2.0 * std::numbers::pi * i / k)) / (4.0 * k);
  return i % k == 0 ? 0.25 + 5.0 / (4.0 * k) : interior;
}

namespace {

// The weights of the common face sizes, computed once: evaluating the
// cosines per corner was a third of the refinement time.
constexpr int kTabulated = 16;
struct WeightTable {
  std::array<std::array<double, kTabulated + 1>, kTabulated + 1> w{};
  WeightTable() {
    for (int k = 3; k <= kTabulated; ++k)
      for (int i = 0; i < k; ++i) w[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)] = doo_sabin_weight(k, i);
  }
};
const WeightTable kWeights;

void corner_point(const LevelView& level, Index corner, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  const Index f = t.corner_face(corner), first = t.face_first_corner(f), k = t.face_size(f);
  const Index i = corner - first;
  if (k <= kTabulated) {
    const auto& w = kWeights.w[static_cast<std::size_t>(k)];
    for (Index j = 0; j < k; ++j) mask.add(t.corner_vertex(first + j), w[static_cast<std::size_t>((j - i + k) % k)]);
    return;
  }
  for (Index j = 0; j < k; ++j) mask.add(t.corner_vertex(first + j), doo_sabin_weight(k, (j - i + k) % k));
}

void boundary_point(const LevelView& level, Index edge, Index vertex, MaskBuilder& mask) {
  // Chaikin's cut of the edge nearer `vertex` (its even mask: 3/4, 1/4).
  const Index other = level.topology.other_vertex(edge, vertex);
  for (const CurveMaskEntry& e : chaikin_curve_scheme().even) mask.add(e.offset == 0 ? vertex : other, e.weight);
}

}  // namespace

const Scheme& doo_sabin_scheme() {
  static const Scheme scheme{
      .name = "doo-sabin",
      .summary = "approximating, dual split, any polygon mesh; the biquadratic B-spline on regular quad meshes, C1",
      .citation = "D. Doo, M. Sabin: Behaviour of recursive division surfaces near extraordinary points, Computer-Aided "
      "Design 10(6), 1978; boundaries by Doo's replicated edges (Zorin's survey, section 4.1)",
      .split = SplitRule::dual,
      .traits = {.paper_depth_bound = PaperDepthBound::doo_sabin_theorem_5},
      .masks = {.corner_point = corner_point,
                .boundary_point = boundary_point,
                .boundary_curve = &chaikin_curve_scheme()}};
  return scheme;
}

}  // namespace subdiv
