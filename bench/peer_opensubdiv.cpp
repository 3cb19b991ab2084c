#include "peer_opensubdiv.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

namespace subdiv::bench {

using namespace OpenSubdiv;

std::unique_ptr<Far::TopologyRefiner> osd_refiner(const PolygonMesh& mesh, Sdc::SchemeType type) {
  std::vector<int> sizes(static_cast<std::size_t>(mesh.face_count()));
  for (Index f = 0; f < mesh.face_count(); ++f) sizes[static_cast<std::size_t>(f)] = mesh.face_size(f);
  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.vertex_count();
  desc.numFaces = mesh.face_count();
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = mesh.face_indices.data();
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  return std::unique_ptr<Far::TopologyRefiner>(Factory::Create(desc, Factory::Options(type, sdc)));
}

int osd_refine_uniform(const PolygonMesh& mesh, Sdc::SchemeType type, int levels, std::vector<OsdVertex>& buffer) {
  auto refiner = osd_refiner(mesh, type);
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));
  buffer.assign(static_cast<std::size_t>(refiner->GetNumVerticesTotal()), OsdVertex{});
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3 p = mesh.positions[static_cast<std::size_t>(v)];
    buffer[static_cast<std::size_t>(v)] = {p.x, p.y, p.z};
  }
  Far::PrimvarRefiner primvar(*refiner);
  OsdVertex* src = buffer.data();
  for (int level = 1; level <= levels; ++level) {
    OsdVertex* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
    primvar.Interpolate(level, src, dst);
    src = dst;
  }
  return refiner->GetLevel(levels).GetNumFaces();
}

}  // namespace subdiv::bench
