#include "gcc_report.h"

#include <fmt/format.h>

#include "analysis_report.h"
#include "subdiv/analysis/generalized_catmull_clark.h"
#include "subdiv/rules/generalized_catmull_clark.h"

namespace subdiv::cli {

namespace {

const char* yes_no(bool b) { return b ? "yes" : "no"; }

bool closed_forms_apply(const Scheme& scheme) {
  return std::get<DegreeParameters>(scheme.parameters).degree == 3 && std::get<DegreeParameters>(scheme.parameters).smoothing.size() == 1;
}

}  // namespace

std::string format_gcc_report(const Scheme& scheme, const std::vector<ConfigurationAnalysis>& results) {
  const int n = std::get<DegreeParameters>(scheme.parameters).degree;
  std::string out = fmt::format("Chen-Prautzsch ({}): Lemma 4.7: rho_B <= {:.6g}, rho_A <= {:.6g}\n",
                                describe_smoothing(scheme.parameters), gcc_rho_b_bound(n), gcc_rho_a_bound(n));
  if (closed_forms_apply(scheme)) {
    out += fmt::format("{:<15} {:>20} {:>14} {:>14}  {:<5} {:<5} {:<42} {}\n", "configuration", "mu_0(m)",
                       "lambda_2pi/m", "lambda_1", "(5.1)", "(5.2)", "paper (Theorem 6.1, Remark 5.7)", "numerical");
    for (const ConfigurationAnalysis& a : results) {
      const int m = a.matrix.configuration.k;
      const GccTheorem t = gcc_theorem(scheme, m);
      const std::string numeric_lambda = a.leading.size() > 1 ? format_complex(a.leading[1]) : "-";
      out += fmt::format("{:<15} {:>20} {:>14.6f} {:>14}  {:<5} {:<5} {:<42} {}\n", a.matrix.configuration.name(),
                         format_complex(t.mu0), t.lambda, numeric_lambda, yes_no(t.condition_5_1),
                         yes_no(t.condition_5_2), (t.proves_c1 ? "C1: " : "open: ") + t.reason, to_string(a.verdict));
    }
  } else {
    out += "(the closed forms of Example 6.2 are M_3-bar's, with one smoothing operator)\n";
  }
  const double norm = regular_second_difference_norm(scheme);
  const std::string bound =
      n < 3 ? std::string("; n = 2 has no B (A R)")
            : fmt::format("; Lemma 3.2 (c) bound for B_1 R: max{{(2a+b)/4, 1/2-(2a+b)/4}} = {:.6g}",
                          gcc_second_difference_bound(std::get<DegreeParameters>(scheme.parameters).smoothing.front()));
  out += fmt::format("regular case (Theorem 3.1): |U_dd| = {:.6g} from the stencils{}{}: {}\n", norm,
                     n == 3 ? "" : " (the whole level)", bound,
                     norm < 0.5 ? "C1 on regular meshes (|U_dd| < 1/2)" : "not shown C1 (|U_dd| >= 1/2)");
  return out;
}

nlohmann::json gcc_report_json(const Scheme& scheme, const std::vector<ConfigurationAnalysis>& results) {
  const int n = std::get<DegreeParameters>(scheme.parameters).degree;
  nlohmann::json j;
  j["parameters"] = describe_smoothing(scheme.parameters);
  j["rho_b_bound"] = gcc_rho_b_bound(n);
  j["rho_a_bound"] = gcc_rho_a_bound(n);
  j["regular_second_difference_norm"] = regular_second_difference_norm(scheme);
  if (n >= 3) j["lemma_3_2_bound"] = gcc_second_difference_bound(std::get<DegreeParameters>(scheme.parameters).smoothing.front());
  if (closed_forms_apply(scheme)) {
    nlohmann::json rows = nlohmann::json::array();
    for (const ConfigurationAnalysis& a : results) {
      const GccTheorem t = gcc_theorem(scheme, a.matrix.configuration.k);
      rows.push_back({{"name", a.matrix.configuration.name()},
                      {"mu0", {{"re", t.mu0.real()}, {"im", t.mu0.imag()}}},
                      {"lambda", t.lambda},
                      {"condition_5_1", t.condition_5_1},
                      {"condition_5_2", t.condition_5_2},
                      {"proves_c1", t.proves_c1},
                      {"reason", t.reason},
                      {"numerical_verdict", to_string(a.verdict)}});
    }
    j["closed_forms"] = rows;
  }
  return j;
}

}  // namespace subdiv::cli
