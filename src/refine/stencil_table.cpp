#include "subdiv/refine/stencil_table.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <string>

#include "subdiv/core/error.h"

namespace subdiv {

StencilTable StencilTable::identity(Index n) {
  StencilTable t(n);
  t.reserve(static_cast<std::size_t>(n), static_cast<std::size_t>(n));
  const double one = 1.0;
  for (Index i = 0; i < n; ++i) t.append_row(std::span<const Index>(&i, 1), std::span<const double>(&one, 1));
  return t;
}

void StencilTable::reserve(std::size_t rows, std::size_t entries) {
  offsets_.reserve(rows + 1);
  vertices_.reserve(entries);
  weights_.reserve(entries);
}

void StencilTable::append_row(std::span<const Index> vertices, std::span<const double> weights) {
  if (vertices.size() != weights.size()) throw InvalidInputError("stencil row: vertex and weight counts differ");
  for (const Index v : vertices)
    if (v < 0 || v >= source_count_)
      throw InvalidInputError("stencil row " + std::to_string(row_count()) + " refers to vertex " + std::to_string(v) +
                              " outside [0, " + std::to_string(source_count_) + ")");
  vertices_.insert(vertices_.end(), vertices.begin(), vertices.end());
  weights_.insert(weights_.end(), weights.begin(), weights.end());
  offsets_.push_back(static_cast<Index>(vertices_.size()));
}

StencilTable StencilTable::then(const StencilTable& next) const {
  if (next.source_count() != row_count())
    throw InvalidInputError("cannot compose stencil tables: the second has " + std::to_string(next.source_count()) +
                            " sources, the first " + std::to_string(row_count()) + " rows");
  // Rows are computed in parallel into per-row buffers with a dense
  // accumulator per block, then concatenated in order: deterministic.
  const Index rows = next.row_count();
  std::vector<std::vector<Index>> merged_vertices(static_cast<std::size_t>(rows));
  std::vector<std::vector<double>> merged_weights(static_cast<std::size_t>(rows));
  struct Accumulator {
    std::vector<double> dense;
    std::vector<char> used;
    std::vector<Index> touched;
  };
  tbb::enumerable_thread_specific<Accumulator> accumulators([this] {
    return Accumulator{std::vector<double>(static_cast<std::size_t>(source_count_), 0.0),
                       std::vector<char>(static_cast<std::size_t>(source_count_), 0), {}};
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, rows, 1024), [&](const tbb::blocked_range<Index>& range) {
    auto& [dense, used, touched] = accumulators.local();
    for (Index r = range.begin(); r != range.end(); ++r) {
      touched.clear();
      const auto mid = next.row_vertices(r);
      const auto mid_w = next.row_weights(r);
      for (std::size_t i = 0; i < mid.size(); ++i) {
        const auto src = row_vertices(mid[i]);
        const auto src_w = row_weights(mid[i]);
        for (std::size_t j = 0; j < src.size(); ++j) {
          const auto s = static_cast<std::size_t>(src[j]);
          if (!used[s]) {
            used[s] = 1;
            touched.push_back(src[j]);
          }
          dense[s] += mid_w[i] * src_w[j];
        }
      }
      std::sort(touched.begin(), touched.end());
      auto& out_v = merged_vertices[static_cast<std::size_t>(r)];
      auto& out_w = merged_weights[static_cast<std::size_t>(r)];
      for (const Index s : touched) {
        out_v.push_back(s);
        out_w.push_back(dense[static_cast<std::size_t>(s)]);
        dense[static_cast<std::size_t>(s)] = 0.0;
        used[static_cast<std::size_t>(s)] = 0;
      }
    }
  });
  StencilTable out(source_count_);
  std::size_t entries = 0;
  for (const auto& v : merged_vertices) entries += v.size();
  out.reserve(static_cast<std::size_t>(rows), entries);
  for (Index r = 0; r < rows; ++r) {
    const auto& v = merged_vertices[static_cast<std::size_t>(r)];
    const auto& w = merged_weights[static_cast<std::size_t>(r)];
    out.vertices_.insert(out.vertices_.end(), v.begin(), v.end());
    out.weights_.insert(out.weights_.end(), w.begin(), w.end());
    out.offsets_.push_back(static_cast<Index>(out.vertices_.size()));
  }
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
