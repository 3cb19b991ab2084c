// OFF writer: positions and faces; OFF has no place for data channels.

#include "subdiv/io/off.h"
#include "text_format.h"

namespace subdiv {

std::string format_off(const PolygonMesh& mesh, std::vector<std::string>* warnings) {
  using detail::append_number;
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
  for (const Vec3& p : mesh.positions) {
    append_number(out, p.x);
    out += ' ';
    append_number(out, p.y);
    out += ' ';
    append_number(out, p.z);
    out += '\n';
  }
  for (Index f = 0; f < mesh.face_count(); ++f) {
    append_number(out, mesh.face_size(f));
    for (const Index v : mesh.face(f)) {
      out += ' ';
      append_number(out, v);
    }
    out += '\n';
  }
  return out;
}

}  // namespace subdiv
