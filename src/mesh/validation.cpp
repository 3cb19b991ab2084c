#include "subdiv/mesh/validation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "subdiv/mesh/topology.h"

namespace subdiv {

const char* to_string(IssueKind k) noexcept {
  switch (k) {
    case IssueKind::index_out_of_range: return "index out of range";
    case IssueKind::face_too_small: return "face with fewer than 3 vertices";
    case IssueKind::repeated_vertex: return "face with a repeated vertex";
    case IssueKind::non_finite_coordinate: return "non-finite coordinate";
    case IssueKind::non_manifold_edge: return "non-manifold edge";
    case IssueKind::non_manifold_vertex: return "non-manifold vertex";
    case IssueKind::inconsistent_orientation: return "inconsistent orientation";
    case IssueKind::invalid_tag: return "invalid tag";
    case IssueKind::invalid_channel: return "invalid data channel";
    case IssueKind::isolated_vertex: return "isolated vertex";
  }
  return "?";
}

Severity severity_of(IssueKind k) noexcept {
  return k == IssueKind::isolated_vertex ? Severity::warning : Severity::error;
}

std::size_t ValidationReport::error_count() const noexcept {
  std::size_t n = 0;
  for (int k = 0; k < kIssueKindCount; ++k)
    if (severity_of(static_cast<IssueKind>(k)) == Severity::error) n += counts[static_cast<std::size_t>(k)];
  return n;
}

std::size_t ValidationReport::warning_count() const noexcept {
  std::size_t n = 0;
  for (int k = 0; k < kIssueKindCount; ++k)
    if (severity_of(static_cast<IssueKind>(k)) == Severity::warning) n += counts[static_cast<std::size_t>(k)];
  return n;
}

std::string ValidationReport::first_error(const std::string& path) const {
  for (const auto& issue : issues)
    if (issue.severity == Severity::error) return format_issue(issue, path);
  // No error was listed (max_issues_per_kind = 0): name the first counted kind.
  for (int k = 0; k < kIssueKindCount; ++k) {
    const auto kind = static_cast<IssueKind>(k);
    const std::size_t n = counts[static_cast<std::size_t>(k)];
    if (severity_of(kind) == Severity::error && n > 0) {
      const std::string what = std::to_string(n) + " x " + to_string(kind) + " (not listed)";
      return path.empty() ? what : path + ": " + what;
    }
  }
  return {};
}

std::string format_issue(const ValidationIssue& issue, const std::string& path) {
  std::string where = path;
  if (issue.line > 0) where += (where.empty() ? "line " : ":") + std::to_string(issue.line);
  return where.empty() ? issue.message : where + ": " + issue.message;
}

namespace {

class Reporter {
 public:
  Reporter(ValidationReport& report, const ValidationOptions& options)
      : report_(report), options_(options) {}
  void add(IssueKind kind, Index element, std::uint32_t line, std::string message) {
    auto& n = report_.counts[static_cast<std::size_t>(kind)];
    if (n++ < options_.max_issues_per_kind)
      report_.issues.push_back({kind, severity_of(kind), element, line, std::move(message)});
  }

 private:
  ValidationReport& report_;
  const ValidationOptions& options_;
};

std::uint32_t line_of(const std::vector<std::uint32_t> SourceLines::*member, const SourceLines* lines, Index i) {
  return lines ? SourceLines::at(lines->*member, i) : 0;
}

bool has_repeated_vertex(std::span<const Index> face, std::vector<Index>& scratch) {
  if (face.size() <= 16) {
    for (std::size_t i = 0; i < face.size(); ++i)
      for (std::size_t j = i + 1; j < face.size(); ++j)
        if (face[i] == face[j]) return true;
    return false;
  }
  scratch.assign(face.begin(), face.end());
  std::sort(scratch.begin(), scratch.end());
  return std::adjacent_find(scratch.begin(), scratch.end()) != scratch.end();
}

std::string str(Index i) { return std::to_string(i); }
std::string str(double d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", d);
  return buf;
}

// Per-face and per-vertex checks that need no topology. Returns false when an
// index is out of range (topology cannot be built then).
bool check_elements(const PolygonMesh& mesh, const SourceLines* lines, Reporter& out) {
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (!is_finite(mesh.positions[v]))
      out.add(IssueKind::non_finite_coordinate, v, line_of(&SourceLines::vertex_lines, lines, v),
              "vertex " + str(v) + " has a NaN or infinite coordinate");

  const auto& off = mesh.face_offsets;
  if (off.empty() || off.front() != 0 || static_cast<std::size_t>(off.back()) != mesh.face_indices.size() ||
      !std::is_sorted(off.begin(), off.end())) {
    out.add(IssueKind::index_out_of_range, 0, 0, "face offsets are malformed");
    return false;
  }
  bool in_range = true;
  std::vector<Index> scratch;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    const std::uint32_t line = line_of(&SourceLines::face_lines, lines, f);
    bool face_in_range = true;
    for (const Index v : face)
      if (v < 0 || v >= mesh.vertex_count()) {
        out.add(IssueKind::index_out_of_range, f, line,
                "face " + str(f) + " refers to vertex " + str(v) + ", but the mesh has " +
                    str(mesh.vertex_count()) + " vertices");
        face_in_range = in_range = false;
        break;
      }
    if (face.size() < 3)
      out.add(IssueKind::face_too_small, f, line,
              "face " + str(f) + " has " + std::to_string(face.size()) +
                  (face.size() == 1 ? " vertex" : " vertices") + "; a face needs at least 3");
    else if (face_in_range && has_repeated_vertex(face, scratch))
      out.add(IssueKind::repeated_vertex, f, line, "face " + str(f) + " uses a vertex more than once");
  }
  return in_range;
}

void check_channels(const PolygonMesh& mesh, Reporter& out) {
  const auto nv = static_cast<std::size_t>(mesh.vertex_count());
  for (Index i = 0; i < static_cast<Index>(mesh.vertex_channels.size()); ++i) {
    const VertexChannel& ch = mesh.vertex_channels[static_cast<std::size_t>(i)];
    if (ch.components <= 0 || ch.values.size() != nv * static_cast<std::size_t>(ch.components))
      out.add(IssueKind::invalid_channel, i, 0,
              "vertex channel '" + ch.name + "' has " + std::to_string(ch.values.size()) + " values for " +
                  std::to_string(nv) + " vertices of " + std::to_string(ch.components) + " components");
  }
  for (Index i = 0; i < static_cast<Index>(mesh.face_varying_channels.size()); ++i) {
    const FaceVaryingChannel& ch = mesh.face_varying_channels[static_cast<std::size_t>(i)];
    const std::string name = "face-varying channel '" + ch.name + "'";
    if (ch.components <= 0 || ch.values.size() % static_cast<std::size_t>(ch.components) != 0) {
      out.add(IssueKind::invalid_channel, i, 0, name + " has a value count that is not a multiple of its components");
      continue;
    }
    if (ch.indices.size() != mesh.face_indices.size()) {
      out.add(IssueKind::invalid_channel, i, 0,
              name + " has " + std::to_string(ch.indices.size()) + " indices for " +
                  std::to_string(mesh.face_indices.size()) + " face corners");
      continue;
    }
    for (std::size_t c = 0; c < ch.indices.size(); ++c)
      if (ch.indices[c] < 0 || ch.indices[c] >= ch.value_count()) {
        out.add(IssueKind::invalid_channel, i, 0,
                name + " corner " + std::to_string(c) + " refers to value " + str(ch.indices[c]) + ", outside [0, " +
                    str(ch.value_count()) + ")");
        break;
      }
  }
}

// Edges here are vertex pairs, as the collection's statistics count them:
// where faces repeating a vertex made coincident edges, they are merged.
void check_topology(const PolygonMesh& mesh, const MeshTopology& given, const SourceLines* lines,
                    Reporter& out) {
  std::optional<MeshTopology> merged;
  if (given.has_coincident_edges()) merged.emplace(mesh, std::vector<Index>(static_cast<std::size_t>(mesh.corner_count()), 0));
  const MeshTopology& topo = merged ? *merged : given;
  auto face_line = [&](Index f) { return line_of(&SourceLines::face_lines, lines, f); };
  for (Index e = 0; e < topo.edge_count(); ++e) {
    const auto [a, b] = topo.edge_vertices(e);
    const auto sides = topo.edge_corners(e);
    const Index f0 = topo.corner_face(sides[0]);
    if (sides.size() > 2)
      out.add(IssueKind::non_manifold_edge, e, face_line(topo.corner_face(sides[2])),
              "edge " + str(a) + "-" + str(b) + " is shared by " + std::to_string(sides.size()) +
                  " faces (" + str(f0) + ", " + str(topo.corner_face(sides[1])) + ", " +
                  str(topo.corner_face(sides[2])) + (sides.size() > 3 ? ", ..." : "") + ")");
    else if (topo.is_flipped_edge(e)) {
      const Index f1 = topo.corner_face(sides[1]);
      out.add(IssueKind::inconsistent_orientation, e, face_line(f1),
              "faces " + str(f0) + " and " + str(f1) + " traverse their shared edge " + str(a) + "-" +
                  str(b) + " in the same direction (inconsistent orientation)");
    }
  }
  // A vertex on a polyline (OBJ `l` line) is used, though by no face.
  std::vector<bool> on_polyline;
  if (!mesh.polylines.empty()) {
    on_polyline.assign(static_cast<std::size_t>(topo.vertex_count()), false);
    for (const MeshPolyline& l : mesh.polylines)
      for (const Index v : l.vertices)
        if (v >= 0 && v < topo.vertex_count()) on_polyline[static_cast<std::size_t>(v)] = true;
  }
  for (Index v = 0; v < topo.vertex_count(); ++v) {
    const std::uint32_t vline = line_of(&SourceLines::vertex_lines, lines, v);
    if (topo.fan_count(v) > 1)
      out.add(IssueKind::non_manifold_vertex, v, vline,
              "vertex " + str(v) + " is non-manifold: its faces form " + str(topo.fan_count(v)) +
                  " separate fans");
    else if (topo.vertex_kind(v) == VertexKind::isolated &&
             (on_polyline.empty() || !on_polyline[static_cast<std::size_t>(v)]))
      out.add(IssueKind::isolated_vertex, v, vline, "vertex " + str(v) + " is used by no face");
  }
  (void)mesh;
}

void check_tags(const PolygonMesh& mesh, const MeshTopology* topo, const SourceLines* lines, Reporter& out) {
  const Tags& tags = mesh.tags;
  const Index nv = mesh.vertex_count();
  for (Index i = 0; i < static_cast<Index>(tags.creases.size()); ++i) {
    const CreaseTag& t = tags.creases[static_cast<std::size_t>(i)];
    const std::uint32_t line = line_of(&SourceLines::crease_lines, lines, i);
    const std::string name = "crease tag " + str(i) + " (edge " + str(t.v0) + "-" + str(t.v1) + ")";
    if (!(t.sharpness >= 0.0) || !std::isfinite(t.sharpness))
      out.add(IssueKind::invalid_tag, i, line, name + " has sharpness " + str(t.sharpness) + "; it must be finite and >= 0");
    else if (t.v0 < 0 || t.v1 < 0 || t.v0 >= nv || t.v1 >= nv)
      out.add(IssueKind::invalid_tag, i, line, name + " refers to a vertex outside [0, " + str(nv) + ")");
    else if (topo && topo->find_edge(t.v0, t.v1) == kInvalidIndex)
      out.add(IssueKind::invalid_tag, i, line, name + " names an edge the mesh does not have");
  }
  for (Index i = 0; i < static_cast<Index>(tags.corners.size()); ++i) {
    const CornerTag& t = tags.corners[static_cast<std::size_t>(i)];
    const std::uint32_t line = line_of(&SourceLines::corner_lines, lines, i);
    const std::string name = "corner tag " + str(i) + " (vertex " + str(t.vertex) + ")";
    if (t.vertex < 0 || t.vertex >= nv)
      out.add(IssueKind::invalid_tag, i, line, name + " refers to a vertex outside [0, " + str(nv) + ")");
    else if (!(t.sharpness >= 0.0) || !std::isfinite(t.sharpness))
      out.add(IssueKind::invalid_tag, i, line, name + " has sharpness " + str(t.sharpness) + "; it must be finite and >= 0");
    else if (t.angle && !(*t.angle > 0.0 && *t.angle < 2.0 * std::numbers::pi))
      out.add(IssueKind::invalid_tag, i, line, name + " has angle " + str(*t.angle) + " rad, outside (0, 2 pi)");
  }
  for (Index i = 0; i < static_cast<Index>(tags.holes.size()); ++i) {
    const Index f = tags.holes[static_cast<std::size_t>(i)];
    if (f < 0 || f >= mesh.face_count())
      out.add(IssueKind::invalid_tag, i, line_of(&SourceLines::hole_lines, lines, i),
              "hole tag " + str(i) + " refers to face " + str(f) + ", outside [0, " + str(mesh.face_count()) + ")");
  }
}

}  // namespace

ValidationReport validate(const PolygonMesh& mesh, const SourceLines* lines, const ValidationOptions& options) {
  ValidationReport report;
  Reporter out(report, options);
  check_channels(mesh, out);
  if (!check_elements(mesh, lines, out)) {
    check_tags(mesh, nullptr, lines, out);
    return report;
  }
  const MeshTopology topo(mesh);
  check_topology(mesh, topo, lines, out);
  check_tags(mesh, &topo, lines, out);
  return report;
}

ValidationReport validate(const PolygonMesh& mesh, const MeshTopology& topology, const SourceLines* lines,
                          const ValidationOptions& options) {
  ValidationReport report;
  Reporter out(report, options);
  check_channels(mesh, out);
  check_elements(mesh, lines, out);
  check_topology(mesh, topology, lines, out);
  check_tags(mesh, &topology, lines, out);
  return report;
}

ValidationError::ValidationError(ValidationReport report, const std::string& path)
    : TopologyError(report.first_error(path)), report_(std::move(report)) {}

void require_valid(const ValidationReport& report, const std::string& path) {
  if (!report.ok()) throw ValidationError(report, path);
}

}  // namespace subdiv
