#include "subdiv/core/stencil_table.h"

#include <gtest/gtest.h>

#include "subdiv/core/error.h"

namespace subdiv {

TEST(StencilTable, AppendApplyAndCompose) {
  StencilTable a(3);  // 3 -> 2
  const Index r0[] = {0, 1};
  const double w0[] = {0.5, 0.5};
  const Index r1[] = {1, 2, 1};
  const double w1[] = {0.25, 0.5, 0.25};
  a.append_row(r0, w0);
  a.append_row(r1, w1);
  EXPECT_EQ(a.row_count(), 2);
  EXPECT_EQ(a.entry_count(), 5u);
  const std::vector<Vec3> src{{0, 0, 0}, {4, 0, 0}, {0, 8, 0}};
  std::vector<Vec3> dst(2);
  a.apply(src, dst);
  EXPECT_EQ(dst[0], (Vec3{2, 0, 0}));
  EXPECT_EQ(dst[1], (Vec3{2, 4, 0}));

  StencilTable b(2);  // 2 -> 1
  const Index r[] = {0, 1};
  const double w[] = {0.75, 0.25};
  b.append_row(r, w);
  const StencilTable ab = a.then(b);
  EXPECT_EQ(ab.source_count(), 3);
  ASSERT_EQ(ab.row_count(), 1);
  // 0.75 (v0 + v1)/2 + 0.25 (v1/2 + v2/2): merged and sorted by vertex.
  EXPECT_EQ(std::vector<Index>(ab.row_vertices(0).begin(), ab.row_vertices(0).end()), (std::vector<Index>{0, 1, 2}));
  EXPECT_DOUBLE_EQ(ab.row_weights(0)[0], 0.375);
  EXPECT_DOUBLE_EQ(ab.row_weights(0)[1], 0.5);
  EXPECT_DOUBLE_EQ(ab.row_weights(0)[2], 0.125);

  const std::vector<double> values{1, 10, 2, 20, 3, 30};  // two components
  std::vector<double> out(2);
  ab.apply(values, 2, out);
  EXPECT_DOUBLE_EQ(out[0], 0.375 * 1 + 0.5 * 2 + 0.125 * 3);
  EXPECT_DOUBLE_EQ(out[1], 0.375 * 10 + 0.5 * 20 + 0.125 * 30);
}

TEST(StencilTable, IdentityAndErrors) {
  const StencilTable id = StencilTable::identity(3);
  std::vector<Vec3> src{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}, dst(3);
  id.apply(src, dst);
  EXPECT_EQ(dst, src);
  StencilTable t(2);
  const Index bad[] = {2};
  const double w[] = {1.0};
  EXPECT_THROW(t.append_row(bad, w), InvalidInputError);
  std::vector<Vec3> wrong(5);
  EXPECT_THROW(id.apply(src, wrong), InvalidInputError);
  EXPECT_THROW(id.then(StencilTable(2)), InvalidInputError);
}

TEST(StencilTable, AppendRowsRefusesNegativeSizesAndLeavesTheTable) {
  // Sizes {3, -1} add up to the two entries in an unsigned sum: the old
  // check passed them and wrote a decreasing offset.
  StencilTable t(2);
  const Index sizes[] = {3, -1};
  const Index vertices[] = {0, 1};
  const double weights[] = {0.5, 0.5};
  EXPECT_THROW(t.append_rows(sizes, vertices, weights), InvalidInputError);
  EXPECT_EQ(t.row_count(), 0);
  EXPECT_EQ(t.entry_count(), 0u);
  const Index good[] = {1, 1};
  t.append_rows(good, vertices, weights);
  EXPECT_EQ(t.row_count(), 2);
  EXPECT_EQ(t.offsets()[2], 2);
}

}  // namespace subdiv
