#pragma once
/// \file
/// The smoothness verdicts of the analysis, for configurations (analyze.h),
/// regular rules (regular_smoothness.h) and curves (curve_analysis.h). Each
/// verdict comes with a reason that names what it rests on.

namespace subdiv {

/// What the analysis concludes about the C1 smoothness of a limit surface or
/// curve, at a configuration or for the regular rules.
enum class SmoothnessVerdict {
  c1,                            ///< every condition the reason lists was checked and holds
  not_c1,                        ///< a condition necessary for C1 fails; the reason names it
  not_tangent_plane_continuous,  ///< the subdominant eigenvalues rule it out
  inconclusive,                  ///< a sufficient condition fails or is undecided; see the reason
};
/// The verdict's name as the CLI prints it ("C1", "not C1", ...).
/// \param verdict The verdict.
/// \return A static, null-terminated string; "?" for a value outside the enum.
const char* to_string(SmoothnessVerdict verdict) noexcept;

}  // namespace subdiv
