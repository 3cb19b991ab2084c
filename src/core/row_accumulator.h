#pragma once
// Building stencil rows as weighted sums of other rows: a dense accumulator
// over the sources (one per thread) that emits each row merged and sorted by
// source, and the parallel construction of a block of rows in order.

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <vector>

#include "subdiv/core/stencil_table.h"

namespace subdiv::detail {

class RowAccumulator {
 public:
  explicit RowAccumulator(Index sources)
      : dense_(static_cast<std::size_t>(sources), 0.0), used_(static_cast<std::size_t>(sources), 0) {}

  void add(Index source, double weight) {
    const auto s = static_cast<std::size_t>(source);
    if (!used_[s]) {
      used_[s] = 1;
      touched_.push_back(source);
    }
    dense_[s] += weight;
  }
  /// weight times row r of t.
  void add_row(const StencilTable& t, Index r, double weight) {
    const auto vertices = t.row_vertices(r);
    const auto weights = t.row_weights(r);
    for (std::size_t j = 0; j < vertices.size(); ++j) add(vertices[j], weight * weights[j]);
  }
  /// Appends the accumulated row, sorted by source, and starts a new one.
  void emit(std::vector<Index>& vertices, std::vector<double>& weights) {
    std::sort(touched_.begin(), touched_.end());
    for (const Index s : touched_) {
      const auto i = static_cast<std::size_t>(s);
      vertices.push_back(s);
      weights.push_back(dense_[i]);
      dense_[i] = 0.0;
      used_[i] = 0;
    }
    touched_.clear();
  }

 private:
  std::vector<double> dense_;
  std::vector<char> used_;
  std::vector<Index> touched_;
};

/// Appends rows [begin, end) to `table`, in order: fill(row, accumulator)
/// adds each row's terms. Blocks of rows run in parallel into their own
/// buffers; the result does not depend on the thread count.
template <typename Fill>
void append_rows(StencilTable& table, Index begin, Index end, Fill&& fill) {
  struct Block {
    std::vector<Index> sizes, vertices;
    std::vector<double> weights;
  };
  std::map<Index, Block> blocks;  // by first row
  std::mutex blocks_mutex;
  tbb::enumerable_thread_specific<RowAccumulator> accumulators([&] { return RowAccumulator(table.source_count()); });
  tbb::parallel_for(tbb::blocked_range<Index>(begin, end, 2048), [&](const tbb::blocked_range<Index>& range) {
    RowAccumulator& acc = accumulators.local();
    Block block;
    block.sizes.reserve(range.size());
    block.vertices.reserve(16 * range.size());
    block.weights.reserve(16 * range.size());
    for (Index r = range.begin(); r != range.end(); ++r) {
      const std::size_t before = block.vertices.size();
      fill(r, acc);
      acc.emit(block.vertices, block.weights);
      block.sizes.push_back(static_cast<Index>(block.vertices.size() - before));
    }
    const std::lock_guard lock(blocks_mutex);
    blocks.emplace(range.begin(), std::move(block));
  });
  std::size_t entries = table.entry_count();
  for (const auto& [first, block] : blocks) entries += block.vertices.size();
  table.reserve(static_cast<std::size_t>(table.row_count() + end - begin), entries);
  for (const auto& [first, block] : blocks) table.append_rows(block.sizes, block.vertices, block.weights);
}

}  // namespace subdiv::detail
