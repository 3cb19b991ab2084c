#include "subdiv/analysis/spectrum.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <set>
#include <string>

#include "subdiv/core/error.h"

namespace subdiv {
namespace {

using Complex = std::complex<double>;

void check_tolerance(double tolerance, const char* function) {
  if (!(tolerance > 0.0 && tolerance < 0.1))
    throw InvalidInputError(std::string(function) + ": tolerance " + std::to_string(tolerance) + " is not in (0, 0.1)");
}

void check_matrix(const Eigen::MatrixXd& S, const char* function) {
  if (S.rows() != S.cols())
    throw InvalidInputError(std::string(function) + ": the matrix is " + std::to_string(S.rows()) + " x " +
                            std::to_string(S.cols()) + ", not square");
  for (Eigen::Index c = 0; c < S.cols(); ++c)
    for (Eigen::Index r = 0; r < S.rows(); ++r)
      if (!std::isfinite(S(r, c)))
        throw InvalidInputError(std::string(function) + ": entry (" + std::to_string(r) + ", " + std::to_string(c) +
                                ") is not finite");
}

// Two computed values are one when they differ by the tolerance relative to
// their size (an absolute floor of 1 so that values near 0 cluster too).
bool within(Complex a, Complex b, double tolerance) {
  return std::abs(a - b) <= tolerance * std::max({1.0, std::abs(a), std::abs(b)});
}

// |a| > |b| beyond the tolerance: the gap the subdominant conditions need.
bool larger(double a, double b, double tolerance) { return a - b > tolerance * std::max(1.0, a); }

// One diagonal block of S in some basis: real where the transform keeps it
// real (the dense path, Fourier frequencies 0 and k / 2).
struct Block {
  bool real = true;
  Eigen::MatrixXd re;
  Eigen::MatrixXcd cx;
  Eigen::Index size() const { return real ? re.rows() : cx.rows(); }
};

// Numerical rank deficiency from a column-pivoted QR (rank revealing): the
// pivots |R_ii| at or below tolerance * max(1, |R_00|). QR rather than SVD:
// forty times faster at n = 200, and Eigen 3.4's BDCSVD fails an index
// assertion on some subdivision matrices.
template <typename Matrix>
int nullity_of(const Matrix& a, double tolerance) {
  if (a.rows() == 0) return 0;
  const Eigen::ColPivHouseholderQR<Matrix> qr(a);
  const Eigen::VectorXd pivots = qr.matrixQR().diagonal().cwiseAbs();
  const double threshold = tolerance * std::max(1.0, pivots.maxCoeff());
  return static_cast<int>((pivots.array() <= threshold).count());
}

// dim null(B - mu I).
int nullity(const Block& block, Complex mu, double tolerance) {
  const Eigen::Index n = block.size();
  if (block.real && mu.imag() == 0.0)
    return nullity_of<Eigen::MatrixXd>(block.re - mu.real() * Eigen::MatrixXd::Identity(n, n), tolerance);
  Eigen::MatrixXcd a = block.real ? Eigen::MatrixXcd(block.re.cast<Complex>()) : block.cx;
  a.diagonal().array() -= mu;
  return nullity_of<Eigen::MatrixXcd>(a, tolerance);
}

// Orthonormal basis of the null space of a^* (the orthogonal complement of
// a's range): the trailing columns of Q in a P = Q R. With a = S - lambda I
// these are the left eigenvectors; with a = (S - lambda I)^* the right ones.
template <typename Matrix>
Matrix cokernel(const Matrix& a, double tolerance) {
  const Eigen::Index n = a.rows();
  const Eigen::ColPivHouseholderQR<Matrix> qr(a);
  const Eigen::VectorXd pivots = qr.matrixQR().diagonal().cwiseAbs();
  const double threshold = tolerance * std::max(1.0, n > 0 ? pivots.maxCoeff() : 0.0);
  const Eigen::Index d = (pivots.array() <= threshold).count();
  const Matrix q = qr.householderQ();
  return q.rightCols(d);
}

double infinity_norm(const Block& block) {
  if (block.size() == 0) return 0.0;
  return block.real ? block.re.cwiseAbs().rowwise().sum().maxCoeff() : block.cx.cwiseAbs().rowwise().sum().maxCoeff();
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(static_cast<std::size_t>(n)) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
      i = parent[static_cast<std::size_t>(i)];
    }
    return i;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
};

// An eigenvalue of one block with its multiplicities, before the blocks are
// merged. `conjugate` indexes the piece holding the conjugate value (itself
// when real); -1 when not tracked (complex blocks, until mirrored).
struct Piece {
  Complex value;
  int algebraic = 1;
  int geometric = 1;
  int block = 0;
  std::vector<int> frequencies;
  int conjugate = -1;
};

// The eigenvalues of a block from its Schur form. For a real block the real
// Schur form gives exact conjugate pairs; conjugate[i] records them.
void schur_eigenvalues(const Block& block, std::vector<Complex>& values, std::vector<int>& conjugate) {
  const Eigen::Index n = block.size();
  values.assign(static_cast<std::size_t>(n), Complex{});
  conjugate.assign(static_cast<std::size_t>(n), -1);
  if (block.real) {
    // EigenSolver without eigenvectors is the real Schur form read block by block.
    const Eigen::EigenSolver<Eigen::MatrixXd> solver(block.re, false);
    if (solver.info() != Eigen::Success) throw Error("spectrum: the real Schur iteration did not converge");
    for (Eigen::Index i = 0; i < n; ++i) values[static_cast<std::size_t>(i)] = solver.eigenvalues()(i);
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (conjugate[i] >= 0) continue;
      if (values[i].imag() == 0.0) {
        conjugate[i] = static_cast<int>(i);
        continue;
      }
      for (std::size_t j = i + 1; j < values.size(); ++j)
        if (conjugate[j] < 0 && values[j] == std::conj(values[i])) {
          conjugate[i] = static_cast<int>(j);
          conjugate[j] = static_cast<int>(i);
          break;
        }
    }
  } else {
    const Eigen::ComplexSchur<Eigen::MatrixXcd> schur(block.cx, false);
    if (schur.info() != Eigen::Success) throw Error("spectrum: the complex Schur iteration did not converge");
    for (Eigen::Index i = 0; i < n; ++i) values[static_cast<std::size_t>(i)] = schur.matrixT()(i, i);
  }
}

// The distinct eigenvalues of one block: computed copies clustered, then the
// geometric multiplicities as the nullity of B - mu I.
std::vector<Piece> block_pieces(const Block& block, double tolerance, int block_id) {
  std::vector<Complex> values;
  std::vector<int> conjugate;
  schur_eigenvalues(block, values, conjugate);
  const int n = static_cast<int>(values.size());
  UnionFind clusters(n);
  auto unite = [&](int a, int b) {
    clusters.unite(a, b);
    // Keep the clustering closed under conjugation (real blocks).
    const int ca = conjugate[static_cast<std::size_t>(a)];
    const int cb = conjugate[static_cast<std::size_t>(b)];
    if (ca >= 0 && cb >= 0) clusters.unite(ca, cb);
  };
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (within(values[static_cast<std::size_t>(i)], values[static_cast<std::size_t>(j)], tolerance)) unite(i, j);

  struct Cluster {
    int root = 0;
    Complex sum;
    std::vector<int> members;
    int count() const { return static_cast<int>(members.size()); }
    Complex mean() const { return sum / static_cast<double>(members.size()); }
  };
  auto gather = [&] {
    std::vector<Cluster> out;
    std::vector<int> slot(static_cast<std::size_t>(n), -1);
    for (int i = 0; i < n; ++i) {
      const int r = clusters.find(i);
      if (slot[static_cast<std::size_t>(r)] < 0) {
        slot[static_cast<std::size_t>(r)] = static_cast<int>(out.size());
        out.push_back({r, Complex{}, {}});
      }
      Cluster& c = out[static_cast<std::size_t>(slot[static_cast<std::size_t>(r)])];
      c.members.push_back(i);
      c.sum += values[static_cast<std::size_t>(i)];
    }
    return out;
  };

  // A Jordan block of size m is split by a perturbation eta into m values
  // about eta^(1/m) from it (Lidskii), around a mean that stays accurate.
  // So clusters further apart than the tolerance still join into a group
  // when (1) the group's values lie within that radius of their mean mu,
  // with eta = tolerance * max(1, |B|_inf) and m the group's multiplicity
  // capped at 4 (roundoff is far below the tolerance, so this also covers
  // somewhat larger blocks), (2) the group holds every computed value in the
  // smallest disc around mu that holds the group (else mu may land on a
  // third eigenvalue; several Jordan blocks of one eigenvalue interleave, so
  // the group grows until it is closed), and (3) B - mu I is numerically
  // singular.
  constexpr int kMaxJordanExponent = 4;
  const double perturbation = tolerance * std::max(1.0, infinity_norm(block));
  auto radius = [&](int m, Complex mu) {
    return std::pow(perturbation, 1.0 / std::min(m, kMaxJordanExponent)) * std::max(1.0, std::abs(mu));
  };
  // Tries the group grown from `seed`; true when it was merged.
  auto try_group = [&](const std::vector<Cluster>& all, std::vector<char> in) {
    Complex mu;
    for (;;) {
      Complex sum{};
      int count = 0;
      for (std::size_t o = 0; o < all.size(); ++o)
        if (in[o]) {
          sum += all[o].sum;
          count += all[o].count();
        }
      mu = sum / static_cast<double>(count);
      double spread = 0.0;
      for (std::size_t o = 0; o < all.size(); ++o)
        if (in[o])
          for (const int i : all[o].members)
            spread = std::max(spread, std::abs(values[static_cast<std::size_t>(i)] - mu));
      if (spread > radius(count, mu)) return false;
      bool grew = false;
      for (std::size_t o = 0; o < all.size(); ++o)
        if (!in[o])
          for (const int i : all[o].members)
            if (std::abs(values[static_cast<std::size_t>(i)] - mu) <= spread) {
              in[o] = 1;
              grew = true;
              break;
            }
      if (!grew) break;
    }
    // A real block's group around a real eigenvalue is closed under
    // conjugation: its mean is real up to roundoff.
    if (block.real && std::abs(mu.imag()) <= 0.5 * tolerance * std::max(1.0, std::abs(mu))) mu = mu.real();
    if (nullity(block, mu, tolerance) == 0) return false;
    std::size_t first = all.size();
    for (std::size_t o = 0; o < all.size(); ++o)
      if (in[o]) {
        if (first == all.size()) first = o;
        unite(all[first].root, all[o].root);
      }
    return true;
  };
  auto key_of = [](const std::vector<Cluster>& all, const std::vector<char>& in) {
    std::vector<int> key;
    for (std::size_t o = 0; o < all.size(); ++o)
      if (in[o]) {
        key.push_back(all[o].root);
        key.push_back(all[o].count());
      }
    return key;
  };
  std::set<std::vector<int>> rejected;
  for (bool merged = true; merged;) {
    merged = false;
    const std::vector<Cluster> all = gather();
    struct Candidate {
      double distance;
      std::size_t a, b;
    };
    std::vector<Candidate> candidates;
    UnionFind linked(static_cast<int>(all.size()));
    for (std::size_t a = 0; a < all.size(); ++a)
      for (std::size_t b = a + 1; b < all.size(); ++b) {
        const Complex ma = all[a].mean(), mb = all[b].mean();
        const double distance = std::abs(ma - mb);
        if (distance > radius(all[a].count() + all[b].count(), std::abs(ma) > std::abs(mb) ? ma : mb)) continue;
        candidates.push_back({distance, a, b});
        linked.unite(static_cast<int>(a), static_cast<int>(b));
      }
    // Seeds: first each connected set of candidates as a whole (a cloud of
    // split Jordan blocks joins in one step), then the pairs, closest first.
    std::vector<std::vector<char>> components(all.size());
    for (const Candidate& c : candidates) {
      std::vector<char>& comp = components[static_cast<std::size_t>(linked.find(static_cast<int>(c.a)))];
      if (comp.empty()) comp.assign(all.size(), 0);
      comp[c.a] = comp[c.b] = 1;
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
      return x.distance != y.distance ? x.distance < y.distance : (x.a != y.a ? x.a < y.a : x.b < y.b);
    });
    auto attempt = [&](const std::vector<char>& seed) {
      std::vector<int> key = key_of(all, seed);
      if (rejected.count(key)) return false;
      if (try_group(all, seed)) return true;
      rejected.insert(std::move(key));
      return false;
    };
    for (const std::vector<char>& comp : components)
      if (std::count(comp.begin(), comp.end(), 1) > 2 && attempt(comp)) {
        merged = true;
        break;
      }
    for (std::size_t c = 0; c < candidates.size() && !merged; ++c) {
      std::vector<char> pair(all.size(), 0);
      pair[candidates[c].a] = pair[candidates[c].b] = 1;
      merged = attempt(pair);
    }
  }

  // One piece per cluster. A real block's cluster is either closed under
  // conjugation (a real eigenvalue, made exactly real) or has a partner
  // cluster, whose value is made the exact conjugate.
  const std::vector<Cluster> all = gather();
  std::vector<int> piece_of(static_cast<std::size_t>(n), -1);
  for (std::size_t p = 0; p < all.size(); ++p) piece_of[static_cast<std::size_t>(all[p].root)] = static_cast<int>(p);
  std::vector<Piece> pieces(all.size());
  for (std::size_t p = 0; p < all.size(); ++p) {
    Piece& piece = pieces[p];
    piece.block = block_id;
    piece.algebraic = all[p].count();
    piece.value = all[p].mean();
    const int c = conjugate[static_cast<std::size_t>(all[p].root)];
    if (c >= 0) {
      piece.conjugate = piece_of[static_cast<std::size_t>(clusters.find(c))];
      if (piece.conjugate == static_cast<int>(p)) piece.value = Complex(piece.value.real(), 0.0);
    }
  }
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    Piece& piece = pieces[p];
    const int c = piece.conjugate;
    // The partner with negative imaginary part copies the other's numbers.
    const bool copy =
        c >= 0 && c != static_cast<int>(p) &&
        (piece.value.imag() < pieces[static_cast<std::size_t>(c)].value.imag() ||
         (piece.value.imag() == pieces[static_cast<std::size_t>(c)].value.imag() && c < static_cast<int>(p)));
    if (copy) continue;
    if (piece.algebraic > 1) {
      // 1 <= geometric <= algebraic holds exactly; the clamp guards the
      // thresholds against nearby eigenvalues of other clusters.
      piece.geometric = std::clamp(nullity(block, piece.value, tolerance), 1, piece.algebraic);
    }
  }
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    Piece& piece = pieces[p];
    const int c = piece.conjugate;
    if (c < 0 || c == static_cast<int>(p)) continue;
    const Piece& other = pieces[static_cast<std::size_t>(c)];
    const bool copy = piece.value.imag() < other.value.imag() ||
                      (piece.value.imag() == other.value.imag() && c < static_cast<int>(p));
    if (!copy) continue;
    piece.value = std::conj(other.value);
    piece.geometric = other.geometric;
    piece.algebraic = other.algebraic;
  }
  return pieces;
}

// Orders by decreasing magnitude; equal magnitudes (within the tolerance,
// chained) list reals first by decreasing value, then complex values by
// increasing |argument|, positive imaginary part first.
void sort_values(std::vector<Eigenvalue>& values, double tolerance) {
  auto fine_less = [](const Eigenvalue& x, const Eigenvalue& y) {
    if (x.real() != y.real()) return x.real();
    if (x.real()) return x.value.real() > y.value.real();
    const double ax = std::abs(std::arg(x.value)), ay = std::abs(std::arg(y.value));
    if (ax != ay) return ax < ay;
    const double mx = std::abs(x.value), my = std::abs(y.value);
    if (mx != my) return mx > my;
    if (x.value.imag() != y.value.imag()) return x.value.imag() > y.value.imag();
    return x.value.real() > y.value.real();
  };
  std::sort(values.begin(), values.end(), [&](const Eigenvalue& x, const Eigenvalue& y) {
    const double mx = std::abs(x.value), my = std::abs(y.value);
    return mx != my ? mx > my : fine_less(x, y);
  });
  std::vector<int> group(values.size(), 0);
  for (std::size_t i = 1; i < values.size(); ++i) {
    const double previous = std::abs(values[i - 1].value), current = std::abs(values[i].value);
    group[i] = group[i - 1] + (larger(previous, current, tolerance) ? 1 : 0);
  }
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return group[a] != group[b] ? group[a] < group[b] : fine_less(values[a], values[b]);
  });
  std::vector<Eigenvalue> sorted;
  sorted.reserve(values.size());
  for (const std::size_t i : order) sorted.push_back(std::move(values[i]));
  values = std::move(sorted);
}

// Pieces from different blocks that hold the same eigenvalue join; being
// eigenvalues of independent blocks, their multiplicities add.
Spectrum merge_pieces(const std::vector<Piece>& pieces, double tolerance) {
  const int n = static_cast<int>(pieces.size());
  UnionFind groups(n);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const Piece& a = pieces[static_cast<std::size_t>(i)];
      const Piece& b = pieces[static_cast<std::size_t>(j)];
      if (a.block != b.block && within(a.value, b.value, tolerance)) groups.unite(i, j);
    }
  std::vector<int> slot(static_cast<std::size_t>(n), -1);
  std::vector<int> root_of_slot;
  Spectrum result;
  std::vector<Complex> sums;
  for (int i = 0; i < n; ++i) {
    const int r = groups.find(i);
    if (slot[static_cast<std::size_t>(r)] < 0) {
      slot[static_cast<std::size_t>(r)] = static_cast<int>(result.values.size());
      root_of_slot.push_back(r);
      result.values.push_back({Complex{}, 0, 0, {}});
      sums.emplace_back();
    }
    const std::size_t s = static_cast<std::size_t>(slot[static_cast<std::size_t>(r)]);
    const Piece& p = pieces[static_cast<std::size_t>(i)];
    Eigenvalue& e = result.values[s];
    e.algebraic += p.algebraic;
    e.geometric += p.geometric;
    e.frequencies.insert(e.frequencies.end(), p.frequencies.begin(), p.frequencies.end());
    sums[s] += p.value * static_cast<double>(p.algebraic);
  }
  // Conjugation maps groups to groups (the pieces are closed under it): a
  // group that is its own conjugate is real, the others pair up exactly.
  std::vector<int> conjugate_slot(result.values.size(), -1);
  for (std::size_t s = 0; s < result.values.size(); ++s) {
    Eigenvalue& e = result.values[s];
    e.value = sums[s] / static_cast<double>(e.algebraic);
    std::sort(e.frequencies.begin(), e.frequencies.end());
    const int c = pieces[static_cast<std::size_t>(root_of_slot[s])].conjugate;
    if (c >= 0) conjugate_slot[s] = slot[static_cast<std::size_t>(groups.find(c))];
    if (conjugate_slot[s] == static_cast<int>(s)) e.value = Complex(e.value.real(), 0.0);
  }
  for (std::size_t s = 0; s < result.values.size(); ++s) {
    const int c = conjugate_slot[s];
    if (c < 0 || c == static_cast<int>(s)) continue;
    const Eigenvalue& other = result.values[static_cast<std::size_t>(c)];
    Eigenvalue& e = result.values[s];
    if (e.value.imag() < other.value.imag() || (e.value.imag() == other.value.imag() && c < static_cast<int>(s)))
      e.value = std::conj(other.value);
  }
  sort_values(result.values, tolerance);
  return result;
}

// Makes the first entry above half the largest magnitude positive: a sign
// fixed by the data, not by the solver.
void orient(Eigen::VectorXd& v) {
  const double top = v.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (std::abs(v(i)) > 0.5 * top) {
      if (v(i) < 0.0) v = -v;
      return;
    }
}

// Left and right null spaces of S - lambda I (orthonormal columns).
struct NullSpaces {
  Eigen::MatrixXd left;
  Eigen::MatrixXd right;
};

NullSpaces null_spaces(const Eigen::MatrixXd& S, double lambda, double tolerance) {
  const Eigen::MatrixXd a = S - lambda * Eigen::MatrixXd::Identity(S.rows(), S.cols());
  return {cokernel<Eigen::MatrixXd>(a, tolerance), cokernel<Eigen::MatrixXd>(a.transpose(), tolerance)};
}

// A unit vector of a one-dimensional space, signed by orient().
std::optional<Eigen::VectorXd> single(const Eigen::MatrixXd& basis) {
  if (basis.cols() != 1) return std::nullopt;
  Eigen::VectorXd v = basis.col(0).normalized();
  orient(v);
  return v;
}

// The orthonormal basis of a two-dimensional space that depends on the
// space only: l_1 is the projection of e_a, a the first coordinate of
// largest weight; l_2 completes it, signed by orient(). On a k-fold
// symmetric ring whose space holds (cos, sin) patterns, the projection of
// e_a is cos(theta_i - theta_a): the survey's pair.
std::array<Eigen::VectorXd, 2> canonical_pair(const Eigen::MatrixXd& q, double tolerance) {
  const Eigen::VectorXd weight = q.rowwise().squaredNorm();
  const double top = weight.maxCoeff();
  Eigen::Index a = 0;
  while (weight(a) < top * (1.0 - tolerance)) ++a;
  const Eigen::Vector2d c1 = q.row(a).transpose().normalized();
  const Eigen::Vector2d c2(-c1(1), c1(0));
  Eigen::VectorXd l2 = q * c2;
  orient(l2);
  return {q * c1, l2};
}

struct Selection {
  enum class Kind { distinct_real, double_real, complex_pair };
  Kind kind = Kind::distinct_real;
  Complex lambda1, lambda2;
};

// lambda_0 = 1 simple > |lambda_1| >= |lambda_2| > |lambda_3|, with a real
// pair having a two-dimensional eigenspace or a simple complex pair.
std::optional<Selection> select_subdominant(const Spectrum& s, double tolerance) {
  const std::vector<Eigenvalue>& v = s.values;
  if (v.size() < 2 || v[0].algebraic != 1 || !within(v[0].value, 1.0, tolerance)) return std::nullopt;
  if (!larger(1.0, std::abs(v[1].value), tolerance)) return std::nullopt;
  // Everything after the pair must be strictly smaller in magnitude.
  auto gap_after = [&](std::size_t last) {
    return last + 1 >= v.size() || larger(std::abs(v[last].value), std::abs(v[last + 1].value), tolerance);
  };
  const Eigenvalue& e1 = v[1];
  if (!e1.real()) {
    if (e1.algebraic != 1 || v.size() < 3 || v[2].algebraic != 1 || v[2].value != std::conj(e1.value) || !gap_after(2))
      return std::nullopt;
    return Selection{Selection::Kind::complex_pair, e1.value, v[2].value};
  }
  if (e1.algebraic == 2) {
    if (e1.geometric != 2 || !gap_after(1)) return std::nullopt;
    return Selection{Selection::Kind::double_real, e1.value, e1.value};
  }
  if (e1.algebraic != 1 || v.size() < 3) return std::nullopt;
  const Eigenvalue& e2 = v[2];
  if (!e2.real() || e2.algebraic != 1 || !gap_after(2)) return std::nullopt;
  return Selection{Selection::Kind::distinct_real, e1.value, e2.value};
}

void check_spectrum_size(const Eigen::MatrixXd& S, const Spectrum& s, const char* function) {
  if (s.dimension() != S.rows())
    throw InvalidInputError(std::string(function) + ": the spectrum has dimension " + std::to_string(s.dimension()) +
                            ", the matrix " + std::to_string(S.rows()));
}

// Real pair: the eigenvectors (left or right) of the selected eigenvalues.
std::optional<std::array<Eigen::VectorXd, 2>> real_pair(const Eigen::MatrixXd& S, const Selection& sel, bool left,
                                                        double tolerance) {
  if (sel.kind == Selection::Kind::double_real) {
    const NullSpaces ns = null_spaces(S, sel.lambda1.real(), tolerance);
    const Eigen::MatrixXd& q = left ? ns.left : ns.right;
    if (q.cols() != 2) return std::nullopt;
    return canonical_pair(q, tolerance);
  }
  const NullSpaces n1 = null_spaces(S, sel.lambda1.real(), tolerance);
  const NullSpaces n2 = null_spaces(S, sel.lambda2.real(), tolerance);
  std::optional<Eigen::VectorXd> v1 = single(left ? n1.left : n1.right);
  std::optional<Eigen::VectorXd> v2 = single(left ? n2.left : n2.right);
  if (!v1 || !v2) return std::nullopt;
  return std::array<Eigen::VectorXd, 2>{std::move(*v1), std::move(*v2)};
}

}  // namespace

bool Spectrum::defective() const noexcept {
  return std::any_of(values.begin(), values.end(), [](const Eigenvalue& e) { return e.defective(); });
}

int Spectrum::dimension() const noexcept {
  int n = 0;
  for (const Eigenvalue& e : values) n += e.algebraic;
  return n;
}

std::vector<std::complex<double>> Spectrum::expanded() const {
  std::vector<std::complex<double>> out;
  for (const Eigenvalue& e : values) out.insert(out.end(), static_cast<std::size_t>(e.algebraic), e.value);
  return out;
}

Spectrum spectrum(const Eigen::MatrixXd& S, double tolerance) {
  check_matrix(S, "spectrum");
  check_tolerance(tolerance, "spectrum");
  if (S.rows() == 0) return {};
  Block block;
  block.re = S;
  // One block: merge_pieces only sorts.
  return merge_pieces(block_pieces(block, tolerance, 0), tolerance);
}

Spectrum spectrum_by_rotation(const Eigen::MatrixXd& S, const RotationalStructure& rotation, double tolerance) {
  constexpr const char* kName = "spectrum_by_rotation";
  check_matrix(S, kName);
  check_tolerance(tolerance, kName);
  const int n = static_cast<int>(S.rows());
  const int k = rotation.k;
  if (k < 1) throw InvalidInputError(std::string(kName) + ": k = " + std::to_string(k) + " is not positive");
  if (rotation.rotate.size() != static_cast<std::size_t>(n))
    throw InvalidInputError(std::string(kName) + ": rotate has " + std::to_string(rotation.rotate.size()) +
                            " entries for a " + std::to_string(n) + " x " + std::to_string(n) + " matrix");
  std::vector<char> hit(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    const int r = rotation.rotate[static_cast<std::size_t>(i)];
    if (r < 0 || r >= n)
      throw InvalidInputError(std::string(kName) + ": rotate[" + std::to_string(i) + "] = " + std::to_string(r) +
                              " is outside 0 .. " + std::to_string(n - 1));
    if (hit[static_cast<std::size_t>(r)])
      throw InvalidInputError(std::string(kName) + ": rotate is not a permutation (vertex " + std::to_string(r) +
                              " is the image of two vertices)");
    hit[static_cast<std::size_t>(r)] = 1;
  }
  auto rot = [&](int i) { return rotation.rotate[static_cast<std::size_t>(i)]; };

  // Orbits, each listed from its smallest vertex r as r, rot(r), rot^2(r)...
  std::vector<std::vector<int>> orbits;
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    if (seen[static_cast<std::size_t>(i)]) continue;
    std::vector<int> orbit;
    for (int v = i; !seen[static_cast<std::size_t>(v)]; v = rot(v)) {
      seen[static_cast<std::size_t>(v)] = 1;
      orbit.push_back(v);
    }
    if (k % static_cast<int>(orbit.size()) != 0)
      throw InvalidInputError(std::string(kName) + ": vertex " + std::to_string(i) + " lies on an orbit of " +
                              std::to_string(orbit.size()) +
                              " vertices, which does not divide k = " + std::to_string(k));
    orbits.push_back(std::move(orbit));
  }

  // S P = P S, entry by entry: rotating both ends of a weight keeps it.
  const double commute_tolerance = tolerance * std::max(1.0, S.cwiseAbs().maxCoeff());
  for (int l = 0; l < n; ++l)
    for (int i = 0; i < n; ++i)
      if (std::abs(S(rot(i), rot(l)) - S(i, l)) > commute_tolerance)
        throw InvalidInputError(std::string(kName) + ": the matrix does not commute with the rotation: S(" +
                                std::to_string(i) + ", " + std::to_string(l) + ") = " + std::to_string(S(i, l)) +
                                " but S(" + std::to_string(rot(i)) + ", " + std::to_string(rot(l)) +
                                ") = " + std::to_string(S(rot(i), rot(l))));

  // Frequency j: on an orbit of d vertices the unit vector u[rot^m r] =
  // w^(-j m) / sqrt(d), w = exp(2 pi i / k), satisfies P u = w^j u, and exists
  // when j d = 0 mod k. These vectors form a unitary basis U in which U* S U
  // is block diagonal; with S(rot^m x, rot^m y) = S(x, y) the entry of block
  // j for orbits o, o' reduces to
  //   sqrt(d_o / d_o') sum_t w^(-j t) S(r_o, rot^t r_o').
  // Blocks j and k - j are conjugate (S is real), so only j <= k / 2 are
  // computed; j = 0 and j = k / 2 are real.
  std::vector<Piece> pieces;
  for (int j = 0; 2 * j <= k; ++j) {
    std::vector<std::size_t> members;
    for (std::size_t o = 0; o < orbits.size(); ++o)
      if ((static_cast<long long>(j) * static_cast<long long>(orbits[o].size())) % k == 0) members.push_back(o);
    if (members.empty()) continue;
    const Eigen::Index b = static_cast<Eigen::Index>(members.size());
    Block block;
    block.real = (j == 0 || 2 * j == k);
    if (block.real)
      block.re.setZero(b, b);
    else
      block.cx.setZero(b, b);
    for (Eigen::Index x = 0; x < b; ++x)
      for (Eigen::Index y = 0; y < b; ++y) {
        const std::vector<int>& ox = orbits[members[static_cast<std::size_t>(x)]];
        const std::vector<int>& oy = orbits[members[static_cast<std::size_t>(y)]];
        const double scale = std::sqrt(static_cast<double>(ox.size()) / static_cast<double>(oy.size()));
        Complex sum{};
        for (std::size_t t = 0; t < oy.size(); ++t) {
          // Reduce j t mod k first: exact phases for large k.
          const long long phase = (static_cast<long long>(j) * static_cast<long long>(t)) % k;
          const double angle = -2.0 * std::numbers::pi * static_cast<double>(phase) / static_cast<double>(k);
          const double weight = S(ox.front(), oy[t]);
          sum += block.real ? Complex(phase == 0 ? weight : -weight) : weight * std::polar(1.0, angle);
        }
        if (block.real)
          block.re(x, y) = scale * sum.real();
        else
          block.cx(x, y) = scale * sum;
      }
    const int offset = static_cast<int>(pieces.size());
    std::vector<Piece> own = block_pieces(block, tolerance, j);
    for (Piece& p : own) {
      p.frequencies.assign(static_cast<std::size_t>(p.algebraic), j);
      if (p.conjugate >= 0) p.conjugate += offset;
    }
    if (block.real) {
      pieces.insert(pieces.end(), own.begin(), own.end());
      continue;
    }
    // Block k - j: the conjugate values, each the conjugate partner of its
    // source.
    const int count = static_cast<int>(own.size());
    for (int p = 0; p < count; ++p) {
      Piece mirror = own[static_cast<std::size_t>(p)];
      mirror.value = std::conj(mirror.value);
      mirror.block = k - j;
      mirror.frequencies.assign(static_cast<std::size_t>(mirror.algebraic), k - j);
      mirror.conjugate = offset + p;
      own[static_cast<std::size_t>(p)].conjugate = offset + count + p;
      own.push_back(std::move(mirror));
    }
    pieces.insert(pieces.end(), own.begin(), own.end());
  }
  return merge_pieces(pieces, tolerance);
}

std::optional<Eigen::VectorXd> left_eigenvector(const Eigen::MatrixXd& S, double lambda, double tolerance) {
  check_matrix(S, "left_eigenvector");
  check_tolerance(tolerance, "left_eigenvector");
  if (!std::isfinite(lambda)) throw InvalidInputError("left_eigenvector: lambda is not finite");
  if (S.rows() == 0) return std::nullopt;
  const NullSpaces ns = null_spaces(S, lambda, tolerance);
  if (ns.left.cols() != 1) return std::nullopt;
  if (within(lambda, 1.0, tolerance)) {
    // The limit-position mask: affine invariance makes the weights sum to 1.
    const double sum = ns.left.col(0).sum();
    if (std::abs(sum) <= tolerance * ns.left.col(0).cwiseAbs().sum()) return std::nullopt;
    return Eigen::VectorXd(ns.left.col(0) / sum);
  }
  return single(ns.left);
}

std::optional<SubdominantPair> subdominant_eigenvectors(const Eigen::MatrixXd& S, const Spectrum& spectrum,
                                                        double tolerance) {
  check_matrix(S, "subdominant_eigenvectors");
  check_tolerance(tolerance, "subdominant_eigenvectors");
  check_spectrum_size(S, spectrum, "subdominant_eigenvectors");
  const std::optional<Selection> sel = select_subdominant(spectrum, tolerance);
  if (!sel) return std::nullopt;
  SubdominantPair out;
  out.lambda1 = sel->lambda1;
  out.lambda2 = sel->lambda2;
  if (sel->kind != Selection::Kind::complex_pair) {
    std::optional<std::array<Eigen::VectorXd, 2>> pair = real_pair(S, *sel, false, tolerance);
    if (!pair) return std::nullopt;
    out.vectors = std::move(*pair);
    return out;
  }
  out.complex_pair = true;
  Eigen::MatrixXcd a = S.cast<Complex>();
  a.diagonal().array() -= sel->lambda1;
  const Eigen::MatrixXcd right = cokernel<Eigen::MatrixXcd>(a.adjoint(), tolerance);
  if (right.cols() != 1) return std::nullopt;
  Eigen::VectorXcd v = right.col(0).normalized();
  // Phase: the first entry of largest modulus real and positive.
  const double top = v.cwiseAbs().maxCoeff();
  Eigen::Index i = 0;
  while (std::abs(v(i)) < top * (1.0 - tolerance)) ++i;
  v *= std::conj(v(i)) / std::abs(v(i));
  out.vectors = {v.real(), v.imag()};
  return out;
}

std::optional<SubdominantPair> subdominant_eigenvectors(const Eigen::MatrixXd& S, double tolerance) {
  return subdominant_eigenvectors(S, spectrum(S, tolerance), tolerance);
}

std::optional<std::array<Eigen::VectorXd, 2>> tangent_masks(const Eigen::MatrixXd& S, const Spectrum& spectrum,
                                                            double tolerance) {
  check_matrix(S, "tangent_masks");
  check_tolerance(tolerance, "tangent_masks");
  check_spectrum_size(S, spectrum, "tangent_masks");
  const std::optional<Selection> sel = select_subdominant(spectrum, tolerance);
  if (!sel || sel->kind == Selection::Kind::complex_pair) return std::nullopt;
  return real_pair(S, *sel, true, tolerance);
}

std::optional<std::array<Eigen::VectorXd, 2>> tangent_masks(const Eigen::MatrixXd& S, double tolerance) {
  return tangent_masks(S, spectrum(S, tolerance), tolerance);
}

}  // namespace subdiv
