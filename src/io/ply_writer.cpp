// PLY writer: positions as doubles, the vertex channels "normal" (float),
// "uv" (float) and "color" (uchar), and faces as a vertex_indices list, in
// ASCII or binary of either byte order.

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <limits>

#include "subdiv/io/ply.h"
#include "text_format.h"

namespace subdiv {

namespace {

using detail::append_lines;
using detail::append_number;
using detail::append_point;

/// Shortest text that reads back as the same float.
void append_float(std::string& out, float value) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, result.ptr);
}

/// A double as float; values beyond float's range become infinities
/// (explicitly: such a conversion is undefined behaviour in C++).
float to_float(double x) {
  constexpr double largest = static_cast<double>(std::numeric_limits<float>::max());
  if (x > largest) return std::numeric_limits<float>::infinity();
  if (x < -largest) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(x);
}

/// A colour component in [0, 1] as a byte; NaN becomes 0.
std::uint8_t color_byte(double c) {
  if (!(c > 0.0)) return 0;
  if (c >= 1.0) return 255;
  return static_cast<std::uint8_t>(std::lround(c * 255.0));
}

class BinaryWriter {
 public:
  BinaryWriter(std::string& out, bool big_endian)
      : out_(out), swap_(big_endian != (std::endian::native == std::endian::big)) {}

  template <typename T>
  void put(T value) {
    char buf[sizeof(T)];
    std::memcpy(buf, &value, sizeof(T));
    if (swap_) std::reverse(buf, buf + sizeof(T));
    out_.append(buf, sizeof(T));
  }

 private:
  std::string& out_;
  bool swap_;
};

}  // namespace

std::string format_ply(const PolygonMesh& mesh, PlyEncoding encoding, std::vector<std::string>* warnings,
                       int threads) {
  check_face_arrays(mesh);
  const auto nv = static_cast<std::size_t>(mesh.vertex_count());
  const Index nf = mesh.face_count();

  const VertexChannel* normal = nullptr;
  const VertexChannel* uv = nullptr;
  const VertexChannel* color = nullptr;
  for (const auto& ch : mesh.vertex_channels) {
    const bool sized = ch.components > 0 && ch.values.size() == nv * static_cast<std::size_t>(ch.components);
    if (sized && ch.name == "normal" && ch.components == 3 && !normal) normal = &ch;
    else if (sized && ch.name == "uv" && ch.components == 2 && !uv) uv = &ch;
    else if (sized && ch.name == "color" && ch.components == 3 && !color) color = &ch;
    else if (warnings)
      warnings->push_back("PLY has no place for vertex channel '" + ch.name + "' (" +
                          std::to_string(ch.components) + " components): not written");
  }
  if (warnings)
    for (const auto& ch : mesh.face_varying_channels)
      warnings->push_back("PLY has no place for face-varying channel '" + ch.name + "': not written");

  Index largest_face = 0;
  for (Index f = 0; f < nf; ++f) largest_face = std::max(largest_face, mesh.face_size(f));
  const bool wide_counts = largest_face > 255;

  std::string out;
  out += "ply\nformat ";
  out += encoding == PlyEncoding::ascii                  ? "ascii"
         : encoding == PlyEncoding::binary_little_endian ? "binary_little_endian"
                                                         : "binary_big_endian";
  out += " 1.0\ncomment subdiv\nelement vertex ";
  append_number(out, mesh.vertex_count());
  out += "\nproperty double x\nproperty double y\nproperty double z\n";
  if (normal) out += "property float nx\nproperty float ny\nproperty float nz\n";
  if (uv) out += "property float u\nproperty float v\n";
  if (color) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out += "element face ";
  append_number(out, nf);
  out += wide_counts ? "\nproperty list uint int vertex_indices\n" : "\nproperty list uchar int vertex_indices\n";
  out += "end_header\n";

  auto channel_value = [](const VertexChannel* ch, std::size_t v, std::size_t i) {
    return ch->values[v * static_cast<std::size_t>(ch->components) + i];
  };

  if (encoding == PlyEncoding::ascii) {
    out.reserve(out.size() + nv * 64 + static_cast<std::size_t>(mesh.corner_count()) * 8);
    append_lines(out, nv, threads, [&](std::string& text, std::size_t v) {
      append_point(text, mesh.positions[v]);
      if (normal)
        for (std::size_t i = 0; i < 3; ++i) {
          text += ' ';
          append_float(text, to_float(channel_value(normal, v, i)));
        }
      if (uv)
        for (std::size_t i = 0; i < 2; ++i) {
          text += ' ';
          append_float(text, to_float(channel_value(uv, v, i)));
        }
      if (color)
        for (std::size_t i = 0; i < 3; ++i) {
          text += ' ';
          append_number(text, static_cast<int>(color_byte(channel_value(color, v, i))));
        }
      text += '\n';
    });
    append_lines(out, static_cast<std::size_t>(nf), threads, [&](std::string& text, std::size_t f) {
      append_number(text, mesh.face_size(static_cast<Index>(f)));
      for (const Index i : mesh.face(static_cast<Index>(f))) {
        text += ' ';
        append_number(text, i);
      }
      text += '\n';
    });
    return out;
  }

  std::size_t vertex_bytes = 24 + (normal ? 12 : 0) + (uv ? 8 : 0) + (color ? 3 : 0);
  out.reserve(out.size() + nv * vertex_bytes + static_cast<std::size_t>(nf) * (wide_counts ? 4 : 1) +
              static_cast<std::size_t>(mesh.corner_count()) * 4);
  BinaryWriter w(out, encoding == PlyEncoding::binary_big_endian);
  for (std::size_t v = 0; v < nv; ++v) {
    const Vec3 p = mesh.positions[v];
    w.put(p.x);
    w.put(p.y);
    w.put(p.z);
    if (normal)
      for (std::size_t i = 0; i < 3; ++i) w.put(to_float(channel_value(normal, v, i)));
    if (uv)
      for (std::size_t i = 0; i < 2; ++i) w.put(to_float(channel_value(uv, v, i)));
    if (color)
      for (std::size_t i = 0; i < 3; ++i) w.put(color_byte(channel_value(color, v, i)));
  }
  for (Index f = 0; f < nf; ++f) {
    if (wide_counts) w.put(static_cast<std::uint32_t>(mesh.face_size(f)));
    else w.put(static_cast<std::uint8_t>(mesh.face_size(f)));
    for (const Index i : mesh.face(f)) w.put(static_cast<std::int32_t>(i));
  }
  return out;
}

}  // namespace subdiv
