#pragma once
/// \file
/// Spectral analysis of a local subdivision matrix S (p_next = S p), after
/// Zorin's survey, sections 2.1-2.2 ("Subdivision matrices", "Limit positions
/// and tangent vectors") and 5.3: eigenvalues with algebraic and geometric
/// multiplicities (an eigenbasis is never assumed), the limit-position and
/// tangent masks (left eigenvectors) and the subdominant right eigenvectors
/// (control points of the characteristic map).
///
/// Eigenvalues come from a Schur form. Computed copies of one eigenvalue are
/// clustered: copies within `tolerance * max(1, |lambda|)` of each other join;
/// groups further apart, up to (tolerance * max(1, |S|))^(1/m) from their
/// mean mu for a joint multiplicity m (capped at 4; roundoff splits a Jordan
/// block of size m that far), join when no other computed eigenvalue lies as
/// close to mu and S - mu I is numerically singular. So a nearly defective
/// matrix (two eigenvalues closer than about sqrt(tolerance) with nearly
/// parallel eigenvectors) is reported as defective: at that tolerance it is.
/// Ranks and null spaces come from a column-pivoted QR: pivots at or below
/// `tolerance * max(1, largest pivot)` count as zero. `tolerance` must lie in
/// (0, 0.1).

#include <Eigen/Core>
#include <array>
#include <complex>
#include <optional>
#include <vector>

namespace subdiv {

/// One distinct eigenvalue. A real eigenvalue has value.imag() == 0 exactly;
/// a complex one is listed next to its conjugate (exactly conjugate values).
struct Eigenvalue {
  std::complex<double> value;  ///< the eigenvalue (the mean of its clustered copies)
  /// Multiplicity as a root of the characteristic polynomial.
  int algebraic = 1;
  /// Dimension of the null space of S - value I (1 <= geometric <= algebraic).
  int geometric = 1;
  /// From spectrum_by_rotation: the Fourier frequency j (0 .. k-1) of each
  /// copy, ascending, one entry per unit of `algebraic`. Empty otherwise.
  std::vector<int> frequencies;

  /// Whether the eigenvalue is real.
  /// \return value.imag() == 0.
  bool real() const noexcept { return value.imag() == 0.0; }
  /// A Jordan block: fewer eigenvectors than copies.
  /// \return geometric < algebraic.
  bool defective() const noexcept { return geometric < algebraic; }
};

/// The spectrum of S: distinct eigenvalues by decreasing magnitude. Equal
/// magnitudes (within the tolerance) list real values first, larger real
/// part first, then complex values by increasing |argument|, the one with
/// positive imaginary part before its conjugate.
struct Spectrum {
  std::vector<Eigenvalue> values;  ///< the distinct eigenvalues, in the order described above

  /// Some eigenvalue has a Jordan block: S has no eigenbasis.
  /// \return Whether any value is defective().
  bool defective() const noexcept;
  /// The matrix size: the sum of the algebraic multiplicities.
  /// \return The sum of `algebraic` over `values`.
  int dimension() const noexcept;
  /// lambda_0, lambda_1, ...: each value repeated `algebraic` times.
  /// \return dimension() values, by decreasing magnitude.
  /// \throws std::bad_alloc if memory runs out.
  std::vector<std::complex<double>> expanded() const;
};

/// The spectrum of a square, finite matrix (dense path: real Schur form).
/// \param S The matrix (p_next = S p); 0 x 0 gives an empty spectrum.
/// \param tolerance The relative tolerance, in (0, 0.1): computed copies of
///        one eigenvalue within `tolerance * max(1, |lambda|)` join (and
///        further apart under the Jordan-block test), and rank pivots at or
///        below `tolerance * max(1, largest pivot)` count as zero.
/// \return The distinct eigenvalues with their multiplicities.
/// \throws InvalidInputError if \p S is not square or has a non-finite entry,
///         or \p tolerance is not in (0, 0.1).
/// \throws Error if the Schur iteration does not converge.
/// \throws std::bad_alloc if memory runs out.
Spectrum spectrum(const Eigen::MatrixXd& S, double tolerance = 1e-9);

/// Rotation of a k-sector neighbourhood: vertex i goes to rotate[i] (the
/// same vertex in the next sector); the centre is fixed. rotate must be a
/// permutation whose k-th power is the identity.
struct RotationalStructure {
  int k = 1;                ///< the number of sectors (the rotation's order), at least 1
  std::vector<int> rotate;  ///< per vertex (row of S): its image under the rotation
};

/// The spectrum of S computed per Fourier frequency: the discrete Fourier
/// transform over each orbit of the rotation makes S block diagonal with k
/// blocks of about n / k rows (an orbit of d vertices contributes to the
/// frequencies that are multiples of k / d; fixed points only to 0). Each
/// eigenvalue is tagged with its frequencies. Agrees with spectrum() and
/// stays fast and accurate at high valence.
/// \param S The square, finite matrix.
/// \param rotation The rotation S commutes with.
/// \param tolerance The clustering and rank tolerance, in (0, 0.1); also
///        the commutation test's relative tolerance.
/// \return The spectrum, each eigenvalue with its `frequencies`.
/// \throws InvalidInputError if \p S is not square or has a non-finite entry,
///         \p tolerance is not in (0, 0.1), the structure is malformed (k < 1,
///         `rotate` not a permutation of S's rows, an orbit whose length does
///         not divide k), or S does not commute with the rotation
///         (|S(rotate[i], rotate[l]) - S(i, l)| > tolerance * max(1, max |S|)).
/// \throws Error if a Schur iteration does not converge.
/// \throws std::bad_alloc if memory runs out.
Spectrum spectrum_by_rotation(const Eigen::MatrixXd& S, const RotationalStructure& rotation, double tolerance = 1e-9);

/// The left eigenvector l (l^T S = lambda l^T) of a real eigenvalue whose
/// left eigenspace is one-dimensional; nullopt when lambda is not an
/// eigenvalue or has more than one eigenvector. For lambda = 1 (within the
/// tolerance) l is normalised to sum 1: the limit-position mask (a_0 = l.p);
/// nullopt if its entries sum to 0.
/// Otherwise |l| = 1 and the first entry above half the largest magnitude is
/// positive.
/// \param S The square, finite matrix.
/// \param lambda The real eigenvalue.
/// \param tolerance The rank tolerance, in (0, 0.1).
/// \return l, or nullopt as described.
/// \throws InvalidInputError if \p S is not square or has a non-finite entry,
///         \p lambda is not finite, or \p tolerance is not in (0, 0.1).
/// \throws std::bad_alloc if memory runs out.
std::optional<Eigen::VectorXd> left_eigenvector(const Eigen::MatrixXd& S, double lambda, double tolerance = 1e-9);

/// The subdominant eigenvalues lambda_1, lambda_2 (the two after lambda_0)
/// and a real basis of their eigenspace. Exists when lambda_0 = 1 is simple
/// and 1 > |lambda_1| >= |lambda_2| > |lambda_3| (section 5.3), with either
/// real lambda_1, lambda_2 whose eigenspace has dimension 2, or a simple
/// complex pair lambda_2 = conj(lambda_1).
struct SubdominantPair {
  std::complex<double> lambda1;  ///< lambda_1
  std::complex<double> lambda2;  ///< lambda_2
  /// lambda_2 = conj(lambda_1), Im lambda_1 > 0.
  bool complex_pair = false;
  /// Real pair: two eigenvectors (for lambda_1 = lambda_2 an orthonormal
  /// basis of the eigenspace, see tangent_masks). Complex pair: the real and
  /// imaginary parts of the unit eigenvector of lambda_1 whose first entry of
  /// largest modulus is real and positive (cos / sin patterns on a symmetric
  /// ring).
  std::array<Eigen::VectorXd, 2> vectors;
};

/// Right eigenvectors of the subdominant pair, e.g. the control points of
/// the characteristic map. nullopt when the conditions of SubdominantPair fail. This
/// overload takes the spectrum of \p S (e.g. from spectrum_by_rotation) and
/// skips the dense eigenvalue computation.
/// \param S The square, finite matrix.
/// \param spectrum The spectrum of \p S, computed with the same tolerance.
/// \param tolerance The clustering and rank tolerance, in (0, 0.1).
/// \return The pair and a real basis of its eigenspace, or nullopt.
/// \throws InvalidInputError if \p S is not square or has a non-finite entry,
///         \p tolerance is not in (0, 0.1), or the spectrum's dimension is
///         not the matrix size.
/// \throws std::bad_alloc if memory runs out.
std::optional<SubdominantPair> subdominant_eigenvectors(const Eigen::MatrixXd& S, const Spectrum& spectrum,
                                                        double tolerance = 1e-9);
/// Right eigenvectors of the subdominant pair, as above, with the spectrum
/// computed by spectrum().
/// \param S The square, finite matrix.
/// \param tolerance The clustering and rank tolerance, in (0, 0.1).
/// \return The pair and a real basis of its eigenspace, or nullopt.
/// \throws InvalidInputError if \p S is not square or has a non-finite entry,
///         or \p tolerance is not in (0, 0.1).
/// \throws Error if the Schur iteration does not converge.
/// \throws std::bad_alloc if memory runs out.
std::optional<SubdominantPair> subdominant_eigenvectors(const Eigen::MatrixXd& S, double tolerance = 1e-9);

/// The tangent masks: left eigenvectors l_1, l_2 of the subdominant pair
/// when it is real (tangents a_i = l_i.p); nullopt otherwise (conditions as
/// for SubdominantPair). Normalisation: |l_i| = 1. Distinct lambda_1,
/// lambda_2: signs as in left_eigenvector. lambda_1 = lambda_2: the
/// orthonormal basis of the two-dimensional left eigenspace whose l_1 is the
/// eigenspace's projection of e_a, a the first vertex of largest weight
/// (largest projection), and l_2 the orthogonal vector signed as in
/// left_eigenvector; on a rotationally symmetric ring this is the
/// (cos 2 pi j / k, sin 2 pi j / k) pair of the survey (section 2.2), up to
/// scale. This overload takes the spectrum of \p S.
/// \param S The square, finite matrix.
/// \param spectrum The spectrum of \p S, computed with the same tolerance.
/// \param tolerance The clustering and rank tolerance, in (0, 0.1).
/// \return l_1 and l_2, or nullopt.
/// \throws InvalidInputError if \p S is not square or has a non-finite entry,
///         \p tolerance is not in (0, 0.1), or the spectrum's dimension is
///         not the matrix size.
/// \throws std::bad_alloc if memory runs out.
std::optional<std::array<Eigen::VectorXd, 2>> tangent_masks(const Eigen::MatrixXd& S, const Spectrum& spectrum,
                                                            double tolerance = 1e-9);
/// The tangent masks, as above, with the spectrum computed by spectrum().
/// \param S The square, finite matrix.
/// \param tolerance The clustering and rank tolerance, in (0, 0.1).
/// \return l_1 and l_2, or nullopt.
/// \throws InvalidInputError if \p S is not square or has a non-finite entry,
///         or \p tolerance is not in (0, 0.1).
/// \throws Error if the Schur iteration does not converge.
/// \throws std::bad_alloc if memory runs out.
std::optional<std::array<Eigen::VectorXd, 2>> tangent_masks(const Eigen::MatrixXd& S, double tolerance = 1e-9);

}  // namespace subdiv
