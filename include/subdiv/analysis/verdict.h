#pragma once
// The smoothness verdicts of the analysis, for configurations (analyze.h),
// regular rules (regular_smoothness.h) and curves (curve_analysis.h). Each
// verdict comes with a reason that names what it rests on.

namespace subdiv {

enum class SmoothnessVerdict {
  c1,                            ///< every condition the reason lists was checked and holds
  not_c1,                        ///< a condition necessary for C1 fails; the reason names it
  not_tangent_plane_continuous,  ///< the subdominant eigenvalues rule it out
  inconclusive,                  ///< a sufficient condition fails or is undecided; see the reason
};
const char* to_string(SmoothnessVerdict);

}  // namespace subdiv
