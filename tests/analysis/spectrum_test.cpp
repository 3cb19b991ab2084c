// Spectra of local subdivision matrices: the survey's worked examples
// (Zorin, sections 2.1 and 2.2), Jordan blocks, complex pairs, and the
// Fourier path against the dense one.

#include "subdiv/analysis/spectrum.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <random>

#include "subdiv/core/error.h"

namespace subdiv {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;

// Cubic B-spline curve, five points around p_i (survey, section 2.1).
Eigen::MatrixXd bspline_matrix() {
  Eigen::MatrixXd S(5, 5);
  S << 1, 6, 1, 0, 0,  //
      0, 4, 4, 0, 0,   //
      0, 1, 6, 1, 0,   //
      0, 0, 4, 4, 0,   //
      0, 0, 1, 6, 1;
  return S / 8.0;
}

// V J V^-1 for a fixed, well-conditioned V: the structure of J is no longer
// visible in the entries, so the solver sees a generic dense matrix.
Eigen::MatrixXd disguise(const Eigen::MatrixXd& J) {
  const Eigen::Index n = J.rows();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  Eigen::MatrixXd V = 2.0 * Eigen::MatrixXd::Identity(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) V(i, j) += u(rng);
  return V * J * V.inverse();
}

// A neighbourhood with k-fold rotational structure: a centre and `fixed`
// other fixed points first, then `layers` full orbits of k vertices (vertex
// s of a layer goes to s + 1), then one orbit for each size in `short_orbits`.
RotationalStructure make_rotation(int k, int fixed, int layers, const std::vector<int>& short_orbits = {}) {
  RotationalStructure r;
  r.k = k;
  for (int i = 0; i < fixed; ++i) r.rotate.push_back(i);
  std::vector<int> sizes(static_cast<std::size_t>(layers), k);
  sizes.insert(sizes.end(), short_orbits.begin(), short_orbits.end());
  for (const int d : sizes) {
    const int base = static_cast<int>(r.rotate.size());
    for (int s = 0; s < d; ++s) r.rotate.push_back(base + (s + 1) % d);
  }
  return r;
}

// A random matrix commuting with the rotation: one random weight per orbit
// of vertex pairs (i, l) -> (rot i, rot l), so S(rot i, rot l) = S(i, l)
// holds exactly.
Eigen::MatrixXd random_commuting(const RotationalStructure& r, unsigned seed, double diagonal = 0.0) {
  const int n = static_cast<int>(r.rotate.size());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd S = Eigen::MatrixXd::Constant(n, n, std::nan(""));
  for (int i = 0; i < n; ++i)
    for (int l = 0; l < n; ++l) {
      if (!std::isnan(S(i, l))) continue;
      const double w = u(rng) + (i == l ? diagonal : 0.0);
      for (int a = i, b = l, t = 0; t < r.k;
           ++t, a = r.rotate[static_cast<std::size_t>(a)], b = r.rotate[static_cast<std::size_t>(b)])
        S(a, b) = w;
    }
  return S;
}

// Loop's vertex rule on the one-ring (centre, then k neighbours in order),
// built here from the survey's weights (section 3.2) with Loop's beta.
double one_ring_beta(int k) {
  const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * kPi / k);
  return (5.0 / 8.0 - c * c) / k;
}

Eigen::MatrixXd loop_one_ring(int k) {
  const double beta = one_ring_beta(k);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(k + 1, k + 1);
  S(0, 0) = 1.0 - k * beta;
  for (int i = 1; i <= k; ++i) {
    S(0, i) = beta;
    S(i, 0) = 3.0 / 8.0;
    S(i, i) = 3.0 / 8.0;
    S(i, 1 + (i % k)) += 1.0 / 8.0;
    S(i, 1 + ((i + k - 2) % k)) += 1.0 / 8.0;
  }
  return S;
}

void expect_same_spectrum(const Spectrum& a, const Spectrum& b, double tolerance) {
  ASSERT_EQ(a.values.size(), b.values.size());
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    EXPECT_LE(std::abs(a.values[i].value - b.values[i].value), tolerance)
        << "eigenvalue " << i << ": " << a.values[i].value << " vs " << b.values[i].value;
    EXPECT_EQ(a.values[i].algebraic, b.values[i].algebraic) << "eigenvalue " << i;
    EXPECT_EQ(a.values[i].geometric, b.values[i].geometric) << "eigenvalue " << i;
    EXPECT_EQ(a.values[i].real(), b.values[i].real()) << "eigenvalue " << i;
  }
}

// Ordering contract: magnitudes non-increasing, conjugates adjacent with the
// positive imaginary part first, multiplicities consistent.
void expect_well_formed(const Spectrum& s, Eigen::Index n) {
  EXPECT_EQ(s.dimension(), n);
  for (std::size_t i = 0; i < s.values.size(); ++i) {
    const Eigenvalue& e = s.values[i];
    EXPECT_GE(e.geometric, 1);
    EXPECT_LE(e.geometric, e.algebraic);
    if (i > 0) {
      EXPECT_LE(std::abs(e.value), std::abs(s.values[i - 1].value) * (1 + 1e-9) + 1e-9);
    }
    if (!e.real() && e.value.imag() > 0) {
      ASSERT_LT(i + 1, s.values.size());
      EXPECT_EQ(s.values[i + 1].value, std::conj(e.value));
      EXPECT_EQ(s.values[i + 1].algebraic, e.algebraic);
    }
    if (!e.real() && e.value.imag() < 0) {
      ASSERT_GT(i, 0u);
      EXPECT_EQ(s.values[i - 1].value, std::conj(e.value));
    }
  }
}

TEST(Spectrum, CubicBSplineCurveMatrix) {
  const Eigen::MatrixXd S = bspline_matrix();
  const Spectrum s = spectrum(S);
  expect_well_formed(s, 5);
  // Survey: (1, 1/2, 1/4, 1/8, 1/8). By hand, 1/8 is not defective: columns
  // 0 and 4 of S are e_0 / 8 and e_4 / 8 (an outer point feeds only the
  // outer child), so e_0 and e_4 are two independent eigenvectors (the
  // survey's x_3, x_4): geometric multiplicity 2 = algebraic.
  const double expected[] = {1.0, 0.5, 0.25, 0.125};
  const int algebraic[] = {1, 1, 1, 2};
  ASSERT_EQ(s.values.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(s.values[i].real());
    EXPECT_NEAR(s.values[i].value.real(), expected[i], 1e-13);
    EXPECT_EQ(s.values[i].algebraic, algebraic[i]);
    EXPECT_EQ(s.values[i].geometric, algebraic[i]);
  }
  EXPECT_FALSE(s.defective());

  // Limit mask: [0, 1/6, 2/3, 1/6, 0] (survey), the point (p_{i-1} + 4 p_i + p_{i+1}) / 6.
  const std::optional<Eigen::VectorXd> limit = left_eigenvector(S, 1.0);
  ASSERT_TRUE(limit.has_value());
  const double mask[] = {0.0, 1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0, 0.0};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR((*limit)(i), mask[i], 1e-14);

  // Tangent mask: proportional to the survey's [0, -1, 0, 1, 0] (signed
  // here [0, 1, 0, -1, 0]: the first entry above half the largest is positive).
  const std::optional<Eigen::VectorXd> tangent = left_eigenvector(S, 0.5);
  ASSERT_TRUE(tangent.has_value());
  EXPECT_NEAR(tangent->norm(), 1.0, 1e-14);
  EXPECT_NEAR((*tangent)(0), 0.0, 1e-14);
  EXPECT_NEAR((*tangent)(2), 0.0, 1e-14);
  EXPECT_NEAR((*tangent)(4), 0.0, 1e-14);
  EXPECT_NEAR((*tangent)(1), std::sqrt(0.5), 1e-14);
  EXPECT_NEAR((*tangent)(3), -std::sqrt(0.5), 1e-14);
  EXPECT_LT((S.transpose() * *tangent - 0.5 * *tangent).norm(), 1e-14);

  // Two eigenvectors, or none: no single left eigenvector.
  EXPECT_FALSE(left_eigenvector(S, 0.125).has_value());
  EXPECT_FALSE(left_eigenvector(S, 0.3).has_value());

  // lambda_1 = 1/2 > lambda_2 = 1/4 > lambda_3 = 1/8: the second mask is
  // the second difference [0, 1, -2, 1, 0] (derived by hand from l S = l / 4),
  // signed so that its first entry above half the largest (the 2) is positive.
  const auto masks = tangent_masks(S);
  ASSERT_TRUE(masks.has_value());
  EXPECT_LT(((*masks)[0] - *tangent).norm(), 1e-14);
  Eigen::VectorXd second(5);
  second << 0, -1, 2, -1, 0;
  second.normalize();
  EXPECT_LT(((*masks)[1] - second).norm(), 1e-13);

  // The matrix commutes with the reflection i -> 4 - i (k = 2, centre
  // fixed): symmetric eigenvectors (frequency 0) give 1, 1/4, 1/8 and
  // antisymmetric ones (frequency 1) 1/2, 1/8.
  const Spectrum r = spectrum_by_rotation(S, {2, {4, 3, 2, 1, 0}});
  expect_same_spectrum(s, r, 1e-13);
  EXPECT_EQ(r.values[0].frequencies, std::vector<int>{0});
  EXPECT_EQ(r.values[1].frequencies, std::vector<int>{1});
  EXPECT_EQ(r.values[2].frequencies, std::vector<int>{0});
  EXPECT_EQ(r.values[3].frequencies, (std::vector<int>{0, 1}));
}

TEST(Spectrum, JordanBlocksAreDefective) {
  Eigen::MatrixXd J2(2, 2);
  J2 << 1, 1, 0, 1;
  const Spectrum s2 = spectrum(J2);
  ASSERT_EQ(s2.values.size(), 1u);
  EXPECT_EQ(s2.values[0].value, Complex(1.0, 0.0));
  EXPECT_EQ(s2.values[0].algebraic, 2);
  EXPECT_EQ(s2.values[0].geometric, 1);
  EXPECT_TRUE(s2.defective());

  // Disguised, the double eigenvalue comes out of the solver split by about
  // sqrt(roundoff) = 1e-8, far more than the tolerance; it must still be
  // recognised as one eigenvalue with one eigenvector.
  Eigen::MatrixXd J(3, 3);
  J << 0.5, 1, 0,  //
      0, 0.5, 0,   //
      0, 0, 0.25;
  const Spectrum s = spectrum(disguise(J));
  expect_well_formed(s, 3);
  ASSERT_EQ(s.values.size(), 2u);
  EXPECT_NEAR(std::abs(s.values[0].value - 0.5), 0.0, 1e-12);
  EXPECT_TRUE(s.values[0].real());
  EXPECT_EQ(s.values[0].algebraic, 2);
  EXPECT_EQ(s.values[0].geometric, 1);
  EXPECT_TRUE(s.values[0].defective());
  EXPECT_FALSE(s.values[1].defective());
  EXPECT_TRUE(s.defective());

  // A full 3 x 3 block: computed copies about 1e-5 apart.
  Eigen::MatrixXd J3(3, 3);
  J3 << 0.5, 1, 0,  //
      0, 0.5, 1,    //
      0, 0, 0.5;
  const Spectrum s3 = spectrum(disguise(J3));
  ASSERT_EQ(s3.values.size(), 1u);
  EXPECT_NEAR(std::abs(s3.values[0].value - 0.5), 0.0, 1e-12);
  EXPECT_EQ(s3.values[0].algebraic, 3);
  EXPECT_EQ(s3.values[0].geometric, 1);

  // Close but distinct eigenvalues (1e-3 apart) stay apart.
  Eigen::MatrixXd near(2, 2);
  near << 0.5, 1, 0, 0.501;
  const Spectrum sn = spectrum(disguise(near));
  ASSERT_EQ(sn.values.size(), 2u);
  EXPECT_FALSE(sn.defective());
  EXPECT_NEAR(sn.values[0].value.real(), 0.501, 1e-12);
}

TEST(Spectrum, RepeatedEigenvaluesWithAnEigenbasis) {
  const Spectrum id = spectrum(Eigen::MatrixXd::Identity(3, 3));
  ASSERT_EQ(id.values.size(), 1u);
  EXPECT_EQ(id.values[0].algebraic, 3);
  EXPECT_EQ(id.values[0].geometric, 3);
  EXPECT_FALSE(id.defective());

  const Eigen::Vector3d d(1.0, 0.5, 0.5);
  const Spectrum s = spectrum(disguise(d.asDiagonal().toDenseMatrix()));
  ASSERT_EQ(s.values.size(), 2u);
  EXPECT_NEAR(s.values[0].value.real(), 1.0, 1e-13);
  EXPECT_NEAR(s.values[1].value.real(), 0.5, 1e-13);
  EXPECT_EQ(s.values[1].algebraic, 2);
  EXPECT_EQ(s.values[1].geometric, 2);
  EXPECT_FALSE(s.defective());
  EXPECT_EQ(s.expanded().size(), 3u);
}

TEST(Spectrum, ComplexPairsSortNextToTheirConjugates) {
  // 0.9, then five values of magnitude 0.5: the reals 0.5 and -0.5, the pair
  // 0.3 +- 0.4i (|arg| 0.93) and the pair -0.3 +- 0.4i (|arg| 2.21).
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(7, 7);
  B(0, 0) = -0.5;
  B.block<2, 2>(1, 1) << -0.3, -0.4, 0.4, -0.3;
  B(3, 3) = 0.9;
  B.block<2, 2>(4, 4) << 0.3, -0.4, 0.4, 0.3;
  B(6, 6) = 0.5;
  const Spectrum s = spectrum(disguise(B));
  expect_well_formed(s, 7);
  const Complex expected[] = {{0.9, 0}, {0.5, 0}, {-0.5, 0}, {0.3, 0.4}, {0.3, -0.4}, {-0.3, 0.4}, {-0.3, -0.4}};
  ASSERT_EQ(s.values.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_LT(std::abs(s.values[i].value - expected[i]), 1e-13) << i << ": " << s.values[i].value;
    EXPECT_EQ(s.values[i].real(), expected[i].imag() == 0.0) << i;
  }
  EXPECT_EQ(s.values[4].value, std::conj(s.values[3].value));
  EXPECT_EQ(s.values[6].value, std::conj(s.values[5].value));
}

TEST(Spectrum, ComplexSubdominantPair) {
  // 1, 0.3 +- 0.4i, 0.2: the characteristic map's control points are the
  // real and imaginary parts of one eigenvector; there are no real tangent
  // masks.
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(4, 4);
  B(0, 0) = 1.0;
  B.block<2, 2>(1, 1) << 0.3, -0.4, 0.4, 0.3;
  B(3, 3) = 0.2;
  const Eigen::MatrixXd S = disguise(B);
  const auto pair = subdominant_eigenvectors(S);
  ASSERT_TRUE(pair.has_value());
  EXPECT_TRUE(pair->complex_pair);
  EXPECT_LT(std::abs(pair->lambda1 - Complex(0.3, 0.4)), 1e-13);
  EXPECT_EQ(pair->lambda2, std::conj(pair->lambda1));
  const Eigen::VectorXd& x = pair->vectors[0];
  const Eigen::VectorXd& y = pair->vectors[1];
  // S (x + i y) = (a + i b)(x + i y).
  EXPECT_LT((S * x - (0.3 * x - 0.4 * y)).norm(), 1e-12);
  EXPECT_LT((S * y - (0.4 * x + 0.3 * y)).norm(), 1e-12);
  EXPECT_NEAR(x.squaredNorm() + y.squaredNorm(), 1.0, 1e-12);
  EXPECT_FALSE(tangent_masks(S).has_value());
}

TEST(Spectrum, LoopOneRing) {
  for (const int k : {3, 4, 5, 6, 7, 8, 12, 64}) {
    SCOPED_TRACE("valence " + std::to_string(k));
    const Eigen::MatrixXd S = loop_one_ring(k);
    const double beta = one_ring_beta(k);
    // Frequency 0: the centre and the ring average give 1 and 5/8 - k beta;
    // frequency j: 3/8 + (1/4) cos(2 pi j / k) (survey, section 3.2).
    std::vector<double> expected{1.0, 5.0 / 8.0 - k * beta};
    for (int j = 1; j < k; ++j) expected.push_back(3.0 / 8.0 + 0.25 * std::cos(2.0 * kPi * j / k));
    std::sort(expected.begin(), expected.end(), std::greater<>());

    const Spectrum dense = spectrum(S);
    const RotationalStructure rotation = make_rotation(k, 1, 1);
    const Spectrum fourier = spectrum_by_rotation(S, rotation);
    expect_well_formed(dense, k + 1);
    expect_same_spectrum(dense, fourier, 1e-12);
    const std::vector<Complex> values = dense.expanded();
    ASSERT_EQ(values.size(), expected.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
      EXPECT_EQ(values[i].imag(), 0.0);
      EXPECT_NEAR(values[i].real(), expected[i], 1e-13);
    }
    EXPECT_FALSE(dense.defective());
    // lambda_1 = lambda_2 from frequencies 1 and k - 1, two eigenvectors.
    EXPECT_EQ(fourier.values[0].frequencies, std::vector<int>{0});
    EXPECT_EQ(fourier.values[1].frequencies, (std::vector<int>{1, k - 1}));
    EXPECT_EQ(dense.values[1].algebraic, 2);
    EXPECT_EQ(dense.values[1].geometric, 2);
    if (k == 6) {
      // 5/8 - 6 beta = (1/2)^2 = 1/4 coincides with frequencies 2 and 4.
      EXPECT_NEAR(dense.values[2].value.real(), 0.25, 1e-14);
      EXPECT_EQ(dense.values[2].algebraic, 3);
      EXPECT_EQ(dense.values[2].geometric, 3);
      EXPECT_EQ(fourier.values[2].frequencies, (std::vector<int>{0, 2, 4}));
    }

    // Limit mask: the vertex rule with beta_limit = 8 beta / (3 + 8 k beta)
    // (survey, section 2.2): centre 1 - k beta_limit = 3 / (3 + 8 k beta).
    const std::optional<Eigen::VectorXd> limit = left_eigenvector(S, 1.0);
    ASSERT_TRUE(limit.has_value());
    const double beta_limit = 8.0 * beta / (3.0 + 8.0 * k * beta);
    EXPECT_NEAR((*limit)(0), 1.0 - k * beta_limit, 1e-13);
    EXPECT_NEAR((*limit)(0), 3.0 / (3.0 + 8.0 * k * beta), 1e-13);
    for (int i = 1; i <= k; ++i) EXPECT_NEAR((*limit)(i), beta_limit, 1e-13);

    // Tangent masks: (cos, sin)(2 pi (i - 1) / k) on the ring, 0 at the
    // centre, with unit norm: scale sqrt(2 / k).
    const double lambda1 = 3.0 / 8.0 + 0.25 * std::cos(2.0 * kPi / k);
    const auto masks = tangent_masks(S, fourier);
    ASSERT_TRUE(masks.has_value());
    const auto right = subdominant_eigenvectors(S, fourier);
    ASSERT_TRUE(right.has_value());
    EXPECT_FALSE(right->complex_pair);
    EXPECT_NEAR(right->lambda1.real(), lambda1, 1e-13);
    const double scale = std::sqrt(2.0 / k);
    for (const auto& pair : {*masks, right->vectors}) {
      EXPECT_NEAR(pair[0](0), 0.0, 1e-13);
      EXPECT_NEAR(pair[1](0), 0.0, 1e-13);
      for (int i = 1; i <= k; ++i) {
        EXPECT_NEAR(pair[0](i), scale * std::cos(2.0 * kPi * (i - 1) / k), 1e-12) << "vertex " << i;
        EXPECT_NEAR(pair[1](i), scale * std::sin(2.0 * kPi * (i - 1) / k), 1e-12) << "vertex " << i;
      }
    }
    for (const Eigen::VectorXd& l : *masks) EXPECT_LT((S.transpose() * l - lambda1 * l).norm(), 1e-13);
  }
}

TEST(SpectrumByRotation, AgreesWithTheDenseSpectrum) {
  unsigned seed = 1;
  for (int k = 3; k <= 12; ++k)
    for (int layers = 1; layers <= 3; ++layers) {
      SCOPED_TRACE("k " + std::to_string(k) + ", layers " + std::to_string(layers));
      // Orbits shorter than k where k allows: on them only the frequencies
      // that are multiples of k / d live.
      std::vector<int> short_orbits;
      if (k % 2 == 0) short_orbits.push_back(2);
      if (k % 3 == 0) short_orbits.push_back(k / 3);
      const RotationalStructure rotation = make_rotation(k, 2, layers, short_orbits);
      const Eigen::MatrixXd S = random_commuting(rotation, seed++);
      const Spectrum dense = spectrum(S);
      const Spectrum fourier = spectrum_by_rotation(S, rotation);
      expect_well_formed(fourier, S.rows());
      expect_same_spectrum(dense, fourier, 1e-10);
      // Frequency j holds one eigenvalue per orbit whose size d has j d = 0 mod k.
      std::map<int, int> per_frequency;
      for (const Eigenvalue& e : fourier.values) {
        EXPECT_EQ(static_cast<int>(e.frequencies.size()), e.algebraic);
        for (const int j : e.frequencies) ++per_frequency[j];
      }
      for (int j = 0; j < k; ++j) {
        int orbits = layers + (j == 0 ? 2 : 0);
        for (const int d : short_orbits) orbits += (j * d) % k == 0 ? 1 : 0;
        EXPECT_EQ(per_frequency[j], orbits) << "frequency " << j;
      }
    }
}

TEST(SpectrumByRotation, FrequencyConvention) {
  // S = P itself ((P p)[rotate[i]] = p[i]): its eigenvalue on frequency j is
  // exp(2 pi i j / k), which pins down the sign convention of the tags.
  const int k = 7;
  const RotationalStructure rotation = make_rotation(k, 1, 1);
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(k + 1, k + 1);
  for (int i = 0; i <= k; ++i) P(rotation.rotate[static_cast<std::size_t>(i)], i) = 1.0;
  const Spectrum s = spectrum_by_rotation(P, rotation);
  expect_well_formed(s, k + 1);
  expect_same_spectrum(spectrum(P), s, 1e-12);
  ASSERT_EQ(s.values.size(), static_cast<std::size_t>(k));
  EXPECT_EQ(s.values[0].value, Complex(1.0, 0.0));
  EXPECT_EQ(s.values[0].frequencies, (std::vector<int>{0, 0}));
  for (std::size_t i = 1; i < s.values.size(); ++i) {
    ASSERT_EQ(s.values[i].frequencies.size(), 1u);
    const int j = s.values[i].frequencies[0];
    EXPECT_LT(std::abs(s.values[i].value - std::polar(1.0, 2.0 * kPi * j / k)), 1e-14) << "frequency " << j;
  }
  // Increasing |argument|, positive imaginary part first: frequencies 1, 6, 2, 5, 3, 4.
  EXPECT_EQ(s.values[1].frequencies[0], 1);
  EXPECT_EQ(s.values[2].frequencies[0], k - 1);
}

TEST(SpectrumByRotation, JordanBlocksInEveryFrequency) {
  // Centre, then two layers with S = a on both and the first layer coupled
  // 1:1 to the second: every frequency has the block [[a, 1], [0, a]], so a
  // has algebraic multiplicity 2k and geometric k. Conjugated by a random
  // invertible matrix that commutes with the rotation, to hide it.
  const int k = 5;
  const double a = 0.5;
  const RotationalStructure rotation = make_rotation(k, 1, 2);
  Eigen::MatrixXd S0 = Eigen::MatrixXd::Zero(2 * k + 1, 2 * k + 1);
  S0(0, 0) = 1.0;
  for (int s = 0; s < k; ++s) {
    S0(1 + s, 1 + s) = a;
    S0(1 + k + s, 1 + k + s) = a;
    S0(1 + s, 1 + k + s) = 1.0;
    S0(1 + s, 0) = 0.1;
    S0(1 + k + s, 0) = 0.2;
  }
  const Eigen::MatrixXd V = random_commuting(rotation, 99, 4.0);
  const Eigen::MatrixXd S = V * S0 * V.inverse();
  const Spectrum dense = spectrum(S);
  const Spectrum fourier = spectrum_by_rotation(S, rotation);
  for (const Spectrum* s : {&dense, &fourier}) {
    ASSERT_EQ(s->values.size(), 2u);
    EXPECT_NEAR(std::abs(s->values[1].value - a), 0.0, 1e-12);
    EXPECT_EQ(s->values[1].algebraic, 2 * k);
    EXPECT_EQ(s->values[1].geometric, k);
    EXPECT_TRUE(s->defective());
  }
}

TEST(SpectrumByRotation, RejectsMatricesAndStructuresThatDoNotFit) {
  const RotationalStructure rotation = make_rotation(4, 1, 2);
  Eigen::MatrixXd S = random_commuting(rotation, 3);
  EXPECT_NO_THROW(spectrum_by_rotation(S, rotation));
  S(2, 6) += 1e-3;
  EXPECT_THROW(spectrum_by_rotation(S, rotation), InvalidInputError);
  S(2, 6) -= 1e-3;

  RotationalStructure wrong = rotation;
  wrong.rotate.pop_back();  // size
  EXPECT_THROW(spectrum_by_rotation(S, wrong), InvalidInputError);
  wrong = rotation;
  wrong.rotate[1] = wrong.rotate[2];  // not a permutation
  EXPECT_THROW(spectrum_by_rotation(S, wrong), InvalidInputError);
  wrong = rotation;
  wrong.k = 3;  // orbits of 4 do not divide 3
  EXPECT_THROW(spectrum_by_rotation(S, wrong), InvalidInputError);
  wrong = rotation;
  wrong.k = 0;
  EXPECT_THROW(spectrum_by_rotation(S, wrong), InvalidInputError);
  wrong = rotation;
  wrong.rotate[0] = 9;  // out of range
  EXPECT_THROW(spectrum_by_rotation(S, wrong), InvalidInputError);

  EXPECT_THROW(spectrum(Eigen::MatrixXd::Zero(2, 3)), InvalidInputError);
  Eigen::MatrixXd bad = Eigen::MatrixXd::Identity(2, 2);
  bad(1, 0) = std::nan("");
  EXPECT_THROW(spectrum(bad), InvalidInputError);
  EXPECT_THROW(spectrum(Eigen::MatrixXd::Identity(2, 2), 0.0), InvalidInputError);
  EXPECT_THROW(left_eigenvector(bad, 1.0), InvalidInputError);
  EXPECT_TRUE(spectrum(Eigen::MatrixXd(0, 0)).values.empty());
}

TEST(SpectrumByRotation, HighValenceAboutTwoHundredRows) {
  // k = 64: two fixed points, three full layers, orbits of 4 and 2: 200 rows.
  const int k = 64;
  const RotationalStructure rotation = make_rotation(k, 2, 3, {4, 2});
  ASSERT_EQ(rotation.rotate.size(), 200u);
  const Eigen::MatrixXd S = random_commuting(rotation, 2024);
  const Spectrum fourier = spectrum_by_rotation(S, rotation);
  expect_well_formed(fourier, 200);
  const Spectrum dense = spectrum(S);
  expect_same_spectrum(dense, fourier, 1e-10);
}

}  // namespace
}  // namespace subdiv
