#pragma once
// Checks shared by the scheme tests: every stencil row sums to one (affine
// invariance), the fast path gives what the recorded stencils give, and
// refinement commutes with an affine map.

#include <gtest/gtest.h>

#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/refine/refine.h"
#include "subdiv/core/stencil_table.h"
#include "support/stencil_rows.h"

namespace subdiv::test {

inline void expect_rows_sum_to_one(const std::vector<StencilTable>& tables, double tolerance) {
  for (std::size_t l = 0; l < tables.size(); ++l)
    for (Index r = 0; r < tables[l].row_count(); ++r) {
      double sum = 0.0;
      for (const auto& [v, w] : merged_row(tables[l], r)) sum += w;
      EXPECT_NEAR(sum, 1.0, tolerance) << "level " << l + 1 << ", row " << r;
    }
}

inline void expect_same_positions(const PolygonMesh& a, const PolygonMesh& b, double tolerance) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i) EXPECT_NEAR(norm(a.positions[i] - b.positions[i]), 0.0, tolerance) << i;
}

/// `levels` levels of `scheme` on `mesh` as stencil tables: every row sums
/// to one (within `row_tolerance`) and applying them gives the fast path's
/// positions (within `position_tolerance`, by default the same). Returns
/// the fast path's mesh.
inline PolygonMesh expect_stencils_are_the_fast_path(const PolygonMesh& mesh, const Scheme& scheme, int levels,
                                                     double row_tolerance, double position_tolerance = -1.0) {
  RefineOptions options;
  options.levels = levels;
  PolygonMesh last;
  expect_rows_sum_to_one(refine_stencils(mesh, scheme, options, &last), row_tolerance);
  PolygonMesh fast = refine(mesh, scheme, options);
  expect_same_positions(fast, last, position_tolerance < 0.0 ? row_tolerance : position_tolerance);
  return fast;
}

/// Refining the image of `mesh` under a fixed shearing, scaling and
/// translating map gives the image of its refinement.
inline void expect_refinement_commutes_with_an_affine_map(const PolygonMesh& mesh, const Scheme& scheme, int levels,
                                                          double tolerance) {
  auto map = [](Vec3 p) { return Vec3{p.x - 2.0 * p.z + 1.0, 3.0 * p.y, p.x + p.y + p.z}; };
  PolygonMesh moved = mesh;
  for (Vec3& p : moved.positions) p = map(p);
  RefineOptions options;
  options.levels = levels;
  const PolygonMesh a = refine(mesh, scheme, options), b = refine(moved, scheme, options);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i)
    EXPECT_NEAR(norm(map(a.positions[i]) - b.positions[i]), 0.0, tolerance) << scheme.name << " vertex " << i;
}

}  // namespace subdiv::test
