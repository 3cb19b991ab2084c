// The regular rules of a scheme as a lattice rule (regular_smoothness.h),
// read off the scheme's own recorded stencils on a regular mesh.
//
// Parent vertex (i, j) of the regular mesh sits at lattice point (i, j). A
// child's lattice position is its row applied to its parents' lattice
// positions: this is the rule applied to linear data, which it reproduces
// when it reproduces linear functions (the test then confirms it). The
// children's lattice basis is two of a child's edges, taken in the order
// that makes the child mesh the parent's shape (quads: two edges in turn;
// triangles: e1 and e2 - e1 of two edges in turn), so the rule of the next
// step, in child indices, is the same rule.

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "subdiv/analysis/regular_smoothness.h"
#include "subdiv/core/error.h"

namespace subdiv {

namespace {

constexpr int kSize = 12;  // lattice period: masks reach a few points, wrap never

// A regular mesh: a torus (periodic in both directions) or a cylinder
// (periodic in x, rows 0 .. rows-1, boundaries at rows 0 and rows-1).
struct RegularMesh {
  PolygonMesh mesh;
  int columns = kSize;
  int rows = kSize;
  bool periodic_y = true;
};

RegularMesh regular_mesh(bool triangles, bool periodic_y) {
  RegularMesh r;
  r.periodic_y = periodic_y;
  if (!periodic_y) r.rows = kSize + 1;
  const int n = r.columns;
  const auto id = [&](int i, int j) { return static_cast<Index>(((i % n + n) % n) + n * (periodic_y ? (j % n + n) % n : j)); };
  for (int j = 0; j < r.rows; ++j)
    for (int i = 0; i < n; ++i) r.mesh.positions.push_back({static_cast<double>(i), static_cast<double>(j), 0.0});
  const int face_rows = periodic_y ? r.rows : r.rows - 1;
  for (int j = 0; j < face_rows; ++j)
    for (int i = 0; i < n; ++i) {
      const Index a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (triangles) {
        r.mesh.add_face({a, b, c});
        r.mesh.add_face({a, c, d});
      } else {
        r.mesh.add_face({a, b, c, d});
      }
    }
  return r;
}

bool takes_triangles(const Scheme& scheme) {
  return scheme.traits.needs_triangles || scheme.split == SplitRule::triangle || scheme.split == SplitRule::sqrt3;
}

// x reduced to the nearest image of `near` (periodic directions only).
Eigen::Vector2d unwrap(Eigen::Vector2d x, const Eigen::Vector2d& near, const RegularMesh& r) {
  x[0] -= r.columns * std::round((x[0] - near[0]) / r.columns);
  if (r.periodic_y) x[1] -= r.rows * std::round((x[1] - near[1]) / r.rows);
  return x;
}

Eigen::Vector2d lattice_point(const RegularMesh& r, Index v) {
  return {r.mesh.positions[static_cast<std::size_t>(v)].x, r.mesh.positions[static_cast<std::size_t>(v)].y};
}

// The integer x is, to rounding.
int rounded(double x, const std::string& what) {
  const double k = std::round(x);
  if (std::fabs(x - k) > 1e-6)
    throw InvalidInputError(what + ": the children are not on a lattice (the rules do not reproduce linear functions, "
                            "or the refined mesh is not regular there)");
  return static_cast<int>(k);
}

// Reads the rule of `levels` steps on `r`. With a boundary, children are
// keyed by their row above row 0.
LatticeRule read_rule(const Scheme& scheme, const RefineOptions& rules, RegularMesh r, int levels,
                      const std::string& what) {
  RefineOptions options = rules;
  options.levels = levels;
  options.threads = 1;
  options.start_level = 0;
  options.on_level = nullptr;
  const StencilTable table = refine_stencil_table(r.mesh, scheme, options);
  const PolygonMesh child = refine(r.mesh, scheme, options);  // its faces give the children's lattice basis
  if (table.row_count() != child.vertex_count())
    throw InvalidInputError(what + ": the stencils and the refined mesh disagree in size");

  // Child lattice positions, each in the frame of its row's first parent.
  std::vector<Eigen::Vector2d> x(static_cast<std::size_t>(table.row_count()));
  for (Index c = 0; c < table.row_count(); ++c) {
    const auto vertices = table.row_vertices(c);
    const auto weights = table.row_weights(c);
    const Eigen::Vector2d frame = lattice_point(r, vertices[0]);
    Eigen::Vector2d p = Eigen::Vector2d::Zero();
    for (std::size_t k = 0; k < vertices.size(); ++k) p += weights[k] * unwrap(lattice_point(r, vertices[k]), frame, r);
    x[static_cast<std::size_t>(c)] = p;
  }

  // The origin child: nearest the middle of row 0 (boundary) or of the torus.
  const Eigen::Vector2d middle(r.columns / 2.0, r.periodic_y ? r.rows / 2.0 : 0.0);
  Index origin = 0;
  double best = 1e300;
  for (Index c = 0; c < table.row_count(); ++c) {
    const Eigen::Vector2d d = unwrap(x[static_cast<std::size_t>(c)], middle, r) - middle;
    if (!r.periodic_y && std::fabs(x[static_cast<std::size_t>(c)][1]) > 1e-9) continue;
    const double dist = d.squaredNorm() + 1e-9 * (d[0] < 0 ? 1 : 0) + 1e-10 * (d[1] < 0 ? 1 : 0);
    if (dist < best) best = dist, origin = c;
  }
  if (!(best < 1e300)) throw InvalidInputError(what + ": no child on the boundary");
  const Eigen::Vector2d x0 = unwrap(x[static_cast<std::size_t>(origin)], middle, r);

  // Its neighbours in the child mesh, by angle from +x.
  std::vector<std::pair<double, Eigen::Vector2d>> neighbours;
  for (Index f = 0; f < child.face_count(); ++f) {
    const auto face = child.face(f);
    for (std::size_t k = 0; k < face.size(); ++k) {
      if (face[k] != origin) continue;
      for (const Index n : {face[(k + 1) % face.size()], face[(k + face.size() - 1) % face.size()]}) {
        const Eigen::Vector2d d = unwrap(x[static_cast<std::size_t>(n)], x0, r) - x0;
        double angle = std::atan2(d[1], d[0]);
        if (angle < -1e-9) angle += 2 * std::numbers::pi;
        if (std::none_of(neighbours.begin(), neighbours.end(),
                         [&](const auto& e) { return (e.second - d).norm() < 1e-9; }))
          neighbours.emplace_back(std::max(angle, 0.0), d);
      }
    }
  }
  std::sort(neighbours.begin(), neighbours.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const std::size_t expected = takes_triangles(scheme) ? 6 : 4;
  if (neighbours.size() != (r.periodic_y ? expected : expected / 2 + 1))
    throw InvalidInputError(fmt::format("{}: the refined mesh is not regular ({} neighbours at a child vertex)", what,
                                        neighbours.size()));
  const Eigen::Vector2d b1 = neighbours[0].second;
  const Eigen::Vector2d b2 = takes_triangles(scheme) ? Eigen::Vector2d(neighbours[1].second - b1) : neighbours[1].second;
  Eigen::Matrix2d basis;
  basis << b1, b2;
  const Eigen::Matrix2d to_child = basis.inverse();  // child index = to_child (x - x0)

  LatticeRule rule;
  rule.dimension = 2;
  rule.description = what;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) rule.dilation[a][b] = rounded(to_child(a, b), what);
  const auto& D = rule.dilation;
  if (D[0][0] * D[1][1] - D[0][1] * D[1][0] <= 1) throw InvalidInputError(what + ": the children do not refine the lattice");

  // Weights keyed by (child row or -1 for the interior, offset c - M j).
  std::map<std::pair<int, std::array<int, 2>>, double> weights;
  const int boundary_depth = 8;  // child rows keyed separately above the boundary
  for (Index c = 0; c < table.row_count(); ++c) {
    const Eigen::Vector2d xc = unwrap(x[static_cast<std::size_t>(c)], x0, r);
    if (!r.periodic_y && xc[1] > r.rows / 2.0) continue;  // the far boundary's children
    const Eigen::Vector2d index = to_child * (xc - x0);
    const std::array<int, 2> ci{rounded(index[0], what), rounded(index[1], what)};
    if (!r.periodic_y && ci[1] < 0) throw InvalidInputError(what + ": a child below the boundary");
    const int row = !r.periodic_y && ci[1] < boundary_depth ? ci[1] : -1;
    const auto vertices = table.row_vertices(c);
    const auto row_weights = table.row_weights(c);
    std::map<std::array<int, 2>, double> entries;
    for (std::size_t k = 0; k < vertices.size(); ++k) {
      const Eigen::Vector2d j = unwrap(lattice_point(r, vertices[k]), xc, r);
      // Parent coordinates from the parent point at the child origin, so that
      // child 0 and parent 0 sit together (up to the dual splits' offset).
      const int j0 = static_cast<int>(std::lround(j[0] - std::round(x0[0])));
      const int j1 = static_cast<int>(std::lround(j[1] - std::round(x0[1])));
      const auto& M = rule.dilation;
      entries[{ci[0] - M[0][0] * j0 - M[0][1] * j1, ci[1] - M[1][0] * j0 - M[1][1] * j1}] += row_weights[k];
    }
    for (const auto& [offset, w] : entries) {
      if (w == 0.0) continue;
      const auto [it, inserted] = weights.try_emplace({row, offset}, w);
      if (!inserted && std::fabs(it->second - w) > 1e-12)
        throw InvalidInputError(fmt::format("{}: the rule is not shift-invariant (offset ({}, {}): {} and {})", what,
                                            offset[0], offset[1], it->second, w));
    }
  }
  for (const auto& [key, w] : weights) {
    const LatticeWeight entry{key.second, w};
    if (key.first < 0) {
      rule.mask.push_back(entry);
    } else {
      if (rule.boundary_rows.size() <= static_cast<std::size_t>(key.first))
        rule.boundary_rows.resize(static_cast<std::size_t>(key.first) + 1);
      rule.boundary_rows[static_cast<std::size_t>(key.first)].push_back(entry);
    }
  }
  if (!r.periodic_y) rule.boundary_rows.resize(boundary_depth);
  return rule;
}

}  // namespace

LatticeRule regular_interior_rule(const Scheme& scheme, const RefineOptions& rules) {
  const std::string what = fmt::format("{}: regular interior rule", scheme.name);
  return read_rule(scheme, rules, regular_mesh(takes_triangles(scheme), true), 1, what);
}

LatticeRule regular_boundary_rule(const Scheme& scheme, const RefineOptions& rules) {
  const std::string what = fmt::format("{}: regular boundary rule", scheme.name);
  if (scheme.traits.needs_closed_mesh) throw InvalidInputError(what + ": the scheme has no boundary rules");
  LatticeRule rule = read_rule(scheme, rules, regular_mesh(takes_triangles(scheme), false), scheme.traits.period, what);
  const auto& M = rule.dilation;
  if (M[0][1] != 0 || M[1][0] != 0 || M[0][0] != M[1][1])
    throw InvalidInputError(what + ": the children's lattice turns against the boundary");
  return rule;
}

LatticeRule curve_lattice_rule(const CurveScheme& scheme) {
  // Child 2i + e <- mask_e anchored at i: offset c - 2 j = e - 2 o. Dual
  // schemes' children sit a quarter step off the parents; the lattice
  // index needs no offset (linear data stay linear in the index).
  LatticeRule rule;
  rule.dimension = 1;
  rule.dilation = {{{2, 0}, {0, 0}}};
  rule.description = fmt::format("{}: curve rule", scheme.name);
  std::map<int, double> mask;
  for (int e = 0; e < 2; ++e)
    for (const CurveMaskEntry& entry : e == 0 ? scheme.even : scheme.odd) mask[e - 2 * entry.offset] += entry.weight;
  for (const auto& [offset, w] : mask)
    if (w != 0.0) rule.mask.push_back({{offset, 0}, w});
  return rule;
}

}  // namespace subdiv
