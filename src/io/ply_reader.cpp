// PLY reader: the header, then every element in ASCII or binary (either byte
// order). Header counts are checked against the bytes that follow the header
// before anything is reserved, so a lying header cannot exhaust memory, and
// every read is bounds-checked, so a truncated or corrupted file ends in a
// ParseError.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "subdiv/core/error.h"
#include "subdiv/io/ply.h"
#include "text_scan.h"

namespace subdiv {

namespace {

using detail::LineReader;
using detail::LineScanner;
using detail::clamp_line;
using detail::printable;

enum class Scalar : std::uint8_t { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::optional<Scalar> scalar_from_name(std::string_view s) {
  if (s == "char" || s == "int8") return Scalar::int8;
  if (s == "uchar" || s == "uint8") return Scalar::uint8;
  if (s == "short" || s == "int16") return Scalar::int16;
  if (s == "ushort" || s == "uint16") return Scalar::uint16;
  if (s == "int" || s == "int32") return Scalar::int32;
  if (s == "uint" || s == "uint32") return Scalar::uint32;
  if (s == "float" || s == "float32") return Scalar::float32;
  if (s == "double" || s == "float64") return Scalar::float64;
  return std::nullopt;
}

std::size_t scalar_size(Scalar t) {
  switch (t) {
    case Scalar::int8:
    case Scalar::uint8: return 1;
    case Scalar::int16:
    case Scalar::uint16: return 2;
    case Scalar::int32:
    case Scalar::uint32:
    case Scalar::float32: return 4;
    case Scalar::float64: return 8;
  }
  return 1;
}

bool is_integer(Scalar t) { return t != Scalar::float32 && t != Scalar::float64; }

enum class Encoding { ascii, little_endian, big_endian };

// What a vertex or face property means to us. The vertex roles index the
// per-vertex value array in read_vertices().
enum Role : std::uint8_t { role_none, role_x, role_y, role_z, role_nx, role_ny, role_nz, role_red, role_green,
                           role_blue, role_u, role_v, role_count, role_indices = role_count };

struct Property {
  std::string name;
  Scalar type = Scalar::float32;  ///< the scalar type, or a list's item type
  bool is_list = false;
  Scalar count_type = Scalar::uint8;
  Role role = role_none;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  std::uint64_t line = 0;  ///< header line of the declaration
};

std::string describe(const Element& e, std::uint64_t index) { return e.name + " " + std::to_string(index); }

// --- data sources ----------------------------------------------------------
// Both sources offer the same operations; the element readers are templates
// over them. Errors name the element being read ("face 12").

/// ASCII data: one element per line (blank lines between elements allowed).
class AsciiSource {
 public:
  AsciiSource(LineReader reader, const std::string& path) : reader_(reader), path_(path), scan_(std::string_view{}) {}

  void begin(const Element& e, std::uint64_t index) {
    element_ = &e;
    index_ = index;
    std::string_view text;
    while (reader_.next(text)) {
      line_ = reader_.line_number();
      scan_ = LineScanner(text);
      if (!scan_.at_end()) return;
    }
    throw ParseError(path_, 0, "unexpected end of file in " + describe(e, index));
  }
  void end() {
    if (!scan_.at_end())
      fail("more values on the line than the header declares (found '" + printable(scan_.token()) + "')");
  }

  double read_value(const Property& p) {
    double value;
    if (!scan_.number(value)) bad_value(p);
    return value;
  }
  long long read_integer(const Property& p) {
    long long value;
    if (scan_.integer(value)) return value;
    double d;  // tolerate integral values written as "3.0"
    if (scan_.number(d) && std::floor(d) == d && std::fabs(d) < 9.0e15) return static_cast<long long>(d);
    bad_value(p, "an integer");
  }
  long long read_count(const Property& p) { return read_integer(p); }
  void skip_value(const Property& p) { read_value(p); }
  void require_items(long long, Scalar) {}  // a line ends: reading stops there
  void skip_list(const Property& p) {
    const long long n = read_count(p);
    if (n < 0) fail("negative list length " + std::to_string(n) + " for property '" + p.name + "'");
    for (long long i = 0; i < n; ++i) read_value(p);
  }

  /// Everything after the last element must be blank.
  void finish(std::vector<std::string>&) {
    std::string_view text;
    while (reader_.next(text)) {
      LineScanner s(text);
      if (!s.at_end())
        throw ParseError(path_, reader_.line_number(),
                         "unexpected data after the last element: '" + printable(s.token()) + "'");
    }
  }

  std::uint64_t line() const { return line_; }
  static constexpr bool has_lines = true;

  [[noreturn]] void fail(const std::string& what) const {
    throw ParseError(path_, line_, describe(*element_, index_) + ": " + what);
  }

 private:
  [[noreturn]] void bad_value(const Property& p, const char* expected = "a number") {
    const std::string_view tok = scan_.token();
    if (tok.empty()) fail("the line ends before property '" + p.name + "' (truncated file?)");
    fail("bad value '" + printable(tok) + "' for property '" + p.name + "' (expected " + expected + ")");
  }

  LineReader reader_;
  const std::string& path_;
  LineScanner scan_;
  std::uint64_t line_ = 0;
  const Element* element_ = nullptr;
  std::uint64_t index_ = 0;
};

/// Binary data in either byte order; values are copied out with memcpy.
class BinarySource {
 public:
  BinarySource(std::string_view data, bool big_endian, const std::string& path)
      : p_(data.data()), end_(data.data() + data.size()), path_(path),
        swap_(big_endian != (std::endian::native == std::endian::big)) {}

  void begin(const Element& e, std::uint64_t index) {
    element_ = &e;
    index_ = index;
  }
  void end() {}

  double read_value(const Property& p) { return read_scalar(p.type); }
  long long read_integer(const Property& p) { return read_int(p.type); }
  long long read_count(const Property& p) { return read_int(p.count_type); }
  void skip_value(const Property& p) { skip(scalar_size(p.type)); }
  void require_items(long long n, Scalar type) {
    if (static_cast<std::uint64_t>(n) > remaining() / scalar_size(type)) truncated();
  }
  void skip_list(const Property& p) {
    const long long n = read_count(p);
    if (n < 0) fail("negative list length " + std::to_string(n) + " for property '" + p.name + "'");
    require_items(n, p.type);
    p_ += static_cast<std::size_t>(n) * scalar_size(p.type);
  }
  void skip(std::size_t bytes) {
    if (bytes > remaining()) truncated();
    p_ += bytes;
  }
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }

  void finish(std::vector<std::string>& warnings) const {
    if (p_ != end_)
      warnings.push_back(std::to_string(remaining()) + " bytes after the last element ignored");
  }

  std::uint64_t line() const { return 0; }
  static constexpr bool has_lines = false;

  [[noreturn]] void fail(const std::string& what) const {
    throw ParseError(path_, 0, describe(*element_, index_) + ": " + what);
  }

 private:
  [[noreturn]] void truncated() const {
    throw ParseError(path_, 0, "unexpected end of file in " + describe(*element_, index_));
  }

  template <typename T>
  T get() {
    if (sizeof(T) > remaining()) truncated();
    char buf[sizeof(T)];
    std::memcpy(buf, p_, sizeof(T));
    if (swap_) std::reverse(buf, buf + sizeof(T));
    T value;
    std::memcpy(&value, buf, sizeof(T));
    p_ += sizeof(T);
    return value;
  }

  long long read_int(Scalar t) {
    switch (t) {
      case Scalar::int8: return get<std::int8_t>();
      case Scalar::uint8: return get<std::uint8_t>();
      case Scalar::int16: return get<std::int16_t>();
      case Scalar::uint16: return get<std::uint16_t>();
      case Scalar::int32: return get<std::int32_t>();
      case Scalar::uint32: return get<std::uint32_t>();
      case Scalar::float32:
      case Scalar::float64: break;  // the header check keeps floats out of counts and indices
    }
    fail("integer expected");
  }

  double read_scalar(Scalar t) {
    switch (t) {
      case Scalar::float32: return static_cast<double>(get<float>());
      case Scalar::float64: return get<double>();
      default: return static_cast<double>(read_int(t));
    }
  }

  const char* p_;
  const char* end_;
  const std::string& path_;
  bool swap_;
  const Element* element_ = nullptr;
  std::uint64_t index_ = 0;
};

// --- the parser --------------------------------------------------------------

class PlyParser {
 public:
  PlyParser(std::string_view bytes, const std::string& path) : bytes_(bytes), path_(path) {}

  MeshFile parse() {
    LineReader reader(bytes_);
    parse_header(reader);
    line_ = 0;
    assign_vertex_roles();
    assign_face_roles();
    check_counts(reader.bytes_left());
    if (encoding_ == Encoding::ascii) {
      AsciiSource source(reader, path_);
      read_elements(source);
    } else {
      BinarySource source(bytes_.substr(bytes_.size() - reader.bytes_left()), encoding_ == Encoding::big_endian,
                          path_);
      read_elements(source);
    }
    out_.lines.path = path_;
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw ParseError(path_, line_, what); }

  // --- header ----------------------------------------------------------------
  void parse_header(LineReader& reader) {
    std::string_view text;
    if (!reader.next(text)) fail("empty file: expected a PLY header");
    line_ = 1;
    {
      LineScanner s(text);
      if (s.token() != "ply" || !s.at_end()) fail("not a PLY file (the first line must be 'ply')");
    }
    bool have_format = false;
    while (reader.next(text)) {
      line_ = reader.line_number();
      LineScanner s(text);
      const std::string_view keyword = s.token();
      if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "end_header") {
        if (!s.at_end()) fail("unexpected text after end_header");
        if (!have_format) fail("the header has no format line");
        return;
      }
      if (keyword == "format") {
        if (have_format) fail("second format line");
        parse_format(s);
        have_format = true;
      } else if (keyword == "element") {
        parse_element(s);
      } else if (keyword == "property") {
        parse_property(s);
      } else {
        fail("unknown header line '" + printable(keyword) + "'");
      }
    }
    line_ = 0;
    fail("the PLY header has no end_header line");
  }

  void parse_format(LineScanner& s) {
    const std::string_view name = s.token();
    if (name == "ascii") encoding_ = Encoding::ascii;
    else if (name == "binary_little_endian") encoding_ = Encoding::little_endian;
    else if (name == "binary_big_endian") encoding_ = Encoding::big_endian;
    else
      fail("unknown PLY format '" + printable(name) +
           "' (expected ascii, binary_little_endian or binary_big_endian)");
    if (s.at_end()) return;  // some writers leave the version out
    double version;
    if (!s.number(version) || version != 1.0) fail("unsupported PLY version '" + printable(s.rest()) + "'");
    if (!s.at_end()) fail("unexpected text after the format line");
  }

  void parse_element(LineScanner& s) {
    Element e;
    e.name = std::string(s.token());
    e.line = line_;
    if (e.name.empty()) fail("element declaration without a name");
    long long count;
    if (!s.integer(count) || count < 0)
      fail("bad count for element '" + printable(e.name) + "' ('" + printable(s.token()) + "')");
    if (!s.at_end()) fail("unexpected text after the declaration of element '" + printable(e.name) + "'");
    e.count = static_cast<std::uint64_t>(count);
    for (const Element& other : elements_)
      if (other.name == e.name && (e.name == "vertex" || e.name == "face"))
        fail("second '" + e.name + "' element");
    elements_.push_back(std::move(e));
  }

  Scalar need_type(std::string_view name) const {
    const auto t = scalar_from_name(name);
    if (!t) fail(name.empty() ? std::string("property declaration without a type")
                              : "unknown property type '" + printable(name) + "'");
    return *t;
  }

  void parse_property(LineScanner& s) {
    if (elements_.empty()) fail("property declared before any element");
    Property p;
    const std::string_view type = s.token();
    if (type == "list") {
      p.is_list = true;
      p.count_type = need_type(s.token());
      if (!is_integer(p.count_type)) fail("a list's count type must be an integer type");
      p.type = need_type(s.token());
    } else {
      p.type = need_type(type);
    }
    p.name = std::string(s.token());
    if (p.name.empty()) fail("property declaration without a name");
    if (!s.at_end()) fail("unexpected text after property '" + printable(p.name) + "'");
    elements_.back().properties.push_back(std::move(p));
  }

  Element* find_element(std::string_view name) {
    for (Element& e : elements_)
      if (e.name == name) return &e;
    return nullptr;
  }

  // Gives each vertex property its meaning; channels need all components.
  void assign_vertex_roles() {
    vertex_ = find_element("vertex");
    if (!vertex_) fail("the header declares no vertex element");
    Element& e = *vertex_;
    auto find = [&](std::string_view name) -> Property* {
      for (Property& p : e.properties)
        if (p.name == name) return &p;
      return nullptr;
    };
    for (const auto& [name, role] : {std::pair{"x", role_x}, std::pair{"y", role_y}, std::pair{"z", role_z}}) {
      Property* p = find(name);
      line_ = e.line;
      if (!p) fail(std::string("the vertex element has no '") + name + "' property");
      if (p->is_list) fail(std::string("vertex property '") + name + "' is a list, not a number");
      p->role = role;
    }
    // Assigns a group of roles if every name is a scalar property; returns
    // whether it did.
    auto assign = [&](std::initializer_list<const char*> names, Role first) {
      std::vector<Property*> found;
      for (const char* name : names) {
        Property* p = find(name);
        if (!p || p->is_list || p->role != role_none) return false;
        found.push_back(p);
      }
      for (std::size_t i = 0; i < found.size(); ++i) found[i]->role = static_cast<Role>(first + i);
      return true;
    };
    has_normal_ = assign({"nx", "ny", "nz"}, role_nx);
    has_color_ = assign({"red", "green", "blue"}, role_red) ||
                 assign({"diffuse_red", "diffuse_green", "diffuse_blue"}, role_red);
    has_uv_ = assign({"u", "v"}, role_u) || assign({"s", "t"}, role_u) ||
              assign({"texture_u", "texture_v"}, role_u) || assign({"texture_s", "texture_t"}, role_u);
    std::string ignored;
    for (const Property& p : e.properties)
      if (p.role == role_none) ignored += (ignored.empty() ? "" : ", ") + printable(p.name);
    if (!ignored.empty()) out_.warnings.push_back("PLY vertex properties not read: " + ignored);
  }

  void assign_face_roles() {
    face_ = find_element("face");
    std::string ignored_elements;
    for (const Element& e : elements_)
      if (&e != vertex_ && &e != face_)
        ignored_elements += (ignored_elements.empty() ? "" : ", ") + printable(e.name) + " (" +
                            std::to_string(e.count) + ")";
    if (!ignored_elements.empty()) out_.warnings.push_back("PLY elements not read: " + ignored_elements);
    if (!face_) return;
    line_ = face_->line;
    Property* indices = nullptr;
    for (const char* name : {"vertex_indices", "vertex_index"}) {
      for (Property& p : face_->properties)
        if (p.name == name) {
          indices = &p;
          break;
        }
      if (indices) break;
    }
    if (!indices) {
      if (face_->count > 0) fail("the face element has no vertex_indices list");
    } else {
      if (!indices->is_list) fail("face property '" + indices->name + "' must be a list");
      if (!is_integer(indices->type)) fail("face property '" + indices->name + "' must hold integers");
      indices->role = role_indices;
    }
    std::string ignored;
    for (const Property& p : face_->properties)
      if (p.role == role_none) ignored += (ignored.empty() ? "" : ", ") + printable(p.name);
    if (!ignored.empty()) out_.warnings.push_back("PLY face properties not read: " + ignored);
  }

  // The fewest bytes one item of `e` can occupy in the data.
  std::uint64_t minimum_bytes(const Element& e) const {
    std::uint64_t bytes = 0;
    for (const Property& p : e.properties) {
      if (encoding_ == Encoding::ascii) bytes += 2;  // a digit and a separator
      else bytes += scalar_size(p.is_list ? p.count_type : p.type);
    }
    return bytes;
  }

  // Runs before anything is reserved: every element's count must fit in the
  // bytes that follow the header.
  void check_counts(std::size_t data_bytes) {
    // In ASCII the last value needs no separator after it.
    std::uint64_t available = data_bytes + (encoding_ == Encoding::ascii ? 1 : 0);
    for (const Element& e : elements_) {
      const std::uint64_t min = minimum_bytes(e);
      if (min == 0) continue;
      line_ = e.line;
      const std::uint64_t most = available / min;
      if (e.count > most) {
        const std::string what = &e == vertex_ ? std::string("vertices")
                                 : &e == face_ ? std::string("faces")
                                               : "'" + printable(e.name) + "' elements";
        fail("header declares " + std::to_string(e.count) + " " + what + " but the file holds at most " +
             std::to_string(most));
      }
      available -= e.count * min;
    }
    for (const Element* e : {vertex_, face_}) {
      if (e && e->count > static_cast<std::uint64_t>(kMaxElements)) {
        line_ = e->line;
        fail("too many " + std::string(e == vertex_ ? "vertices" : "faces") + ": " + std::to_string(e->count) +
             " (at most " + std::to_string(kMaxElements) + ")");
      }
    }
    line_ = 0;
  }

  // --- data ----------------------------------------------------------------
  template <typename Source>
  void read_elements(Source& source) {
    for (const Element& e : elements_) {
      if (&e == vertex_) read_vertices(source, e);
      else if (&e == face_) read_faces(source, e);
      else skip_element(source, e);
    }
    source.finish(out_.warnings);
  }

  template <typename Source>
  void read_vertices(Source& source, const Element& e) {
    PolygonMesh& mesh = out_.mesh;
    const auto n = static_cast<std::size_t>(e.count);
    mesh.positions.reserve(n);
    std::vector<double> normals, colors, uvs;
    if (has_normal_) normals.reserve(n * 3);
    if (has_color_) colors.reserve(n * 3);
    if (has_uv_) uvs.reserve(n * 2);
    if (Source::has_lines) out_.lines.vertex_lines.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      source.begin(e, i);
      double value[role_count] = {};
      for (const Property& p : e.properties) {
        if (p.is_list) {
          source.skip_list(p);
        } else if (p.role == role_none) {
          source.skip_value(p);
        } else {
          double v = source.read_value(p);
          if (p.role >= role_red && p.role <= role_blue && is_integer(p.type)) v /= 255.0;
          value[p.role] = v;
        }
      }
      source.end();
      mesh.positions.push_back({value[role_x], value[role_y], value[role_z]});
      if (has_normal_) normals.insert(normals.end(), {value[role_nx], value[role_ny], value[role_nz]});
      if (has_color_) colors.insert(colors.end(), {value[role_red], value[role_green], value[role_blue]});
      if (has_uv_) uvs.insert(uvs.end(), {value[role_u], value[role_v]});
      if (Source::has_lines) out_.lines.vertex_lines.push_back(clamp_line(source.line()));
    }
    if (has_normal_) mesh.vertex_channels.push_back({"normal", 3, std::move(normals)});
    if (has_color_) mesh.vertex_channels.push_back({"color", 3, std::move(colors)});
    if (has_uv_) mesh.vertex_channels.push_back({"uv", 2, std::move(uvs)});
  }

  template <typename Source>
  void read_faces(Source& source, const Element& e) {
    PolygonMesh& mesh = out_.mesh;
    const auto n = static_cast<std::size_t>(e.count);
    const auto vertex_count = static_cast<long long>(vertex_->count);
    mesh.face_offsets.reserve(n + 1);
    mesh.face_indices.reserve(std::min<std::size_t>(n * 3, bytes_.size()));
    if (Source::has_lines) out_.lines.face_lines.reserve(n);
    for (std::size_t f = 0; f < n; ++f) {
      source.begin(e, f);
      for (const Property& p : e.properties) {
        if (p.role != role_indices) {
          if (p.is_list) source.skip_list(p);
          else source.skip_value(p);
          continue;
        }
        const long long size = source.read_count(p);
        if (size < 0) source.fail("negative vertex count " + std::to_string(size));
        source.require_items(size, p.type);
        if (static_cast<unsigned long long>(size) >
            static_cast<unsigned long long>(kMaxElements) - mesh.face_indices.size())
          source.fail("too many face corners in the file (at most " + std::to_string(kMaxElements) + ")");
        for (long long k = 0; k < size; ++k) {
          const long long v = source.read_integer(p);
          if (v < 0 || v >= vertex_count)
            source.fail("vertex index " + std::to_string(v) + " is out of range (the file has " +
                        std::to_string(vertex_count) + " vertices)");
          mesh.face_indices.push_back(static_cast<Index>(v));
        }
      }
      source.end();
      mesh.face_offsets.push_back(static_cast<Index>(mesh.face_indices.size()));
      if (Source::has_lines) out_.lines.face_lines.push_back(clamp_line(source.line()));
    }
  }

  template <typename Source>
  void skip_element(Source& source, const Element& e) {
    if (e.properties.empty()) return;  // nothing stored, however large the count
    if constexpr (!Source::has_lines) {
      const bool fixed = std::none_of(e.properties.begin(), e.properties.end(),
                                      [](const Property& p) { return p.is_list; });
      if (fixed) {  // checked against the file size: the product cannot overflow
        if (e.count > 0) source.begin(e, 0);
        source.skip(static_cast<std::size_t>(e.count * minimum_bytes(e)));
        return;
      }
    }
    for (std::uint64_t i = 0; i < e.count; ++i) {
      source.begin(e, i);
      for (const Property& p : e.properties) {
        if (p.is_list) source.skip_list(p);
        else source.skip_value(p);
      }
      source.end();
    }
  }

  std::string_view bytes_;
  const std::string& path_;
  std::uint64_t line_ = 0;
  Encoding encoding_ = Encoding::ascii;
  std::vector<Element> elements_;
  Element* vertex_ = nullptr;
  Element* face_ = nullptr;
  bool has_normal_ = false, has_color_ = false, has_uv_ = false;
  MeshFile out_;
};

}  // namespace

MeshFile parse_ply(std::string_view bytes, const std::string& path) { return PlyParser(bytes, path).parse(); }

}  // namespace subdiv
