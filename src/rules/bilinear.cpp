// Bilinear: face centroid, edge midpoint, vertices kept (quad split).
// OpenSubdiv's Sdc::SCHEME_BILINEAR.

#include "subdiv/rules/bilinear.h"

#include "rule_helpers.h"

namespace subdiv {

namespace {

void face_point(const LevelView& level, Index f, MaskBuilder& mask) { detail::add_face_average(level, f, 1.0, mask); }
void edge_point(const LevelView& level, Index e, EdgeRule, MaskBuilder& mask) { detail::add_edge_midpoint(level, e, mask); }
void vertex_point(const LevelView&, Index v, VertexRule, MaskBuilder& mask) { mask.add(v, 1.0); }

// Along a grid line: old points kept, new ones at midpoints.
constexpr RegularGrid kRegularGrid{.even = {0.0, 0.0, 1.0, 0.0, 0.0}, .odd = {0.0, 0.5, 0.5, 0.0}};

}  // namespace

const Scheme& bilinear_scheme() noexcept {
  static const Scheme scheme{
      .name = "bilinear",
      .summary = "interpolating baseline, quad split: face centroids, edge midpoints",
      .citation = "bilinear refinement (OpenSubdiv's SCHEME_BILINEAR)",
      .split = SplitRule::quad,
      .traits = {.interpolating = true, .degenerate_faces = true},
      .masks = {.face_point = face_point, .edge_point = edge_point, .vertex_point = vertex_point},
      .fast_path = {.regular_grid = &kRegularGrid}};
  return scheme;
}

}  // namespace subdiv
