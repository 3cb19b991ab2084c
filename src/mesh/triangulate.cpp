#include "subdiv/mesh/triangulate.h"

namespace subdiv {

PolygonMesh triangulate(const PolygonMesh& mesh) {
  check_indices(mesh);
  PolygonMesh out;
  out.positions = mesh.positions;
  out.vertex_channels = mesh.vertex_channels;
  out.tags = mesh.tags;
  out.tags.holes.clear();
  out.face_varying_channels.resize(mesh.face_varying_channels.size());
  for (std::size_t i = 0; i < mesh.face_varying_channels.size(); ++i) {
    const auto& in = mesh.face_varying_channels[i];
    out.face_varying_channels[i] = {in.name, in.components, in.values, {}};
  }
  std::vector<char> is_hole(static_cast<std::size_t>(mesh.face_count()), 0);
  for (const Index f : mesh.tags.holes)
    if (f >= 0 && f < mesh.face_count()) is_hole[static_cast<std::size_t>(f)] = 1;

  auto emit = [&](Index f, std::initializer_list<Index> corners) {
    if (is_hole[static_cast<std::size_t>(f)]) out.tags.holes.push_back(out.face_count());
    for (const Index c : corners) {
      out.face_indices.push_back(mesh.face_indices[static_cast<std::size_t>(c)]);
      for (std::size_t i = 0; i < mesh.face_varying_channels.size(); ++i)
        out.face_varying_channels[i].indices.push_back(mesh.face_varying_channels[i].indices[static_cast<std::size_t>(c)]);
    }
    out.face_offsets.push_back(static_cast<Index>(out.face_indices.size()));
  };
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Index first = mesh.face_offsets[static_cast<std::size_t>(f)];
    const Index n = mesh.face_size(f);
    if (n == 3) {
      emit(f, {first, first + 1, first + 2});
    } else if (n < 3) {  // degenerate: copied as it is, for validation to report
      if (is_hole[static_cast<std::size_t>(f)]) out.tags.holes.push_back(out.face_count());
      for (Index c = first; c < first + n; ++c) out.face_indices.push_back(mesh.face_indices[static_cast<std::size_t>(c)]);
      for (std::size_t i = 0; i < mesh.face_varying_channels.size(); ++i)
        for (Index c = first; c < first + n; ++c)
          out.face_varying_channels[i].indices.push_back(mesh.face_varying_channels[i].indices[static_cast<std::size_t>(c)]);
      out.face_offsets.push_back(static_cast<Index>(out.face_indices.size()));
    } else {
      for (Index t = 1; t + 1 < n; ++t) emit(f, {first, first + t, first + t + 1});
    }
  }
  return out;
}

}  // namespace subdiv
