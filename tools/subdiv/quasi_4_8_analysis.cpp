#include "quasi_4_8_analysis.h"

#include <fmt/format.h>

#include <cstdio>
#include <string>

#include "commands.h"
#include "subdiv/analysis/quasi_4_8_experiment.h"

namespace subdiv::cli {

int run_quasi_4_8_analysis(int first, int last, int warmup) {
  std::string text = fmt::format(
      "quasi-4-8: the regular n-gon triangulated around its centre, {} binary steps, then the matrix of one 4-8 step "
      "(two binary steps) on the centre's invariant neighbourhood\n",
      warmup);
  text += fmt::format("{:<4} {:>7} {:>5} {:>4} {:>10} {:>10} {:>10} {:>10} {:>10}  {:<11} {}\n", "n", "valence",
                      "rings", "size", "lambda_1", "lambda_2", "|lambda_3|", "|lambda_4|", "lambda_1^2", "eigenvalues",
                      "charmap (piecewise linear, 2 more 4-8 steps)");
  for (int n = first; n <= last; ++n) {
    const Quasi48Experiment x = quasi_4_8_ngon_experiment(n, warmup);
    if (x.rings == 0) {
      text += fmt::format("{:<4} {:>7} {:>5} {:>4}  no matrix: {}\n", n, x.centre_valence, "-", "-", x.note);
      continue;
    }
    const auto& l = x.leading;
    const auto at = [&](std::size_t i) { return i < l.size() ? std::abs(l[i]) : 0.0; };
    std::string charmap = x.note.empty() ? std::string() : x.note;
    if (x.charmap_faces > 0)
      charmap = x.charmap_regular ? fmt::format("regular: {} faces alike, winds once", x.charmap_faces)
                                  : fmt::format("not regular: {} of {} faces flipped or flat, winding {}",
                                                x.charmap_flipped, x.charmap_faces, x.charmap_winding);
    text += fmt::format("{:<4} {:>7} {:>5} {:>4} {:>10.6f} {:>10.6f} {:>10.6f} {:>10.6f} {:>10.6f}  {:<11} {}\n", n,
                        x.centre_valence, x.rings, x.size, l.size() > 1 ? l[1].real() : 0.0,
                        l.size() > 2 ? l[2].real() : 0.0, at(3), at(4), at(1) * at(1),
                        x.eigenvalue_condition ? "Reif holds" : "Reif fails", charmap);
  }
  text +=
      "(valence: the centre's after the warm-up steps. Reif: lambda_1 = lambda_2 real, 1 > lambda_1 > |lambda_3|. The "
      "characteristic map is checked on its piecewise-linear approximation only: evidence for C1, not a proof)\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  return kExitOk;
}

}  // namespace subdiv::cli
