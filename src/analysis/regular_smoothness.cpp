// The regular-rule smoothness test (regular_smoothness.h): transition
// matrices on a closed window, their action on the quotient by linear
// functions, and bounds on their joint spectral radius.

#include "subdiv/analysis/regular_smoothness.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <set>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "subdiv/core/error.h"

namespace subdiv {

namespace {

using Point = std::array<int, 2>;
constexpr std::size_t kMaxWindow = 400;

struct Family {
  std::vector<Eigen::MatrixXd> matrices;  // on the quotient
  int window = 0;
  double critical = 0.0;
  std::string failure;  // non-empty: the test cannot run, and why
};

class RuleLookup {
 public:
  explicit RuleLookup(const LatticeRule& rule) : rule_(rule) {
    for (const LatticeWeight& w : rule.mask) interior_[w.offset] = w.weight;
    for (const auto& row : rule.boundary_rows) {
      rows_.emplace_back();
      for (const LatticeWeight& w : row) rows_.back()[w.offset] = w.weight;
    }
  }
  bool boundary() const { return !rows_.empty(); }
  const std::map<Point, double>& mask_of(const Point& child) const {
    if (boundary() && child[1] >= 0 && child[1] < static_cast<int>(rows_.size()))
      return rows_[static_cast<std::size_t>(child[1])];
    return interior_;
  }
  Point apply_dilation(const Point& j) const {
    const auto& M = rule_.dilation;
    return {M[0][0] * j[0] + M[0][1] * j[1], M[1][0] * j[0] + M[1][1] * j[1]};
  }
  // j with M j = c, if any.
  std::optional<Point> solve(const Point& c) const {
    const auto& M = rule_.dilation;
    if (rule_.dimension == 1) {
      if (c[0] % M[0][0] != 0) return std::nullopt;
      return Point{c[0] / M[0][0], 0};
    }
    const int det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
    const int x = M[1][1] * c[0] - M[0][1] * c[1];
    const int y = -M[1][0] * c[0] + M[0][0] * c[1];
    if (x % det != 0 || y % det != 0) return std::nullopt;
    return Point{x / det, y / det};
  }
  double weight(const Point& child, const Point& parent) const {
    const Point m = apply_dilation(parent);
    const auto& mask = mask_of(child);
    const auto it = mask.find({child[0] - m[0], child[1] - m[1]});
    return it == mask.end() ? 0.0 : it->second;
  }

 private:
  const LatticeRule& rule_;
  std::map<Point, double> interior_;
  std::vector<std::map<Point, double>> rows_;
};

int determinant(const LatticeRule& rule) {
  const auto& M = rule.dilation;
  return rule.dimension == 1 ? std::abs(M[0][0]) : std::abs(M[0][0] * M[1][1] - M[0][1] * M[1][0]);
}

// Representatives of Z^d / M Z^d (along the boundary: of Z / m Z in x).
std::vector<Point> digits(const LatticeRule& rule, const RuleLookup& lookup) {
  std::vector<Point> result;
  if (rule.dimension == 1 || lookup.boundary()) {
    for (int i = 0; i < std::abs(rule.dilation[0][0]); ++i) result.push_back({i, 0});
    return result;
  }
  const int det = determinant(rule);
  std::vector<Point> candidates;
  for (int x = -det; x <= det; ++x)
    for (int y = -det; y <= det; ++y) candidates.push_back({x, y});
  std::stable_sort(candidates.begin(), candidates.end(), [](const Point& a, const Point& b) {
    return a[0] * a[0] + a[1] * a[1] < b[0] * b[0] + b[1] * b[1];
  });
  for (const Point& e : candidates) {
    if (static_cast<int>(result.size()) == det) break;
    const bool new_class = std::none_of(result.begin(), result.end(), [&](const Point& f) {
      return lookup.solve({e[0] - f[0], e[1] - f[1]}).has_value();
    });
    if (new_class) result.push_back(e);
  }
  return result;
}

// 1/mu, or 0 when M is not a similarity.
double critical_value(const LatticeRule& rule) {
  const auto& M = rule.dilation;
  if (rule.dimension == 1) return 1.0 / std::abs(M[0][0]);
  const double tr = M[0][0] + M[1][1];
  const double det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
  const double disc = tr * tr - 4.0 * det;
  if (disc < 0.0) return 1.0 / std::sqrt(det);
  const double a = std::fabs((tr + std::sqrt(disc)) / 2.0), b = std::fabs((tr - std::sqrt(disc)) / 2.0);
  if (std::fabs(a - b) > 1e-12 * a) return 0.0;
  return 1.0 / a;
}

Family transition_family(const LatticeRule& rule) {
  Family family;
  const RuleLookup lookup(rule);
  family.critical = critical_value(rule);
  if (!(family.critical > 0.0)) {
    family.failure = "the dilation is not a similarity";
    return family;
  }
  const std::vector<Point> ds = digits(rule, lookup);

  // The window: the 1-neighbourhood of the origin, closed under the rules.
  std::set<Point> window;
  const int low_y = lookup.boundary() ? 0 : -1;
  for (int x = -1; x <= 1; ++x)
    for (int y = low_y; y <= 1; ++y)
      if (rule.dimension == 2 || y == 0) window.insert({x, y});
  for (bool grew = true; grew;) {
    grew = false;
    const std::vector<Point> current(window.begin(), window.end());
    for (const Point& k : current)
      for (const Point& e : ds) {
        const Point c{k[0] + e[0], k[1] + e[1]};
        for (const auto& [offset, w] : lookup.mask_of(c)) {
          const auto j = lookup.solve({c[0] - offset[0], c[1] - offset[1]});
          if (!j) continue;
          if (lookup.boundary() && (*j)[1] < 0) {
            family.failure = "the boundary rules read below the boundary";
            return family;
          }
          grew = window.insert(*j).second || grew;
        }
      }
    if (window.size() > kMaxWindow) {
      family.failure = fmt::format("the rules' window exceeds {} points", kMaxWindow);
      return family;
    }
  }
  const std::vector<Point> K(window.begin(), window.end());
  const auto n = static_cast<Eigen::Index>(K.size());
  family.window = static_cast<int>(n);

  // Linear functions on the window, and a basis of the quotient by them.
  const int d = rule.dimension;
  Eigen::MatrixXd U(n, d + 1);
  for (Eigen::Index i = 0; i < n; ++i) {
    U(i, 0) = 1.0;
    for (int a = 0; a < d; ++a) U(i, a + 1) = K[static_cast<std::size_t>(i)][static_cast<std::size_t>(a)];
  }
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(U);
  const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd N = Q.rightCols(n - (d + 1));
  const Eigen::MatrixXd Urange = Q.leftCols(d + 1);
  for (const Point& e : ds) {
    Eigen::MatrixXd T(n, n);
    for (Eigen::Index r = 0; r < n; ++r)
      for (Eigen::Index c = 0; c < n; ++c) {
        const Point& kr = K[static_cast<std::size_t>(r)];
        T(r, c) = lookup.weight({kr[0] + e[0], kr[1] + e[1]}, K[static_cast<std::size_t>(c)]);
      }
    const double leak = (N.transpose() * T * Urange).cwiseAbs().maxCoeff();
    if (leak > 1e-9 * std::max(1.0, T.cwiseAbs().maxCoeff())) {
      family.failure = "the rules do not map linear data to linear data (the test needs linear precision)";
      return family;
    }
    family.matrices.push_back(N.transpose() * T * N);
  }
  return family;
}

// The spectral radius and norm of products of one size, with the solvers'
// workspaces kept from one product to the next: allocated afresh for each
// product (thousands of them, hundreds of KB each), they spent a third of
// the test's time in the kernel's page faults.
class SpectralRadius {
 public:
  explicit SpectralRadius(Eigen::Index n) : solver_(n) {}
  double operator()(const Eigen::MatrixXd& P) {
    if (P.size() == 0) return 0.0;
    solver_.compute(P, false);
    return solver_.eigenvalues().cwiseAbs().maxCoeff();
  }

 private:
  Eigen::EigenSolver<Eigen::MatrixXd> solver_;
};

class SpectralNorm {
 public:
  explicit SpectralNorm(Eigen::Index n) : gram_(n, n), solver_(n) {}
  double operator()(const Eigen::MatrixXd& P) {
    if (P.size() == 0) return 0.0;
    gram_.noalias() = P.transpose() * P;
    solver_.compute(gram_, Eigen::EigenvaluesOnly);
    return std::sqrt(std::max(solver_.eigenvalues().maxCoeff(), 0.0));
  }

 private:
  Eigen::MatrixXd gram_;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver_;
};

// Calls visit(word, product) for every word of length 1 .. max_length, the
// product applying the word's first letter first. One product per length is
// kept, each written over the last one of its length.
template <class Visit>
void for_each_product(const std::vector<Eigen::MatrixXd>& family, int max_length, Visit&& visit) {
  std::vector<int> word;
  std::vector<Eigen::MatrixXd> prefix(static_cast<std::size_t>(std::max(max_length, 0)));
  const auto recurse = [&](auto&& self) -> void {
    const std::size_t depth = word.size();
    if (static_cast<int>(depth) == max_length) return;
    for (std::size_t e = 0; e < family.size(); ++e) {
      word.push_back(static_cast<int>(e));
      if (depth == 0)
        prefix[0] = family[e];
      else
        prefix[depth].noalias() = family[e] * prefix[depth - 1];
      visit(word, prefix[depth]);
      self(self);
      word.pop_back();
    }
  };
  recurse(recurse);
}

// A word counted once among its rotations, and not a power of a shorter one.
bool primitive_necklace(const std::vector<int>& w) {
  const std::size_t n = w.size();
  for (std::size_t s = 1; s < n; ++s) {
    for (std::size_t i = 0; i < n; ++i) {
      const int a = w[(i + s) % n], b = w[i];
      if (a < b) return false;  // a smaller rotation
      if (a > b) break;
      if (i + 1 == n) return false;  // equal rotation: a power
    }
  }
  return true;
}

}  // namespace

RegularSmoothness regular_smoothness(const LatticeRule& rule, const RegularSmoothnessOptions& options) {
  RegularSmoothness result;
  const Family family = transition_family(rule);
  result.critical = family.critical;
  result.window = family.window;
  result.digits = static_cast<int>(family.matrices.size());
  if (!family.failure.empty()) {
    result.reason = "regular rules: " + family.failure;
    return result;
  }
  const int digits = result.digits;
  int length = 1;
  for (long long count = digits; count * digits <= options.products_per_length; count *= digits) ++length;

  // Lower bound: spectral radii of primitive products.
  const auto n = family.matrices.front().rows();
  SpectralRadius spectral_radius(n);
  for_each_product(family.matrices, length, [&](const std::vector<int>& word, const Eigen::MatrixXd& P) {
    if (!primitive_necklace(word)) return;
    const double r = std::pow(spectral_radius(P), 1.0 / static_cast<double>(word.size()));
    if (r > result.lower) {
      result.lower = r;
      result.lower_length = static_cast<int>(word.size());
    }
  });

  // Upper bound: norms of products in the norm of X = sum P^T P / s^(2|w|).
  const double s = std::max(result.lower, 1e-3 * result.critical);
  Eigen::MatrixXd X = Eigen::MatrixXd::Identity(n, n);
  for_each_product(family.matrices, (length + 1) / 2, [&](const std::vector<int>& word, const Eigen::MatrixXd& P) {
    X += P.transpose() * P / std::pow(s, 2.0 * static_cast<double>(word.size()));
  });
  const Eigen::LLT<Eigen::MatrixXd> llt(X);
  const Eigen::MatrixXd R = llt.matrixU();
  const Eigen::MatrixXd R_inverse = R.inverse();
  std::vector<Eigen::MatrixXd> fitted;
  for (const Eigen::MatrixXd& T : family.matrices) fitted.push_back(R * T * R_inverse);
  std::vector<double> largest(static_cast<std::size_t>(length) + 1, 0.0);
  SpectralNorm spectral_norm(n);
  for_each_product(fitted, length, [&](const std::vector<int>& word, const Eigen::MatrixXd& P) {
    double& m = largest[word.size()];
    m = std::max(m, spectral_norm(P));
  });
  result.upper = 1e300;
  for (int L = 1; L <= length; ++L) {
    const double bound = std::pow(largest[static_cast<std::size_t>(L)], 1.0 / L);
    if (bound < result.upper) {
      result.upper = bound;
      result.upper_length = L;
    }
  }
  result.upper = std::max(result.upper, result.lower);

  const double c = result.critical;
  const std::string bracket = fmt::format("{:.4f} <= rho <= {:.4f}", result.lower, result.upper);
  if (result.upper < c * (1.0 - options.margin)) {
    result.verdict = SmoothnessVerdict::c1;
    result.reason = fmt::format("regular rules C1: the joint spectral radius of their second differences is "
                                "below 1/mu = {:.4f} ({}; norms of products of length {})",
                                c, bracket, result.upper_length);
  } else if (result.lower >= c * (1.0 - options.margin)) {
    result.verdict = SmoothnessVerdict::not_c1;
    result.reason = fmt::format("regular rules not C1: on second differences a product of {} transition matrices "
                                "has spectral radius r^{} with r = {:.4f}, not below 1/mu = {:.4f}",
                                result.lower_length, result.lower_length, result.lower, c);
  } else {
    result.reason = fmt::format("regular rules undecided: {} brackets 1/mu = {:.4f} (products up to length {})",
                                bracket, c, length);
  }
  return result;
}

namespace {

std::string rule_key(const LatticeRule& rule) {
  std::string key = fmt::format("{} {} {} {} {};", rule.dimension, rule.dilation[0][0], rule.dilation[0][1],
                                rule.dilation[1][0], rule.dilation[1][1]);
  const auto add = [&](const std::vector<LatticeWeight>& mask) {
    for (const LatticeWeight& w : mask) key += fmt::format("{},{}:{:.17g} ", w.offset[0], w.offset[1], w.weight);
    key += ';';
  };
  add(rule.mask);
  for (const auto& row : rule.boundary_rows) add(row);
  return key;
}

RegularSmoothness remembered(const LatticeRule& rule) {
  static std::mutex mutex;
  static std::map<std::string, RegularSmoothness> results;
  const std::string key = rule_key(rule);
  {
    const std::lock_guard lock(mutex);
    if (const auto it = results.find(key); it != results.end()) return it->second;
  }
  RegularSmoothness result = regular_smoothness(rule);
  const std::lock_guard lock(mutex);
  return results.emplace(key, std::move(result)).first->second;
}

RegularSmoothness unreadable(const std::string& message) {
  RegularSmoothness r;
  r.reason = "regular rules not read: " + message;
  return r;
}

}  // namespace

RegularSmoothness regular_smoothness_of(const Scheme& scheme, const RefineOptions& rules, bool boundary) {
  RegularSmoothness interior;
  try {
    interior = remembered(regular_interior_rule(scheme, rules));
  } catch (const Error& e) {
    interior = unreadable(e.what());
  }
  if (!boundary) return interior;
  RegularSmoothness edge;
  try {
    edge = remembered(regular_boundary_rule(scheme, rules));
  } catch (const Error& e) {
    edge = unreadable(e.what());
  }
  RegularSmoothness both = interior;
  both.reason = "interior " + interior.reason + "; boundary " + edge.reason;
  if (interior.verdict == SmoothnessVerdict::not_c1 || edge.verdict == SmoothnessVerdict::not_c1)
    both.verdict = SmoothnessVerdict::not_c1;
  else if (interior.verdict == SmoothnessVerdict::c1 && edge.verdict == SmoothnessVerdict::c1)
    both.verdict = SmoothnessVerdict::c1;
  else
    both.verdict = SmoothnessVerdict::inconclusive;
  return both;
}

}  // namespace subdiv
