#include "rule_options.h"

#include <charconv>
#include <cmath>
#include <numbers>

#include "subdiv/core/error.h"

namespace subdiv::cli {

namespace {

CornerTag parse_corner(const std::string& text, Index vertex_count) {
  const std::string what = "--corner " + text;
  CornerTag tag;
  const std::size_t colon = text.find(':');
  const std::string index = text.substr(0, colon);
  long long v = -1;
  const auto [end, ec] = std::from_chars(index.data(), index.data() + index.size(), v);
  if (index.empty() || ec != std::errc() || end != index.data() + index.size())
    throw InvalidInputError(what + ": expected VERTEX[:convex|concave[:DEGREES]] with a 0-based vertex index");
  if (v < 0 || v >= vertex_count)
    throw InvalidInputError(what + ": vertex " + index + " is not in the mesh (" + std::to_string(vertex_count) +
                            " vertices)");
  tag.vertex = static_cast<Index>(v);
  if (colon == std::string::npos) return tag;
  const std::string rest = text.substr(colon + 1);
  const std::size_t colon2 = rest.find(':');
  const std::string type = rest.substr(0, colon2);
  if (type == "convex") tag.type = CornerType::convex;
  else if (type == "concave") tag.type = CornerType::concave;
  else throw InvalidInputError(what + ": the type must be 'convex' or 'concave', not '" + type + "'");
  if (colon2 == std::string::npos) return tag;
  const std::string degrees_text = rest.substr(colon2 + 1);
  double degrees = 0.0;
  const auto [end2, ec2] = std::from_chars(degrees_text.data(), degrees_text.data() + degrees_text.size(), degrees);
  if (degrees_text.empty() || ec2 != std::errc() || end2 != degrees_text.data() + degrees_text.size() ||
      !(degrees > 0.0 && degrees < 360.0))
    throw InvalidInputError(what + ": the angle must be a number of degrees in (0, 360)");
  if ((tag.type == CornerType::convex) != (degrees < 180.0))
    throw InvalidInputError(what + ": a " + type + " corner's angle must be " +
                            (tag.type == CornerType::convex ? "below" : "above") + " 180 degrees");
  tag.angle = degrees * std::numbers::pi / 180.0;
  return tag;
}

}  // namespace

void add_rule_options(CLI::App& cmd, RuleOptionValues& values) {
  cmd.add_option("--boundary-rules", values.boundary_rules,
                 "Rules next to boundaries, creases and corners: standard (OpenSubdiv's) or piecewise-smooth "
                 "(Biermann-Levin-Zorin: gamma(theta) edge weights, flatness at concave corners)")
      ->check(CLI::IsMember({"standard", "piecewise-smooth"}))
      ->capture_default_str();
  cmd.add_option("--corner-angles", values.corner_angles,
                 "Piecewise-smooth corner angle where a tag gives none: fixed (90 convex, 270 concave degrees) or "
                 "measured from the control mesh")
      ->check(CLI::IsMember({"fixed", "measured"}))
      ->capture_default_str();
  cmd.add_option("--flatness", values.flatness,
                 "Flatness parameter s at concave corners (piecewise-smooth; default 1 - (1/4)/lambda_3, 0 = off)")
      ->check(CLI::Range(0.0, 1.0));
  cmd.add_option("--corner", values.corners,
                 "Tag a vertex as an infinitely sharp corner, optionally convex or concave, with an angle in degrees "
                 "(repeatable)")
      ->type_name("V[:TYPE[:DEG]]");
}

void apply_rule_options(const RuleOptionValues& values, PolygonMesh& mesh, RefineOptions& options) {
  if (values.boundary_rules != "piecewise-smooth") {
    if (values.flatness) throw InvalidInputError("--flatness applies to --boundary-rules piecewise-smooth");
    if (values.corner_angles != "fixed")
      throw InvalidInputError("--corner-angles applies to --boundary-rules piecewise-smooth");
  }
  options.boundary_rules =
      values.boundary_rules == "piecewise-smooth" ? BoundaryRules::piecewise_smooth : BoundaryRules::standard;
  options.corner_angles = values.corner_angles == "measured" ? CornerAngles::measured : CornerAngles::fixed;
  options.flatness = values.flatness;
  for (const std::string& text : values.corners) {
    const CornerTag tag = parse_corner(text, mesh.vertex_count());
    std::erase_if(mesh.tags.corners, [&](const CornerTag& c) { return c.vertex == tag.vertex; });
    mesh.tags.corners.push_back(tag);
  }
}

}  // namespace subdiv::cli
