// Uniform refinement, topology included, the fast path and the stencil path.
// Arguments: mesh size n, levels, threads (0 = all). The OpenSubdiv peer
// (bench_peer_opensubdiv.cpp) runs the same inputs.

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "bench_meshes.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/generalized_catmull_clark.h"

namespace subdiv::bench {
namespace {

void refine_bench(benchmark::State& state, const PolygonMesh& mesh, const Scheme& scheme, bool grids = true) {
  RefineOptions options;
  options.regular_grids = grids;
  options.levels = static_cast<int>(state.range(1));
  const int threads = static_cast<int>(state.range(2));
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  Index faces = 0;
  for (auto _ : state) {
    const PolygonMesh out = refine(mesh, scheme, options);
    faces = out.face_count();
    benchmark::DoNotOptimize(out.positions.data());
  }
  state.counters["faces_out"] = faces;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * faces);
}

void refine_bench(benchmark::State& state, const PolygonMesh& mesh, const char* scheme_name, bool grids = true) {
  refine_bench(state, mesh, *find_scheme(scheme_name), grids);
}

void BM_Refine_CatmullClark(benchmark::State& state) {
  refine_bench(state, torus(static_cast<int>(state.range(0))), "catmull-clark");
}
// ~25k quads to level 4 (6.4M quads); 1M quads to level 2 (16M quads).
BENCHMARK(BM_Refine_CatmullClark)
    ->Args({158, 4, 1})->Args({158, 4, 2})->Args({1000, 2, 1})->Args({1000, 2, 2})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

// The same by the masks alone, level by level (RefineOptions::regular_grids
// off): what the grid path gains.
void BM_Refine_CatmullClark_ByMasks(benchmark::State& state) {
  refine_bench(state, torus(static_cast<int>(state.range(0))), "catmull-clark", false);
}
BENCHMARK(BM_Refine_CatmullClark_ByMasks)
    ->Args({158, 4, 1})->Args({1000, 2, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Refine_Loop(benchmark::State& state) {
  refine_bench(state, triangulated_torus(static_cast<int>(state.range(0))), "loop");
}
// 25k triangles to level 4 (6.4M triangles); 1M triangles to level 2 (16M triangles).
BENCHMARK(BM_Refine_Loop)->Args({256, 3, 1})->Args({112, 4, 1})->Args({708, 2, 1})->Args({708, 2, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Refine_Loop_ByMasks(benchmark::State& state) {
  refine_bench(state, triangulated_torus(static_cast<int>(state.range(0))), "loop", false);
}
BENCHMARK(BM_Refine_Loop_ByMasks)->Args({256, 3, 1})->Args({112, 4, 1})->Args({708, 2, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

// Every scheme on the same inputs, one thread, items = output faces: the
// Butterfly schemes against Loop, Doo-Sabin against Catmull-Clark
// (~25k quads or 50k triangles to level 3).
void BM_Refine_QuadScheme(benchmark::State& state, const char* scheme) { refine_bench(state, torus(158), scheme); }
void BM_Refine_TriangleScheme(benchmark::State& state, const char* scheme) {
  refine_bench(state, triangulated_torus(158), scheme);
}
BENCHMARK_CAPTURE(BM_Refine_QuadScheme, catmull_clark, "catmull-clark")->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Refine_QuadScheme, doo_sabin, "doo-sabin")->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Refine_TriangleScheme, loop, "loop")->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Refine_TriangleScheme, butterfly, "butterfly")->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Refine_TriangleScheme, modified_butterfly, "modified-butterfly")
    ->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

// The sqrt3 schemes (three faces per face and step: level 4 from 50k
// triangles, 4M faces) against Loop, and 4-8 (two faces per face and step:
// level 6 from 25k quads, 1.6M faces) against Catmull-Clark; items are
// output faces, so rates compare per output face.
BENCHMARK_CAPTURE(BM_Refine_TriangleScheme, sqrt3, "sqrt3")->Args({158, 4, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Refine_TriangleScheme, interpolatory_sqrt3, "interpolatory-sqrt3")
    ->Args({158, 4, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Refine_QuadScheme, four_eight, "four-eight")->Args({158, 6, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
// Composite schemes against the native schemes they equal or resemble
// (level 3 from 50k triangles, 1.35M faces): their masks are composed from
// the averaging operators as they refine.
BENCHMARK_CAPTURE(BM_Refine_TriangleScheme, sqrt3_l3, "sqrt3")->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Refine_TriangleScheme, composite_sqrt3_kobbelt, "composite-sqrt3-kobbelt")
    ->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Refine_TriangleScheme, composite_sqrt3, "composite-sqrt3")
    ->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
// Kobbelt's interpolatory quad scheme (quad split, same output as
// Catmull-Clark's) against Catmull-Clark and, per output face, Loop.
BENCHMARK_CAPTURE(BM_Refine_QuadScheme, kobbelt, "kobbelt")->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

// The schemes whose regular rule is a wider tensor stencil (patch reach 2
// or 3: Kobbelt's four-point rule, the B-splines of degree 5 and 7 of the
// generalized Catmull-Clark and midpoint families) or a composite of steps
// (degree 3), through the grid path and by the masks alone, one thread.
void BM_Refine_WideStencil(benchmark::State& state, const char* name, int degree, bool grids) {
  Scheme scheme = *find_scheme(name);
  if (degree > 0) set_degree(scheme, degree);
  refine_bench(state, torus(static_cast<int>(state.range(0))), scheme, grids);
}
#define SUBDIV_WIDE_STENCIL_BENCH(id, name, degree)                                                        \
  BENCHMARK_CAPTURE(BM_Refine_WideStencil, id##_grids, name, degree, true)                                  \
      ->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();                                    \
  BENCHMARK_CAPTURE(BM_Refine_WideStencil, id##_masks, name, degree, false)                                 \
      ->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime()
SUBDIV_WIDE_STENCIL_BENCH(kobbelt, "kobbelt", 0);
SUBDIV_WIDE_STENCIL_BENCH(gcc, "gcc", 0);
SUBDIV_WIDE_STENCIL_BENCH(gcc_5, "gcc", 5);
SUBDIV_WIDE_STENCIL_BENCH(midpoint_5, "midpoint", 5);
SUBDIV_WIDE_STENCIL_BENCH(midpoint_7, "midpoint", 7);

// The Butterfly schemes' 8-point rule (triangle patches of reach 2)
// through the grid path and by the masks alone, one thread, 50k triangles
// to level 3.
void BM_Refine_ButterflyGrid(benchmark::State& state, const char* name, bool grids) {
  refine_bench(state, triangulated_torus(static_cast<int>(state.range(0))), name, grids);
}
BENCHMARK_CAPTURE(BM_Refine_ButterflyGrid, butterfly_grids, "butterfly", true)
    ->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Refine_ButterflyGrid, butterfly_masks, "butterfly", false)
    ->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Refine_ButterflyGrid, modified_butterfly_grids, "modified-butterfly", true)
    ->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Refine_ButterflyGrid, modified_butterfly_masks, "modified-butterfly", false)
    ->Args({158, 3, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

// Stencil path: build the table once (coarse -> level 2; arguments: mesh
// size, levels, threads), then re-apply it to new positions, as for animation.
void stencil_build_bench(benchmark::State& state, bool grids) {
  const PolygonMesh mesh = torus(static_cast<int>(state.range(0)));
  RefineOptions options;
  options.levels = static_cast<int>(state.range(1));
  options.regular_grids = grids;
  const int threads = static_cast<int>(state.range(2));
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  for (auto _ : state) {
    const StencilTable table = refine_stencil_table(mesh, *find_scheme("catmull-clark"), options);
    benchmark::DoNotOptimize(table.entry_count());
  }
}
void BM_StencilBuild_CatmullClark(benchmark::State& state) { stencil_build_bench(state, true); }
BENCHMARK(BM_StencilBuild_CatmullClark)->Args({158, 2, 1})->Args({158, 2, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
// The masks alone (RefineOptions::regular_grids off).
void BM_StencilBuild_CatmullClark_ByMasks(benchmark::State& state) { stencil_build_bench(state, false); }
BENCHMARK(BM_StencilBuild_CatmullClark_ByMasks)->Args({158, 2, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_StencilApply_CatmullClark(benchmark::State& state) {
  const PolygonMesh mesh = torus(static_cast<int>(state.range(0)));
  RefineOptions options;
  options.levels = static_cast<int>(state.range(1));
  const StencilTable table = refine_stencil_table(mesh, *find_scheme("catmull-clark"), options);
  std::vector<Vec3> out(static_cast<std::size_t>(table.row_count()));
  for (auto _ : state) {
    table.apply(mesh.positions, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["rows"] = table.row_count();
}
BENCHMARK(BM_StencilApply_CatmullClark)->Args({158, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace subdiv::bench
