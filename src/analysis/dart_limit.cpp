#include "analysis/dart_limit.h"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <mutex>
#include <numeric>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "subdiv/core/stencil_table.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/configuration.h"
#include "subdiv/refine/refine.h"
#include "subdiv/topology/split.h"

namespace subdiv::detail {

void add_dart(RingMesh& model, Index regular_valence) {
  const MeshTopology t(model.mesh);
  Index from = model.centre;
  Index e = t.corner_edge(t.vertex_corners(model.centre)[0]);
  while (true) {
    const auto [a, b] = t.edge_vertices(e);
    model.mesh.tags.creases.push_back({a, b, kInfiniteSharpness});
    const Index to = a == from ? b : a;
    const auto edges = t.vertex_edges(to);
    if (t.vertex_kind(to) != VertexKind::interior || static_cast<Index>(edges.size()) != regular_valence) break;
    const auto i = static_cast<std::size_t>(std::find(edges.begin(), edges.end(), e) - edges.begin());
    e = edges[(i + edges.size() / 2) % edges.size()];
    from = to;
  }
}

namespace {

/// A dart's masks with its sharp edge at ring position 0.
struct DartMasks {
  bool valid = false;
  Eigen::VectorXd position, tangent1, tangent2;  // over [centre, k edge neighbours, k face opposites]
};

DartMasks compute_dart_masks(const Scheme& scheme, int valence) {
  DartMasks out;
  const bool quads = scheme.split == SplitRule::quad;
  // Three face rings keep the ring mesh's boundary (sharp under edge_only)
  // two rings away from every row of the one-ring's image.
  RingMesh model = ring_mesh(scheme.split, Configuration{Configuration::Kind::interior, valence}, 3);
  add_dart(model, quads ? 4 : 6);
  const MeshTopology parent(model.mesh);
  const Index centre = model.centre;
  const auto edges = parent.vertex_edges(centre);
  const auto corners = parent.vertex_corners(centre);
  const auto k = static_cast<int>(edges.size());
  if (k != valence || static_cast<int>(corners.size()) != valence) return out;
  // Rotate the ring so that the sharp edge comes first.
  int sharp = -1;
  for (int i = 0; i < k; ++i)
    for (const CreaseTag& c : model.mesh.tags.creases)
      if (parent.find_edge(c.v0, c.v1) == edges[static_cast<std::size_t>(i)]) sharp = i;
  if (sharp < 0) return out;

  // The one-ring in limit_mask.h's layout, and its image one step down.
  PolygonMesh child_mesh;
  const SplitMap map = split_topology(model.mesh, parent, scheme.split, child_mesh);
  std::vector<Index> ring{centre};
  std::vector<Index> image{map.vertex_point(centre)};
  for (int i = 0; i < k; ++i) {
    const Index e = edges[static_cast<std::size_t>((sharp + i) % k)];
    ring.push_back(parent.other_vertex(e, centre));
    image.push_back(map.edge_point(e));
  }
  if (quads) {
    for (int j = 0; j < k; ++j) {
      const Index c = corners[static_cast<std::size_t>((sharp + j) % k)];
      ring.push_back(parent.corner_vertex(parent.corner_next(parent.corner_next(c))));
      image.push_back(map.face_point(parent.corner_face(c)));
    }
  }
  const auto size = static_cast<Eigen::Index>(ring.size());
  std::vector<Eigen::Index> column_of(static_cast<std::size_t>(parent.vertex_count()), -1);
  for (Eigen::Index i = 0; i < size; ++i) column_of[static_cast<std::size_t>(ring[static_cast<std::size_t>(i)])] = i;

  RefineOptions one_step;
  one_step.levels = 1;
  one_step.regular_grids = false;
  one_step.boundary = BoundaryInterpolation::edge_only;
  const StencilTable table = refine_stencil_table(model.mesh, scheme, one_step);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(size, size);
  for (Eigen::Index r = 0; r < size; ++r) {
    const Index row = image[static_cast<std::size_t>(r)];
    const auto vertices = table.row_vertices(row);
    const auto weights = table.row_weights(row);
    for (std::size_t e = 0; e < vertices.size(); ++e) {
      const Eigen::Index column = column_of[static_cast<std::size_t>(vertices[e])];
      if (column < 0) return out;  // not invariant
      S(r, column) += weights[e];
    }
  }

  // Position: the centre's row of S^256 (the subdominant powers vanish).
  Eigen::MatrixXd power = S;
  for (int i = 0; i < 8; ++i) power = power * power;
  out.position = power.row(0).transpose();

  // Tangents: the left eigenvectors of the two largest eigenvalues below 1
  // (the real and imaginary parts of one vector for a complex pair).
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(S.transpose());
  if (solver.info() != Eigen::Success) return out;
  const Eigen::VectorXcd values = solver.eigenvalues();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(size));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::sort(order.begin(), order.end(),
            [&](Eigen::Index a, Eigen::Index b) { return std::abs(values(a)) > std::abs(values(b)); });
  if (size < 4 || std::abs(values(order[0]) - 1.0) > 1e-9) return out;
  const std::complex<double> l1 = values(order[1]);
  const std::complex<double> l2 = values(order[2]);
  if (std::abs(l2) <= std::abs(values(order[3])) + 1e-9) return out;  // no pair separated from the rest
  if (std::abs(l1.imag()) > 1e-12) {
    const Eigen::VectorXcd v = solver.eigenvectors().col(order[1]);
    out.tangent1 = v.real();
    out.tangent2 = v.imag();
  } else {
    out.tangent1 = solver.eigenvectors().col(order[1]).real();
    out.tangent2 = solver.eigenvectors().col(order[2]).real();
  }
  // Orientation: on the planar layout, whose faces are counter-clockwise
  // seen from +z, tangent1 x tangent2 must point to +z.
  const auto apply = [&](const Eigen::VectorXd& mask) {
    Vec3 sum{};
    for (Eigen::Index i = 0; i < size; ++i)
      sum += mask(i) * model.mesh.positions[static_cast<std::size_t>(ring[static_cast<std::size_t>(i)])];
    return sum;
  };
  const Vec3 t1 = apply(out.tangent1);
  const Vec3 t2 = apply(out.tangent2);
  const double z = cross(t1, t2).z;
  if (!(std::fabs(z) > 1e-9 * norm(t1) * norm(t2))) return out;  // the pair does not span the plane
  if (z < 0.0) out.tangent2 = -out.tangent2;
  out.valid = true;
  return out;
}

const DartMasks& cached_dart_masks(const Scheme& scheme, int valence, DartMasks& uncached) {
  // The closed-form schemes have no parameters: their name and valence
  // determine the matrix. A scheme with parameters is computed each time.
  if (!std::holds_alternative<std::monostate>(scheme.parameters)) {
    uncached = compute_dart_masks(scheme, valence);
    return uncached;
  }
  static std::mutex mutex;
  static std::map<std::pair<std::string, int>, DartMasks> cache;
  const std::lock_guard lock(mutex);
  const auto key = std::make_pair(std::string(scheme.name), valence);
  auto found = cache.find(key);
  if (found == cache.end()) found = cache.emplace(key, compute_dart_masks(scheme, valence)).first;
  return found->second;
}

void write_mask(const Eigen::VectorXd& weights, int sharp, bool quads, LimitMask& mask) {
  const auto k = static_cast<int>((weights.size() - 1) / (quads ? 2 : 1));
  mask.reset(k, quads ? k : 0);
  mask.vertex = weights(0);
  for (int i = 0; i < k; ++i) {
    mask.edges[static_cast<std::size_t>((sharp + i) % k)] = weights(1 + i);
    if (quads) mask.faces[static_cast<std::size_t>((sharp + i) % k)] = weights(1 + k + i);
  }
}

}  // namespace

bool dart_limit_masks(const Scheme& scheme, const VertexNeighbourhood& neighbourhood, LimitMasks& masks) {
  if (scheme.split != SplitRule::quad && scheme.split != SplitRule::triangle) return false;
  const int k = neighbourhood.edges;
  if (k < 3 || neighbourhood.faces != k) return false;
  DartMasks uncached;
  const DartMasks& dart = cached_dart_masks(scheme, k, uncached);
  if (!dart.valid) return false;
  const bool quads = scheme.split == SplitRule::quad;
  write_mask(dart.position, neighbourhood.sharp[0], quads, masks.position);
  write_mask(dart.tangent1, neighbourhood.sharp[0], quads, masks.tangent1);
  write_mask(dart.tangent2, neighbourhood.sharp[0], quads, masks.tangent2);
  return true;
}

}  // namespace subdiv::detail
