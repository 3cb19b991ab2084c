// OpenSubdiv's Bfr (libosd-dev) evaluating the points of bench_eval.cpp
// (near the corners, Bfr's isolation stops at its level and approximates):
// per face a Surface is initialised and its patch points prepared (as Bfr's
// tutorials do, once per face), then its 16 points evaluated with all
// derivatives. The "Prepared" variants time the evaluations alone, the
// surfaces made beforehand. Default isolation (approximation level 2).

#include <benchmark/benchmark.h>
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>

#include <memory>
#include <vector>

#include "bench_meshes.h"
#include "eval_points.h"
#include "peer_opensubdiv.h"

namespace subdiv::bench {
namespace {

using namespace OpenSubdiv;

struct BfrMesh {
  explicit BfrMesh(const PolygonMesh& mesh)
      : refiner(osd_refiner(mesh, Sdc::SCHEME_CATMARK)), factory(*refiner, Bfr::RefinerSurfaceFactory<>::Options()) {
    for (const Vec3& p : mesh.positions) points.insert(points.end(), {p.x, p.y, p.z});
  }
  std::unique_ptr<Far::TopologyRefiner> refiner;
  Bfr::RefinerSurfaceFactory<> factory;
  std::vector<double> points;
};

double evaluate_face(const Bfr::Surface<double>& surface, const std::vector<double>& patch,
                     const SurfaceLocation* at, int count) {
  const Bfr::Surface<double>::PointDescriptor desc(3);
  double sum = 0.0;
  for (int k = 0; k < count; ++k) {
    const double uv[2] = {at[k].u, at[k].v};
    double p[3], du[3], dv[3], duu[3], duv[3], dvv[3];
    surface.Evaluate(uv, patch.data(), desc, p, du, dv, duu, duv, dvv);
    sum += du[0];
  }
  return sum;
}

// `at`: 16 points per face of `faces`, face after face.
void bfr_points(benchmark::State& state, const PolygonMesh& mesh, const std::vector<Index>& faces,
                const std::vector<SurfaceLocation>& at, bool prepared) {
  BfrMesh bfr(mesh);
  const Bfr::Surface<double>::PointDescriptor desc(3);
  std::vector<Bfr::Surface<double>> surfaces(faces.size());
  std::vector<std::vector<double>> patches(faces.size());
  const auto prepare = [&](std::size_t i) {
    bfr.factory.InitVertexSurface<double>(faces[i], &surfaces[i]);
    patches[i].resize(3 * static_cast<std::size_t>(surfaces[i].GetNumPatchPoints()));
    surfaces[i].PreparePatchPoints(bfr.points.data(), desc, patches[i].data(), desc);
  };
  if (prepared)
    for (std::size_t i = 0; i < faces.size(); ++i) prepare(i);
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t i = 0; i < faces.size(); ++i) {
      if (!prepared) prepare(i);
      sum += evaluate_face(surfaces[i], patches[i], &at[16 * i], 16);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(at.size()));
}

void BM_Peer_Bfr_Eval_CatmullClark_Regular(benchmark::State& state) {
  const PolygonMesh mesh = torus(static_cast<int>(state.range(0)));
  const std::vector<Index> faces = all_faces(mesh);
  bfr_points(state, mesh, faces, points_in_faces(faces, 16), state.range(1) != 0);
}
BENCHMARK(BM_Peer_Bfr_Eval_CatmullClark_Regular)->Args({64, 0})->Args({64, 1})->Unit(benchmark::kMillisecond);

void BM_Peer_Bfr_Eval_CatmullClark_Extraordinary(benchmark::State& state) {
  const PolygonMesh mesh = refined_cube(static_cast<int>(state.range(0)));
  const std::vector<Index> faces = faces_at_extraordinary_vertices(mesh);
  bfr_points(state, mesh, faces, points_in_faces(faces, 16), state.range(1) != 0);
}
BENCHMARK(BM_Peer_Bfr_Eval_CatmullClark_Extraordinary)->Args({3, 0})->Args({3, 1})->Unit(benchmark::kMillisecond);

void BM_Peer_Bfr_Eval_CatmullClark_NearCorner(benchmark::State& state) {
  const PolygonMesh mesh = refined_cube(static_cast<int>(state.range(0)));
  const std::vector<Index> faces = faces_at_extraordinary_vertices(mesh);
  bfr_points(state, mesh, faces, points_near_extraordinary_corners(mesh, faces, 16, 0x1p-10), state.range(1) != 0);
}
BENCHMARK(BM_Peer_Bfr_Eval_CatmullClark_NearCorner)->Args({3, 0})->Args({3, 1})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace subdiv::bench
