#pragma once
// `subdiv analyze` for generalized Catmull-Clark schemes: the paper's
// closed forms and conditions (Chen and Prautzsch 2012) next to the
// numerical analysis.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "subdiv/analysis/analyze.h"

namespace subdiv::cli {

/// For degree 3, a row per configuration: mu_0(m), lambda_{2pi/m}(m)
/// (Example 6.2), the numerical lambda_1, conditions (5.1) and (5.2), what
/// the paper proves and the numerical verdict; for every degree the Lemma
/// 4.7 bounds and the regular case (Theorem 3.1, Lemma 3.2).
std::string format_gcc_report(const Scheme& scheme, const std::vector<ConfigurationAnalysis>& results);
nlohmann::json gcc_report_json(const Scheme& scheme, const std::vector<ConfigurationAnalysis>& results);

}  // namespace subdiv::cli
