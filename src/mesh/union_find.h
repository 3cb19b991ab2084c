#pragma once
// Disjoint sets over [0, n) with path halving and union by index (the
// smaller root wins, so results do not depend on the order of unions).

#include <vector>

#include "subdiv/core/types.h"

namespace subdiv::detail {

class UnionFind {
 public:
  explicit UnionFind(Index n) : parent_(static_cast<std::size_t>(n)) {
    for (Index i = 0; i < n; ++i) parent_[static_cast<std::size_t>(i)] = i;
  }
  Index find(Index i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b) parent_[b] = a; else parent_[a] = b;
  }

 private:
  std::vector<Index> parent_;
};

}  // namespace subdiv::detail
