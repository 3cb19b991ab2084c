#include "refinement_options.h"

#include <charconv>
#include <variant>

#include "input_mesh.h"
#include "subdiv/core/error.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/quasi_4_8.h"

namespace subdiv::cli {

namespace {

// --crease A,B: the edge (A, B), 0-based, as an infinitely sharp crease tag.
CreaseTag parse_crease(const std::string& text, Index vertex_count) {
  const std::size_t comma = text.find(',');
  long long v[2] = {-1, -1};
  bool ok = comma != std::string::npos;
  for (int i = 0; ok && i < 2; ++i) {
    const std::string part = i == 0 ? text.substr(0, comma) : text.substr(comma + 1);
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v[i]);
    ok = !part.empty() && ec == std::errc() && end == part.data() + part.size();
  }
  if (!ok) throw InvalidInputError("--crease " + text + ": expected A,B with two 0-based vertex indices");
  for (const long long x : v)
    if (x < 0 || x >= vertex_count)
      throw InvalidInputError("--crease " + text + ": vertex " + std::to_string(x) + " is not in the mesh (" +
                              std::to_string(vertex_count) + " vertices)");
  return {static_cast<Index>(v[0]), static_cast<Index>(v[1]), kInfiniteSharpness};
}

}  // namespace

void add_refinement_options(CLI::App& cmd, RefinementOptionValues& values, const std::string& scheme_help) {
  cmd.add_option("-s,--scheme", values.scheme, scheme_help)->capture_default_str();
  cmd.add_option("--tension", values.tension, "butterfly, kobbelt and the four-point curve scheme: the tension w (default 1/16)");
  add_degree_options(cmd, values.degree);
  cmd.add_option("--quasi-boundary", values.quasi_boundary,
                 "quasi-4-8: boundary vertices fixed (default) or the boundary polygon smoothed")
      ->check(CLI::IsMember({"fixed", "smoothed"}));
  cmd.add_option("--boundary", values.boundary,
                 "Boundary interpolation, overriding the file's tag (default: the tag, else edge-and-corner)")
      ->check(CLI::IsMember({"edge-only", "edge-and-corner"}));
  cmd.add_option("--crease-method", values.crease_method,
                 "Semi-sharp crease rule, overriding the file's creasemethod tag (default: the tag, else uniform)")
      ->check(CLI::IsMember(crease_method_names()));
  cmd.add_option("--triangle-rule", values.triangle_rule,
                 "catmull-clark: the edge rule next to triangles, overriding the file's smoothtriangles tag: catmark, "
                 "or OpenSubdiv's smooth (default: the tag, else catmark)")
      ->check(CLI::IsMember({to_string(TriangleSubdivision::catmark), to_string(TriangleSubdivision::smooth)}));
  std::vector<std::string> face_varying_names;
  for (const FaceVaryingInterpolation f : kFaceVaryingInterpolations) face_varying_names.push_back(to_string(f));
  cmd.add_option("--face-varying", values.face_varying,
                 "catmull-clark, loop and loop-warren: how face-varying channels (UV seams) are refined, overriding the file's "
                 "facevaryinginterpolateboundary tag, as OpenSubdiv's option: none (smooth everywhere), corners-only, "
                 "corners-plus1, corners-plus2, boundaries, all (linear; default: the tag, else all)")
      ->check(CLI::IsMember(face_varying_names));
  add_rule_options(cmd, values.rules);
  cmd.add_option("--crease", values.creases,
                 "Tag edge A,B (0-based vertices) as infinitely sharp (repeatable); quasi-4-8 does not smooth it")
      ->type_name("A,B");
  cmd.add_flag("--allow-non-manifold", values.allow_non_manifold,
               "Accept non-manifold or inconsistently oriented meshes, treating those elements as sharp");
  cmd.add_flag("--triangulate", values.triangulate,
               "Triangulate polygons first (for the schemes that read triangles, such as loop; refused for others)");
  cmd.add_option("--threads", values.threads, "Worker threads (0 = all cores); results do not depend on it")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
}

Scheme chosen_scheme(const RefinementOptionValues& values) {
  Scheme chosen = with_degree_options(with_tension(scheme_named(values.scheme), values.tension), values.degree);
  if (!values.quasi_boundary.empty()) {
    auto* quasi = std::get_if<Quasi48Parameters>(&chosen.parameters);
    if (!quasi) throw InvalidInputError("--quasi-boundary applies to quasi-4-8, not to " + values.scheme);
    quasi->boundary = values.quasi_boundary == "smoothed" ? Quasi48Boundary::smoothed : Quasi48Boundary::fixed;
  }
  return chosen;
}

void apply_refinement_options(const RefinementOptionValues& values, const Scheme& scheme, MeshFile& file,
                              RefineOptions& options) {
  if (values.triangulate && !scheme.traits.needs_triangles)
    throw InvalidInputError(
        "--triangulate applies to the schemes that read triangles (" +
        names_where([](const Scheme& s) { return s.traits.needs_triangles; }) + "), not to " +
        std::string(scheme.name) + ", which reads the polygons as they are");
  triangulate_if_asked(scheme, values.triangulate, file);
  apply_rule_options(values.rules, file.mesh, options);
  for (const std::string& text : values.creases)
    file.mesh.tags.creases.push_back(parse_crease(text, file.mesh.vertex_count()));
  options.allow_non_manifold = values.allow_non_manifold;
  options.threads = values.threads;
  if (values.boundary == "edge-only") options.boundary = BoundaryInterpolation::edge_only;
  else if (values.boundary == "edge-and-corner") options.boundary = BoundaryInterpolation::edge_and_corner;
  if (const auto method = crease_method_named(values.crease_method)) options.crease_method = *method;
  if (!values.triangle_rule.empty()) {
    if (scheme.name != catmull_clark_scheme().name)
      throw InvalidInputError("--triangle-rule applies to " + std::string(catmull_clark_scheme().name) +
                              " (the only scheme with a rule for triangles among quads), not to " +
                              std::string(scheme.name));
    options.triangle_subdivision = values.triangle_rule == to_string(TriangleSubdivision::smooth)
                                       ? TriangleSubdivision::smooth
                                       : TriangleSubdivision::catmark;
  }
  if (!values.face_varying.empty()) {
    if (!scheme.traits.smooth_face_varying)
      throw InvalidInputError("--face-varying applies to the schemes that refine face-varying channels smoothly (" +
                              names_where([](const Scheme& s) { return s.traits.smooth_face_varying; }) +
                              "), not to " + std::string(scheme.name) + ", which refines them linearly");
    for (const FaceVaryingInterpolation f : kFaceVaryingInterpolations)
      if (values.face_varying == to_string(f)) options.face_varying = f;
  }
}

const char* surface_option_given(const RefinementOptionValues& values) {
  if (!values.boundary.empty()) return "--boundary";
  if (!values.crease_method.empty()) return "--crease-method";
  if (!values.triangle_rule.empty()) return "--triangle-rule";
  if (!values.face_varying.empty()) return "--face-varying";
  if (values.allow_non_manifold) return "--allow-non-manifold";
  if (values.triangulate) return "--triangulate";
  if (values.rules.boundary_rules != "standard") return "--boundary-rules";
  if (values.rules.corner_angles != "fixed") return "--corner-angles";
  if (values.rules.flatness) return "--flatness";
  if (!values.rules.corners.empty()) return "--corner";
  if (values.degree.degree) return "--degree";
  if (!values.degree.alpha.empty() || !values.degree.beta.empty()) return "--alpha/--beta";
  if (!values.degree.valence_weights.empty()) return "--valence-weights";
  if (!values.creases.empty()) return "--crease";
  if (!values.quasi_boundary.empty()) return "--quasi-boundary";
  return nullptr;
}

}  // namespace subdiv::cli
