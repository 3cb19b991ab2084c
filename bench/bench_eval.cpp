// Exact limit evaluation (LimitEvaluator), one thread: points on regular
// faces (a torus), on faces at extraordinary vertices (a refined cube's
// corners) and within 2^-10 of those vertices, 16 per face, position and
// all derivatives. The Bfr peer
// (bench_peer_bfr.cpp) evaluates the same points.

#include <benchmark/benchmark.h>

#include <tbb/task_arena.h>

#include "bench_meshes.h"
#include "eval_points.h"
#include "subdiv/eval/limit_evaluator.h"

namespace subdiv::bench {
namespace {

void evaluate_points(benchmark::State& state, const PolygonMesh& mesh, const std::vector<SurfaceLocation>& at) {
  const LimitEvaluator evaluator(mesh, *find_scheme("catmull-clark"));
  for (auto _ : state) {
    // One by one, as a caller's loop does (the batch call is parallel).
    Vec3 sum;
    for (const SurfaceLocation& l : at) sum += evaluator.evaluate(l.face, l.u, l.v).du;
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(at.size()));
}

void BM_Eval_CatmullClark_Regular(benchmark::State& state) {
  const PolygonMesh mesh = torus(static_cast<int>(state.range(0)));
  evaluate_points(state, mesh, points_in_faces(all_faces(mesh), 16));
}
BENCHMARK(BM_Eval_CatmullClark_Regular)->Arg(64)->Unit(benchmark::kMillisecond);

void BM_Eval_CatmullClark_Extraordinary(benchmark::State& state) {
  const PolygonMesh mesh = refined_cube(static_cast<int>(state.range(0)));
  evaluate_points(state, mesh, points_in_faces(faces_at_extraordinary_vertices(mesh), 16));
}
BENCHMARK(BM_Eval_CatmullClark_Extraordinary)->Arg(3)->Unit(benchmark::kMillisecond);

// Within 2^-10 of the extraordinary corners: past the patches' cached
// levels, every point goes through the eigenbasis.
void BM_Eval_CatmullClark_NearCorner(benchmark::State& state) {
  const PolygonMesh mesh = refined_cube(static_cast<int>(state.range(0)));
  evaluate_points(state, mesh, points_near_extraordinary_corners(mesh, faces_at_extraordinary_vertices(mesh), 16, 0x1p-10));
}
BENCHMARK(BM_Eval_CatmullClark_NearCorner)->Arg(3)->Unit(benchmark::kMillisecond);

void BM_Eval_CatmullClark_Prepare(benchmark::State& state) {
  const PolygonMesh mesh = refined_cube(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const LimitEvaluator evaluator(mesh, *find_scheme("catmull-clark"));
    benchmark::DoNotOptimize(evaluator.patch_count());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * mesh.face_count());
}
BENCHMARK(BM_Eval_CatmullClark_Prepare)->Arg(3)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace subdiv::bench
