#pragma once
// Reading stencil rows as {vertex: weight} maps (duplicates merged), for
// golden-weight tests.

#include <map>

#include "subdiv/core/stencil_table.h"

namespace subdiv::test {

inline std::map<Index, double> merged_row(const StencilTable& table, Index row) {
  std::map<Index, double> out;
  const auto v = table.row_vertices(row);
  const auto w = table.row_weights(row);
  for (std::size_t i = 0; i < v.size(); ++i) out[v[i]] += w[i];
  return out;
}

}  // namespace subdiv::test
