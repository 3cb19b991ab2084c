#include "opensubdiv_refiner.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <span>

#include "subdiv/mesh/topology.h"

namespace subdiv::test {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

Sdc::Options::VtxBoundaryInterpolation boundary_option(BoundaryInterpolation boundary) {
  switch (boundary) {
    case BoundaryInterpolation::none: return Sdc::Options::VTX_BOUNDARY_NONE;
    case BoundaryInterpolation::edge_only: return Sdc::Options::VTX_BOUNDARY_EDGE_ONLY;
    case BoundaryInterpolation::edge_and_corner: return Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER;
  }
  return Sdc::Options::VTX_BOUNDARY_NONE;
}

Sdc::Options::VtxBoundaryInterpolation their_boundary(const Tags& tags) {
  return tags.boundary_interpolation_set ? boundary_option(tags.boundary_interpolation)
                                         : Sdc::Options::VTX_BOUNDARY_NONE;
}

void round_sharpness_to_float(Tags& tags) {
  for (CreaseTag& c : tags.creases) c.sharpness = static_cast<double>(static_cast<float>(c.sharpness));
  for (CornerTag& c : tags.corners) c.sharpness = static_cast<double>(static_cast<float>(c.sharpness));
}

std::vector<std::vector<OsdVertex>> their_positions(const Far::TopologyRefiner& refiner, const PolygonMesh& mesh) {
  std::vector<std::vector<OsdVertex>> levels(static_cast<std::size_t>(refiner.GetNumLevels()));
  for (std::size_t l = 0; l < levels.size(); ++l)
    levels[l].resize(static_cast<std::size_t>(refiner.GetLevel(static_cast<int>(l)).GetNumVertices()));
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    levels[0][v] = {mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z};
  const Far::PrimvarRefinerReal<double> primvar(refiner);
  for (std::size_t l = 1; l < levels.size(); ++l) {
    const OsdVertex* src = levels[l - 1].data();
    OsdVertex* dst = levels[l].data();
    primvar.Interpolate(static_cast<int>(l), src, dst);
  }
  return levels;
}

double bbox_diagonal(const std::vector<Vec3>& points) {
  if (points.empty()) return 0.0;
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  return norm(hi - lo);
}

namespace {

Sdc::Options::FVarLinearInterpolation their_face_varying(FaceVaryingInterpolation mode) {
  switch (mode) {
    case FaceVaryingInterpolation::none: return Sdc::Options::FVAR_LINEAR_NONE;
    case FaceVaryingInterpolation::corners_only: return Sdc::Options::FVAR_LINEAR_CORNERS_ONLY;
    case FaceVaryingInterpolation::corners_plus1: return Sdc::Options::FVAR_LINEAR_CORNERS_PLUS1;
    case FaceVaryingInterpolation::corners_plus2: return Sdc::Options::FVAR_LINEAR_CORNERS_PLUS2;
    case FaceVaryingInterpolation::boundaries: return Sdc::Options::FVAR_LINEAR_BOUNDARIES;
    case FaceVaryingInterpolation::all: return Sdc::Options::FVAR_LINEAR_ALL;
  }
  return Sdc::Options::FVAR_LINEAR_ALL;
}

bool same_cycle(std::span<const Index> a, Far::ConstIndexArray b) {
  const int n = static_cast<int>(a.size());
  if (b.size() != n) return false;
  for (int r = 0; r < n; ++r) {
    bool all = true;
    for (int k = 0; k < n && all; ++k) all = a[static_cast<std::size_t>(k)] == b[(k + r) % n];
    if (all) return true;
  }
  return false;
}

}  // namespace

std::unique_ptr<Far::TopologyRefiner> make_refiner(const PolygonMesh& mesh, Sdc::SchemeType scheme, int levels,
                                                   Sdc::Options::VtxBoundaryInterpolation boundary,
                                                   const FaceVaryingChannel* channel,
                                                   FaceVaryingInterpolation face_varying) {
  std::vector<int> verts_per_face(static_cast<std::size_t>(mesh.face_count()));
  for (Index f = 0; f < mesh.face_count(); ++f) verts_per_face[static_cast<std::size_t>(f)] = mesh.face_size(f);
  const std::vector<Far::Index> face_vertices(mesh.face_indices.begin(), mesh.face_indices.end());
  std::vector<Far::Index> crease_pairs;
  std::vector<float> crease_weights;
  for (const CreaseTag& c : mesh.tags.creases) {
    crease_pairs.push_back(c.v0);
    crease_pairs.push_back(c.v1);
    crease_weights.push_back(static_cast<float>(c.sharpness));
  }
  std::vector<Far::Index> corner_vertices;
  std::vector<float> corner_weights;
  for (const CornerTag& c : mesh.tags.corners) {
    corner_vertices.push_back(c.vertex);
    corner_weights.push_back(static_cast<float>(c.sharpness));
  }
  const std::vector<Far::Index> holes(mesh.tags.holes.begin(), mesh.tags.holes.end());

  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.vertex_count();
  desc.numFaces = mesh.face_count();
  desc.numVertsPerFace = verts_per_face.data();
  desc.vertIndicesPerFace = face_vertices.data();
  desc.numCreases = static_cast<int>(crease_weights.size());
  desc.creaseVertexIndexPairs = crease_pairs.data();
  desc.creaseWeights = crease_weights.data();
  desc.numCorners = static_cast<int>(corner_weights.size());
  desc.cornerVertexIndices = corner_vertices.data();
  desc.cornerWeights = corner_weights.data();
  desc.numHoles = static_cast<int>(holes.size());
  desc.holeIndices = holes.data();
  std::vector<Far::Index> value_indices;
  Far::TopologyDescriptor::FVarChannel fvar;
  if (channel) {
    value_indices.assign(channel->indices.begin(), channel->indices.end());
    fvar.numValues = channel->value_count();
    fvar.valueIndices = value_indices.data();
    desc.numFVarChannels = 1;
    desc.fvarChannels = &fvar;
  }

  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(boundary);
  options.SetCreasingMethod(mesh.tags.crease_method == CreaseMethod::chaikin ? Sdc::Options::CREASE_CHAIKIN
                                                                            : Sdc::Options::CREASE_UNIFORM);
  options.SetTriangleSubdivision(mesh.tags.triangle_subdivision == TriangleSubdivision::smooth
                                     ? Sdc::Options::TRI_SUB_SMOOTH
                                     : Sdc::Options::TRI_SUB_CATMARK);
  options.SetFVarLinearInterpolation(their_face_varying(face_varying));
  std::unique_ptr<Far::TopologyRefiner> refiner(Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Create(
      desc, Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Options(scheme, options)));
  if (!refiner || levels == 0) return refiner;
  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);
  return refiner;
}

Correspondence Correspondence::identity(const PolygonMesh& mesh) {
  Correspondence c;
  c.vertices.resize(static_cast<std::size_t>(mesh.vertex_count()));
  c.faces.resize(static_cast<std::size_t>(mesh.face_count()));
  for (std::size_t i = 0; i < c.vertices.size(); ++i) c.vertices[i] = static_cast<Far::Index>(i);
  for (std::size_t i = 0; i < c.faces.size(); ++i) c.faces[i] = static_cast<Far::Index>(i);
  return c;
}

SplitMap split_ranges(const PolygonMesh& parent, SplitRule rule) {
  const MeshTopology topology(parent);
  SplitMap map;
  map.rule = rule;
  map.face_points = 0;
  map.edge_points = rule == SplitRule::quad ? parent.face_count() : 0;
  map.vertex_points = map.edge_points + topology.edge_count();
  map.child_vertex_count = map.vertex_points + parent.vertex_count();
  return map;
}

std::string describe_child(const SplitMap& map, Index i) {
  if (i < map.edge_points) return "face point of parent face " + std::to_string(i - map.face_points);
  if (i < map.vertex_points) return "edge point of parent edge " + std::to_string(i - map.edge_points);
  return "vertex point of parent vertex " + std::to_string(i - map.vertex_points);
}

std::string child_correspondence(const PolygonMesh& parent, SplitRule rule, const PolygonMesh& child,
                                 const Far::TopologyLevel& their_parent, const Far::TopologyLevel& their_child,
                                 const Correspondence& parent_map, Correspondence& child_map) {
  const MeshTopology topology(parent);
  const SplitMap map = split_ranges(parent, rule);
  if (map.child_vertex_count != child.vertex_count()) return "the child's vertex count is not the split's";
  if (topology.edge_count() != their_parent.GetNumEdges()) return "the parents' edge counts differ";

  child_map.vertices.assign(static_cast<std::size_t>(child.vertex_count()), -1);
  if (rule == SplitRule::quad)
    for (Index f = 0; f < parent.face_count(); ++f)
      child_map.vertices[static_cast<std::size_t>(map.face_point(f))] =
          their_parent.GetFaceChildVertex(parent_map.faces[static_cast<std::size_t>(f)]);
  for (Index e = 0; e < topology.edge_count(); ++e) {
    const auto [a, b] = topology.edge_vertices(e);
    const Far::Index te = their_parent.FindEdge(parent_map.vertices[static_cast<std::size_t>(a)],
                                                parent_map.vertices[static_cast<std::size_t>(b)]);
    if (te == Far::INDEX_INVALID)
      return "OpenSubdiv has no edge for our edge " + std::to_string(e) + " (" + std::to_string(a) + ", " +
             std::to_string(b) + ")";
    child_map.vertices[static_cast<std::size_t>(map.edge_point(e))] = their_parent.GetEdgeChildVertex(te);
  }
  for (Index v = 0; v < parent.vertex_count(); ++v)
    child_map.vertices[static_cast<std::size_t>(map.vertex_point(v))] =
        their_parent.GetVertexChildVertex(parent_map.vertices[static_cast<std::size_t>(v)]);

  // One to one.
  std::vector<char> hit(child_map.vertices.size(), 0);
  for (std::size_t i = 0; i < child_map.vertices.size(); ++i) {
    const Far::Index t = child_map.vertices[i];
    if (!(t >= 0 && static_cast<std::size_t>(t) < hit.size() && !hit[static_cast<std::size_t>(t)]))
      return "child vertex " + std::to_string(i) + " (" + describe_child(map, static_cast<Index>(i)) +
             ") maps to OpenSubdiv vertex " + std::to_string(t) + ", out of range or already taken";
    hit[static_cast<std::size_t>(t)] = 1;
  }

  // Child faces: the same vertices in the same cyclic order.
  child_map.faces.assign(static_cast<std::size_t>(child.face_count()), -1);
  std::vector<char> taken(child_map.faces.size(), 0);
  std::vector<Index> mapped;
  for (Index f = 0; f < child.face_count(); ++f) {
    mapped.clear();
    for (const Index v : child.face(f)) mapped.push_back(child_map.vertices[static_cast<std::size_t>(v)]);
    Far::Index match = -1;
    for (const Far::Index tf : their_child.GetVertexFaces(mapped.front()))
      if (!taken[static_cast<std::size_t>(tf)] && same_cycle(mapped, their_child.GetFaceVertices(tf))) {
        match = tf;
        break;
      }
    if (match == -1) return "our child face " + std::to_string(f) + " has no OpenSubdiv counterpart";
    taken[static_cast<std::size_t>(match)] = 1;
    child_map.faces[static_cast<std::size_t>(f)] = match;
  }
  return "";
}

}  // namespace subdiv::test
