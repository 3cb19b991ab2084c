// Reading and writing speed. Throughput is reported as bytes_per_second of
// file text, so OBJ parsing can be read off in MB/s.

#include <benchmark/benchmark.h>

#include "bench_meshes.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/io/obj.h"
#include "subdiv/io/ply.h"

namespace subdiv::bench {
namespace {

void parse_obj_text(benchmark::State& state, const std::string& text) {
  for (auto _ : state) {
    MeshFile f = parse_obj(text);
    benchmark::DoNotOptimize(f.mesh.positions.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(text.size()));
  state.counters["MB"] = static_cast<double>(text.size()) / 1e6;
}

void BM_ParseObj_GeneratedTriangles(benchmark::State& state) {
  const std::string text = format_obj(triangulated_torus(static_cast<int>(state.range(0))));
  parse_obj_text(state, text);
}
BENCHMARK(BM_ParseObj_GeneratedTriangles)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_ParseObj_SharedMesh(benchmark::State& state, const char* relative) {
  const std::string path = shared_mesh(relative);
  if (path.empty()) {
    state.SkipWithError("shared mesh collection not found (../shared/data/meshes): skipped");
    return;
  }
  parse_obj_text(state, read_text(path));
}
BENCHMARK_CAPTURE(BM_ParseObj_SharedMesh, amo, "pmp/amo.obj")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ParseObj_SharedMesh, bunny00, "cgal/bunny00.obj")->Unit(benchmark::kMillisecond);

void BM_ReadObjFile_SharedMesh(benchmark::State& state, const char* relative) {
  const std::string path = shared_mesh(relative);
  if (path.empty()) {
    state.SkipWithError("shared mesh collection not found (../shared/data/meshes): skipped");
    return;
  }
  for (auto _ : state) {
    MeshFile f = read_mesh(path);
    benchmark::DoNotOptimize(f.mesh.positions.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(read_text(path).size()));
}
BENCHMARK_CAPTURE(BM_ReadObjFile_SharedMesh, amo, "pmp/amo.obj")->Unit(benchmark::kMillisecond);

// Args: torus size, formatting threads (the bytes are the same for any).
void BM_FormatObj(benchmark::State& state) {
  const PolygonMesh mesh = triangulated_torus(static_cast<int>(state.range(0)));
  WriteOptions options;
  options.threads = static_cast<int>(state.range(1));
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string text = format_obj(mesh, options);
    bytes = text.size();
    benchmark::DoNotOptimize(text.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_FormatObj)->Args({1000, 1})->Args({1000, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ParsePly(benchmark::State& state) {
  const auto encoding = static_cast<PlyEncoding>(state.range(1));
  const std::string bytes = format_ply(triangulated_torus(static_cast<int>(state.range(0))), encoding);
  for (auto _ : state) {
    MeshFile f = parse_ply(bytes);
    benchmark::DoNotOptimize(f.mesh.positions.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(bytes.size()));
}
BENCHMARK(BM_ParsePly)
    ->Args({1000, static_cast<int>(PlyEncoding::binary_little_endian)})
    ->Args({1000, static_cast<int>(PlyEncoding::ascii)})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace subdiv::bench
