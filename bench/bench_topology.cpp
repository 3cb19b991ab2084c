// Building the topology layer and validating, on meshes of a million faces.

#include <benchmark/benchmark.h>

#include "bench_meshes.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/validation.h"

namespace subdiv::bench {
namespace {

void build_topology(benchmark::State& state, const PolygonMesh& mesh) {
  for (auto _ : state) {
    MeshTopology t(mesh);
    benchmark::DoNotOptimize(t.edge_count());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * mesh.face_count());
  state.counters["faces"] = mesh.face_count();
}

void BM_BuildTopology_Quads(benchmark::State& state) { build_topology(state, torus(static_cast<int>(state.range(0)))); }
BENCHMARK(BM_BuildTopology_Quads)->Arg(250)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_BuildTopology_Triangles(benchmark::State& state) {
  build_topology(state, triangulated_torus(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_BuildTopology_Triangles)->Arg(707)->Unit(benchmark::kMillisecond);

void BM_Validate(benchmark::State& state) {
  const PolygonMesh mesh = torus(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    ValidationReport r = validate(mesh);
    benchmark::DoNotOptimize(r.counts.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * mesh.face_count());
}
BENCHMARK(BM_Validate)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace subdiv::bench
