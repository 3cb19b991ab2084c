// Linear: edge midpoints, vertices kept (triangle split).

#include "subdiv/rules/linear.h"

#include "rule_helpers.h"

namespace subdiv {

namespace {

void edge_point(const LevelView& level, Index e, EdgeRule, MaskBuilder& mask) { detail::add_edge_midpoint(level, e, mask); }
void vertex_point(const LevelView&, Index v, VertexRule, MaskBuilder& mask) { mask.add(v, 1.0); }

// Old points kept, new ones at edge midpoints.
constexpr RegularTriangleGrid kRegularGrid{.centre = 1.0, .ring = 0.0, .near = 0.5, .far = 0.0};

}  // namespace

const Scheme& linear_scheme() noexcept {
  static const Scheme scheme{.name = "linear",
                             .summary = "interpolating baseline, triangle split: edge midpoints",
                             .citation = "linear (midpoint) refinement of triangle meshes",
                             .split = SplitRule::triangle,
                             .traits = {.interpolating = true, .needs_triangles = true},
                             .masks = {.edge_point = edge_point, .vertex_point = vertex_point},
                             .fast_path = {.regular_triangle_grid = &kRegularGrid}};
  return scheme;
}

}  // namespace subdiv
