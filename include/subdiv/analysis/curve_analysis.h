#pragma once
// Analysis of curve schemes (Zorin's survey, section 2.1, whose first
// example is the cubic B-spline's 5 x 5 matrix): the local subdivision
// matrix at a regular point, read off the scheme's own recorded stencils on
// a closed polygon, its spectrum, the limit and tangent masks, and the C1
// verdict. A curve is regular everywhere, so the verdict is the regular
// rules' (regular_smoothness.h: the difference test); the point's own
// conditions must agree with it: lambda_0 = 1 simple, a real simple lambda_1
// in (0, 1) above every other magnitude, and a strictly monotone eigenvector
// (the one-dimensional characteristic map is injective).

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

struct CurveAnalysis {
  /// The neighbourhood: 2m + 1 points centred on a point (primal schemes),
  /// or 2m points centred on an edge's midpoint (dual schemes), m the
  /// smallest half-width whose image one level down depends on it alone.
  /// Its matrix S gives the masks.
  int half_width = 0;
  Eigen::MatrixXd S;
  /// One point wider on either side (the survey's 5 x 5 for the cubic
  /// B-spline): the limit curve around the centre depends on these points,
  /// so the spectrum and the verdict are taken here, as for surfaces.
  Eigen::MatrixXd wide_S;
  Spectrum spectrum;  ///< of wide_S
  std::vector<std::complex<double>> leading;  ///< lambda_0 .. lambda_3 with multiplicity
  /// Left eigenvectors of S: eigenvalue 1 (sums to 1) and lambda_1 (scaled so
  /// that it gives 1 on the point positions ..., -1, 0, 1, ...: the limit
  /// derivative per parent edge length). Empty when they do not exist.
  std::optional<Eigen::VectorXd> limit_mask;
  std::optional<Eigen::VectorXd> tangent_mask;
  /// The difference test on the scheme's masks (decides the verdict).
  RegularSmoothness regular;
  SmoothnessVerdict verdict = SmoothnessVerdict::inconclusive;
  bool c1 = false;     ///< verdict == c1
  std::string reason;  ///< what the verdict rests on
};

/// Throws InvalidInputError when no neighbourhood up to 8 points on either
/// side is invariant.
CurveAnalysis analyze_curve(const CurveScheme& scheme, double tolerance = 1e-9);

}  // namespace subdiv
