// subdiv limit IN -s SCHEME -o OUT [-l N]: the mesh (refined N levels first)
// with every vertex moved to its limit position under the scheme (and, with
// --normals, the limit normals), through the scheme's closed-form masks or
// the masks the analysis reads off its rules.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "read_options.h"
#include "input_mesh.h"
#include "memory_guard.h"
#include "output_checks.h"
#include "command_report.h"
#include "refinement_options.h"
#include "wording.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"

namespace subdiv::cli {

namespace {

struct LimitCommandOptions {
  ReadOptions read;  ///< --weld-tolerance
  std::string input;
  std::string output;
  std::optional<int> isolation_levels;
  int levels = 0;
  std::optional<std::string> masks;
  bool normals = false;
  bool ascii = false;
  bool no_memory_check = false;
  RefinementOptionValues refinement;
  ReportOptionValues report;
};

// The schemes with closed-form limit masks, as "a, b and c".
std::string closed_form_scheme_names() {
  return names_where([](const Scheme& s) { return s.limit_masks != nullptr; });
}

int run_limit(const LimitCommandOptions& opt) {
  const Scheme chosen = chosen_scheme(opt.refinement);
  const Scheme* scheme = &chosen;
  const std::string name(scheme->name);
  check_output_path(opt.input, opt.output);
  check_ascii_applies(opt.ascii, opt.output);
  const bool generic = opt.masks == "generic" || !scheme->limit_masks;
  if (opt.masks == "closed-form" && !scheme->limit_masks)
    throw InvalidInputError("--masks closed-form: " + name + " has no closed-form limit masks (" +
                            closed_form_scheme_names() + " have); use --masks generic, its default");
  if (opt.isolation_levels && !generic)
    throw InvalidInputError("--isolation-levels applies to the generic masks, and " + name +
                            " uses closed-form ones (refining only where they need it); add --masks generic");

  PhaseClock clock;
  MeshFile file = read_mesh(opt.input, opt.read);
  print_warnings(opt.input, file.warnings);
  LimitOptions options;
  apply_refinement_options(opt.refinement, *scheme, file, options.refine);
  options.route = generic ? LimitRoute::generic : LimitRoute::closed_form;
  if (opt.isolation_levels) options.isolation_levels = *opt.isolation_levels;
  options.normals = opt.normals;
  clock.lap("read");

  // What the input cannot be refined for is said with its file and line,
  // as refine says it.
  RefineOptions refine_options = options.refine;
  refine_options.levels = opt.levels;
  check_refinable(file.mesh, *scheme, refine_options, &file.lines);
  check_fits_in_memory(file.mesh, *scheme, opt.levels, opt.no_memory_check, "limit -l");
  // The mesh whose vertices are written: the input, or its refinement.
  PolygonMesh out = std::move(file.mesh);
  if (opt.levels > 0) {
    warn_dropped_tags(opt.input, out, scheme, opt.levels);
    drop_input_normals(opt.input, out);
    out = refine(out, *scheme, refine_options);
    clock.lap("refine");
  }
  const LimitResult limit = limit_positions(out, *scheme, options);
  clock.lap("limit");
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
  wopt.stl_encoding = opt.ascii ? StlEncoding::ascii : StlEncoding::binary;
  wopt.threads = opt.refinement.threads;
  print_warnings(opt.output, write_mesh(out, opt.output, wopt));
  clock.lap("write");
  // Why vertices were left short of the limit, and what would reach it.
  const std::string levels_refined = count_of(limit.levels_refined, "level", "levels");
  if (limit.semi_sharp > 0) {
    const int more = static_cast<int>(std::ceil(limit.sharpness_left));
    const std::string which = count_of(limit.semi_sharp, "vertex is", "vertices are");
    if (generic)
      warnf("subdiv: warning: %s at or next to semi-sharp features still unresolved after %s (sharpness up to %g "
            "left: --isolation-levels %d resolves them): written at their position there, not at the limit\n",
            which.c_str(), levels_refined.c_str(), limit.sharpness_left, limit.levels_refined + more);
    else
      warnf("subdiv: warning: %s at or next to semi-sharp features still unresolved after %s (sharpness up to %g "
            "left), as far as the closed-form masks refine (the next level would pass %lld faces): written at their "
            "position there, not at the limit\n",
            which.c_str(), levels_refined.c_str(), limit.sharpness_left,
            static_cast<long long>(options.max_resolve_faces));
  }
  const Index other = limit.approximated - limit.semi_sharp;
  if (other > 0) {
    if (generic)
      warnf("subdiv: warning: %s no canonical configuration (darts, non-manifold vertices, interior creases "
            "between single faces, interior vertices of two triangles, or another extraordinary vertex within the "
            "masks' neighbourhood, which more --isolation-levels separate): written at their position after %s, "
            "not at the limit\n",
            count_of(other, "vertex matches", "vertices match").c_str(), levels_refined.c_str());
    else
      warnf("subdiv: warning: %s no closed form and %s no canonical configuration (non-manifold or "
            "inconsistently oriented neighbourhoods): written at their position after %s, not at the limit\n",
            count_of(other, "vertex has", "vertices have").c_str(), other == 1 ? "matches" : "match",
            levels_refined.c_str());
  }
  const auto no_normal = opt.normals ? std::count_if(limit.normals.begin(), limit.normals.end(),
                                                     [](const Vec3& n) { return !(norm(n) > 0.0); })
                                     : 0;
  if (no_normal > 0)
    warnf("subdiv: warning: %s no limit normal (no tangent plane there, or no tangent masks for their "
          "configuration): written as vn 0 0 0\n",
          count_of(no_normal, "vertex has", "vertices have").c_str());
  const bool closed = std::any_of(limit.sources.begin(), limit.sources.end(),
                                  [](LimitSource s) { return s == LimitSource::closed_form; });
  if (opt.report.json) {
    print_json({{"command", "limit"},
                {"input", opt.input},
                {"output", opt.output},
                {"scheme", name},
                {"levels", opt.levels},
                {"masks", closed ? "closed-form" : "generic"},
                {"vertices", out.vertex_count()},
                {"at_limit", out.vertex_count() - limit.approximated},
                {"semi_sharp_unresolved", limit.semi_sharp},
                {"no_configuration", other},
                {"levels_refined", limit.levels_refined},
                {"normals", opt.normals},
                {"no_normal", no_normal},
                {"seconds", clock.json()}});
    return kExitOk;
  }
  if (opt.report.stats) std::printf("%s\n", clock.text().c_str());
  // The summary counts what the warnings count.
  const std::string short_of = limit.approximated > 0 ? ", " + std::to_string(limit.approximated) +
                                                            " at their positions after " + levels_refined
                                                      : std::string();
  const std::string vertices = count_of(out.vertex_count(), "vertex", "vertices");
  const std::string at_limit = limit.approximated > 0
                                   ? vertices + ", " + std::to_string(out.vertex_count() - limit.approximated) + " at"
                                   : vertices + " at";
  std::printf("wrote %s: %s their %s limit positions (%s masks)%s%s\n", opt.output.c_str(), at_limit.c_str(),
              name.c_str(), closed ? "closed-form" : "generic", short_of.c_str(),
              opt.normals ? ", with limit normals" : "");
  return kExitOk;
}

}  // namespace

Command add_limit_command(CLI::App& app) {
  auto opt = std::make_shared<LimitCommandOptions>();
  CLI::App* cmd = app.add_subcommand("limit", "Move every vertex to its limit position under a scheme");
  add_read_options(cmd, opt->read);
  cmd->add_option("input", opt->input, "Mesh (.obj, .ply, .off, .gltf, .glb or .stl)")->required();
  cmd->add_option("-o,--output", opt->output, "Where to write the result (format from the extension)")->required();
  add_refinement_options(*cmd, opt->refinement, "Scheme (see 'subdiv schemes')");
  cmd->add_option("-l,--levels", opt->levels,
                  "Refine this many levels first and write the refined mesh, every vertex at its limit")
      ->capture_default_str()
      ->check(CLI::Range(0, 8));
  cmd->add_option("--masks", opt->masks,
                  "closed-form (" + closed_form_scheme_names() + ": their default) or generic (eigenvectors of the "
                  "local subdivision matrix: every other scheme's default)")
      ->check(CLI::IsMember({"closed-form", "generic"}));
  cmd->add_option("--isolation-levels", opt->isolation_levels,
                  "Generic masks: refinement steps before they apply (default 2; makes faces uniform, separates "
                  "extraordinary vertices)")
      ->check(CLI::Range(0, 6));
  cmd->add_flag("--normals", opt->normals, "Also write limit normals (from the tangent masks)");
  add_report_options(*cmd, opt->report, "Print the time of each phase");
  cmd->add_flag("--ascii", opt->ascii, "ASCII PLY or STL output instead of binary");
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
