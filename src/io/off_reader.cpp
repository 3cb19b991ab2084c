// OFF reader. The file is read as whitespace-separated tokens with '#'
// comments, so values may wrap across lines; what follows the values a vertex
// or face needs on its last line (colours, normals, texture coordinates) is
// skipped.

#include <algorithm>
#include <cstring>
#include <limits>

#include "subdiv/core/error.h"
#include "subdiv/io/off.h"
#include "text_scan.h"

namespace subdiv {

namespace {

using detail::LineScanner;
using detail::clamp_line;
using detail::printable;

struct Token {
  std::string_view text;  ///< empty at the end of the file
  std::uint64_t line = 0;
};

/// Tokens separated by whitespace, newlines and '#' comments.
class Tokenizer {
 public:
  explicit Tokenizer(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}

  Token next() {
    skip_blank();
    const char* start = p_;
    while (p_ != end_ && *p_ != '\n' && *p_ != '#' && !detail::is_space(*p_)) ++p_;
    return {{start, static_cast<std::size_t>(p_ - start)}, line_};
  }
  Token peek() const {
    Tokenizer copy = *this;
    return copy.next();
  }
  /// Bytes from the cursor to the end of the text.
  std::size_t bytes_left() const { return static_cast<std::size_t>(end_ - p_); }
  std::uint64_t line() const { return line_; }

 private:
  void skip_blank() {
    while (p_ != end_) {
      if (*p_ == '\n') {
        ++line_;
        ++p_;
      } else if (detail::is_space(*p_)) {
        ++p_;
      } else if (*p_ == '#') {
        const void* nl = std::memchr(p_, '\n', static_cast<std::size_t>(end_ - p_));
        p_ = nl ? static_cast<const char*>(nl) : end_;
      } else {
        break;
      }
    }
  }

  const char* p_;
  const char* end_;
  std::uint64_t line_ = 1;
};

bool parse_double(std::string_view text, double& value) {
  LineScanner s(text);
  return !text.empty() && s.number(value) && s.at_end();
}

bool parse_integer(std::string_view text, long long& value) {
  LineScanner s(text);
  return !text.empty() && s.integer(value) && s.at_end();
}

class OffParser {
 public:
  OffParser(std::string_view text, const std::string& path) : tokens_(text), path_(path) {}

  MeshFile parse() {
    parse_header();
    read_vertices();
    read_faces();
    const Token extra = tokens_.next();
    if (!extra.text.empty())
      out_.warnings.push_back("OFF: data after the last face ignored (from line " + std::to_string(extra.line) + ")");
    out_.lines.path = path_;
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(std::uint64_t line, const std::string& what) const { throw ParseError(path_, line, what); }

  // [ST][C][N][4][n]OFF; false if `word` is not such a keyword.
  bool parse_keyword(std::string_view word) {
    if (word.size() < 3 || word.substr(word.size() - 3) != "OFF") return false;
    std::string_view prefix = word.substr(0, word.size() - 3);
    auto take = [&](std::string_view p) {
      if (prefix.substr(0, p.size()) != p) return false;
      prefix.remove_prefix(p.size());
      return true;
    };
    texture_ = take("ST");
    color_ = take("C");
    normal_ = take("N");
    homogeneous_ = take("4");
    dimension_line_ = take("n");
    return prefix.empty();
  }

  long long need_count(const char* what) {
    const Token t = tokens_.next();
    long long value;
    if (t.text.empty()) fail(0, std::string("unexpected end of file: missing the ") + what);
    if (!parse_integer(t.text, value) || value < 0)
      fail(t.line, std::string("bad ") + what + " '" + printable(t.text) + "'");
    counts_line_ = t.line;
    return value;
  }

  void parse_header() {
    const Token first = tokens_.peek();
    if (first.text.empty()) fail(0, "empty file: expected an OFF header");
    long long number;
    if (!parse_integer(first.text, number)) {  // the keyword is optional: counts may come first
      tokens_.next();
      if (!parse_keyword(first.text))
        fail(first.line, "not an OFF file: expected a header keyword such as OFF, COFF or NOFF, found '" +
                             printable(first.text) + "'");
      const Token after = tokens_.peek();
      if (after.line == first.line && after.text == "BINARY") fail(first.line, "binary OFF is not supported");
    }
    coordinates_ = 3;
    if (dimension_line_) {
      const long long dimension = need_count("dimension");
      if (dimension < 1 || dimension > 1000)
        fail(counts_line_, "unsupported dimension " + std::to_string(dimension) + " (expected 1 to 1000)");
      coordinates_ = static_cast<int>(dimension);
    }
    kept_coordinates_ = std::min(coordinates_, 3);
    if (homogeneous_) ++coordinates_;  // x y z w: w is dropped

    const long long nv = need_count("vertex count");
    const long long nf = need_count("face count");
    const Token edges = tokens_.peek();
    if (!edges.text.empty() && edges.line == counts_line_) need_count("edge count");  // not used

    // Counts must fit in the rest of the file (each value takes at least a
    // digit and a separator) before anything is reserved.
    values_per_vertex_ = coordinates_ + (normal_ ? 3 : 0) + (color_ ? 3 : 0) + (texture_ ? 2 : 0);
    std::uint64_t available = tokens_.bytes_left() + 1;
    const auto vertex_bytes = static_cast<std::uint64_t>(2 * values_per_vertex_);
    if (static_cast<std::uint64_t>(nv) > available / vertex_bytes)
      fail(counts_line_, "header declares " + std::to_string(nv) + " vertices but the file holds at most " +
                             std::to_string(available / vertex_bytes));
    available -= static_cast<std::uint64_t>(nv) * vertex_bytes;
    if (static_cast<std::uint64_t>(nf) > available / 2)
      fail(counts_line_, "header declares " + std::to_string(nf) + " faces but the file holds at most " +
                             std::to_string(available / 2));
    if (nv > kMaxElements || nf > kMaxElements) fail(counts_line_, "too many vertices or faces");
    vertex_count_ = nv;
    face_count_ = nf;
  }

  // Skips, after checking they are numbers, the tokens left on `line`.
  void skip_rest_of_line(std::uint64_t line, const char* element, std::size_t index) {
    for (Token t = tokens_.peek(); !t.text.empty() && t.line == line; t = tokens_.peek()) {
      double ignored;
      if (!parse_double(t.text, ignored))
        fail(t.line, element + std::to_string(index) + ": bad value '" + printable(t.text) + "'");
      tokens_.next();
    }
  }

  void read_vertices() {
    auto& positions = out_.mesh.positions;
    const auto n = static_cast<std::size_t>(vertex_count_);
    positions.reserve(n);
    out_.lines.vertex_lines.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 p;
      std::uint64_t first_line = 0, last_line = 0;
      for (int k = 0; k < values_per_vertex_; ++k) {
        const Token t = tokens_.next();
        if (t.text.empty())
          fail(0, "unexpected end of file in vertex " + std::to_string(i) + " (the header declares " +
                      std::to_string(n) + " vertices)");
        double value;
        if (!parse_double(t.text, value))
          fail(t.line, "vertex " + std::to_string(i) + ": bad number '" + printable(t.text) + "'");
        if (k == 0) first_line = t.line;
        if (k < kept_coordinates_) p[k] = value;
        last_line = t.line;
      }
      skip_rest_of_line(last_line, "vertex ", i);
      positions.push_back(p);
      out_.lines.vertex_lines.push_back(clamp_line(first_line));
    }
  }

  void read_faces() {
    PolygonMesh& mesh = out_.mesh;
    const auto n = static_cast<std::size_t>(face_count_);
    mesh.face_offsets.reserve(n + 1);
    out_.lines.face_lines.reserve(n);
    for (std::size_t f = 0; f < n; ++f) {
      const auto name = [f] { return "face " + std::to_string(f); };
      Token t = tokens_.next();
      if (t.text.empty())
        fail(0, "unexpected end of file in " + name() + " (the header declares " + std::to_string(n) + " faces)");
      const std::uint64_t first_line = t.line;
      long long size;
      if (!parse_integer(t.text, size) || size < 0)
        fail(t.line, name() + ": bad vertex count '" + printable(t.text) + "'");
      if (static_cast<unsigned long long>(size) >
          static_cast<unsigned long long>(kMaxElements) - mesh.face_indices.size())
        fail(t.line, name() + ": too many face corners in the file");
      std::uint64_t last_line = t.line;
      for (long long k = 0; k < size; ++k) {
        t = tokens_.next();
        if (t.text.empty()) fail(0, "unexpected end of file in " + name());
        long long v;
        if (!parse_integer(t.text, v)) fail(t.line, name() + ": bad vertex index '" + printable(t.text) + "'");
        if (v < 0 || v >= vertex_count_)
          fail(t.line, name() + ": vertex index " + std::to_string(v) + " is out of range (the file has " +
                           std::to_string(vertex_count_) + " vertices)");
        mesh.face_indices.push_back(static_cast<Index>(v));
        last_line = t.line;
      }
      skip_rest_of_line(last_line, "face ", f);  // colour
      mesh.face_offsets.push_back(static_cast<Index>(mesh.face_indices.size()));
      out_.lines.face_lines.push_back(clamp_line(first_line));
    }
  }

  Tokenizer tokens_;
  const std::string& path_;
  MeshFile out_;
  bool texture_ = false, color_ = false, normal_ = false, homogeneous_ = false, dimension_line_ = false;
  int coordinates_ = 3;       ///< values that make up a position
  int kept_coordinates_ = 3;  ///< of which x, y, z
  int values_per_vertex_ = 3;
  std::uint64_t counts_line_ = 0;
  long long vertex_count_ = 0;
  long long face_count_ = 0;
};

}  // namespace

MeshFile parse_off(std::string_view text, const std::string& path) { return OffParser(text, path).parse(); }

}  // namespace subdiv
