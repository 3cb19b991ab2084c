#include "subdiv/analysis/analyze.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace subdiv {

const char* to_string(SmoothnessVerdict v) noexcept {
  switch (v) {
    case SmoothnessVerdict::c1: return "C1";
    case SmoothnessVerdict::not_c1: return "not C1";
    case SmoothnessVerdict::not_tangent_plane_continuous: return "not tangent-plane continuous";
    case SmoothnessVerdict::inconclusive: return "inconclusive";
  }
  return "?";
}

const char* to_string(CurvatureBehaviour c) noexcept {
  switch (c) {
    case CurvatureBehaviour::zero: return "zero curvature";
    case CurvatureBehaviour::bounded: return "bounded curvature";
    case CurvatureBehaviour::unbounded: return "unbounded curvature";
    case CurvatureBehaviour::not_applicable: return "-";
  }
  return "?";
}

namespace {

bool close(double a, double b, double tolerance) { return std::fabs(a - b) <= tolerance * std::max(1.0, std::fabs(b)); }

struct ConditionFailure {
  std::string reason;  ///< empty when the condition holds
  /// The failure rules out tangent-plane continuity for generic data.
  bool rules_out_tangent_plane = false;
};

// Reif's eigenvalue condition on the spectrum, and why it fails.
ConditionFailure eigenvalue_condition_failure(const Spectrum& s, double tolerance) {
  if (s.values.empty() || !s.values[0].real() || !close(s.values[0].value.real(), 1.0, tolerance))
    return {"the dominant eigenvalue is not 1 (the scheme is not affine invariant or diverges)"};
  if (s.values[0].algebraic != 1) return {"the eigenvalue 1 is not simple"};
  const std::vector<std::complex<double>> l = s.expanded();
  if (l.size() < 4) return {"the neighbourhood is too small"};
  if (std::abs(l[1]) >= 1.0 - tolerance) return {"a second eigenvalue of magnitude 1"};
  // A simple real lambda_1 followed by two of one magnitude: the normal is
  // the limit direction of c_1 ^ c_2 J[f_1, f_2] + c_1 ^ c_3 J[f_1, f_3]
  // (survey, section 5.3), whose two terms shrink alike (lambda_2 = |lambda_3|),
  // so it depends on the direction of approach.
  // (With a Jordan block at that magnitude the terms grow like j lambda^j
  // and the argument does not hold.)
  if (l[1].imag() == 0.0 && std::abs(l[1]) > std::abs(l[2]) * (1.0 + tolerance) &&
      close(std::abs(l[2]), std::abs(l[3]), tolerance)) {
    const bool jordan = std::any_of(s.values.begin(), s.values.end(), [&](const Eigenvalue& e) {
      return e.defective() && close(std::abs(e.value), std::abs(l[2]), tolerance);
    });
    return {fmt::format("lambda_1 = {:.6g} is simple and lambda_2, lambda_3 have one magnitude {:.6g}{}",
                        l[1].real(), std::abs(l[2]),
                        jordan ? ", with a Jordan block there" : ": the tangent plane depends on the direction of approach"),
            !jordan};
  }
  if (l[1].imag() != 0.0 || l[2].imag() != 0.0)
    return {fmt::format("the subdominant eigenvalues are complex ({:.6g} +- {:.6g}i): the limit spirals",
                        l[1].real(), std::fabs(l[1].imag()))};
  if (l[1].real() <= 0.0 || l[2].real() <= 0.0) return {"a subdominant eigenvalue is not positive"};
  if (std::abs(l[2]) <= std::abs(l[3]) * (1.0 + tolerance))
    return {fmt::format("lambda_2 = {:.6g} does not dominate |lambda_3| = {:.6g}", std::abs(l[2]), std::abs(l[3]))};
  for (const Eigenvalue& e : s.values)
    if (e.defective() && std::abs(e.value) >= std::abs(l[2]) * (1.0 - tolerance))
      return {fmt::format("the eigenvalue {:.6g} has a Jordan block", std::abs(e.value))};
  return {};
}

CurvatureBehaviour curvature_of(const std::vector<std::complex<double>>& l, double tolerance) {
  if (l.size() < 4 || !close(l[1].real(), l[2].real(), tolerance)) return CurvatureBehaviour::not_applicable;
  const double lambda2 = l[1].real() * l[1].real();
  // The largest magnitude among the eigenvalues other than 1 and lambda.
  double mu = 0.0;
  for (std::size_t i = 3; i < l.size(); ++i)
    if (!close(std::abs(l[i]), l[1].real(), tolerance)) mu = std::max(mu, std::abs(l[i]));
  if (close(mu, lambda2, tolerance)) return CurvatureBehaviour::bounded;
  return mu < lambda2 ? CurvatureBehaviour::zero : CurvatureBehaviour::unbounded;
}

// Boundary and corner configurations: whether the characteristic map's
// control points x, y vanish on the boundary curve (the centre and the
// neighbourhood's points on the first and last ray). Under the curve rules
// the curve's rows use the curve alone, so an eigenvector of an eigenvalue
// the curve does not have is zero there: when both subdominant eigenvalues
// are such, the map collapses the boundary curve to the centre.
bool collapses_boundary(const LocalSubdivisionMatrix& m, const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  if (m.configuration.kind == Configuration::Kind::interior) return false;
  constexpr double kLayout = 1e-9;
  auto angle = [](Vec3 p) {
    const double a = std::atan2(p.y, p.x);
    return a < -kLayout ? a + 2.0 * std::numbers::pi : std::max(a, 0.0);
  };
  double last = 0.0;
  for (const Vec3& p : m.layout)
    if (norm(p) > kLayout) last = std::max(last, angle(p));
  const double scale = std::max(x.cwiseAbs().maxCoeff(), y.cwiseAbs().maxCoeff());
  if (!(scale > 0.0)) return false;
  for (std::size_t a = 0; a < m.layout.size(); ++a) {
    const Vec3 p = m.layout[a];
    const bool on_curve = norm(p) <= kLayout || angle(p) <= kLayout || std::fabs(angle(p) - last) <= kLayout;
    const auto i = static_cast<Eigen::Index>(a);
    if (on_curve && std::max(std::fabs(x[i]), std::fabs(y[i])) > 1e-9 * scale) return false;
  }
  return true;
}

// The spectrum of the masks' matrix: per Fourier frequency where it is
// large and rotationally symmetric (see AnalysisOptions::rotation_rows).
Spectrum mask_spectrum(const LocalSubdivisionMatrix& m, const AnalysisOptions& options) {
  if (!m.rotate.empty() && m.S.rows() >= options.rotation_rows)
    return spectrum_by_rotation(m.S, {m.configuration.k, m.rotate}, options.tolerance);
  return spectrum(m.S, options.tolerance);
}

// Everything at the configuration itself: Reif's criterion.
ConfigurationAnalysis analyze_point(const Scheme& scheme, const Configuration& configuration,
                                    const AnalysisOptions& options) {
  ConfigurationAnalysis a;
  a.matrix = invariant_subdivision_matrix(scheme, configuration, options.max_rings, options.rules);
  if (!a.matrix.invariant) {
    a.reason = "no invariant neighbourhood within " + std::to_string(a.matrix.rings) +
               " rings: " + a.matrix.invariance_note;
    return a;
  }
  a.wide_matrix = local_subdivision_matrix(scheme, configuration, a.matrix.rings + 1, options.rules);
  if (!a.wide_matrix.rotate.empty())
    a.spectrum = spectrum_by_rotation(a.wide_matrix.S, {configuration.k, a.wide_matrix.rotate}, options.tolerance);
  else
    a.spectrum = spectrum(a.wide_matrix.S, options.tolerance);
  const auto all = a.spectrum.expanded();
  a.leading.assign(all.begin(), all.begin() + std::min<std::ptrdiff_t>(4, static_cast<std::ptrdiff_t>(all.size())));
  if (options.masks) {
    a.limit_mask = left_eigenvector(a.matrix.S, 1.0, options.tolerance);
    a.tangent_masks = tangent_masks(a.matrix.S, mask_spectrum(a.matrix, options), options.tolerance);
  }

  const ConditionFailure failure = eigenvalue_condition_failure(a.spectrum, options.tolerance);
  a.eigenvalue_condition = failure.reason.empty();
  a.curvature = a.eigenvalue_condition ? curvature_of(all, options.tolerance) : CurvatureBehaviour::not_applicable;
  if (!a.eigenvalue_condition) {
    a.verdict = failure.rules_out_tangent_plane ? SmoothnessVerdict::not_tangent_plane_continuous
                                                : SmoothnessVerdict::inconclusive;
    a.reason = "Reif's eigenvalue condition fails: " + failure.reason;
    return a;
  }
  if (!options.characteristic_map) {
    a.reason = "eigenvalue condition holds; characteristic map not checked";
    return a;
  }
  const auto pair = subdominant_eigenvectors(a.wide_matrix.S, a.spectrum, options.tolerance);
  if (!pair) {
    a.reason = "no real basis of the subdominant eigenspace";
    return a;
  }
  a.characteristic_map =
      characteristic_map(scheme, a.wide_matrix, pair->vectors[0], pair->vectors[1], options.characteristic_levels);
  if (a.characteristic_map->regular && a.characteristic_map->injective) {
    a.verdict = SmoothnessVerdict::c1;
    a.reason = "Reif's criterion: eigenvalue condition, characteristic map regular and injective";
  } else {
    a.reason = "characteristic map: " + a.characteristic_map->note;
    if (!a.characteristic_map->regular && collapses_boundary(a.wide_matrix, pair->vectors[0], pair->vectors[1]))
      a.reason += "; the subdominant eigenvectors vanish on the boundary curve (lambda_1, lambda_2 are not the "
                  "curve's eigenvalues), so the map collapses the boundary to the centre";
  }
  return a;
}

}  // namespace

ConfigurationAnalysis analyze(const Scheme& scheme, const Configuration& configuration, const AnalysisOptions& options) {
  ConfigurationAnalysis a = analyze_point(scheme, configuration, options);
  if (options.regular_rules)
    a.regular = regular_smoothness_of(scheme, options.rules, configuration.kind != Configuration::Kind::interior);
  else
    a.regular.reason = "the regular rules were not tested (AnalysisOptions::regular_rules is false)";
  a.configuration_reason = a.reason;
  // Reif's criterion presumes the surface C1 away from the centre: the
  // regular rules' own verdict decides that part.
  if (a.regular.verdict == SmoothnessVerdict::not_c1) {
    a.verdict = SmoothnessVerdict::not_c1;
    a.reason = a.regular.reason + "; at the configuration: " + a.reason;
  } else if (a.verdict == SmoothnessVerdict::c1) {
    if (a.regular.verdict != SmoothnessVerdict::c1) a.verdict = SmoothnessVerdict::inconclusive;
    a.reason += "; " + a.regular.reason;
  } else {
    a.reason += "; " + a.regular.reason;
  }
  return a;
}

}  // namespace subdiv
