#pragma once
/// \file
/// Sparse linear maps between levels: row i says which parent vertices, with
/// which weights, make child vertex i. Recorded from the same masks as the
/// fast path, composable over levels (coarse -> level N in one table), and
/// re-applicable to new positions or any per-vertex data (animation, UVs).

#include <span>
#include <vector>

#include "subdiv/core/types.h"

namespace subdiv {

/// A sparse linear map from `source_count()` source vertices to
/// `row_count()` destination vertices, stored as compressed rows: row r lists
/// the source vertices and weights whose weighted sum is destination r.
/// Weights are stored as given (rows need not sum to 1).
class StencilTable {
 public:
  /// An empty table over no sources, with no rows.
  StencilTable() = default;
  /// An empty table over \p source_count source vertices; rows are appended.
  /// \param source_count number of source vertices (>= 0).
  /// \throws std::bad_alloc if memory runs out.
  explicit StencilTable(Index source_count) : source_count_(source_count) {}
  /// The identity on \p n vertices: row i is source i with weight 1.
  /// \param n number of vertices (>= 0).
  /// \return a table with n sources and n rows.
  /// \throws std::bad_alloc if memory runs out.
  static StencilTable identity(Index n);
  /// A table from its arrays: row r's entries are [offsets[r], offsets[r+1])
  /// of \p vertices and \p weights. The arrays are taken over, not copied.
  /// \param source_count number of source vertices.
  /// \param offsets row starts, one more than the number of rows.
  /// \param vertices source vertex of every entry, rows concatenated.
  /// \param weights weight of every entry, parallel to \p vertices.
  /// \return the table.
  /// \throws InvalidInputError unless \p offsets is non-empty, starts at 0,
  ///         never decreases and ends at the entry count, \p weights has as
  ///         many entries as \p vertices, and every vertex is in
  ///         [0, source_count).
  static StencilTable from_rows(Index source_count, std::vector<Index> offsets, std::vector<Index> vertices,
                                std::vector<double> weights);

  /// \return the number of source vertices the rows refer to.
  Index source_count() const noexcept { return source_count_; }
  /// \return the number of rows (destination vertices).
  Index row_count() const noexcept { return static_cast<Index>(offsets_.size()) - 1; }
  /// \return the number of (vertex, weight) entries over all rows.
  std::size_t entry_count() const noexcept { return vertices_.size(); }
  /// The table in compressed sparse row form: row r's entries are
  /// [offsets()[r], offsets()[r + 1]) of vertices() and weights().
  /// \return row_count() + 1 ascending offsets, the first 0.
  std::span<const Index> offsets() const noexcept { return offsets_; }
  /// \return every row's source vertices, rows concatenated (entry_count() values).
  std::span<const Index> vertices() const noexcept { return vertices_; }
  /// \return every row's weights, parallel to vertices().
  std::span<const double> weights() const noexcept { return weights_; }
  /// The source vertices of row \p r, in stored order.
  /// \pre 0 <= r < row_count() (not checked).
  /// \param r the row.
  /// \return a view into the table, valid until the table is modified or destroyed.
  std::span<const Index> row_vertices(Index r) const noexcept {
    return {vertices_.data() + offsets_[r], static_cast<std::size_t>(offsets_[r + 1] - offsets_[r])};
  }
  /// The weights of row \p r, parallel to row_vertices(r).
  /// \pre 0 <= r < row_count() (not checked).
  /// \param r the row.
  /// \return a view into the table, valid until the table is modified or destroyed.
  std::span<const double> row_weights(Index r) const noexcept {
    return {weights_.data() + offsets_[r], static_cast<std::size_t>(offsets_[r + 1] - offsets_[r])};
  }

  /// Appends a row. On an InvalidInputError the table is unchanged.
  /// \param vertices the row's source vertices.
  /// \param weights their weights, parallel to \p vertices.
  /// \throws InvalidInputError if the spans differ in size or a vertex lies
  ///         outside [0, source_count()).
  /// \throws std::bad_alloc if memory runs out.
  void append_row(std::span<const Index> vertices, std::span<const double> weights);
  /// Appends many rows at once: their entries concatenated, with each row's
  /// size. On an InvalidInputError the table is unchanged.
  /// \param sizes number of entries of each new row (each >= 0).
  /// \param vertices the rows' source vertices, concatenated.
  /// \param weights their weights, parallel to \p vertices.
  /// \throws InvalidInputError if \p vertices and \p weights differ in size,
  ///         a size is negative, the sizes do not add up to that size, the
  ///         table would exceed what a 32-bit index addresses, or a vertex
  ///         lies outside [0, source_count()).
  /// \throws std::bad_alloc if memory runs out.
  void append_rows(std::span<const Index> sizes, std::span<const Index> vertices, std::span<const double> weights);
  /// Reserves room for \p rows rows and \p entries entries in all, counting
  /// those already present (like std::vector::reserve; large reservations
  /// ask the system for huge pages).
  /// \param rows total number of rows to make room for.
  /// \param entries total number of entries to make room for.
  /// \throws std::bad_alloc if memory runs out.
  /// \throws std::length_error if a count exceeds what a vector can hold.
  void reserve(std::size_t rows, std::size_t entries);

  /// The table that maps this table's sources through \p next (whose sources
  /// are this table's rows): next * this. Duplicate vertices in a row merge.
  /// \param next the table applied second.
  /// \return a table with this table's sources and \p next's rows.
  /// \throws InvalidInputError if next.source_count() != row_count().
  /// \throws std::bad_alloc if memory runs out.
  StencilTable then(const StencilTable& next) const;

  /// Applies the table to points: dst[i] = sum_j w_ij src[v_ij]. Rows are
  /// evaluated in parallel.
  /// \param src one value per source vertex.
  /// \param dst receives one value per row; must not overlap \p src.
  /// \throws InvalidInputError if src.size() != source_count() or
  ///         dst.size() != row_count().
  void apply(std::span<const Vec3> src, std::span<Vec3> dst) const;
  /// The same for values of \p components doubles each, stored interleaved
  /// (value i occupies [i * components, (i + 1) * components)).
  /// \param src source_count() * components doubles.
  /// \param components doubles per value (> 0).
  /// \param dst receives row_count() * components doubles; must not overlap \p src.
  /// \throws InvalidInputError if \p components <= 0 or a span's size does not match.
  void apply(std::span<const double> src, int components, std::span<double> dst) const;

 private:
  Index source_count_ = 0;
  std::vector<Index> offsets_{0};
  std::vector<Index> vertices_;
  std::vector<double> weights_;
};

}  // namespace subdiv
