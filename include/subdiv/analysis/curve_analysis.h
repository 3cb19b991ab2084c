#pragma once
/// \file
/// Analysis of curve schemes (Zorin's survey, section 2.1, whose first
/// example is the cubic B-spline's 5 x 5 matrix): the local subdivision
/// matrix at a regular point, read off the scheme's own recorded stencils on
/// a closed polygon, its spectrum, the limit and tangent masks, and the C1
/// verdict. A curve is regular everywhere, so the verdict is the regular
/// rules' (regular_smoothness.h: the difference test); the point's own
/// conditions must agree with it: lambda_0 = 1 simple, a real simple lambda_1
/// in (0, 1) above every other magnitude, and a strictly monotone eigenvector
/// (the one-dimensional characteristic map is injective).

#include <Eigen/Core>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "subdiv/analysis/regular_smoothness.h"
#include "subdiv/analysis/spectrum.h"
#include "subdiv/analysis/verdict.h"
#include "subdiv/curves/curve_scheme.h"

namespace subdiv {

/// What analyze_curve() finds for a curve scheme: the local subdivision
/// matrices, the spectrum, the masks and the C1 verdict.
struct CurveAnalysis {
  /// The neighbourhood: 2m + 1 points centred on a point (primal schemes),
  /// or 2m points centred on an edge's midpoint (dual schemes), m the
  /// smallest half-width whose image one level down depends on it alone.
  /// Its matrix S gives the masks.
  int half_width = 0;
  /// The local subdivision matrix over the neighbourhood (p_next = S p),
  /// points in parameter order.
  Eigen::MatrixXd S;
  /// One point wider on either side (the survey's 5 x 5 for the cubic
  /// B-spline): the limit curve around the centre depends on these points,
  /// so the spectrum and the verdict are taken here, as for surfaces.
  Eigen::MatrixXd wide_S;
  Spectrum spectrum;  ///< of wide_S
  std::vector<std::complex<double>> leading;  ///< lambda_0 .. lambda_3 with multiplicity
  /// The left eigenvector of S for eigenvalue 1, summing to 1: the limit
  /// point's mask. nullopt when it does not exist.
  std::optional<Eigen::VectorXd> limit_mask;
  /// The left eigenvector of S for lambda_1, scaled so that it gives 1 on
  /// the point positions ..., -1, 0, 1, ... (the limit derivative per parent
  /// edge length). nullopt when it does not exist: lambda_0 = 1 is not simple,
  /// lambda_1 is not real, positive, simple and above |lambda_2|, or the
  /// eigenvector gives 0 on those positions.
  std::optional<Eigen::VectorXd> tangent_mask;
  /// The difference test on the scheme's masks (decides the verdict).
  RegularSmoothness regular;
  /// The regular rules' verdict, made inconclusive when it says C1 but the
  /// point's own conditions fail.
  SmoothnessVerdict verdict = SmoothnessVerdict::inconclusive;
  bool c1 = false;     ///< verdict == c1
  std::string reason;  ///< what the verdict rests on
};

/// Analyses \p scheme at a regular point: the matrices read off its recorded
/// stencils (curve_stencils()) on a closed polygon, their spectrum and masks,
/// the point's conditions, and the difference test on its lattice rule
/// (curve_lattice_rule(), regular_smoothness()).
/// \param scheme The curve scheme.
/// \param tolerance Clustering and rank tolerance of the spectral
///        computations (see spectrum()), in (0, 0.1).
/// \return The analysis; `verdict` and `reason` summarise it.
/// \throws InvalidInputError if no neighbourhood up to 8 points on either
///         side is invariant, the scheme is not binary or has an empty mask,
///         or \p tolerance is not in (0, 0.1).
/// \throws Error if the Schur iteration of the eigenvalue computation does
///         not converge.
/// \throws std::bad_alloc if memory runs out.
CurveAnalysis analyze_curve(const CurveScheme& scheme, double tolerance = 1e-9);

}  // namespace subdiv
