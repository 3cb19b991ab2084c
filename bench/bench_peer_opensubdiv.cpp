// OpenSubdiv (Debian's libosd-dev) building its base-level topology from the
// same face lists: edges, face-edge, edge-face, vertex-face and vertex-edge
// relations with ordered vertex rings, the counterpart of MeshTopology.

#include <benchmark/benchmark.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <memory>
#include <vector>

#include "bench_meshes.h"
#include "peer_opensubdiv.h"

namespace subdiv::bench {
namespace {

using namespace OpenSubdiv;

void build_with_opensubdiv(benchmark::State& state, const PolygonMesh& mesh) {
  for (auto _ : state) {
    auto refiner = osd_refiner(mesh, Sdc::SCHEME_CATMARK);
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

// Uniform refinement: TopologyRefiner::RefineUniform + PrimvarRefiner::Interpolate
// level by level, double precision, the same inputs as bench_refine.cpp.
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/osd/cpuEvaluator.h>
#include <opensubdiv/osd/bufferDescriptor.h>

namespace subdiv::bench {
namespace {

void osd_refine_bench(benchmark::State& state, const PolygonMesh& mesh, Sdc::SchemeType type) {
  const int levels = static_cast<int>(state.range(1));
  int faces = 0;
  std::vector<OsdVertex> buffer;
  for (auto _ : state) {
    faces = osd_refine_uniform(mesh, type, levels, buffer);
    benchmark::DoNotOptimize(buffer.data());
    std::vector<OsdVertex>().swap(buffer);  // each iteration allocates afresh, as refine() does
  }
  state.counters["faces_out"] = faces;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * faces);
}

void BM_Peer_OpenSubdiv_Refine_CatmullClark(benchmark::State& state) {
  osd_refine_bench(state, torus(static_cast<int>(state.range(0))), Sdc::SCHEME_CATMARK);
}
BENCHMARK(BM_Peer_OpenSubdiv_Refine_CatmullClark)
    ->Args({158, 4})->Args({1000, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Peer_OpenSubdiv_Refine_Loop(benchmark::State& state) {
  osd_refine_bench(state, triangulated_torus(static_cast<int>(state.range(0))), Sdc::SCHEME_LOOP);
}
BENCHMARK(BM_Peer_OpenSubdiv_Refine_Loop)->Args({112, 4})->Args({708, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Peer_OpenSubdiv_StencilBuild_CatmullClark(benchmark::State& state) {
  const PolygonMesh mesh = torus(static_cast<int>(state.range(0)));
  const int levels = static_cast<int>(state.range(1));
  for (auto _ : state) {
    auto refiner = osd_refiner(mesh, Sdc::SCHEME_CATMARK);
    refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));
    Far::StencilTableFactoryReal<double>::Options options;
    options.generateIntermediateLevels = false;
    std::unique_ptr<const Far::StencilTableReal<double>> table(
        Far::StencilTableFactoryReal<double>::Create(*refiner, options));
    benchmark::DoNotOptimize(table->GetNumStencils());
  }
}
BENCHMARK(BM_Peer_OpenSubdiv_StencilBuild_CatmullClark)->Args({158, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Peer_OpenSubdiv_StencilApply_CatmullClark(benchmark::State& state) {
  const PolygonMesh mesh = torus(static_cast<int>(state.range(0)));
  const int levels = static_cast<int>(state.range(1));
  auto refiner = osd_refiner(mesh, Sdc::SCHEME_CATMARK);
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));
  Far::StencilTableFactory::Options options;
  options.generateIntermediateLevels = false;
  std::unique_ptr<const Far::StencilTable> table(Far::StencilTableFactory::Create(*refiner, options));
  // Osd::CpuEvaluator works in single precision.
  std::vector<float> src(static_cast<std::size_t>(mesh.vertex_count()) * 3);
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    for (int i = 0; i < 3; ++i) src[static_cast<std::size_t>(v) * 3 + static_cast<std::size_t>(i)] = static_cast<float>(mesh.positions[static_cast<std::size_t>(v)][i]);
  std::vector<float> dst(static_cast<std::size_t>(table->GetNumStencils()) * 3);
  const Osd::BufferDescriptor desc(0, 3, 3);
  for (auto _ : state) {
    Osd::CpuEvaluator::EvalStencils(src.data(), desc, dst.data(), desc, table->GetSizes().data(),
                                    table->GetOffsets().data(), table->GetControlIndices().data(),
                                    table->GetWeights().data(), 0, table->GetNumStencils());
    benchmark::DoNotOptimize(dst.data());
  }
  state.counters["rows"] = table->GetNumStencils();
}
BENCHMARK(BM_Peer_OpenSubdiv_StencilApply_CatmullClark)->Args({158, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace subdiv::bench
