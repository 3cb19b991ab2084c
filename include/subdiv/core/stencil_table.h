#pragma once
// Sparse linear maps between levels: row i says which parent vertices, with
// which weights, make child vertex i. Recorded from the same masks as the
// fast path, composable over levels (coarse -> level N in one table), and
// re-applicable to new positions or any per-vertex data (animation, UVs).

#include <span>
#include <vector>

#include "subdiv/core/types.h"

namespace subdiv {

class StencilTable {
 public:
  StencilTable() = default;
  /// An empty table over `source_count` source vertices; rows are appended.
  explicit StencilTable(Index source_count) : source_count_(source_count) {}
  /// The identity on n vertices.
  static StencilTable identity(Index n);
  /// A table from its arrays: row r's entries are [offsets[r], offsets[r+1])
  /// of `vertices` and `weights`. Throws InvalidInputError unless offsets
  /// start at 0, never decrease and end at the entry count, and every vertex
  /// is a source.
  static StencilTable from_rows(Index source_count, std::vector<Index> offsets, std::vector<Index> vertices,
                                std::vector<double> weights);

  Index source_count() const { return source_count_; }
  Index row_count() const { return static_cast<Index>(offsets_.size()) - 1; }
  std::size_t entry_count() const { return vertices_.size(); }
  std::span<const Index> row_vertices(Index r) const {
    return {vertices_.data() + offsets_[r], static_cast<std::size_t>(offsets_[r + 1] - offsets_[r])};
  }
  std::span<const double> row_weights(Index r) const {
    return {weights_.data() + offsets_[r], static_cast<std::size_t>(offsets_[r + 1] - offsets_[r])};
  }

  /// Appends a row; throws InvalidInputError for a vertex outside the sources.
  void append_row(std::span<const Index> vertices, std::span<const double> weights);
  /// Appends many rows at once: their entries concatenated, with each row's size.
  void append_rows(std::span<const Index> sizes, std::span<const Index> vertices, std::span<const double> weights);
  void reserve(std::size_t rows, std::size_t entries);

  /// The table that maps this table's sources through `next` (whose sources
  /// are this table's rows): next * this. Duplicate vertices in a row merge.
  StencilTable then(const StencilTable& next) const;

  /// dst[i] = sum_j w_ij src[v_ij]. dst must have row_count() elements.
  void apply(std::span<const Vec3> src, std::span<Vec3> dst) const;
  /// The same for values of `components` doubles each.
  void apply(std::span<const double> src, int components, std::span<double> dst) const;

 private:
  Index source_count_ = 0;
  std::vector<Index> offsets_{0};
  std::vector<Index> vertices_;
  std::vector<double> weights_;
};

}  // namespace subdiv
