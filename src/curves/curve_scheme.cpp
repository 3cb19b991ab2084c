// The engine of curve subdivision: which mask makes each child of a level
// (the closed, open primal and open dual layouts of curve_scheme.h), the
// registry, refine() and curve_stencils(). No weight lives here: the masks
// are in the scheme files, and refine() and the recorded tables read them
// through the one RowBuilder below.

#include "subdiv/curves/curve_scheme.h"

#include <algorithm>
#include <array>
#include <map>
#include <cstdint>
#include <string>

#include "subdiv/core/error.h"

namespace subdiv {

namespace {

std::string label(const CurveScheme& s) { return "curve scheme '" + std::string(s.name) + "'"; }

void check_scheme(const CurveScheme& s) {
  if (s.arity != 2)
    throw InvalidInputError(label(s) + ": only binary schemes (arity 2) are supported, got arity " +
                            std::to_string(s.arity));
  if (s.even.empty() || s.odd.empty()) throw InvalidInputError(label(s) + ": the even and odd masks must not be empty");
  for (const CurveMask& m : s.end)
    if (m.empty()) throw InvalidInputError(label(s) + ": an end mask is empty");
}

Index end_mask_count(const CurveScheme& s) { return static_cast<Index>(s.end.size()); }

/// Children of one level of n points (which the caller has checked).
std::int64_t level_count(const CurveScheme& s, std::int64_t n, bool closed) {
  if (closed) return 2 * n;
  return s.dual ? 2 * (n - 1) + 2 * static_cast<std::int64_t>(end_mask_count(s)) : 2 * n - 1;
}

void check_points(const CurveScheme& s, std::int64_t n, bool closed) {
  const Index needed = closed ? std::max<Index>(s.min_closed_points, 1) : std::max<Index>(s.min_open_points, 2);
  if (n < needed)
    throw InvalidInputError(label(s) + ": " + (closed ? "a closed polygon" : "an open polyline") + " needs at least " +
                            std::to_string(needed) + " points, got " + std::to_string(n));
  // A primal scheme's end masks replace children at both ends; they must not overlap.
  if (!closed && !s.dual && 2 * static_cast<std::int64_t>(end_mask_count(s)) > 2 * n - 1)
    throw InvalidInputError(label(s) + ": " + std::to_string(s.end.size()) +
                            " end masks at each end do not fit an open polyline of " + std::to_string(n) + " points");
}

/// The merged (parent point, weight) row of one child: the single place
/// where masks become weights over parent points.
class RowBuilder {
 public:
  RowBuilder(const CurveScheme& s, Index n, bool closed)
      : s_(s), n_(n), closed_(closed), count_(static_cast<Index>(level_count(s, n, closed))) {}

  Index count() const { return count_; }

  void build(Index child) {
    vertices_.clear();
    weights_.clear();
    const Index e = end_mask_count(s_);
    const CurveMask* mask = nullptr;
    std::int64_t anchor = 0;
    bool mirrored = false;
    if (closed_) {
      mask = child % 2 == 0 ? &s_.even : &s_.odd;
      anchor = child / 2;
    } else if (child < e) {
      mask = &s_.end[static_cast<std::size_t>(child)];
    } else if (child >= count_ - e) {
      mask = &s_.end[static_cast<std::size_t>(count_ - 1 - child)];
      mirrored = true;
    } else {
      const Index g = s_.dual ? child - e : child;  // dual: end points come first
      mask = g % 2 == 0 ? &s_.even : &s_.odd;
      anchor = g / 2;
    }
    for (const CurveMaskEntry& entry : *mask) {
      std::int64_t p = mirrored ? std::int64_t{n_} - 1 - entry.offset : anchor + entry.offset;
      if (closed_) {
        p %= n_;
        if (p < 0) p += n_;
      } else if (p < 0 || p >= n_) {
        throw InvalidInputError(label(s_) + ": the mask of child " + std::to_string(child) + " reaches point " +
                                std::to_string(p) + ", outside the open polyline of " + std::to_string(n_) + " points");
      }
      add(static_cast<Index>(p), entry.weight);
    }
  }

  std::span<const Index> vertices() const { return vertices_; }
  std::span<const double> weights() const { return weights_; }

 private:
  // A closed polygon shorter than a mask wraps onto the same point twice.
  void add(Index v, double w) {
    for (std::size_t i = 0; i < vertices_.size(); ++i)
      if (vertices_[i] == v) {
        weights_[i] += w;
        return;
      }
    vertices_.push_back(v);
    weights_.push_back(w);
  }

  const CurveScheme& s_;
  Index n_;
  bool closed_;
  Index count_;
  std::vector<Index> vertices_;
  std::vector<double> weights_;
};

Index checked_size(const std::vector<Vec3>& points) {
  if (points.size() > static_cast<std::size_t>(kMaxElements))
    throw InvalidInputError("polyline has " + std::to_string(points.size()) + " points, more than an Index can count");
  return static_cast<Index>(points.size());
}

StencilTable level_table(const CurveScheme& s, Index n, bool closed) {
  RowBuilder row(s, n, closed);
  StencilTable table(n);
  table.reserve(static_cast<std::size_t>(row.count()), static_cast<std::size_t>(row.count()) * s.odd.size());
  for (Index c = 0; c < row.count(); ++c) {
    row.build(c);
    table.append_row(row.vertices(), row.weights());
  }
  return table;
}

}  // namespace

Index refined_point_count(const CurveScheme& scheme, Index point_count, bool closed, int levels) {
  check_scheme(scheme);
  if (levels < 0) throw InvalidInputError(label(scheme) + ": levels must be >= 0, got " + std::to_string(levels));
  check_points(scheme, point_count, closed);
  std::int64_t n = point_count;
  for (int l = 0; l < levels; ++l) {
    n = level_count(scheme, n, closed);
    if (n > kMaxElements)
      throw InvalidInputError(label(scheme) + ": " + std::to_string(levels) + " levels of " +
                              std::to_string(point_count) + " points would make more than " +
                              std::to_string(kMaxElements) + " points");
  }
  return static_cast<Index>(n);
}

Polyline refine(const Polyline& polyline, const CurveScheme& scheme, int levels) {
  refined_point_count(scheme, checked_size(polyline.points), polyline.closed, levels);
  Polyline out = polyline;
  for (int l = 0; l < levels; ++l) {
    RowBuilder row(scheme, static_cast<Index>(out.points.size()), out.closed);
    std::vector<Vec3> next(static_cast<std::size_t>(row.count()));
    for (Index c = 0; c < row.count(); ++c) {
      row.build(c);
      const auto v = row.vertices();
      const auto w = row.weights();
      Vec3 sum;  // the order of StencilTable::apply, so one level agrees bit for bit
      for (std::size_t k = 0; k < v.size(); ++k) sum += w[k] * out.points[static_cast<std::size_t>(v[k])];
      next[static_cast<std::size_t>(c)] = sum;
    }
    out.points = std::move(next);
  }
  return out;
}

StencilTable curve_stencils(const CurveScheme& scheme, Index point_count, bool closed, int levels) {
  refined_point_count(scheme, point_count, closed, levels);
  if (levels == 0) return StencilTable::identity(point_count);
  StencilTable total = level_table(scheme, point_count, closed);
  for (int l = 1; l < levels; ++l) total = total.then(level_table(scheme, total.row_count(), closed));
  return total;
}

CurveMask limit_at_point(const CurveScheme& scheme) {
  if (!scheme.dual || scheme.limit.empty()) return scheme.limit;
  // Child 2j + e is mask e anchored at parent j; the child edge around
  // point i's parameter runs from child 2i - 1 (odd, anchored at i - 1) to
  // child 2i (even, anchored at i), and `limit` is anchored at its start.
  std::map<int, double> weights;  // by offset from i
  for (const CurveMaskEntry& l : scheme.limit) {
    const int child = -1 + l.offset;  // relative to child 2i
    const int anchor = child >= 0 ? child / 2 : (child - 1) / 2;
    const CurveMask& mask = child - 2 * anchor == 0 ? scheme.even : scheme.odd;
    for (const CurveMaskEntry& m : mask) weights[anchor + m.offset] += l.weight * m.weight;
  }
  CurveMask out;
  for (const auto& [offset, weight] : weights)
    if (weight != 0.0) out.push_back({offset, weight});
  return out;
}

std::span<const CurveScheme* const> all_curve_schemes() {
  static const std::array<const CurveScheme*, 3> schemes = {&cubic_bspline_curve_scheme(), &chaikin_curve_scheme(),
                                                            &four_point_curve_scheme()};
  return schemes;
}

const CurveScheme* find_curve_scheme(std::string_view name) {
  for (const CurveScheme* s : all_curve_schemes())
    if (s->name == name) return s;
  return nullptr;
}

}  // namespace subdiv
