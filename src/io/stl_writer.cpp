// STL writer: every face as triangles (fans from the first corner), ASCII
// with shortest round-trip doubles or binary float32 little-endian.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/io/stl.h"
#include "text_format.h"

namespace subdiv {

namespace {

using detail::append_number;

struct Triangle {
  Index a, b, c;
};

/// The faces as triangles, with notes on faces split or left out.
std::vector<Triangle> triangles_of(const PolygonMesh& mesh, std::vector<std::string>& notes) {
  std::vector<Triangle> out;
  out.reserve(static_cast<std::size_t>(mesh.corner_count()) / 3);
  std::size_t fans = 0, skipped = 0;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const std::span<const Index> face = mesh.face(f);
    if (face.size() < 3) {
      ++skipped;
      continue;
    }
    if (face.size() > 3) ++fans;
    for (std::size_t k = 1; k + 1 < face.size(); ++k) out.push_back({face[0], face[k], face[k + 1]});
  }
  if (fans > 0)
    notes.push_back(std::to_string(fans) + " faces with more than three corners written as fans of triangles");
  if (skipped > 0) notes.push_back(std::to_string(skipped) + " faces with fewer than three corners left out");
  return out;
}

/// One note per kind of channel, naming them.
void note_channels(const PolygonMesh& mesh, std::vector<std::string>& notes) {
  const auto note = [&](const auto& channels, const char* kind) {
    if (channels.empty()) return;
    std::string names;
    for (const auto& ch : channels) names += (names.empty() ? "'" : ", '") + ch.name + "'";
    notes.push_back(std::string("STL has no place for ") + kind + " channels (" + names + "): not written");
  };
  note(mesh.vertex_channels, "vertex");
  note(mesh.face_varying_channels, "face-varying");
}

/// STL cannot hold non-finite positions (the reader refuses them); binary
/// STL nothing beyond float's range.
void check_positions(const PolygonMesh& mesh, const std::vector<Triangle>& triangles, bool binary) {
  constexpr double largest = static_cast<double>(std::numeric_limits<float>::max());
  for (const Triangle& t : triangles)
    for (const Index v : {t.a, t.b, t.c})
      for (int c = 0; c < 3; ++c) {
        const double x = mesh.positions[static_cast<std::size_t>(v)][c];
        if (!std::isfinite(x))
          throw InvalidInputError("STL: vertex " + std::to_string(v) + " has a non-finite coordinate");
        if (binary && std::abs(x) > largest)
          throw InvalidInputError("binary STL: vertex " + std::to_string(v) +
                                  " has a coordinate beyond float's range (write ASCII STL instead)");
      }
}

/// The triangle's unit normal, zero when it is degenerate. The corners are
/// scaled by their largest coordinate first, so that neither huge nor tiny
/// coordinates overflow or underflow the cross product.
Vec3 unit_normal(Vec3 a, Vec3 b, Vec3 c) {
  double scale = 0.0;
  for (const Vec3& p : {a, b, c})
    for (int k = 0; k < 3; ++k) scale = std::max(scale, std::abs(p[k]));
  if (!(scale > 0.0) || !std::isfinite(scale)) return {0, 0, 0};
  const auto scaled = [scale](Vec3 p) { return Vec3{p.x / scale, p.y / scale, p.z / scale}; };
  const Vec3 n = cross(scaled(b) - scaled(a), scaled(c) - scaled(a));
  const double length = norm(n);
  if (!(length > 0.0) || !std::isfinite(length)) return {0, 0, 0};
  return {n.x / length, n.y / length, n.z / length};  // division keeps axis normals exact
}

void append_vec3(std::string& out, Vec3 p) {
  detail::append_point(out, p);
  out += '\n';
}

std::string format_ascii(const PolygonMesh& mesh, const std::vector<Triangle>& triangles) {
  std::string out = "solid subdiv\n";
  out.reserve(triangles.size() * 200 + 32);
  for (const Triangle& t : triangles) {
    const Vec3 a = mesh.positions[static_cast<std::size_t>(t.a)];
    const Vec3 b = mesh.positions[static_cast<std::size_t>(t.b)];
    const Vec3 c = mesh.positions[static_cast<std::size_t>(t.c)];
    out += "facet normal ";
    append_vec3(out, unit_normal(a, b, c));
    out += "  outer loop\n";
    for (const Vec3& p : {a, b, c}) {
      out += "    vertex ";
      append_vec3(out, p);
    }
    out += "  endloop\nendfacet\n";
  }
  out += "endsolid subdiv\n";
  return out;
}

void put_u32_le(std::string& out, std::uint32_t v) {
  for (int shift = 0; shift < 32; shift += 8) out += static_cast<char>((v >> shift) & 0xFFu);
}

void put_vec3_f32(std::string& out, Vec3 p) {
  for (int k = 0; k < 3; ++k) put_u32_le(out, std::bit_cast<std::uint32_t>(static_cast<float>(p[k])));
}

std::string format_binary(const PolygonMesh& mesh, const std::vector<Triangle>& triangles) {
  if (triangles.size() > std::numeric_limits<std::uint32_t>::max())
    throw InvalidInputError("binary STL holds at most 2^32 - 1 triangles; the mesh has " +
                            std::to_string(triangles.size()));
  std::string out = "subdiv STL";  // never "solid": readers that sniff the header would take it for ASCII
  out.resize(80, ' ');
  out.reserve(84 + 50 * triangles.size());
  put_u32_le(out, static_cast<std::uint32_t>(triangles.size()));
  for (const Triangle& t : triangles) {
    const Vec3 a = mesh.positions[static_cast<std::size_t>(t.a)];
    const Vec3 b = mesh.positions[static_cast<std::size_t>(t.b)];
    const Vec3 c = mesh.positions[static_cast<std::size_t>(t.c)];
    put_vec3_f32(out, unit_normal(a, b, c));
    for (const Vec3& p : {a, b, c}) put_vec3_f32(out, p);
    out.append(2, '\0');  // attribute byte count
  }
  return out;
}

}  // namespace

std::string format_stl(const PolygonMesh& mesh, StlEncoding encoding, std::vector<std::string>* warnings) {
  check_face_arrays(mesh);
  const bool binary = encoding == StlEncoding::binary;
  std::vector<std::string> notes;  // handed over only once the file is made
  const std::vector<Triangle> triangles = triangles_of(mesh, notes);
  check_positions(mesh, triangles, binary);
  note_channels(mesh, notes);
  std::string out = binary ? format_binary(mesh, triangles) : format_ascii(mesh, triangles);
  if (warnings) warnings->insert(warnings->end(), notes.begin(), notes.end());
  return out;
}

}  // namespace subdiv
