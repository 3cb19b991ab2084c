#include "report.h"

#include <fmt/format.h>

#include "wording.h"

namespace subdiv::cli {

namespace {

std::string histogram(const std::map<Index, Index>& h) {
  std::string out;
  for (const auto& [key, count] : h) out += fmt::format("{}{}:{}", out.empty() ? "" : "  ", key, count);
  return out.empty() ? "-" : out;
}

}  // namespace

std::string format_stats(const MeshStats& s) {
  std::string out;
  out += fmt::format("vertices        {}\n", s.vertices);
  out += fmt::format("faces           {}  (triangles {}, quads {}, larger {})\n", s.faces, s.triangles, s.quads,
                     s.polygons);
  out += fmt::format("edges           {}  (boundary {}, non-manifold {})\n", s.edges, s.boundary_edges,
                     s.non_manifold_edges);
  out += fmt::format("face corners    {}\n", s.corners);
  out += fmt::format("face sizes      {}\n", histogram(s.face_sizes));
  out += fmt::format("valences        {}  (max {})\n", histogram(s.valences), s.max_valence);
  out += fmt::format("boundary loops  {}\n", s.boundary_loops);
  out += fmt::format("components      {}\n", s.components);
  out += fmt::format("euler char.     {}\n", s.euler_characteristic);
  if (s.vertices > 0)
    out += fmt::format("bounding box    [{:.6g}, {:.6g}, {:.6g}] .. [{:.6g}, {:.6g}, {:.6g}]\n", s.bbox_min.x,
                       s.bbox_min.y, s.bbox_min.z, s.bbox_max.x, s.bbox_max.y, s.bbox_max.z);
  return out;
}

std::string format_channels(const PolygonMesh& mesh) {
  std::string out;
  for (const auto& c : mesh.vertex_channels)
    out += fmt::format("{}{} (per vertex, {} components)", out.empty() ? "" : ", ", c.name, c.components);
  for (const auto& c : mesh.face_varying_channels)
    out += fmt::format("{}{} (face-varying, {} components, {} values)", out.empty() ? "" : ", ", c.name,
                       c.components, c.value_count());
  return fmt::format("channels        {}\n", out.empty() ? "-" : out);
}

std::string format_tags(const Tags& tags) {
  std::size_t sharp = 0, corners_sharp = 0, typed = 0;
  for (const auto& c : tags.creases)
    if (c.sharpness >= kInfiniteSharpness) ++sharp;
  for (const auto& c : tags.corners) {
    if (c.sharpness >= kInfiniteSharpness) ++corners_sharp;
    if (c.type != CornerType::unspecified) ++typed;
  }
  std::string out;
  out += fmt::format("creases         {}  (infinitely sharp {}, semi-sharp {})\n", tags.creases.size(), sharp,
                     tags.creases.size() - sharp);
  out += fmt::format("corners         {}  (infinitely sharp {}, with convex/concave type {})\n", tags.corners.size(),
                     corners_sharp, typed);
  out += fmt::format("holes           {}\n", tags.holes.size());
  out += fmt::format("boundary        {}{}\n", to_string(tags.boundary_interpolation),
                     tags.boundary_interpolation_set ? "" : " (default)");
  if (tags.face_varying_interpolation_set)
    out += fmt::format("face-varying    {}\n", to_string(tags.face_varying_interpolation));
  if (tags.crease_method_set) out += fmt::format("crease method   {}\n", to_string(tags.crease_method));
  if (tags.triangle_subdivision_set)
    out += fmt::format("triangles       {}\n", to_string(tags.triangle_subdivision));
  if (!tags.other.empty()) {
    std::string names;
    for (const auto& t : tags.other) names += (names.empty() ? "" : " ") + t.name;
    out += fmt::format("other tags      {} kept, not interpreted: {}\n", tags.other.size(), names);
  }
  return out;
}

std::string format_validation(const ValidationReport& report, const std::string& path, std::size_t max_listed) {
  std::string out;
  if (report.error_count() == 0 && report.warning_count() == 0) return "validation      ok\n";
  out += fmt::format("validation      {}, {}\n", count_of(static_cast<std::int64_t>(report.error_count()), "error", "errors"),
                     count_of(static_cast<std::int64_t>(report.warning_count()), "warning", "warnings"));
  for (int k = 0; k < kIssueKindCount; ++k) {
    const auto kind = static_cast<IssueKind>(k);
    if (report.count(kind) > 0)
      out += fmt::format("  {:<33}{}\n", to_string(kind), report.count(kind));
  }
  std::size_t listed = 0;
  for (const auto& issue : report.issues) {
    if (listed++ == max_listed) {
      out += fmt::format("  ... ({} more not listed; use --max-issues)\n",
                         report.error_count() + report.warning_count() - max_listed);
      break;
    }
    out += fmt::format("  {}: {}\n", issue.severity == Severity::error ? "error" : "warning", format_issue(issue, path));
  }
  return out;
}

}  // namespace subdiv::cli
