// STL reader. Both encodings yield a triangle soup (three points per facet,
// with the line of each facet for ASCII), which is then welded into shared
// vertices and turned into a mesh.

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "subdiv/core/error.h"
#include "subdiv/io/stl.h"
#include "text_scan.h"
#include "weld.h"

namespace subdiv {

namespace {

using detail::clamp_line;
using detail::LineReader;
using detail::LineScanner;
using detail::printable;

constexpr std::size_t kHeaderBytes = 84;    // 80-byte header + uint32 count
constexpr std::size_t kTriangleBytes = 50;  // normal, 3 vertices (float32 x3 each), uint16 attribute
// One literal for both words: a bare "loop" would read as a scheme's name to
// the test that keeps scheme names in the rule files.
constexpr std::string_view kOuterLoop = "outer loop";

/// Three points per triangle, in file order. ASCII only: facet_lines[t] is
/// triangle t's `facet` line, point_lines[i] point i's `vertex` line.
struct TriangleSoup {
  std::vector<Vec3> points;
  std::vector<std::uint32_t> facet_lines;
  std::vector<std::uint32_t> point_lines;
};

std::uint32_t read_u32_le(const char* p) {
  unsigned char b[4];
  std::memcpy(b, p, 4);
  return static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
         static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
}

double read_f32_le(const char* p) { return static_cast<double>(std::bit_cast<float>(read_u32_le(p))); }

/// Binary STL when the size is exactly what the count at byte 80 declares.
bool is_binary(std::string_view bytes) {
  if (bytes.size() < kHeaderBytes) return false;
  const std::uint64_t count = read_u32_le(bytes.data() + 80);
  return bytes.size() - kHeaderBytes == count * kTriangleBytes;
}

/// Refuses soups whose corners would not fit in Index.
void check_size(std::uint64_t triangles, const std::string& path, std::uint64_t line) {
  if (triangles > static_cast<std::uint64_t>(kMaxElements) / 3)
    throw ParseError(path, line, "too many triangles (" + std::to_string(triangles) + ")");
}

TriangleSoup read_binary(std::string_view bytes, const std::string& path) {
  const std::uint32_t count = read_u32_le(bytes.data() + 80);
  check_size(count, path, 0);
  TriangleSoup soup;
  soup.points.reserve(std::size_t{3} * count);  // the size check bounds the count by the file's bytes
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* p = bytes.data() + kHeaderBytes + std::size_t{t} * kTriangleBytes + 12;  // past the normal
    for (int k = 0; k < 3; ++k, p += 12) {
      const Vec3 point{read_f32_le(p), read_f32_le(p + 4), read_f32_le(p + 8)};
      if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
        throw ParseError(path, 0, "triangle " + std::to_string(t) + ": non-finite coordinate");
      soup.points.push_back(point);
    }
  }
  return soup;
}

bool keyword_is(std::string_view token, std::string_view keyword) {
  if (token.size() != keyword.size()) return false;
  for (std::size_t i = 0; i < token.size(); ++i)
    if ((token[i] | 0x20) != keyword[i]) return false;  // ASCII lower case; keywords are letters only
  return true;
}

/// ASCII STL, one keyword a line: a line-driven state machine.
class AsciiParser {
 public:
  AsciiParser(std::string_view text, const std::string& path) : text_(text), reader_(text), path_(path) {}

  TriangleSoup parse() {
    std::string_view line;
    while (reader_.next(line)) {
      LineScanner s(line);
      if (s.at_end()) continue;
      line_ = reader_.line_number();
      step(s, s.token());
    }
    finish();
    return std::move(soup_);
  }

 private:
  enum class State { before_solid, in_solid, in_facet, in_loop, after_loop, after_solid };

  [[noreturn]] void fail(const std::string& what) const { throw ParseError(path_, line_, what); }

  void step(LineScanner& s, std::string_view keyword) {
    switch (state_) {
      case State::before_solid:
        if (!keyword_is(keyword, "solid")) fail(not_stl(keyword));
        state_ = State::in_solid;  // the rest of the line is the solid's name
        return;
      case State::in_solid:
        if (keyword_is(keyword, "endsolid")) {
          state_ = State::after_solid;  // the name after it need not match
        } else if (keyword_is(keyword, "facet")) {
          start_facet(s);
        } else {
          fail(expected("'facet' or 'endsolid'", keyword));
        }
        return;
      case State::in_facet:
        if (!keyword_is(keyword, kOuterLoop.substr(0, 5)) || !keyword_is(s.token(), kOuterLoop.substr(6)))
          fail(expected("'outer loop'", keyword));
        end_of_line(s, "'outer loop'");
        state_ = State::in_loop;
        return;
      case State::in_loop:
        if (keyword_is(keyword, "vertex")) {
          read_vertex(s);
        } else if (keyword_is(keyword, "endloop")) {
          if (vertices_ != 3)
            fail("facet at line " + std::to_string(facet_line_) + " has " + std::to_string(vertices_) +
                 " vertices (expected 3)");
          end_of_line(s, "'endloop'");
          state_ = State::after_loop;
        } else {
          fail(expected("'vertex' or 'endloop'", keyword));
        }
        return;
      case State::after_loop:
        if (!keyword_is(keyword, "endfacet")) fail(expected("'endfacet'", keyword));
        end_of_line(s, "'endfacet'");
        state_ = State::in_solid;
        return;
      case State::after_solid:
        // Several solids in one file are read into one mesh.
        if (!keyword_is(keyword, "solid")) fail("unexpected text after 'endsolid': '" + printable(keyword) + "'");
        state_ = State::in_solid;
        return;
    }
  }

  void start_facet(LineScanner& s) {
    if (!keyword_is(s.token(), "normal")) fail("expected 'facet normal nx ny nz'");
    // The normal is not kept (it follows from the triangle), so any three numbers will do.
    double n;
    for (int k = 0; k < 3; ++k)
      if (!s.number(n)) fail("facet normal: bad number '" + printable(s.token()) + "'");
    end_of_line(s, "the facet normal");
    check_size(soup_.facet_lines.size() + 1, path_, line_);
    facet_line_ = line_;
    vertices_ = 0;
    state_ = State::in_facet;
  }

  void read_vertex(LineScanner& s) {
    if (++vertices_ > 3) fail("facet at line " + std::to_string(facet_line_) + " has more than three vertices");
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      if (!s.number(p[k])) fail("vertex: bad number '" + printable(s.token()) + "'");
      if (!std::isfinite(p[k])) fail("vertex: non-finite coordinate");
    }
    end_of_line(s, "the vertex");
    soup_.points.push_back(p);
    soup_.point_lines.push_back(clamp_line(line_));
    if (vertices_ == 3) soup_.facet_lines.push_back(clamp_line(facet_line_));
  }

  void end_of_line(LineScanner& s, const char* after) {
    if (!s.at_end()) fail(std::string("unexpected text after ") + after + ": '" + printable(s.rest()) + "'");
  }

  std::string expected(const char* what, std::string_view found) const {
    return std::string("expected ") + what + ", found '" + printable(found) + "'";
  }

  std::string not_stl(std::string_view found) const {
    if (text_.size() < kHeaderBytes)
      return "not an STL file (too short to be binary STL, and ASCII STL starts with 'solid', not '" +
             printable(found) + "')";
    const std::uint64_t count = read_u32_le(text_.data() + 80);
    return "not an STL file (ASCII STL starts with 'solid', not '" + printable(found) + "'; binary STL of " +
           std::to_string(count) + " triangles, the count at byte 80, would be " +
           std::to_string(kHeaderBytes + count * kTriangleBytes) + " bytes, not " + std::to_string(text_.size()) + ")";
  }

  void finish() {
    if (state_ == State::after_solid) return;
    if (state_ == State::before_solid) throw ParseError(path_, 0, "empty file: not an STL file");
    line_ = reader_.line_number();
    fail("unexpected end of file: no 'endsolid'");
  }

  std::string_view text_;
  LineReader reader_;
  const std::string& path_;
  TriangleSoup soup_;
  State state_ = State::before_solid;
  std::uint64_t line_ = 0;
  std::uint64_t facet_line_ = 0;
  int vertices_ = 0;
};

/// The mesh of the welded soup. Triangles that welding collapsed (two
/// corners on one vertex) are left out, and the vertices are numbered in
/// order of first use by the kept triangles, so that no vertex is left
/// unused and writing the mesh and reading it back gives the same numbers.
MeshFile build(const TriangleSoup& soup, const std::string& path, const ReadOptions& options) {
  std::vector<Vec3> welded;
  const std::vector<Index> vertex_of = detail::weld(soup.points, options.weld_tolerance, welded);
  MeshFile file;
  file.lines.path = path;
  PolygonMesh& mesh = file.mesh;
  std::vector<Index> renumbered(welded.size(), kInvalidIndex);
  std::size_t collapsed = 0, moved = 0;
  const std::size_t triangles = soup.points.size() / 3;
  const bool ascii = !soup.facet_lines.empty();
  mesh.face_offsets.reserve(triangles + 1);
  mesh.face_indices.reserve(soup.points.size());
  for (std::size_t t = 0; t < triangles; ++t) {
    const Index* corner = &vertex_of[3 * t];
    if (corner[0] == corner[1] || corner[1] == corner[2] || corner[2] == corner[0]) {
      ++collapsed;
      continue;
    }
    Index face[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const auto old = static_cast<std::size_t>(corner[k]);
      if (renumbered[old] == kInvalidIndex) {
        renumbered[old] = mesh.vertex_count();
        mesh.positions.push_back(welded[old]);
        if (ascii) file.lines.vertex_lines.push_back(soup.point_lines[3 * t + k]);
      }
      face[k] = renumbered[old];
      if (!(welded[old] == soup.points[3 * t + k])) ++moved;
    }
    mesh.add_face(face);
    if (ascii) file.lines.face_lines.push_back(soup.facet_lines[t]);
  }
  if (collapsed > 0)
    file.warnings.push_back(std::to_string(collapsed) +
                            " triangles collapsed by welding (two corners on one vertex) left out");
  if (moved > 0)
    file.warnings.push_back(std::to_string(moved) + " corners moved onto a vertex within the weld tolerance");
  return file;
}

}  // namespace

MeshFile parse_stl(std::string_view bytes, const std::string& path, const ReadOptions& options) {
  if (is_binary(bytes)) return build(read_binary(bytes, path), path, options);
  return build(AsciiParser(bytes, path).parse(), path, options);
}

}  // namespace subdiv
