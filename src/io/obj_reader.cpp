// OBJ reader: one pass over the buffer, no per-line allocation.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "subdiv/core/error.h"
#include "subdiv/io/obj.h"
#include "text_scan.h"

namespace subdiv {

namespace {

using detail::LineScanner;
using detail::clamp_line;
using detail::printable;

class ObjParser {
 public:
  ObjParser(std::string_view text, const std::string& path) : text_(text), path_(path) {}

  MeshFile parse() {
    detail::LineReader reader(text_);
    std::string_view line;
    while (reader.next(line)) {
      line_ = reader.line_number();
      parse_line(line);
    }
    finish();
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw ParseError(path_, line_, what); }

  void parse_line(std::string_view text) {
    LineScanner s(text);
    const std::string_view keyword = s.token();
    if (keyword.empty() || keyword.front() == '#') return;
    if (keyword == "v") return parse_vertex(s);
    if (keyword == "f") return parse_face(s);
    if (keyword == "vt") return parse_uv(s);
    if (keyword == "vn") return parse_normal(s);
    if (keyword == "t") return parse_tag(s);
    if (keyword == "l") return parse_polyline(s);
    if (keyword == "g" || keyword == "o" || keyword == "s" || keyword == "usemtl" || keyword == "mtllib" ||
        keyword == "vp" || keyword == "p" || keyword == "cstype" || keyword == "deg")
      return;  // groups, materials, free-form curves: not kept
    if (!std::all_of(keyword.begin(), keyword.end(), [](char c) { return c > ' ' && c < 127; }))
      fail("unreadable line (binary data or a corrupted file?)");
    if (unknown_keywords_++ == 0)
      out_.warnings.push_back("line " + std::to_string(line_) + ": unknown keyword '" + std::string(keyword) +
                              "' ignored (and any later unknown keywords)");
  }

  double need_number(LineScanner& s, const char* what) {
    double value;
    if (!s.number(value)) {
      const std::string_view tok = s.token();
      fail(tok.empty() ? std::string("missing ") + what
                       : std::string("bad ") + what + " '" + printable(tok) + "'");
    }
    return value;
  }

  void parse_vertex(LineScanner& s) {
    Vec3 p;
    p.x = need_number(s, "x coordinate");
    p.y = need_number(s, "y coordinate");
    p.z = need_number(s, "z coordinate");
    double extra[4];
    int n = 0;
    while (!s.at_end()) {
      if (n == 4) fail("too many numbers on a vertex line (expected x y z [w] or x y z r g b)");
      extra[n++] = need_number(s, "vertex value");
    }
    if (out_.mesh.positions.size() >= static_cast<std::size_t>(kMaxElements)) fail("too many vertices");
    out_.mesh.positions.push_back(p);
    out_.lines.vertex_lines.push_back(clamp_line(line_));
    if (n >= 3) {  // x y z r g b [a]
      colors_.resize(out_.mesh.positions.size() * 3 - 3, 0.0);
      colors_.insert(colors_.end(), extra, extra + 3);
      ++colored_vertices_;
    }
  }

  void parse_uv(LineScanner& s) {
    const double u = need_number(s, "u coordinate");
    double v = 0.0;
    if (!s.at_end()) v = need_number(s, "v coordinate");
    if (!s.at_end()) need_number(s, "w coordinate");  // 3D texture coordinates: w is not kept
    if (!s.at_end()) fail("too many numbers on a vt line");
    uvs_.push_back(u);
    uvs_.push_back(v);
  }

  void parse_normal(LineScanner& s) {
    normals_.push_back(need_number(s, "normal x"));
    normals_.push_back(need_number(s, "normal y"));
    normals_.push_back(need_number(s, "normal z"));
    if (!s.at_end()) fail("too many numbers on a vn line");
  }

  // Resolves a 1-based or negative (relative) OBJ index to 0-based. Positive
  // indices are range-checked at the end of the file (forward references are
  // tolerated); relative ones must point at an element already read.
  long long resolve(long long index, std::size_t count_so_far, const char* what) const {
    if (index > 0 && index <= kMaxElements) [[likely]] return index - 1;
    if (index == 0) fail(std::string(what) + " index 0 is invalid (OBJ indices start at 1)");
    if (index < 0) {
      const long long resolved = static_cast<long long>(count_so_far) + index;
      if (resolved < 0)
        fail(std::string("relative ") + what + " index " + std::to_string(index) + " reaches before the first " +
             what + " (only " + std::to_string(count_so_far) + " so far)");
      return resolved;
    }
    if (index > kMaxElements) fail(std::string(what) + " index " + std::to_string(index) + " is too large");
    return index - 1;
  }

  void parse_face(LineScanner& s) {
    auto& corners = out_.mesh.face_indices;
    while (!s.at_end()) {
      long long v;
      if (!s.integer(v, '/')) fail("bad face vertex '" + printable(s.token()) + "'");
      long long vt = 0, vn = 0;
      if (s.consume('/')) {
        if (s.peek() != '/' && !s.integer(vt, '/')) fail("bad texture index in face");
        if (s.consume('/') && !s.integer(vn)) fail("bad normal index in face");
      }
      if (s.peek() != '\0' && !detail::is_space(s.peek())) fail("bad face vertex");
      // Texture and normal indices are stored lazily: a corner without one
      // gets kInvalidIndex, and finish() drops a channel with gaps.
      const std::size_t corner = corners.size();
      if (vt != 0) {
        uv_index_.resize(corner, kInvalidIndex);
        uv_index_.push_back(static_cast<Index>(resolve(vt, uvs_.size() / 2, "texture")));
      }
      if (vn != 0) {
        normal_index_.resize(corner, kInvalidIndex);
        normal_index_.push_back(static_cast<Index>(resolve(vn, normals_.size() / 3, "normal")));
      }
      corners.push_back(static_cast<Index>(resolve(v, out_.mesh.positions.size(), "vertex")));
      if (corners.size() >= static_cast<std::size_t>(kMaxElements)) fail("too many face corners");
    }
    out_.mesh.face_offsets.push_back(static_cast<Index>(corners.size()));
    out_.lines.face_lines.push_back(clamp_line(line_));
  }

  // `l v1 v2 ...` (or v/vt): a polyline, closed when its last index is its
  // first. Texture indices are read and not kept.
  void parse_polyline(LineScanner& s) {
    MeshPolyline polyline;
    while (!s.at_end()) {
      long long v;
      if (!s.integer(v, '/')) fail("bad polyline vertex '" + printable(s.token()) + "'");
      if (s.consume('/')) {
        long long vt;
        if (!s.integer(vt)) fail("bad texture index in polyline");
        resolve(vt, uv_count(), "texture");
      }
      if (s.peek() != '\0' && !detail::is_space(s.peek())) fail("bad polyline vertex");
      polyline.vertices.push_back(static_cast<Index>(resolve(v, out_.mesh.positions.size(), "vertex")));
      if (++polyline_indices_ >= static_cast<std::size_t>(kMaxElements)) fail("too many polyline vertices");
    }
    if (polyline.vertices.size() >= 2 && polyline.vertices.front() == polyline.vertices.back()) {
      polyline.vertices.pop_back();
      polyline.closed = true;
    }
    if (polyline.vertices.size() < 2)
      fail(std::string("polyline with ") +
           (polyline.closed ? "1 distinct point" : std::to_string(polyline.vertices.size()) + " points") +
           " (a polyline needs at least 2)");
    out_.mesh.polylines.push_back(std::move(polyline));
    out_.lines.polyline_lines.push_back(clamp_line(line_));
  }

  std::size_t uv_count() const { return uvs_.size() / 2; }

  // --- tags --------------------------------------------------------------
  struct TagArgs {
    std::string_view name;
    std::vector<long long> ints;
    std::vector<double> floats;
    std::vector<std::string_view> strings;
  };

  void parse_tag(LineScanner& s) {
    TagArgs t;
    t.name = s.token();
    if (t.name.empty()) fail("tag line without a name");
    LineScanner counts(s.token());
    long long n[3];
    for (int i = 0; i < 3; ++i)
      if (!counts.integer(n[i], '/') || n[i] < 0 || (i < 2 && !counts.consume('/')))
        fail("tag '" + std::string(t.name) + "': expected argument counts ints/floats/strings, e.g. 2/1/0");
    if (!counts.at_end()) fail("tag '" + std::string(t.name) + "': malformed argument counts");
    // Arguments are parsed one at a time, so a huge count fails on the first
    // missing value instead of allocating.
    for (long long i = 0; i < n[0]; ++i) {
      long long v;
      if (!s.integer(v)) fail("tag '" + std::string(t.name) + "': expected " + std::to_string(n[0]) + " integers");
      t.ints.push_back(v);
    }
    for (long long i = 0; i < n[1]; ++i) {
      double v;
      if (!s.number(v)) fail("tag '" + std::string(t.name) + "': expected " + std::to_string(n[1]) + " numbers");
      t.floats.push_back(v);
    }
    for (long long i = 0; i < n[2]; ++i) {
      const std::string_view tok = s.token();
      if (tok.empty()) fail("tag '" + std::string(t.name) + "': expected " + std::to_string(n[2]) + " strings");
      t.strings.push_back(tok);
    }
    if (!s.at_end()) fail("tag '" + std::string(t.name) + "': more arguments than its counts say");
    interpret_tag(t);
  }

  Index tag_index(const TagArgs& t, long long v) const {
    if (v < std::numeric_limits<Index>::min() || v > std::numeric_limits<Index>::max())
      fail("tag '" + std::string(t.name) + "': index " + std::to_string(v) + " out of range");
    return static_cast<Index>(v);
  }

  int single_int(const TagArgs& t, int max) const {
    if (t.ints.size() != 1 || !t.floats.empty() || !t.strings.empty() || t.ints[0] < 0 || t.ints[0] > max)
      fail("tag '" + std::string(t.name) + "' expects one integer in [0, " + std::to_string(max) + "]");
    return static_cast<int>(t.ints[0]);
  }

  std::string_view single_string(const TagArgs& t) const {
    if (t.strings.size() != 1 || !t.ints.empty() || !t.floats.empty())
      fail("tag '" + std::string(t.name) + "' expects one string");
    return t.strings[0];
  }

  void interpret_tag(const TagArgs& t) {
    Tags& tags = out_.mesh.tags;
    const std::uint32_t line = clamp_line(line_);
    if (t.name == "crease") {
      const std::size_t edges = t.ints.size() / 2;
      if (t.ints.empty() || t.ints.size() % 2 != 0 || !t.strings.empty() ||
          (t.floats.size() != 1 && t.floats.size() != edges))
        fail("tag 'crease' expects vertex pairs and one sharpness, or one per pair");
      for (std::size_t i = 0; i < edges; ++i) {
        tags.creases.push_back({tag_index(t, t.ints[2 * i]), tag_index(t, t.ints[2 * i + 1]),
                                t.floats.size() == 1 ? t.floats[0] : t.floats[i]});
        out_.lines.crease_lines.push_back(line);
      }
    } else if (t.name == "corner") {
      const std::size_t n = t.ints.size();
      if (n == 0 || (t.floats.size() != 1 && t.floats.size() != n) ||
          (t.strings.size() > 1 && t.strings.size() != n))
        fail("tag 'corner' expects vertices, one sharpness or one per vertex, and optionally types");
      for (std::size_t i = 0; i < n; ++i) {
        CornerTag c;
        c.vertex = tag_index(t, t.ints[i]);
        c.sharpness = t.floats.size() == 1 ? t.floats[0] : t.floats[i];
        if (!t.strings.empty()) parse_corner_type(t.strings.size() == 1 ? t.strings[0] : t.strings[i], c);
        tags.corners.push_back(c);
        out_.lines.corner_lines.push_back(line);
      }
    } else if (t.name == "hole") {
      if (!t.floats.empty() || !t.strings.empty()) fail("tag 'hole' expects face indices only");
      for (const long long f : t.ints) {
        tags.holes.push_back(tag_index(t, f));
        out_.lines.hole_lines.push_back(line);
      }
    } else if (t.name == "interpolateboundary") {
      static constexpr BoundaryInterpolation modes[] = {BoundaryInterpolation::none,
                                                        BoundaryInterpolation::edge_and_corner,
                                                        BoundaryInterpolation::edge_only};
      tags.boundary_interpolation = modes[single_int(t, 2)];
      tags.boundary_interpolation_set = true;
    } else if (t.name == "facevaryinginterpolateboundary") {
      tags.face_varying_interpolation = static_cast<FaceVaryingInterpolation>(single_int(t, 5));
      tags.face_varying_interpolation_set = true;
    } else if (t.name == "facevaryingpropagatecorners") {
      tags.face_varying_propagate_corners = single_int(t, 1) == 1;
      tags.face_varying_propagate_corners_set = true;
    } else if (t.name == "creasemethod") {
      const std::string_view m = single_string(t);
      if (m != "normal" && m != "chaikin") fail("tag 'creasemethod' expects 'normal' or 'chaikin'");
      tags.crease_method = m == "normal" ? CreaseMethod::uniform : CreaseMethod::chaikin;
      tags.crease_method_set = true;
    } else if (t.name == "smoothtriangles") {
      const std::string_view m = single_string(t);
      if (m != "catmark" && m != "smooth") fail("tag 'smoothtriangles' expects 'catmark' or 'smooth'");
      tags.triangle_subdivision = m == "catmark" ? TriangleSubdivision::catmark : TriangleSubdivision::smooth;
      tags.triangle_subdivision_set = true;
    } else {
      RawTag raw{std::string(t.name), t.ints, t.floats, {}};
      for (const auto s : t.strings) raw.strings.emplace_back(s);
      tags.other.push_back(std::move(raw));
    }
  }

  void parse_corner_type(std::string_view s, CornerTag& c) const {
    const std::size_t colon = s.find(':');
    const std::string_view type = s.substr(0, colon);
    if (type == "convex") c.type = CornerType::convex;
    else if (type == "concave") c.type = CornerType::concave;
    else fail("tag 'corner': type must be 'convex' or 'concave' (optionally ':degrees'), not '" + std::string(s) + "'");
    if (colon != std::string_view::npos) {
      LineScanner angle(s.substr(colon + 1));
      double degrees;
      if (!angle.number(degrees) || !angle.at_end() || !(degrees > 0.0 && degrees < 360.0))
        fail("tag 'corner': angle in '" + std::string(s) + "' must be in (0, 360) degrees");
      c.angle = degrees * std::numbers::pi / 180.0;
    }
  }

  // --- end of file -----------------------------------------------------
  void finish() {
    PolygonMesh& mesh = out_.mesh;
    const std::size_t nv = mesh.positions.size();
    for (Index f = 0; f < mesh.face_count(); ++f)
      for (const Index v : mesh.face(f))
        if (static_cast<std::size_t>(v) >= nv) {
          line_ = out_.lines.face_lines[static_cast<std::size_t>(f)];
          fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(v + 1) + " but the file has " +
               std::to_string(nv) + " vertices");
        }
    for (std::size_t l = 0; l < mesh.polylines.size(); ++l)
      for (const Index v : mesh.polylines[l].vertices)
        if (static_cast<std::size_t>(v) >= nv) {
          line_ = out_.lines.polyline_lines[l];
          fail("polyline " + std::to_string(l) + " refers to vertex " + std::to_string(v + 1) + " but the file has " +
               std::to_string(nv) + " vertices");
        }
    line_ = 0;
    finish_face_varying("uv", 2, uvs_, uv_index_, "vt");
    finish_face_varying("normal", 3, normals_, normal_index_, "vn");
    if (colored_vertices_ > 0) {
      if (colored_vertices_ == nv) mesh.vertex_channels.push_back({"color", 3, std::move(colors_)});
      else out_.warnings.push_back("vertex colours given for only " + std::to_string(colored_vertices_) + " of " +
                                   std::to_string(nv) + " vertices: dropped");
    }
  }

  void finish_face_varying(const char* name, int components, std::vector<double>& values, std::vector<Index>& index,
                           const char* keyword) {
    const std::size_t corners = out_.mesh.face_indices.size();
    if (index.empty() || corners == 0) return;
    index.resize(corners, kInvalidIndex);
    if (std::find(index.begin(), index.end(), kInvalidIndex) != index.end()) {
      out_.warnings.push_back(std::string(keyword) + " indices are missing on some faces: '" + name +
                              "' channel dropped");
      return;
    }
    const std::size_t count = values.size() / static_cast<std::size_t>(components);
    for (std::size_t c = 0; c < corners; ++c)
      if (static_cast<std::size_t>(index[c]) >= count) {
        out_.warnings.push_back(std::string(keyword) + " index " + std::to_string(index[c] + 1) +
                                " is out of range (" + std::to_string(count) + " given): '" + name +
                                "' channel dropped");
        return;
      }
    out_.mesh.face_varying_channels.push_back({name, components, std::move(values), std::move(index)});
  }

  std::string_view text_;
  const std::string& path_;
  std::uint64_t line_ = 0;
  MeshFile out_;
  std::vector<double> uvs_, normals_, colors_;
  std::vector<Index> uv_index_, normal_index_;
  std::size_t colored_vertices_ = 0;
  std::size_t unknown_keywords_ = 0;
  std::size_t polyline_indices_ = 0;
};

}  // namespace

MeshFile parse_obj(std::string_view text, const std::string& path) {
  MeshFile file = ObjParser(text, path).parse();
  file.lines.path = path;
  return file;
}

}  // namespace subdiv
