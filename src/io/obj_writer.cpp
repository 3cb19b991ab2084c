// OBJ writer: positions (with colours when the mesh has a 3-component "color"
// vertex channel), the "uv" and "normal" face-varying channels, faces,
// polylines (`l` lines), and tags in OpenSubdiv's syntax.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include "subdiv/core/error.h"
#include "subdiv/io/obj.h"
#include "obj_tags.h"
#include "text_format.h"

namespace subdiv {

namespace {

using detail::append_lines;
using detail::append_number;

/// A kept tag's name and strings are written as tokens: one that is empty or
/// holds white space or a line break would be read back as something else.
void require_token(std::string_view tag, std::string_view token) {
  const bool splits = token.empty() || std::any_of(token.begin(), token.end(), [](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
  });
  if (splits)
    throw InvalidInputError("tag '" + std::string(tag) + "': the name and strings of a tag must be non-empty and hold no white space, "
                            "so '" + std::string(token) + "' cannot be written to OBJ");
}

void append_tag_header(std::string& out, std::string_view name, std::size_t ints, std::size_t floats, std::size_t strings) {
  out += "t ";
  out += name;
  out += ' ';
  append_number(out, static_cast<long long>(ints));
  out += '/';
  append_number(out, static_cast<long long>(floats));
  out += '/';
  append_number(out, static_cast<long long>(strings));
}

}  // namespace

void detail::append_obj_tag_lines(std::string& out, const Tags& tags) {
  for (const auto& c : tags.creases) {
    append_tag_header(out, "crease", 2, 1, 0);
    for (const double x : {static_cast<double>(c.v0), static_cast<double>(c.v1)}) {
      out += ' ';
      append_number(out, static_cast<long long>(x));
    }
    out += ' ';
    append_number(out, c.sharpness);
    out += '\n';
  }
  for (const auto& c : tags.corners) {
    const bool typed = c.type != CornerType::unspecified;
    append_tag_header(out, "corner", 1, 1, typed ? 1 : 0);
    out += ' ';
    append_number(out, c.vertex);
    out += ' ';
    append_number(out, c.sharpness);
    if (typed) {
      out += ' ';
      out += to_string(c.type);
      if (c.angle) {
        out += ':';
        append_number(out, *c.angle * 180.0 / std::numbers::pi);
      }
    }
    out += '\n';
  }
  if (!tags.holes.empty()) {
    append_tag_header(out, "hole", tags.holes.size(), 0, 0);
    for (const Index f : tags.holes) {
      out += ' ';
      append_number(out, f);
    }
    out += '\n';
  }
  if (tags.boundary_interpolation_set) {
    append_tag_header(out, "interpolateboundary", 1, 0, 0);
    const int code = tags.boundary_interpolation == BoundaryInterpolation::none ? 0
                     : tags.boundary_interpolation == BoundaryInterpolation::edge_and_corner ? 1 : 2;
    out += ' ';
    append_number(out, code);
    out += '\n';
  }
  if (tags.face_varying_interpolation_set) {
    append_tag_header(out, "facevaryinginterpolateboundary", 1, 0, 0);
    out += ' ';
    append_number(out, static_cast<int>(tags.face_varying_interpolation));
    out += '\n';
  }
  if (tags.face_varying_propagate_corners_set) {
    append_tag_header(out, "facevaryingpropagatecorners", 1, 0, 0);
    out += tags.face_varying_propagate_corners ? " 1\n" : " 0\n";
  }
  if (tags.crease_method_set) {
    append_tag_header(out, "creasemethod", 0, 0, 1);
    out += tags.crease_method == CreaseMethod::uniform ? " normal\n" : " chaikin\n";
  }
  if (tags.triangle_subdivision_set) {
    append_tag_header(out, "smoothtriangles", 0, 0, 1);
    out += tags.triangle_subdivision == TriangleSubdivision::catmark ? " catmark\n" : " smooth\n";
  }
  for (const auto& raw : tags.other) {
    require_token(raw.name, raw.name);
    for (const auto& s : raw.strings) require_token(raw.name, s);
    append_tag_header(out, raw.name, raw.ints.size(), raw.floats.size(), raw.strings.size());
    for (const long long i : raw.ints) {
      out += ' ';
      append_number(out, i);
    }
    for (const double f : raw.floats) {
      out += ' ';
      append_number(out, f);
    }
    for (const auto& s : raw.strings) {
      out += ' ';
      out += s;
    }
    out += '\n';
  }
}

std::string format_obj(const PolygonMesh& mesh, const WriteOptions& options, std::vector<std::string>* warnings) {
  check_indices(mesh);  // channel indices are dereferenced below
  std::string out;
  out.reserve(static_cast<std::size_t>(mesh.vertex_count()) * 40 + static_cast<std::size_t>(mesh.corner_count()) * 8);
  out += "# subdiv OBJ: ";
  append_number(out, mesh.vertex_count());
  out += " vertices, ";
  append_number(out, mesh.face_count());
  out += " faces";
  if (!mesh.polylines.empty()) {
    out += ", ";
    append_number(out, static_cast<long long>(mesh.polylines.size()));
    out += " polylines";
  }
  out += '\n';

  const VertexChannel* color = nullptr;
  const FaceVaryingChannel* uv = nullptr;
  const FaceVaryingChannel* normal = nullptr;
  if (options.write_channels) {
    for (const auto& ch : mesh.vertex_channels) {
      if (ch.name == "color" && ch.components == 3) color = &ch;
      else if (warnings) warnings->push_back("OBJ has no place for vertex channel '" + ch.name + "': not written");
    }
    for (const auto& ch : mesh.face_varying_channels) {
      if (ch.name == "uv" && (ch.components == 2 || ch.components == 3)) uv = &ch;
      else if (ch.name == "normal" && ch.components == 3) normal = &ch;
      else if (warnings) warnings->push_back("OBJ has no place for face-varying channel '" + ch.name + "': not written");
    }
  }

  const int threads = options.threads;
  append_lines(out, static_cast<std::size_t>(mesh.vertex_count()), threads, [&](std::string& text, std::size_t v) {
    const Vec3 p = mesh.positions[v];
    text += "v ";
    detail::append_point(text, p);
    if (color) {
      for (std::size_t i = 0; i < 3; ++i) {
        text += ' ';
        append_number(text, color->values[v * 3 + i]);
      }
    }
    text += '\n';
  });
  auto append_values = [&](const FaceVaryingChannel& ch, const char* keyword) {
    const auto k = static_cast<std::size_t>(ch.components);
    append_lines(out, ch.values.size() / k, threads, [&](std::string& text, std::size_t value) {
      text += keyword;
      for (std::size_t j = 0; j < k; ++j) {
        text += ' ';
        append_number(text, ch.values[value * k + j]);
      }
      text += '\n';
    });
  };
  if (uv) append_values(*uv, "vt");
  if (normal) append_values(*normal, "vn");

  append_lines(out, static_cast<std::size_t>(mesh.face_count()), threads, [&](std::string& text, std::size_t f) {
    text += 'f';
    for (std::size_t c = static_cast<std::size_t>(mesh.face_offsets[f]); c < static_cast<std::size_t>(mesh.face_offsets[f + 1]); ++c) {
      text += ' ';
      append_number(text, mesh.face_indices[c] + 1);
      if (uv || normal) {
        text += '/';
        if (uv) append_number(text, uv->indices[c] + 1);
        if (normal) {
          text += '/';
          append_number(text, normal->indices[c] + 1);
        }
      }
    }
    text += '\n';
  });
  // A closed polyline repeats its first vertex at the end (docs/formats.md).
  for (const MeshPolyline& polyline : mesh.polylines) {
    out += 'l';
    for (const Index v : polyline.vertices) {
      out += ' ';
      append_number(out, v + 1);
    }
    if (polyline.closed && !polyline.vertices.empty()) {
      out += ' ';
      append_number(out, polyline.vertices.front() + 1);
    }
    out += '\n';
  }
  if (options.write_tags) detail::append_obj_tag_lines(out, mesh.tags);
  return out;
}

}  // namespace subdiv
