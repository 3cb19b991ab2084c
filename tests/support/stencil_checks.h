#pragma once
// Checks shared by the scheme tests: every stencil row sums to one (affine
// invariance), and the fast path gives what the recorded stencils give.

#include <gtest/gtest.h>

#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/refine/stencil_table.h"
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

}  // namespace subdiv::test
