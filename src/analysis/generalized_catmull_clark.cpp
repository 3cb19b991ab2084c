#include "subdiv/analysis/generalized_catmull_clark.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <fmt/format.h>

#include "subdiv/core/error.h"
#include "subdiv/refine/refine.h"

namespace subdiv {

std::complex<double> gcc_mu0(const SmoothingWeights& w, int m) noexcept {
  const auto [a, b] = w.at(m);
  const auto [a4, b4] = w.at(4);
  const double t = 2.0 * a4 + b4, s = 3.0 * a + b;
  return (s + std::sqrt(std::complex<double>(s * s - 4.0 * t * a, 0.0))) / 8.0;
}

double gcc_lambda(const SmoothingWeights& w, int m) noexcept {
  const auto [a4, b4] = w.at(4);
  const double t = 2.0 * a4 + b4, c = std::cos(2.0 * std::numbers::pi / m), u = 2.0 - t;
  return (4.0 + t + u * c + std::sqrt(u * u * c * c + 2.0 * (4.0 + t) * u * c + (4.0 - t) * (4.0 - t))) / 16.0;
}

double gcc_rho_b_bound(int degree) noexcept { return std::pow(0.5, degree / 2 + 1); }
double gcc_rho_a_bound(int degree) noexcept { return std::pow(0.25, degree / 2 + 1); }

GccTheorem gcc_theorem(const Scheme& scheme, int m) {
  const DegreeParameters* degree = degree_parameters(scheme.parameters);
  if (!scheme.steps || degree == nullptr || degree->degree != 3 || degree->smoothing.size() != 1)
    throw InvalidInputError(std::string(scheme.name) +
                            ": the closed forms of Example 6.2 are those of M_3-bar (degree 3, one smoothing operator)");
  if (m < 3) throw InvalidInputError("closed forms: valence must be >= 3, not " + std::to_string(m));
  const SmoothingWeights& w = degree->smoothing.front();
  GccTheorem r;
  r.valence = m;
  r.mu0 = gcc_mu0(w, m);
  r.lambda = gcc_lambda(w, m);
  r.rho_b_bound = gcc_rho_b_bound(3);
  r.rho_a_bound = gcc_rho_a_bound(3);
  r.constant = w.at(m) == w.at(4);
  r.condition_5_2 = r.lambda > std::abs(r.mu0);
  r.condition_5_1 = r.condition_5_2 && r.lambda > std::max(r.rho_b_bound, r.rho_a_bound);
  if (m == 4) {
    r.proves_c1 = true;
    r.reason = "regular: Theorem 3.3";
  } else if (m == 3) {
    r.proves_c1 = r.condition_5_1;
    r.reason = r.condition_5_1 ? "Remark 5.7: (5.1) holds" : "(5.1) fails: not covered by Theorem 6.1";
  } else if (r.constant) {
    r.proves_c1 = true;
    r.reason = "Theorem 6.1: constant weights, m >= 5";
  } else {
    r.proves_c1 = r.condition_5_2;
    r.reason = r.condition_5_2 ? "Remark 5.7: (5.2) holds" : "(5.2) fails: not covered by Theorem 6.1";
  }
  return r;
}

double gcc_second_difference_bound(const SmoothingWeights& w) noexcept {
  const auto [a, b] = w.at(4);
  const double s = (2.0 * a + b) / 4.0;
  return std::max(s, 0.5 - s);
}

namespace {

using Mask = std::map<std::pair<int, int>, double>;

// q with a = (1 + z_axis) q, or throws when a has a remainder.
Mask divide(const Mask& a, int axis) {
  // Along the axis, for each line of the other coordinate, lowest power first.
  std::map<int, std::map<int, double>> lines;
  for (const auto& [d, w] : a) lines[axis == 0 ? d.second : d.first][axis == 0 ? d.first : d.second] = w;
  Mask q;
  for (const auto& [other, line] : lines) {
    const int low = line.begin()->first, high = line.rbegin()->first;
    double previous = 0.0;
    for (int k = low; k <= high; ++k) {
      const auto it = line.find(k);
      const double value = (it == line.end() ? 0.0 : it->second) - previous;
      if (k == high) {
        if (std::fabs(value) > 1e-12)
          throw InvalidInputError("second differences: the regular mask is not divisible by (1 + z); the scheme "
                                  "does not reproduce linear functions");
        break;
      }
      q[axis == 0 ? std::pair{k, other} : std::pair{other, k}] = value;
      previous = value;
    }
  }
  return q;
}

// The norm of a 2-scaled scheme: the largest sum of |weights| over one parity class.
double scheme_norm(const Mask& q) {
  double sums[2][2] = {{0, 0}, {0, 0}};
  for (const auto& [d, w] : q) sums[d.first & 1][d.second & 1] += std::fabs(w);
  return std::max({sums[0][0], sums[0][1], sums[1][0], sums[1][1]});
}

}  // namespace

double regular_second_difference_norm(const Scheme& scheme) {
  if (scheme.split != SplitRule::quad && scheme.split != SplitRule::dual)
    throw InvalidInputError(std::string(scheme.name) + ": second differences need a quad mesh scheme");
  // A regular grid wide enough that its centre's rows do not see the boundary
  // (schemes without a degree parameter are at most bicubic).
  const DegreeParameters* degree = degree_parameters(scheme.parameters);
  const int reach = 2 * std::max(3, degree != nullptr ? degree->degree : 3) + 4, n = 2 * reach;
  PolygonMesh grid;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) grid.positions.push_back({double(i), double(j), 0.0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      auto id = [n](int x, int y) { return static_cast<Index>(y * (n + 1) + x); };
      grid.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  Scheme open = scheme;
  open.traits.needs_closed_mesh = false;
  RefineOptions once;
  once.levels = 1;
  std::vector<StencilTable> tables;
  PolygonMesh fine;
  tables = refine_stencils(grid, open, once, &fine);
  // Fine point i (position i/2 + shift, shift 1/4 for the dual split) gets
  // sum_j a_(i - 2j) c_j: read a off one fine point of each parity class
  // near the centre.
  const double shift = scheme.split == SplitRule::dual ? 0.25 : 0.0;
  Mask a;
  bool seen[2][2] = {{false, false}, {false, false}};
  for (Index r = 0; r < fine.vertex_count(); ++r) {
    const Vec3 p = fine.positions[static_cast<std::size_t>(r)];
    if (std::fabs(p.x - reach) > 1.0 || std::fabs(p.y - reach) > 1.0) continue;
    const int i1 = static_cast<int>(std::lround(2.0 * (p.x - shift))), i2 = static_cast<int>(std::lround(2.0 * (p.y - shift)));
    if (std::fabs(2.0 * (p.x - shift) - i1) > 1e-9 || std::fabs(2.0 * (p.y - shift) - i2) > 1e-9)
      throw InvalidInputError(std::string(scheme.name) + ": a fine point is off the refined grid");
    if (seen[i1 & 1][i2 & 1]) continue;
    seen[i1 & 1][i2 & 1] = true;
    const auto vertices = tables.front().row_vertices(r);
    const auto weights = tables.front().row_weights(r);
    for (std::size_t e = 0; e < vertices.size(); ++e) {
      const Vec3 c = grid.positions[static_cast<std::size_t>(vertices[e])];
      const std::pair d{i1 - 2 * static_cast<int>(std::lround(c.x)), i2 - 2 * static_cast<int>(std::lround(c.y))};
      a[d] += weights[e];
    }
  }
  const Mask q11 = divide(divide(a, 0), 0);
  const Mask q12 = divide(divide(a, 0), 1);
  const Mask q22 = divide(divide(a, 1), 1);
  return std::max({scheme_norm(q11), scheme_norm(q12), scheme_norm(q22)});
}

}  // namespace subdiv
