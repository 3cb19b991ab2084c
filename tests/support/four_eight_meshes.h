#pragma once
// Control meshes of the quasi 4-8 tests (Velho, section 4): triangulated
// n-gons around a centre, regular 4-8 grids and tori, and a check of the
// regular 4-8 pattern.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"

namespace subdiv::test {

/// The n-gon of radius 1 triangulated around its centre, vertex 0; rim
/// vertex i (vertex i + 1) at angle 2 pi i / n, its radius perturbed by a
/// uniform value in [-noise, noise] (drawn from mt19937 bits, portable).
inline PolygonMesh ngon_fan(int n, double noise = 0.0, std::uint32_t seed = 1) {
  std::mt19937 bits(seed);
  std::vector<Vec3> p{{0, 0, 0}};
  for (int i = 0; i < n; ++i) {
    const double u = static_cast<double>(bits()) / 4294967296.0;  // [0, 1)
    const double r = 1.0 + noise * (2.0 * u - 1.0);
    const double a = 2.0 * std::numbers::pi * i / n;
    p.push_back({r * std::cos(a), r * std::sin(a), 0.0});
  }
  std::vector<std::vector<Index>> faces;
  for (int i = 0; i < n; ++i) faces.push_back({0, i + 1, (i + 1) % n + 1});
  return make_mesh(std::move(p), faces);
}

/// The regular 4-8 grid on [0, n] x [0, n] (unit squares, each cut by the
/// diagonal through its corners of even i + j: those have valence 8 inside,
/// the others 4). Vertex (i, j) is i + (n + 1) j.
inline PolygonMesh four_eight_grid(int n) {
  std::vector<Vec3> p;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) p.push_back({double(i), double(j), 0.0});
  const auto at = [n](int i, int j) { return static_cast<Index>(i + (n + 1) * j); };
  std::vector<std::vector<Index>> faces;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Index a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if ((i + j) % 2 == 0) {
        faces.push_back({a, b, c});
        faces.push_back({a, c, d});
      } else {
        faces.push_back({a, b, d});
        faces.push_back({b, c, d});
      }
    }
  return make_mesh(std::move(p), faces);
}

/// A torus (radii R, r) on an m x n grid (m around the axis, n around the
/// tube, both even) with the 4-8 diagonals of four_eight_grid: 4-8 regular,
/// no extraordinary vertex.
inline PolygonMesh four_eight_torus(int m, int n, double R, double r) {
  std::vector<Vec3> p;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < m; ++i) {
      const double u = 2.0 * std::numbers::pi * i / m, v = 2.0 * std::numbers::pi * j / n;
      p.push_back({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  const auto at = [m, n](int i, int j) { return static_cast<Index>((i % m) + m * (j % n)); };
  std::vector<std::vector<Index>> faces;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < m; ++i) {
      const Index a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if ((i + j) % 2 == 0) {
        faces.push_back({a, b, c});
        faces.push_back({a, c, d});
      } else {
        faces.push_back({a, b, d});
        faces.push_back({b, c, d});
      }
    }
  return make_mesh(std::move(p), faces);
}

/// Interior vertices (other than `skip`) that break the regular 4-8 pattern
/// (Velho, section 2.1): valence 4 or 8; a valence-4 vertex has only
/// valence-8 interior neighbours; around a valence-8 vertex, consecutive
/// interior neighbours alternate between valence 4 and 8. Neighbours that
/// are `skip` or on the boundary are not judged.
inline std::vector<Index> four_eight_irregular(const MeshTopology& t, Index skip = kInvalidIndex) {
  std::vector<Index> bad;
  const auto judged = [&](Index v) { return v != skip && t.vertex_kind(v) != VertexKind::boundary; };
  for (Index v = 0; v < t.vertex_count(); ++v) {
    if (!judged(v)) continue;
    const Index k = t.valence(v);
    bool ok = k == 4 || k == 8;
    const auto ring = t.vertex_edges(v);
    for (std::size_t j = 0; ok && j < ring.size(); ++j) {
      const Index a = t.other_vertex(ring[j], v), b = t.other_vertex(ring[(j + 1) % ring.size()], v);
      if (k == 4 && judged(a) && t.valence(a) != 8) ok = false;
      if (k == 8 && judged(a) && judged(b) && (t.valence(a) == 8) == (t.valence(b) == 8)) ok = false;
    }
    if (!ok) bad.push_back(v);
  }
  return bad;
}

}  // namespace subdiv::test
