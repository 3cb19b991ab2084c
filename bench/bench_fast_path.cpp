// The fast path's hand-written kernels against the masks they shortcut, in
// the same run: each scheme that declares a kernel (Scheme::fast_path)
// refines the same input as declared and as a copy whose fast path is
// cleared, so the engine evaluates its masks. A kernel stays only where it
// is at least 1.3x faster (BENCHMARKS.md); tests hold each to the masks.
// 4-8's two-steps-at-once level is measured three ways: as declared (its
// positions kernel), with that level's masks, and one sqrt2 step at a time.

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <memory>
#include <vector>

#include "bench_meshes.h"
#include "subdiv/refine/refine.h"

namespace subdiv::bench {
namespace {

enum class Variant { declared, masks, two_steps_masks };

// The scheme as declared, or a copy that evaluates masks where it declared
// a kernel. The copies live as long as the program (two_steps points at one).
const Scheme& variant_of(const char* name, Variant variant) {
  static std::vector<std::unique_ptr<Scheme>> copies;
  const Scheme& declared = *find_scheme(name);
  if (variant == Variant::declared) return declared;
  auto copy = std::make_unique<Scheme>(declared);
  if (variant == Variant::masks) {
    copy->fast_path = {};
  } else {
    auto level = std::make_unique<Scheme>(*declared.fast_path.two_steps);
    level->fast_path = {};
    copy->fast_path.two_steps = level.get();
    copies.push_back(std::move(level));
  }
  copies.push_back(std::move(copy));
  return *copies.back();
}

void BM_FastPath(benchmark::State& state, const char* name, bool quads, Variant variant) {
  const Scheme& scheme = variant_of(name, variant);
  const PolygonMesh mesh = quads ? torus(158) : triangulated_torus(158);
  RefineOptions options;
  options.levels = static_cast<int>(state.range(0));
  options.regular_grids = false;  // the kernels, not the grid path (bench_refine.cpp), take every face
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  Index faces = 0;
  for (auto _ : state) {
    const PolygonMesh out = refine(mesh, scheme, options);
    faces = out.face_count();
    benchmark::DoNotOptimize(out.positions.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * faces);
}

#define SUBDIV_FAST_PATH_BENCH(id, name, quads, levels)                                               \
  BENCHMARK_CAPTURE(BM_FastPath, id##_kernel, name, quads, Variant::declared)                          \
      ->Arg(levels)->Unit(benchmark::kMillisecond)->UseRealTime();                                     \
  BENCHMARK_CAPTURE(BM_FastPath, id##_masks, name, quads, Variant::masks)                              \
      ->Arg(levels)->Unit(benchmark::kMillisecond)->UseRealTime()

SUBDIV_FAST_PATH_BENCH(sqrt3, "sqrt3", false, 4);
SUBDIV_FAST_PATH_BENCH(interpolatory_sqrt3, "interpolatory-sqrt3", false, 4);
SUBDIV_FAST_PATH_BENCH(kobbelt, "kobbelt", true, 3);
SUBDIV_FAST_PATH_BENCH(four_eight, "four-eight", true, 6);
BENCHMARK_CAPTURE(BM_FastPath, four_eight_two_steps_masks, "four-eight", true, Variant::two_steps_masks)
    ->Arg(6)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace subdiv::bench
