// subdiv limit IN -s SCHEME -o OUT [-l N]: the mesh (refined N levels first)
// with every vertex moved to its limit position under the scheme (and, with
// --normals, the limit normals), through the scheme's closed-form masks or
// the masks the analysis reads off its rules.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <memory>

#include "commands.h"
#include "input_mesh.h"
#include "memory_guard.h"
#include "output_checks.h"
#include "rule_options.h"
#include "scheme_option.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"

namespace subdiv::cli {

namespace {

struct LimitCommandOptions {
  std::string input;
  std::string output;
  std::string scheme = std::string(default_scheme().name);
  int isolation_levels = 2;
  int levels = 0;
  std::string masks = "closed-form";
  std::string boundary;
  std::string crease_method;
  bool normals = false;
  bool allow_non_manifold = false;
  bool triangulate = false;
  bool ascii = false;
  bool no_memory_check = false;
  RuleOptionValues rules;
};

int run_limit(const LimitCommandOptions& opt) {
  const Scheme* scheme = &scheme_named(opt.scheme);
  check_output_path(opt.input, opt.output);
  MeshFile file = read_mesh(opt.input);
  print_warnings(opt.input, file.warnings);
  triangulate_if_asked(*scheme, opt.triangulate, file);

  LimitOptions options;
  apply_rule_options(opt.rules, file.mesh, options.refine);
  options.route = opt.masks == "generic" ? LimitRoute::generic : LimitRoute::closed_form;
  options.isolation_levels = opt.isolation_levels;
  options.normals = opt.normals;
  options.refine.allow_non_manifold = opt.allow_non_manifold;
  if (opt.boundary == "edge-only") options.refine.boundary = BoundaryInterpolation::edge_only;
  else if (opt.boundary == "edge-and-corner") options.refine.boundary = BoundaryInterpolation::edge_and_corner;
  if (const auto method = crease_method_named(opt.crease_method)) options.refine.crease_method = *method;

  // What the input cannot be refined for is said with its file and line,
  // as refine says it.
  RefineOptions refine_options = options.refine;
  refine_options.levels = opt.levels;
  check_refinable(file.mesh, *scheme, refine_options, &file.lines);
  check_fits_in_memory(file.mesh, *scheme, opt.levels, opt.no_memory_check, "limit -l");
  // The mesh whose vertices are written: the input, or its refinement.
  PolygonMesh out = std::move(file.mesh);
  if (opt.levels > 0) {
    warn_dropped_tags(opt.input, out.tags);
    drop_input_normals(opt.input, out);
    out = refine(out, *scheme, refine_options);
  }
  const LimitResult limit = limit_positions(out, *scheme, options);
  out.positions = limit.positions;
  if (opt.normals) {
    // One normal per vertex, as a face-varying channel indexed by vertex
    // (OBJ's vn lines).
    FaceVaryingChannel normals{"normal", 3, {}, out.face_indices};
    for (const Vec3& n : limit.normals) normals.values.insert(normals.values.end(), {n.x, n.y, n.z});
    std::erase_if(out.face_varying_channels, [](const FaceVaryingChannel& c) { return c.name == "normal"; });
    out.face_varying_channels.push_back(std::move(normals));
  }
  WriteOptions wopt;
  wopt.ply_encoding = opt.ascii ? PlyEncoding::ascii : PlyEncoding::binary_little_endian;
  print_warnings(opt.output, write_mesh(out, opt.output, wopt));
  // Why vertices were left short of the limit, and what would reach it.
  const bool generic = options.route == LimitRoute::generic || !scheme->limit_masks;
  if (limit.semi_sharp > 0) {
    const int more = static_cast<int>(std::ceil(limit.sharpness_left));
    if (generic)
      warnf(
                   "subdiv: warning: %d vertices are at or next to semi-sharp features still unresolved after %d "
                   "levels (sharpness up to %g left: --isolation-levels %d resolves them): written at their position "
                   "there, not at the limit\n",
                   limit.semi_sharp, limit.levels_refined, limit.sharpness_left, limit.levels_refined + more);
    else
      warnf(
                   "subdiv: warning: %d vertices are at or next to semi-sharp features still unresolved after %d "
                   "levels (sharpness up to %g left), as far as the closed-form masks refine (the next level would "
                   "pass %lld faces): written at their position there, not at the limit\n",
                   limit.semi_sharp, limit.levels_refined, limit.sharpness_left,
                   static_cast<long long>(options.max_resolve_faces));
  }
  if (const Index other = limit.approximated - limit.semi_sharp; other > 0) {
    if (generic)
      warnf(
                   "subdiv: warning: %d vertices match no canonical configuration (darts, non-manifold vertices, "
                   "interior creases between single faces, interior vertices of two triangles, or another "
                   "extraordinary vertex within the masks' neighbourhood, which more --isolation-levels separate): "
                   "written at their position after %d levels, not at the limit\n",
                   other, limit.levels_refined);
    else
      warnf(
                   "subdiv: warning: %d vertices have no closed form and match no canonical configuration "
                   "(non-manifold or inconsistently oriented neighbourhoods): written at their position after %d "
                   "levels, not at the limit\n",
                   other, limit.levels_refined);
  }
  if (opt.normals) {
    const auto undefined = std::count_if(limit.normals.begin(), limit.normals.end(),
                                         [](const Vec3& n) { return !(norm(n) > 0.0); });
    if (undefined > 0)
      warnf(
                   "subdiv: warning: %ld vertices have no limit normal (no tangent plane there, or no tangent "
                   "masks for their configuration): written as vn 0 0 0\n",
                   static_cast<long>(undefined));
  }
  const bool closed = std::any_of(limit.sources.begin(), limit.sources.end(),
                                  [](LimitSource s) { return s == LimitSource::closed_form; });
  // The summary counts what the warnings count.
  const std::string short_of =
      limit.approximated > 0 ? ", " + std::to_string(limit.approximated) + " at their positions after " +
                                   std::to_string(limit.levels_refined) + " levels"
                             : std::string();
  const std::string at_limit = limit.approximated > 0
                                   ? std::to_string(out.vertex_count()) + " vertices, " +
                                         std::to_string(out.vertex_count() - limit.approximated) + " at"
                                   : std::to_string(out.vertex_count()) + " vertices at";
  std::printf("wrote %s: %s their %s limit positions (%s masks)%s%s\n", opt.output.c_str(), at_limit.c_str(),
              std::string(scheme->name).c_str(), closed ? "closed-form" : "generic", short_of.c_str(),
              opt.normals ? ", with limit normals" : "");
  return kExitOk;
}

}  // namespace

Command add_limit_command(CLI::App& app) {
  auto opt = std::make_shared<LimitCommandOptions>();
  CLI::App* cmd = app.add_subcommand("limit", "Move every vertex to its limit position under a scheme");
  cmd->add_option("input", opt->input, "Mesh (.obj, .ply or .off)")->required();
  cmd->add_option("-o,--output", opt->output, "Where to write the result (format from the extension)")->required();
  cmd->add_option("-s,--scheme", opt->scheme, "Scheme (see 'subdiv schemes')")->capture_default_str();
  cmd->add_option("-l,--levels", opt->levels,
                  "Refine this many levels first and write the refined mesh, every vertex at its limit")
      ->capture_default_str()
      ->check(CLI::Range(0, 8));
  cmd->add_option("--masks", opt->masks,
                  "closed-form (catmull-clark, loop, loop-warren; other schemes use generic) or generic "
                  "(eigenvectors of the local subdivision matrix)")
      ->capture_default_str()
      ->check(CLI::IsMember({"closed-form", "generic"}));
  cmd->add_option("--isolation-levels", opt->isolation_levels,
                  "Generic masks: refinement steps before they apply (makes faces uniform, separates "
                  "extraordinary vertices)")
      ->capture_default_str()
      ->check(CLI::Range(0, 6));
  cmd->add_option("--boundary", opt->boundary, "Boundary interpolation, overriding the file's tag")
      ->check(CLI::IsMember({"edge-only", "edge-and-corner"}));
  cmd->add_option("--crease-method", opt->crease_method, "Semi-sharp crease rule, overriding the file's tag")
      ->check(CLI::IsMember(crease_method_names()));
  cmd->add_flag("--normals", opt->normals, "Also write limit normals (from the tangent masks)");
  cmd->add_flag("--allow-non-manifold", opt->allow_non_manifold, "Treat non-manifold elements as sharp");
  cmd->add_flag("--triangulate", opt->triangulate, "Triangulate polygons first (for triangle schemes such as loop)");
  add_rule_options(*cmd, opt->rules);
  cmd->add_flag("--ascii", opt->ascii, "ASCII PLY output instead of binary");
  cmd->add_flag("--no-memory-check", opt->no_memory_check,
                "Refine -l levels even when the estimated peak memory exceeds what the machine has available");
  cmd->footer(
      "Catmull-Clark and Loop use closed-form masks (refining only to resolve non-quads\n"
      "and semi-sharp features); every other scheme, or --masks generic, uses the left\n"
      "eigenvectors of the scheme's local subdivision matrices (see 'subdiv analyze').\n"
      "Examples:\n"
      "  subdiv limit data/meshes/spot_control_mesh.obj -s catmull-clark --normals -o /tmp/spot_limit.obj\n"
      "  subdiv limit data/meshes/spot_control_mesh.obj -l 2 --normals -o /tmp/spot_limit_l2.obj");
  return [opt] { return run_limit(*opt); };
}

}  // namespace subdiv::cli
