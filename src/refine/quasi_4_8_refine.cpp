// Refinement with the quasi 4-8 scheme: bisection on the level's positions,
// then Algorithm 2 (rules/quasi_4_8.cpp) in place or recorded as stencils.

#include "quasi_4_8_refine.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "row_accumulator.h"
#include "subdiv/core/error.h"
#include "subdiv/rules/quasi_4_8.h"

namespace subdiv::detail {

namespace {

// What refine.cpp's common checks leave to this path: options that have no
// meaning for the scheme, and holes.
void check_quasi_4_8(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                     const SourceLines* lines) {
  const std::string name(scheme.name);
  if (options.boundary_rules == BoundaryRules::piecewise_smooth)
    throw InvalidInputError(name + " has no piecewise-smooth rules; use the standard boundary rules");
  if (options.allow_non_manifold) throw InvalidInputError(name + " cannot refine non-manifold meshes");
  if (!mesh.tags.holes.empty()) {
    const std::string at = lines && !lines->path.empty() ? lines->path + ": " : std::string();
    throw InvalidInputError(at + name + " has no rules for holes, but face " + std::to_string(mesh.tags.holes[0]) +
                            " is tagged as a hole");
  }
  check_refinable(mesh, scheme, options, lines);
}

// One level: the bisected child, its topology (the next level's parent
// topology) and what smoothing keeps.
struct Step {
  Step(const PolygonMesh& parent, MeshTopology topology, const Scheme& scheme)
      : parent_topology(std::move(topology)),
        map(bisection_split(parent, parent_topology, child)),
        child_topology(child),
        fixed(quasi_4_8_fixed_vertices(child, child_topology,
                                       std::get<Quasi48Parameters>(scheme.parameters).boundary)) {}
  Quasi48Level view() const { return {child_topology, map, fixed, parent_topology}; }

  MeshTopology parent_topology;
  PolygonMesh child;
  BisectionMap map;
  MeshTopology child_topology;
  std::vector<char> fixed;
};

// Runs mask(level, v, builder) then fn(v, builder) for v in [begin, end).
template <typename Mask, typename Fn>
void for_each_mask(const Quasi48Level& level, Index begin, Index end, Mask&& mask, Fn&& fn) {
  tbb::parallel_for(tbb::blocked_range<Index>(begin, end, 2048), [&](const tbb::blocked_range<Index>& range) {
    MaskBuilder builder;
    for (Index v = range.begin(); v != range.end(); ++v) {
      builder.clear();
      mask(level, v, builder);
      fn(v, builder);
    }
  });
}

// Algorithm 2 in place on values of k doubles per child vertex (old
// vertices holding their parent values): pass 1 writes only new vertices
// from old ones, pass 2 only old vertex v from v and the new vertices.
void smooth_in_place(const Quasi48Level& level, double* values, std::size_t k) {
  const Index old_count = level.map.old_vertex_count;
  for_each_mask(level, old_count, level.map.child_vertex_count(), quasi_4_8_new_vertex_mask,
                [&](Index v, const MaskBuilder& m) {
                  double* out = values + static_cast<std::size_t>(v) * k;
                  std::fill(out, out + k, 0.0);
                  for (std::size_t j = 0; j < m.vertices().size(); ++j)
                    for (std::size_t c = 0; c < k; ++c)
                      out[c] += m.weights()[j] * values[static_cast<std::size_t>(m.vertices()[j]) * k + c];
                });
  for_each_mask(level, 0, old_count, quasi_4_8_old_vertex_mask, [&](Index v, const MaskBuilder& m) {
    thread_local std::vector<double> acc;  // v's new value, kept apart until complete
    acc.assign(k, 0.0);
    for (std::size_t j = 0; j < m.vertices().size(); ++j)
      for (std::size_t c = 0; c < k; ++c)
        acc[c] += m.weights()[j] * values[static_cast<std::size_t>(m.vertices()[j]) * k + c];
    for (std::size_t j = 0; j < m.face_points().size(); ++j)
      for (std::size_t c = 0; c < k; ++c)
        acc[c] += m.face_point_weights()[j] * values[static_cast<std::size_t>(old_count + m.face_points()[j]) * k + c];
    std::copy(acc.begin(), acc.end(), values + static_cast<std::size_t>(v) * k);
  });
}

// The masks composed into rows child vertex <- parent vertex: new rows
// first (pass 1), then old rows through them (pass 2), emitted in child order.
StencilTable record(const Quasi48Level& level) {
  const Index old_count = level.map.old_vertex_count;
  StencilTable fresh(old_count);  // new vertices' rows
  append_rows(fresh, old_count, level.map.child_vertex_count(), [&](Index v, RowAccumulator& row) {
    MaskBuilder m;
    quasi_4_8_new_vertex_mask(level, v, m);
    for (std::size_t j = 0; j < m.vertices().size(); ++j) row.add(m.vertices()[j], m.weights()[j]);
  });
  StencilTable table(old_count);
  append_rows(table, 0, old_count, [&](Index v, RowAccumulator& row) {
    MaskBuilder m;
    quasi_4_8_old_vertex_mask(level, v, m);
    for (std::size_t j = 0; j < m.vertices().size(); ++j) row.add(m.vertices()[j], m.weights()[j]);
    for (std::size_t j = 0; j < m.face_points().size(); ++j)
      row.add_row(fresh, m.face_points()[j], m.face_point_weights()[j]);
  });
  for (Index r = 0; r < fresh.row_count(); ++r) table.append_row(fresh.row_vertices(r), fresh.row_weights(r));
  return table;
}

}  // namespace

PolygonMesh refine_quasi_4_8(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                             const SourceLines* lines) {
  check_quasi_4_8(mesh, scheme, options, lines);
  PolygonMesh current = mesh;
  MeshTopology topology(current);
  for (int l = 0; l < options.levels; ++l) {
    Step s(current, std::move(topology), scheme);
    const Quasi48Level level = s.view();
    std::vector<double> xyz;
    xyz.reserve(3 * s.child.positions.size());
    for (const Vec3& p : s.child.positions) xyz.insert(xyz.end(), {p.x, p.y, p.z});
    smooth_in_place(level, xyz.data(), 3);
    for (std::size_t i = 0; i < s.child.positions.size(); ++i)
      s.child.positions[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
    for (const VertexChannel& in : current.vertex_channels) {
      VertexChannel out{in.name, in.components, in.values};
      const auto k = static_cast<std::size_t>(in.components);
      out.values.resize(static_cast<std::size_t>(s.map.child_vertex_count()) * k, 0.0);
      smooth_in_place(level, out.values.data(), k);
      s.child.vertex_channels.push_back(std::move(out));
    }
    current = std::move(s.child);
    topology = std::move(s.child_topology);
    if (options.on_level) options.on_level(l + 1, current);
  }
  return current;
}

std::vector<StencilTable> refine_quasi_4_8_stencils(const PolygonMesh& mesh, const Scheme& scheme,
                                                    const RefineOptions& options, PolygonMesh* final_level) {
  check_quasi_4_8(mesh, scheme, options, nullptr);
  std::vector<StencilTable> tables;
  PolygonMesh current = mesh;
  current.vertex_channels.clear();
  MeshTopology topology(current);
  for (int l = 0; l < options.levels; ++l) {
    Step s(current, std::move(topology), scheme);
    tables.push_back(record(s.view()));
    tables.back().apply(current.positions, s.child.positions);  // the next split reads them
    current = std::move(s.child);
    topology = std::move(s.child_topology);
    if (options.on_level) options.on_level(l + 1, current);
  }
  if (final_level) *final_level = std::move(current);
  return tables;
}

}  // namespace subdiv::detail
