#pragma once
// Text and JSON reports of a scheme's local analysis, for `subdiv analyze`.

#include <complex>
#include <string>
#include <string_view>
#include <vector>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/curve_analysis.h"

namespace subdiv::cli {

/// "0.625000", "0.250000+0.433013i", "0.250000-0.433013i": six decimals.
std::string format_complex(std::complex<double> z);

/// One row per configuration (configuration, neighbourhood size and rings,
/// lambda_1, lambda_2, |lambda_3|, lambda_1^2, Reif's condition, the
/// characteristic map's regularity and injectivity, verdict, curvature),
/// then one line per configuration whose verdict is not C1 with its reason.
std::string format_analysis_table(std::string_view scheme, const std::vector<ConfigurationAnalysis>& results);

/// The whole analysis as a JSON document (numbers at full precision),
/// masks and neighbourhood layout included.
std::string analysis_json(std::string_view scheme, const std::vector<ConfigurationAnalysis>& results);

/// A curve scheme's analysis: the matrix size, the leading eigenvalues,
/// the verdict, the masks; as text or JSON.
std::string format_curve_analysis(std::string_view scheme, const CurveAnalysis& a);
std::string curve_analysis_json(std::string_view scheme, const CurveAnalysis& a);

}  // namespace subdiv::cli
