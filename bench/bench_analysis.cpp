// Scheme analysis: every interior valence 3..32 of one scheme (matrix from
// the rules, spectrum by Fourier blocks, masks, characteristic map).

#include <benchmark/benchmark.h>

#include "subdiv/analysis/analyze.h"

namespace subdiv::bench {
namespace {

void BM_Analyze_AllValences(benchmark::State& state, const char* scheme_name, bool with_characteristic_map) {
  const Scheme& scheme = *find_scheme(scheme_name);
  AnalysisOptions options;
  options.characteristic_map = with_characteristic_map;
  int c1 = 0;
  for (auto _ : state) {
    c1 = 0;
    for (int k = 3; k <= 32; ++k)
      c1 += analyze(scheme, {Configuration::Kind::interior, k, CornerType::convex}, options).verdict ==
            SmoothnessVerdict::c1;
    benchmark::DoNotOptimize(c1);
  }
  state.counters["valences"] = 30;
}
BENCHMARK_CAPTURE(BM_Analyze_AllValences, loop, "loop", true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Analyze_AllValences, catmull_clark, "catmull-clark", true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Analyze_AllValences, catmull_clark_spectrum_only, "catmull-clark", false)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace subdiv::bench
