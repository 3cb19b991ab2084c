// The quasi 4-8 eigenstructure experiment (quasi_4_8_experiment.h).

#include "subdiv/analysis/quasi_4_8_experiment.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <optional>

#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/quasi_4_8.h"
#include "subdiv/topology/bisection_split.h"

namespace subdiv {

namespace {

RefineOptions one_step() {
  RefineOptions o;
  o.levels = 1;
  return o;
}

// The child vertex that edge (c, w) of `parent` leads to from c: w, or the
// split point of (c, w) (bisection_split numbers them V + rank).
Index follow(const PolygonMesh& parent, Index c, Index w) {
  const MeshTopology t(parent);
  const Index e = t.find_edge(c, w);
  if (e == kInvalidIndex) throw InvalidInputError("quasi 4-8 experiment: no edge to follow");
  const std::vector<char> split = bisection_split_edges(t, parent.positions);
  if (!split[static_cast<std::size_t>(e)]) return w;
  const auto rank = std::count(split.begin(), split.begin() + e, char{1});
  return t.vertex_count() + static_cast<Index>(rank);
}

// A canonical numbering of the r-ring: breadth first, each ring from the
// edge to the vertex's parent (the centre's from `first`). Empty when a
// ring in it is not ordered or reaches the mesh boundary.
struct Neighbourhood {
  std::vector<Index> vertices;              // by label
  std::vector<int> label;                   // per mesh vertex, -1 outside
  std::vector<std::vector<int>> adjacency;  // per label: neighbour labels in ring order, -1 outside
  std::vector<int> distance;                // per label
};

bool number(const MeshTopology& t, Index centre, Index first, int rings, Neighbourhood& n) {
  n = Neighbourhood{};
  n.label.assign(static_cast<std::size_t>(t.vertex_count()), -1);
  std::vector<Index> reference(static_cast<std::size_t>(t.vertex_count()), kInvalidIndex);
  std::deque<Index> queue{centre};
  n.label[static_cast<std::size_t>(centre)] = 0;
  n.vertices.push_back(centre);
  n.distance.push_back(0);
  reference[static_cast<std::size_t>(centre)] = first;
  while (!queue.empty()) {
    const Index u = queue.front();
    queue.pop_front();
    if (!t.ring_ordered(u) || t.vertex_kind(u) == VertexKind::boundary) return false;
    const auto edges = t.vertex_edges(u);
    std::vector<Index> ring;
    for (const Index e : edges) ring.push_back(t.other_vertex(e, u));
    const auto start = std::find(ring.begin(), ring.end(), reference[static_cast<std::size_t>(u)]);
    if (start == ring.end()) return false;
    std::rotate(ring.begin(), start, ring.end());
    const int d = n.distance[static_cast<std::size_t>(n.label[static_cast<std::size_t>(u)])];
    for (const Index w : ring)
      if (n.label[static_cast<std::size_t>(w)] < 0 && d + 1 <= rings) {
        n.label[static_cast<std::size_t>(w)] = static_cast<int>(n.vertices.size());
        n.vertices.push_back(w);
        n.distance.push_back(d + 1);
        reference[static_cast<std::size_t>(w)] = u;
        if (d + 1 < rings) queue.push_back(w);
      }
  }
  n.adjacency.resize(n.vertices.size());
  // Adjacency of the inner vertices (distance < rings), in ring order.
  for (std::size_t i = 0; i < n.vertices.size(); ++i) {
    if (n.distance[i] >= rings) continue;
    const Index u = n.vertices[i];
    std::vector<Index> ring;
    for (const Index e : t.vertex_edges(u)) ring.push_back(t.other_vertex(e, u));
    std::rotate(ring.begin(), std::find(ring.begin(), ring.end(), reference[static_cast<std::size_t>(u)]), ring.end());
    for (const Index w : ring) n.adjacency[i].push_back(n.label[static_cast<std::size_t>(w)]);
  }
  return true;
}

// The characteristic map: the subdominant eigenvectors of the wider
// neighbourhood's matrix S, when its pair is the experiment's.
bool check_characteristic_map(const PolygonMesh& coarse, const std::vector<Index>& labels, const Eigen::MatrixXd& S,
                              Quasi48Experiment& x, int steps) {
  const std::optional<SubdominantPair> pair = subdominant_eigenvectors(S);
  if (!pair || std::abs(pair->lambda1 - x.leading[1]) > 1e-9 || std::abs(pair->lambda2 - x.leading[2]) > 1e-9)
    return false;
  std::vector<Vec3> values(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i)
    values[i] = {pair->vectors[0](static_cast<Eigen::Index>(i)), pair->vectors[1](static_cast<Eigen::Index>(i)), 0.0};
  const PiecewiseLinearMap map = piecewise_linear_map(coarse, labels, values, steps);
  x.charmap_faces = map.faces;
  x.charmap_flipped = map.flipped;
  x.charmap_winding = map.winding;
  x.charmap_regular = map.regular;
  return true;
}

}  // namespace

PiecewiseLinearMap piecewise_linear_map(const PolygonMesh& coarse, std::span<const Index> vertices,
                                        std::span<const Vec3> values, int steps) {
  if (vertices.size() != values.size() || vertices.empty() || steps < 1)
    throw InvalidInputError("piecewise-linear map: one value per vertex, at least one vertex and one step");
  std::vector<char> inside(static_cast<std::size_t>(coarse.vertex_count()), 0);
  std::vector<Vec3> data(static_cast<std::size_t>(coarse.vertex_count()));
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    inside[static_cast<std::size_t>(vertices[i])] = 1;
    data[static_cast<std::size_t>(vertices[i])] = {values[i].x, values[i].y, 0.0};
  }
  RefineOptions o;
  o.levels = 2 * steps;
  PolygonMesh fine;
  const StencilTable total = compose(refine_stencils(coarse, quasi_4_8_scheme(), o, &fine));
  std::vector<Vec3> image(static_cast<std::size_t>(total.row_count()));
  total.apply(data, image);
  // Known: the child vertices whose rows lie inside the neighbourhood.
  std::vector<char> known(image.size(), 1);
  for (Index r = 0; r < total.row_count(); ++r) {
    const auto vs = total.row_vertices(r);
    const auto ws = total.row_weights(r);
    for (std::size_t j = 0; j < vs.size(); ++j)
      if (ws[j] != 0.0 && !inside[static_cast<std::size_t>(vs[j])]) known[static_cast<std::size_t>(r)] = 0;
  }
  double scale = 0.0;
  for (std::size_t v = 0; v < image.size(); ++v)
    if (known[v]) scale = std::max(scale, norm(image[v]));
  int positive = 0, negative = 0, degenerate = 0;
  for (Index f = 0; f < fine.face_count(); ++f) {
    const auto vs = fine.face(f);
    if (!known[static_cast<std::size_t>(vs[0])] || !known[static_cast<std::size_t>(vs[1])] ||
        !known[static_cast<std::size_t>(vs[2])])
      continue;
    const Vec3 a = image[static_cast<std::size_t>(vs[0])];
    const double area = cross(image[static_cast<std::size_t>(vs[1])] - a, image[static_cast<std::size_t>(vs[2])] - a).z;
    if (std::abs(area) <= 1e-12 * scale * scale)
      ++degenerate;
    else
      (area > 0 ? positive : negative) += 1;
  }
  PiecewiseLinearMap map;
  map.faces = positive + negative + degenerate;
  map.flipped = std::min(positive, negative) + degenerate;
  // The winding of the centre's ring around the centre's image.
  const MeshTopology t(fine);
  const Index centre = vertices.front();
  const Vec3 c = image[static_cast<std::size_t>(centre)];
  double turn = 0.0;
  const auto ring = t.vertex_edges(centre);
  for (std::size_t j = 0; j < ring.size(); ++j) {
    const Vec3 p = image[static_cast<std::size_t>(t.other_vertex(ring[j], centre))] - c;
    const Vec3 q = image[static_cast<std::size_t>(t.other_vertex(ring[(j + 1) % ring.size()], centre))] - c;
    turn += std::atan2(p.x * q.y - p.y * q.x, p.x * q.x + p.y * q.y);
  }
  map.winding = static_cast<int>(std::lround(turn / (2.0 * std::numbers::pi)));
  map.regular = map.faces > 0 && map.flipped == 0 && std::abs(map.winding) == 1;
  return map;
}

Quasi48Experiment quasi_4_8_experiment(const PolygonMesh& control, Index centre, int warmup, int max_rings,
                                       int charmap_steps) {
  if (warmup < 0) throw InvalidInputError("quasi 4-8 experiment: warm-up steps must be >= 0");
  if (centre < 0 || centre >= control.vertex_count())
    throw InvalidInputError("quasi 4-8 experiment: vertex " + std::to_string(centre) + " is not in the mesh");
  const Scheme& scheme = quasi_4_8_scheme();
  Quasi48Experiment x;
  x.warmup = warmup;
  RefineOptions warm;
  warm.levels = warmup;
  const PolygonMesh coarse = refine(control, scheme, warm);
  PolygonMesh mid, fine;
  const StencilTable t1 = refine_stencils(coarse, scheme, one_step(), &mid).front();
  const StencilTable t2 = refine_stencils(mid, scheme, one_step(), &fine).front();
  const StencilTable two = t1.then(t2);
  const MeshTopology ct(coarse), ft(fine);
  x.centre_valence = ct.valence(centre);
  if (ct.vertex_edges(centre).empty()) throw InvalidInputError("quasi 4-8 experiment: the centre has no edges");
  const Index first = ct.other_vertex(ct.vertex_edges(centre)[0], centre);
  const Index first_fine = follow(mid, centre, follow(coarse, centre, first));
  // The matrix on the r-ring, when both levels' r-rings match and the
  // finer one's rows stay inside the coarser one; `why` says otherwise.
  struct Local {
    Eigen::MatrixXd S;
    std::vector<Index> coarse;  // by label
  };
  const auto local = [&](int r, std::string& why) -> std::optional<Local> {
    Neighbourhood a, b;
    if (!number(ct, centre, first, r, a) || !number(ft, centre, first_fine, r, b)) {
      why = "the " + std::to_string(r) + "-ring reaches the boundary or an unordered ring";
      return std::nullopt;
    }
    if (a.vertices.size() != b.vertices.size() || a.adjacency != b.adjacency) {
      why = "the " + std::to_string(r) + "-rings one 4-8 step apart differ in topology";
      return std::nullopt;
    }
    const auto m = static_cast<Eigen::Index>(a.vertices.size());
    Local l{Eigen::MatrixXd::Zero(m, m), a.vertices};
    for (Eigen::Index i = 0; i < m; ++i) {
      const Index row = b.vertices[static_cast<std::size_t>(i)];
      const auto vs = two.row_vertices(row);
      const auto ws = two.row_weights(row);
      for (std::size_t j = 0; j < vs.size(); ++j) {
        const int col = a.label[static_cast<std::size_t>(vs[j])];
        if (col >= 0)
          l.S(i, col) += ws[j];
        else if (ws[j] != 0.0) {
          why = "the " + std::to_string(r) + "-ring is not invariant";
          return std::nullopt;
        }
      }
    }
    return l;
  };
  for (int r = 1; r <= max_rings; ++r) {
    const std::optional<Local> l = local(r, x.note);
    if (!l) {
      if (x.note.find("boundary") != std::string::npos) break;
      continue;
    }
    x.rings = r;
    x.size = static_cast<int>(l->coarse.size());
    x.S = l->S;
    x.note.clear();
    break;
  }
  if (x.rings == 0) {
    x.note = "no r-ring, r <= " + std::to_string(max_rings) +
             ", is the same one 4-8 step later and invariant (the last: " + x.note + ")";
    return x;
  }
  x.spectrum = spectrum(x.S);
  const auto all = x.spectrum.expanded();
  x.leading.assign(all.begin(), all.begin() + std::min<std::ptrdiff_t>(5, static_cast<std::ptrdiff_t>(all.size())));
  const double tol = 1e-9;
  const auto& l = x.leading;
  if (l.size() < 4) {
    x.note = "neighbourhood too small for the eigenvalue condition";
  } else if (std::abs(l[0] - 1.0) > tol || std::abs(l[1] - 1.0) < tol) {
    x.note = "lambda_0 = 1 is not simple and dominant";
  } else if (std::abs(l[1].imag()) > tol || std::abs(l[1] - l[2]) > tol) {
    x.note = "lambda_1, lambda_2 are not a real double eigenvalue";
  } else if (!(std::abs(l[1]) > std::abs(l[3]) + tol)) {
    x.note = "lambda_1 does not dominate |lambda_3|";
  } else {
    x.eigenvalue_condition = true;
  }
  if (x.eigenvalue_condition && charmap_steps > 0) {
    // The map is refined from a wider neighbourhood (three more rings), so
    // that the refined faces cover the r-ring's region, not a smaller copy.
    std::string why;
    const std::optional<Local> wide = local(x.rings + 3, why);
    if (!wide)
      x.note = "no characteristic map: " + why;
    else if (!check_characteristic_map(coarse, wide->coarse, wide->S, x, charmap_steps))
      x.note = "no characteristic map: the wider matrix's subdominant pair is not the same";
  }
  return x;
}

Quasi48Experiment quasi_4_8_ngon_experiment(int n, int warmup, int max_rings, int charmap_steps) {
  if (n < 3) throw InvalidInputError("quasi 4-8 experiment: n must be >= 3, not " + std::to_string(n));
  std::vector<Vec3> p{{0, 0, 0}};
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    p.push_back({std::cos(a), std::sin(a), 0.0});
  }
  std::vector<std::vector<Index>> faces;
  for (int i = 0; i < n; ++i) faces.push_back({0, i + 1, (i + 1) % n + 1});
  return quasi_4_8_experiment(make_mesh(std::move(p), faces), 0, warmup, max_rings, charmap_steps);
}

}  // namespace subdiv
