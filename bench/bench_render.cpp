// Drawing a surface: a 1M-triangle torus to an 800 x 600 PNG, the whole of
// what `subdiv render` does after refinement (scene with face normals and
// boundary/crease lines, Mesa's rasterization with 2 x 2 samples, PNG).

#include <benchmark/benchmark.h>

#include "bench_meshes.h"
#include "png.h"
#include "rasterizer.h"
#include "render_scene.h"

namespace subdiv::bench {
namespace {

void BM_Render_TriangulatedTorus(benchmark::State& state) {
  const PolygonMesh mesh = triangulated_torus(static_cast<int>(state.range(0)));
  render::RenderStyle style;
  for (auto _ : state) {
    const render::Scene scene = render::surface_scene(mesh, {}, {});
    const std::string png = render::encode_png(render::rasterize(scene, style));
    benchmark::DoNotOptimize(png.data());
  }
  state.counters["triangles"] = static_cast<double>(mesh.face_count());
}
// 708 x 708 quads: 1.0M triangles.
BENCHMARK(BM_Render_TriangulatedTorus)->Arg(708)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace subdiv::bench
