// OFF writer: positions and faces; OFF has no place for data channels.

#include "subdiv/io/off.h"
#include "text_format.h"

namespace subdiv {

std::string format_off(const PolygonMesh& mesh, std::vector<std::string>* warnings, int threads) {
  using detail::append_lines;
  using detail::append_number;
  using detail::append_point;
  check_face_arrays(mesh);
  if (warnings) {
    for (const auto& ch : mesh.vertex_channels)
      warnings->push_back("OFF has no place for vertex channel '" + ch.name + "': not written");
    for (const auto& ch : mesh.face_varying_channels)
      warnings->push_back("OFF has no place for face-varying channel '" + ch.name + "': not written");
  }

  std::string out;
  out.reserve(32 + static_cast<std::size_t>(mesh.vertex_count()) * 40 +
              static_cast<std::size_t>(mesh.face_count()) * 4 + static_cast<std::size_t>(mesh.corner_count()) * 8);
  out += "OFF\n";
  append_number(out, mesh.vertex_count());
  out += ' ';
  append_number(out, mesh.face_count());
  out += " 0\n";
  append_lines(out, mesh.positions.size(), threads, [&](std::string& text, std::size_t v) {
    append_point(text, mesh.positions[v]);
    text += '\n';
  });
  append_lines(out, static_cast<std::size_t>(mesh.face_count()), threads, [&](std::string& text, std::size_t f) {
    append_number(text, mesh.face_size(static_cast<Index>(f)));
    for (const Index v : mesh.face(static_cast<Index>(f))) {
      text += ' ';
      append_number(text, v);
    }
    text += '\n';
  });
  return out;
}

}  // namespace subdiv
