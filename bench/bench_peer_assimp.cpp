// The same inputs through Assimp (Debian's libassimp-dev), the most widely
// used open-source importer, without post-processing, for a side-by-side
// figure. Assimp builds its own scene (float positions, split per material),
// so the comparison is of "bytes in, usable mesh out".

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <benchmark/benchmark.h>

#include "bench_meshes.h"
#include "subdiv/io/obj.h"
#include "subdiv/io/ply.h"

namespace subdiv::bench {
namespace {

void import_with_assimp(benchmark::State& state, const std::string& bytes, const char* hint) {
  for (auto _ : state) {
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, hint);
    if (!scene || scene->mNumMeshes == 0) {
      state.SkipWithError(importer.GetErrorString());
      return;
    }
    benchmark::DoNotOptimize(scene->mMeshes[0]->mVertices);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(bytes.size()));
}

void BM_Peer_Assimp_ParseObj_GeneratedTriangles(benchmark::State& state) {
  import_with_assimp(state, format_obj(triangulated_torus(static_cast<int>(state.range(0)))), "obj");
}
BENCHMARK(BM_Peer_Assimp_ParseObj_GeneratedTriangles)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_Peer_Assimp_ParseObj_SharedMesh(benchmark::State& state, const char* relative) {
  const std::string path = shared_mesh(relative);
  if (path.empty()) {
    state.SkipWithError("shared mesh collection not found (../shared/data/meshes): skipped");
    return;
  }
  import_with_assimp(state, read_text(path), "obj");
}
BENCHMARK_CAPTURE(BM_Peer_Assimp_ParseObj_SharedMesh, amo, "pmp/amo.obj")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Peer_Assimp_ParseObj_SharedMesh, bunny00, "cgal/bunny00.obj")->Unit(benchmark::kMillisecond);

void BM_Peer_Assimp_ParsePly(benchmark::State& state) {
  const auto encoding = static_cast<PlyEncoding>(state.range(1));
  import_with_assimp(state, format_ply(triangulated_torus(static_cast<int>(state.range(0))), encoding), "ply");
}
BENCHMARK(BM_Peer_Assimp_ParsePly)
    ->Args({1000, static_cast<int>(PlyEncoding::binary_little_endian)})
    ->Args({1000, static_cast<int>(PlyEncoding::ascii)})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace subdiv::bench
