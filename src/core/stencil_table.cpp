#include "subdiv/core/stencil_table.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <string>

#include "large_buffers.h"
#include "row_accumulator.h"
#include "subdiv/core/error.h"

namespace subdiv {

StencilTable StencilTable::identity(Index n) {
  StencilTable t(n);
  t.reserve(static_cast<std::size_t>(n), static_cast<std::size_t>(n));
  const double one = 1.0;
  for (Index i = 0; i < n; ++i) t.append_row(std::span<const Index>(&i, 1), std::span<const double>(&one, 1));
  return t;
}

StencilTable StencilTable::from_rows(Index source_count, std::vector<Index> offsets, std::vector<Index> vertices,
                                     std::vector<double> weights) {
  if (offsets.empty() || offsets.front() != 0 || vertices.size() != weights.size() ||
      static_cast<std::size_t>(offsets.back()) != vertices.size() ||
      std::adjacent_find(offsets.begin(), offsets.end(), std::greater<>()) != offsets.end())
    throw InvalidInputError("stencil rows: offsets must start at 0, never decrease and end at the entry count");
  for (const Index v : vertices)
    if (v < 0 || v >= source_count)
      throw InvalidInputError("stencil row refers to vertex " + std::to_string(v) + " outside [0, " +
                              std::to_string(source_count) + ")");
  StencilTable t(source_count);
  t.offsets_ = std::move(offsets);
  t.vertices_ = std::move(vertices);
  t.weights_ = std::move(weights);
  return t;
}

void StencilTable::reserve(std::size_t rows, std::size_t entries) {
  detail::reserve_large(offsets_, rows + 1);
  detail::reserve_large(vertices_, entries);
  detail::reserve_large(weights_, entries);
}

void StencilTable::append_row(std::span<const Index> vertices, std::span<const double> weights) {
  const auto size = static_cast<Index>(vertices.size());
  append_rows(std::span<const Index>(&size, 1), vertices, weights);
}

void StencilTable::append_rows(std::span<const Index> sizes, std::span<const Index> vertices,
                               std::span<const double> weights) {
  if (vertices.size() != weights.size()) throw InvalidInputError("stencil rows: vertex and weight counts differ");
  std::size_t total = 0;
  for (std::size_t r = 0; r < sizes.size(); ++r) {
    // A negative size would wrap the unsigned sum and could still match.
    if (sizes[r] < 0) throw InvalidInputError("stencil rows: row " + std::to_string(r) + " has a negative size");
    total += static_cast<std::size_t>(sizes[r]);
  }
  if (total != vertices.size()) throw InvalidInputError("stencil rows: row sizes do not add up to the entries");
  // The offsets are Index values: the table cannot hold more entries than that.
  if (vertices_.size() + total > static_cast<std::size_t>(std::numeric_limits<Index>::max()))
    throw InvalidInputError("stencil rows: more entries than a 32-bit index can address");
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (vertices[i] < 0 || vertices[i] >= source_count_)
      throw InvalidInputError("stencil row refers to vertex " + std::to_string(vertices[i]) + " outside [0, " +
                              std::to_string(source_count_) + ")");
  vertices_.insert(vertices_.end(), vertices.begin(), vertices.end());
  weights_.insert(weights_.end(), weights.begin(), weights.end());
  for (const Index n : sizes) offsets_.push_back(offsets_.back() + n);
}

StencilTable StencilTable::then(const StencilTable& next) const {
  if (next.source_count() != row_count())
    throw InvalidInputError("cannot compose stencil tables: the second has " + std::to_string(next.source_count()) +
                            " sources, the first " + std::to_string(row_count()) + " rows");
  StencilTable out(source_count_);
  detail::append_rows(out, 0, next.row_count(), [&](Index r, detail::RowAccumulator& acc) {
    const auto mid = next.row_vertices(r);
    const auto mid_w = next.row_weights(r);
    for (std::size_t i = 0; i < mid.size(); ++i) acc.add_row(*this, mid[i], mid_w[i]);
  });
  return out;
}

void StencilTable::apply(std::span<const Vec3> src, std::span<Vec3> dst) const {
  if (src.size() != static_cast<std::size_t>(source_count_) || dst.size() != static_cast<std::size_t>(row_count()))
    throw InvalidInputError("stencil apply: expected " + std::to_string(source_count_) + " sources and " +
                            std::to_string(row_count()) + " destinations");
  tbb::parallel_for(tbb::blocked_range<Index>(0, row_count(), 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index r = range.begin(); r != range.end(); ++r) {
      Vec3 sum;
      for (Index i = offsets_[r]; i < offsets_[r + 1]; ++i) sum += weights_[i] * src[static_cast<std::size_t>(vertices_[i])];
      dst[static_cast<std::size_t>(r)] = sum;
    }
  });
}

void StencilTable::apply(std::span<const double> src, int components, std::span<double> dst) const {
  const auto k = static_cast<std::size_t>(components);
  if (components <= 0 || src.size() != static_cast<std::size_t>(source_count_) * k ||
      dst.size() != static_cast<std::size_t>(row_count()) * k)
    throw InvalidInputError("stencil apply: value arrays do not match the table");
  tbb::parallel_for(tbb::blocked_range<Index>(0, row_count(), 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index r = range.begin(); r != range.end(); ++r) {
      double* out = dst.data() + static_cast<std::size_t>(r) * k;
      std::fill(out, out + k, 0.0);
      for (Index i = offsets_[r]; i < offsets_[r + 1]; ++i) {
        const double* in = src.data() + static_cast<std::size_t>(vertices_[i]) * k;
        for (std::size_t j = 0; j < k; ++j) out[j] += weights_[i] * in[j];
      }
    }
  });
}

}  // namespace subdiv
