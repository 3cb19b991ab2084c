// OpenSubdiv (Debian's libosd-dev) building its base-level topology from the
// same face lists: edges, face-edge, edge-face, vertex-face and vertex-edge
// relations with ordered vertex rings, the counterpart of MeshTopology.

#include <benchmark/benchmark.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <memory>
#include <vector>

#include "bench_meshes.h"

namespace subdiv::bench {
namespace {

using namespace OpenSubdiv;

void build_with_opensubdiv(benchmark::State& state, const PolygonMesh& mesh) {
  std::vector<int> sizes(static_cast<std::size_t>(mesh.face_count()));
  for (Index f = 0; f < mesh.face_count(); ++f) sizes[static_cast<std::size_t>(f)] = mesh.face_size(f);
  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.vertex_count();
  desc.numFaces = mesh.face_count();
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = mesh.face_indices.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  const Factory::Options options(Sdc::SCHEME_CATMARK, Sdc::Options());
  for (auto _ : state) {
    std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, options));
    benchmark::DoNotOptimize(refiner->GetLevel(0).GetNumEdges());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * mesh.face_count());
  state.counters["faces"] = mesh.face_count();
}

void BM_Peer_OpenSubdiv_BuildTopology_Quads(benchmark::State& state) {
  build_with_opensubdiv(state, torus(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_Peer_OpenSubdiv_BuildTopology_Quads)->Arg(250)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_Peer_OpenSubdiv_BuildTopology_Triangles(benchmark::State& state) {
  build_with_opensubdiv(state, triangulated_torus(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_Peer_OpenSubdiv_BuildTopology_Triangles)->Arg(707)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace subdiv::bench
