#include "piecewise_smooth.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <string>
#include <tuple>

#include "../core/row_accumulator.h"
#include "subdiv/refine/subdivision_matrix.h"
#include "subdiv/core/error.h"

namespace subdiv::detail {

namespace {

constexpr double kPi = std::numbers::pi;

// Corner tags by vertex (the last tag wins, as for sharpness).
std::vector<const CornerTag*> corner_tags_by_vertex(const PolygonMesh& mesh, Index vertex_count) {
  std::vector<const CornerTag*> out(static_cast<std::size_t>(vertex_count), nullptr);
  for (const CornerTag& c : mesh.tags.corners)
    if (c.vertex >= 0 && c.vertex < vertex_count) out[static_cast<std::size_t>(c.vertex)] = &c;
  return out;
}

int sharp_edge_count(const MeshTopology& t, const LevelCreasing& creasing, Index v) {
  int n = 0;
  for (const Index e : t.vertex_edges(v)) n += edge_sharpness_of(creasing, e) > 0.0;
  return n;
}

// The angle of a corner's sectors: its tag's angle, else the type's default
// at a boundary corner, else an even share of the full turn.
double corner_alpha(const MeshTopology& t, Index v, const CornerTag* tag, int sharp_edges) {
  if (tag && tag->angle) return *tag->angle;
  if (t.vertex_kind(v) == VertexKind::boundary)
    return tag && tag->type == CornerType::concave ? 1.5 * kPi : 0.5 * kPi;
  return 2.0 * kPi / std::max(1, sharp_edges);
}

double angle_between(const Vec3& a, const Vec3& b) {
  const double c = dot(a, b), s = norm(cross(a, b));
  return std::atan2(s, c);
}

}  // namespace

std::vector<double> sector_angles(const PolygonMesh& mesh, const MeshTopology& t, const LevelCreasing& creasing) {
  std::vector<double> alpha(static_cast<std::size_t>(t.vertex_count()), 0.0);
  const auto tags = corner_tags_by_vertex(mesh, t.vertex_count());
  for (Index v = 0; v < t.vertex_count(); ++v) {
    const auto vi = static_cast<std::size_t>(v);
    const VertexRule rule = creasing.vertex_rule[vi];
    if ((rule != VertexRule::crease && rule != VertexRule::corner) || !t.ring_ordered(v)) continue;
    const int sharp = sharp_edge_count(t, creasing, v);
    if (sharp < 2) continue;  // no sector is bounded by sharp edges
    alpha[vi] = rule == VertexRule::crease ? kPi : corner_alpha(t, v, tags[vi], sharp);
  }
  return alpha;
}

void measure_corner_angles(PolygonMesh& mesh, const MeshTopology& t) {
  for (CornerTag& c : mesh.tags.corners) {
    if (c.angle || c.vertex < 0 || c.vertex >= t.vertex_count()) continue;
    if (t.vertex_kind(c.vertex) != VertexKind::boundary || !t.ring_ordered(c.vertex)) continue;
    const auto edges = t.vertex_edges(c.vertex);
    const Vec3 p = mesh.positions[static_cast<std::size_t>(c.vertex)];
    const Vec3 a = mesh.positions[static_cast<std::size_t>(t.other_vertex(edges.front(), c.vertex))] - p;
    const Vec3 b = mesh.positions[static_cast<std::size_t>(t.other_vertex(edges.back(), c.vertex))] - p;
    const double measured = angle_between(a, b);
    if (!(measured > 0.0)) continue;  // coincident edges: keep the fixed angle
    c.angle = c.type == CornerType::concave ? 2.0 * kPi - measured : measured;
  }
}

std::shared_ptr<const FlatnessSpectrum> flatness_spectrum(const Scheme& scheme, int k, double alpha) {
  static std::mutex mutex;
  // Keyed by what the rules are, not by the Scheme's address: schemes are
  // values, and copies (with other parameters, or made by the analysis) come
  // and go.
  using Key = std::tuple<std::string, double, int, double>;
  static std::map<Key, std::shared_ptr<const FlatnessSpectrum>> cache;
  const TensionParameters* tension = tension_parameters(scheme.parameters);
  const Key key{std::string(scheme.name), tension ? tension->tension : 0.0, k, alpha};
  {
    const std::lock_guard lock(mutex);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
  }
  RefineOptions rules;
  rules.boundary_rules = BoundaryRules::piecewise_smooth;
  rules.flatness = 0.0;
  Configuration corner;
  corner.kind = Configuration::Kind::corner;
  corner.k = k;
  corner.corner = CornerType::concave;
  corner.angle = alpha;
  const Eigen::MatrixXd S = local_subdivision_matrix(scheme, corner, 1, rules).S;
  const Eigen::Index n = S.rows();
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);

  // The right and left eigenspaces of 1 (the limit point) and 1/2 (the two
  // boundary curves' tangents).
  auto kernel = [](const Eigen::MatrixXd& m) {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(m);
    lu.setThreshold(1e-10);
    return Eigen::MatrixXd(lu.kernel());
  };
  const Eigen::MatrixXd x1 = kernel(S - I), xh = kernel(S - 0.5 * I);
  const Eigen::MatrixXd l1 = kernel(S.transpose() - I), lh = kernel(S.transpose() - 0.5 * I);
  if (x1.cols() != 1 || l1.cols() != 1 || xh.cols() != 2 || lh.cols() != 2)
    throw InvalidInputError(std::string(scheme.name) + ": " + corner.name() +
                            ": the flatness modification needs eigenvalue 1 once and 1/2 twice, each with a full "
                            "eigenspace");
  Eigen::MatrixXd X(n, 3), L(n, 3);
  X << x1, xh;
  L << l1, lh;
  auto spectrum = std::make_shared<FlatnessSpectrum>();
  spectrum->projector = X * (L.transpose() * X).inverse() * L.transpose();

  // lambda_3: the largest eigenvalue left once 1 and the pair 1/2 are taken.
  const Eigen::VectorXcd values = Eigen::EigenSolver<Eigen::MatrixXd>(S, false).eigenvalues();
  std::vector<std::complex<double>> rest(values.data(), values.data() + values.size());
  for (const double taken : {1.0, 0.5, 0.5}) {
    const auto it = std::min_element(rest.begin(), rest.end(), [&](auto a, auto b) {
      return std::abs(a - taken) < std::abs(b - taken);
    });
    rest.erase(it);
  }
  for (const auto& z : rest) spectrum->lambda3 = std::max(spectrum->lambda3, std::abs(z));

  const std::lock_guard lock(mutex);
  return cache.emplace(key, std::move(spectrum)).first->second;
}

std::vector<FlatnessSite> flatness_sites(const Scheme& scheme, const MeshTopology& t, const LevelCreasing& creasing,
                                         std::span<const double> sector_angle, const SplitMap& map,
                                         const RefineOptions& options) {
  std::vector<FlatnessSite> sites;
  if (options.boundary_rules != BoundaryRules::piecewise_smooth || sector_angle.empty()) return sites;
  if (options.flatness && *options.flatness == 0.0) return sites;
  if (options.flatness && !(*options.flatness > 0.0 && *options.flatness <= 1.0))
    throw InvalidInputError("the flatness parameter must be in [0, 1], not " + std::to_string(*options.flatness));
  const bool quads = scheme.split == SplitRule::quad;
  for (Index v = 0; v < t.vertex_count(); ++v) {
    const auto vi = static_cast<std::size_t>(v);
    const double alpha = sector_angle[vi];
    if (creasing.vertex_rule[vi] != VertexRule::corner || alpha <= kPi) continue;
    if (t.vertex_kind(v) != VertexKind::boundary || sharp_edge_count(t, creasing, v) != 2) continue;
    const Index k = t.vertex_face_count(v);
    if (k < 2) continue;

    const auto spectrum = flatness_spectrum(scheme, k, alpha);
    double s = options.flatness.value_or(spectrum->lambda3 > 0.25 ? 1.0 - 0.25 / spectrum->lambda3 : 0.0);
    if (s == 0.0) continue;
    const Eigen::Index n = spectrum->projector.rows();
    auto modification = std::make_shared<Eigen::MatrixXd>((1.0 - s) * Eigen::MatrixXd::Identity(n, n) +
                                                          s * spectrum->projector);
    FlatnessSite site;
    site.child_ring.push_back(map.vertex_point(v));
    const auto corners = t.vertex_corners(v);
    for (const Index c : corners) {
      site.child_ring.push_back(map.edge_point(t.corner_edge(c)));
      if (quads) site.child_ring.push_back(map.face_point(t.corner_face(c)));
    }
    site.child_ring.push_back(map.edge_point(t.corner_edge(t.corner_prev(corners.back()))));
    if (static_cast<Eigen::Index>(site.child_ring.size()) != n)
      throw InvalidInputError(std::string(scheme.name) + ": concave corner at vertex " + std::to_string(v) +
                              ": its one-ring (" + std::to_string(site.child_ring.size()) +
                              " vertices) does not match the corner configuration's (" + std::to_string(n) + ")");
    site.modification = std::move(modification);
    sites.push_back(std::move(site));
  }
  return sites;
}

void apply_flatness(const std::vector<FlatnessSite>& sites, PolygonMesh& child) {
  for (const FlatnessSite& site : sites) {
    const Eigen::MatrixXd& M = *site.modification;
    const auto n = static_cast<Eigen::Index>(site.child_ring.size());
    auto modify = [&](auto read, auto write, int components) {
      Eigen::MatrixXd p(n, components);
      for (Eigen::Index i = 0; i < n; ++i) read(site.child_ring[static_cast<std::size_t>(i)], p.row(i));
      const Eigen::MatrixXd q = M * p;
      for (Eigen::Index i = 0; i < n; ++i) write(site.child_ring[static_cast<std::size_t>(i)], q.row(i));
    };
    modify([&](Index v, auto row) {
             const Vec3& x = child.positions[static_cast<std::size_t>(v)];
             row << x.x, x.y, x.z;
           },
           [&](Index v, const auto& row) { child.positions[static_cast<std::size_t>(v)] = {row(0), row(1), row(2)}; },
           3);
    for (VertexChannel& channel : child.vertex_channels) {
      const int c = channel.components;
      double* values = channel.values.data();
      modify([&](Index v, auto row) {
               for (int j = 0; j < c; ++j) row(j) = values[static_cast<std::size_t>(v) * static_cast<std::size_t>(c) + static_cast<std::size_t>(j)];
             },
             [&](Index v, const auto& row) {
               for (int j = 0; j < c; ++j) values[static_cast<std::size_t>(v) * static_cast<std::size_t>(c) + static_cast<std::size_t>(j)] = row(j);
             },
             c);
    }
  }
}

void apply_flatness(const std::vector<FlatnessSite>& sites, StencilTable& table) {
  if (sites.empty()) return;
  for (const FlatnessSite& site : sites) {
    // The site's new rows, combinations of its current rows.
    RowAccumulator acc(table.source_count());
    std::map<Index, std::pair<std::vector<Index>, std::vector<double>>> rows;
    const Eigen::MatrixXd& M = *site.modification;
    for (std::size_t i = 0; i < site.child_ring.size(); ++i) {
      for (std::size_t j = 0; j < site.child_ring.size(); ++j) {
        const double w = M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        if (w != 0.0) acc.add_row(table, site.child_ring[j], w);
      }
      auto& [vertices, weights] = rows[site.child_ring[i]];
      acc.emit(vertices, weights);
    }
    StencilTable modified(table.source_count());
    modified.reserve(static_cast<std::size_t>(table.row_count()), table.entry_count() + 8 * site.child_ring.size());
    for (Index r = 0; r < table.row_count(); ++r) {
      if (auto it = rows.find(r); it != rows.end()) modified.append_row(it->second.first, it->second.second);
      else modified.append_row(table.row_vertices(r), table.row_weights(r));
    }
    table = std::move(modified);
  }
}

}  // namespace subdiv::detail
