#pragma once
/// \file
/// A scheme's behaviour at one configuration, everything the survey's
/// section 5 asks (Zorin, "Subdivision on arbitrary meshes", 2.1-2.2, 5.3):
/// the local subdivision matrix read off the real rules, its spectrum, the
/// limit and tangent masks, Reif's eigenvalue condition, the characteristic
/// map's regularity and injectivity, the C1 verdict, and the curvature
/// behaviour of Proposition 6.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "subdiv/analysis/characteristic_map.h"
#include "subdiv/analysis/regular_smoothness.h"
#include "subdiv/analysis/spectrum.h"
#include "subdiv/refine/subdivision_matrix.h"
#include "subdiv/analysis/verdict.h"
#include "subdiv/refine/refine.h"

namespace subdiv {


/// Proposition 6 (for lambda = lambda_1 = lambda_2): compare lambda^2 with
/// the largest other eigenvalue magnitude mu.
enum class CurvatureBehaviour {
  zero,       ///< mu < lambda^2: C2 possible, with zero curvature at the point
  bounded,    ///< mu = lambda^2: bounded; C2 only if the lambda^2 eigenfunctions are quadratic
  unbounded,  ///< mu > lambda^2: curvature diverges for generic data, not C2
  not_applicable,  ///< lambda_1 != lambda_2, or no valid subdominant pair
};
/// The behaviour's name as the CLI prints it ("zero curvature", ...).
/// \param behaviour The curvature behaviour.
/// \return A static, null-terminated string: "-" for not_applicable, "?" for
///         a value outside the enum.
const char* to_string(CurvatureBehaviour behaviour) noexcept;

/// Everything analyze() finds at one configuration: the local subdivision
/// matrices, the spectrum, the masks, Reif's criterion and the verdict.
struct ConfigurationAnalysis {
  /// The smallest invariant neighbourhood: its matrix gives the masks.
  LocalSubdivisionMatrix matrix;
  /// One ring wider: its spectrum and eigenvectors give the verdicts and the
  /// characteristic map (the limit surface around the centre depends on it).
  LocalSubdivisionMatrix wide_matrix;
  Spectrum spectrum;  ///< of wide_matrix
  /// The leading eigenvalues lambda_0 .. lambda_3 (with multiplicity).
  std::vector<std::complex<double>> leading;
  /// The limit-position mask: the left eigenvector of eigenvalue 1 on
  /// `matrix`'s neighbourhood, summing to 1. nullopt when it does not exist,
  /// the neighbourhood is not invariant, or AnalysisOptions::masks is false.
  std::optional<Eigen::VectorXd> limit_mask;
  /// The two tangent masks on `matrix`'s neighbourhood (left eigenvectors of
  /// the subdominant pair, see subdiv::tangent_masks()). nullopt when the pair
  /// is complex or missing, the neighbourhood is not invariant, or
  /// AnalysisOptions::masks is false.
  std::optional<std::array<Eigen::VectorXd, 2>> tangent_masks;
  /// Reif's eigenvalue condition: lambda_0 = 1 simple > lambda_1 >= lambda_2
  /// > |lambda_3|, lambda_1 and lambda_2 real and positive, non-defective.
  bool eigenvalue_condition = false;
  /// The characteristic map of `wide_matrix`'s subdominant eigenvectors;
  /// nullopt when the eigenvalue condition fails, the eigenvectors have no
  /// real basis, or AnalysisOptions::characteristic_map is false.
  std::optional<CharacteristicMap> characteristic_map;
  /// The smoothness of the scheme's regular rules (interior, and at boundary
  /// and corner configurations the straight boundary's too): Reif's
  /// criterion at the configuration presumes them C1.
  RegularSmoothness regular;
  /// C1 when Reif's criterion holds at the configuration and the regular
  /// rules are C1; not C1 when the regular rules are not.
  SmoothnessVerdict verdict = SmoothnessVerdict::inconclusive;
  std::string reason;  ///< what the verdict rests on: the configuration's part and the regular rules'
  std::string configuration_reason;  ///< the configuration's part alone (Reif's criterion)
  /// Proposition 6's curvature behaviour; not_applicable unless the
  /// eigenvalue condition holds.
  CurvatureBehaviour curvature = CurvatureBehaviour::not_applicable;
};

/// What analyze() computes and how.
struct AnalysisOptions {
  /// Clustering and rank tolerance of the spectral computations (see
  /// spectrum()); must lie in (0, 0.1).
  double tolerance = 1e-9;
  int max_rings = 4;           ///< largest neighbourhood tried for invariance
  /// Analysis steps the characteristic map is refined (its `levels`).
  int characteristic_levels = 3;
  bool characteristic_map = true;  ///< false: spectrum and masks only (faster)
  /// false: no limit or tangent masks either (the depth bound's rates need
  /// the spectrum alone).
  bool masks = true;
  /// false: the regular rules' verdict (`regular`) is not computed, and a C1
  /// verdict at the configuration is reported inconclusive. For callers that
  /// read the spectrum or the masks alone: the regular rules' test can take
  /// seconds the first time a rule is met.
  bool regular_rules = true;
  /// Interior configurations whose mask matrix (`matrix`) has at least this
  /// many rows find the tangent masks' subdominant pair through
  /// spectrum_by_rotation, as the spectrum of `wide_matrix` always is: the
  /// dense eigensolver and its clustering take minutes at valence 360. The
  /// masks agree to rounding (tests/analysis/rotation_route_test.cpp); smaller
  /// matrices keep the dense route, and with it their masks bit for bit.
  int rotation_rows = 128;
  /// The rules the configuration is refined with (boundary rules, flatness).
  RefineOptions rules;
};

/// Analyses \p scheme at \p configuration: reads the local subdivision
/// matrices off the scheme's own refinement of the configuration's ring
/// mesh, computes the spectrum, the masks and Reif's criterion, and combines
/// them with the regular rules' verdict (regular_smoothness_of(), remembered
/// per rule). Without an invariant neighbourhood within
/// `options.max_rings` rings the result carries only `matrix` and a reason.
/// \param scheme The scheme whose rules are analysed.
/// \param configuration The vertex configuration (interior, boundary or
///        corner, valence k).
/// \param options Tolerance, neighbourhood size, what to compute, and the
///        refinement rules.
/// \return The analysis; `verdict` and `reason` summarise it.
/// \throws InvalidInputError if the ring layout does not cover the scheme or
///         configuration, the scheme's period is below 1, refinement rejects
///         the ring mesh or the scheme's parameters, or `options.tolerance`
///         is not in (0, 0.1).
/// \throws Error if the Schur iteration of an eigenvalue computation does not
///         converge.
/// \throws std::bad_alloc if memory runs out.
ConfigurationAnalysis analyze(const Scheme& scheme, const Configuration& configuration,
                              const AnalysisOptions& options = {});

}  // namespace subdiv
