// subdiv refine IN -s SCHEME -l N -o OUT: uniform refinement with any scheme
// of the registry, carrying vertex and face-varying data through.

#include <chrono>
#include <cstdio>
#include <map>

#include <fmt/format.h>

#include "commands.h"
#include "rule_options.h"
#include "scheme_option.h"
#include "output_checks.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/refine/refine.h"

namespace subdiv::cli {

namespace {

struct RefineCommandOptions {
  std::string input;
  std::string output;
  std::string scheme = "catmull-clark";
  int levels = 1;
  std::string boundary;
  std::string crease_method;
  int threads = 0;
  bool stats = false;
  bool allow_non_manifold = false;
  bool triangulate = false;
  bool ascii = false;
  bool quiet = false;
  RuleOptionValues rules;
};

int run_refine(const RefineCommandOptions& opt) {
  const Scheme* scheme = &scheme_named(opt.scheme);
  check_output_path(opt.input, opt.output);

  MeshFile file = read_mesh(opt.input);
  print_warnings(opt.input, file.warnings);
  if (opt.triangulate && scheme->needs_triangles) {
    file.mesh = triangulate(file.mesh);
    file.lines.face_lines.clear();  // faces and holes were renumbered
    file.lines.hole_lines.clear();
  }
  if (!file.mesh.tags.other.empty())
    std::fprintf(stderr, "subdiv: warning: %s: %zu tags not interpreted (e.g. '%s'), carried through unchanged\n",
                 opt.input.c_str(), file.mesh.tags.other.size(), file.mesh.tags.other.front().name.c_str());

  RefineOptions options;
  apply_rule_options(opt.rules, file.mesh, options);
  options.levels = opt.levels;
  options.allow_non_manifold = opt.allow_non_manifold;
  options.threads = opt.threads;
  if (opt.boundary == "edge-only") options.boundary = BoundaryInterpolation::edge_only;
  else if (opt.boundary == "edge-and-corner") options.boundary = BoundaryInterpolation::edge_and_corner;
  if (opt.crease_method == "uniform") options.crease_method = CreaseMethod::uniform;
  else if (opt.crease_method == "chaikin") options.crease_method = CreaseMethod::chaikin;

  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  auto last = start;
  std::vector<std::string> stats;
  options.on_level = [&](int level, const PolygonMesh& mesh) {
    const auto now = clock::now();
    const double seconds = std::chrono::duration<double>(now - last).count();
    last = now;
    const std::string line = fmt::format("level {}: {} vertices, {} faces, {:.3f} s", level, mesh.vertex_count(),
                                         mesh.face_count(), seconds);
    stats.push_back(line);
    // Progress for long runs only, so that quick runs stay quiet.
    if (!opt.quiet && std::chrono::duration<double>(now - start).count() > 1.0)
      std::fprintf(stderr, "subdiv: %s\n", line.c_str());
  };
  const PolygonMesh result = refine(file.mesh, *scheme, options, &file.lines);

  WriteOptions wopt;
  wopt.ply_encoding = opt.ascii ? PlyEncoding::ascii : PlyEncoding::binary_little_endian;
  const auto write_start = clock::now();
  print_warnings(opt.output, write_mesh(result, opt.output, wopt));
  if (opt.stats) {
    std::printf("scheme %s, %d levels, threads %s\n", std::string(scheme->name).c_str(), opt.levels,
                opt.threads > 0 ? std::to_string(opt.threads).c_str() : "all");
    std::printf("level 0: %d vertices, %d faces\n", file.mesh.vertex_count(), file.mesh.face_count());
    for (const auto& s : stats) std::printf("%s\n", s.c_str());
    std::printf("refine %.3f s, write %.3f s\n", std::chrono::duration<double>(write_start - start).count(),
                std::chrono::duration<double>(clock::now() - write_start).count());
  }
  std::printf("wrote %s: %d vertices, %d faces\n", opt.output.c_str(), result.vertex_count(), result.face_count());
  return kExitOk;
}

int run_schemes() {
  for (const Scheme* s : all_schemes()) {
    std::printf("%-15s %s\n", std::string(s->name).c_str(), std::string(s->summary).c_str());
    std::printf("%-15s   %s; %s\n", "", to_string(s->split), std::string(s->citation).c_str());
  }
  return kExitOk;
}

}  // namespace

Command add_refine_command(CLI::App& app) {
  auto opt = std::make_shared<RefineCommandOptions>();
  CLI::App* cmd = app.add_subcommand("refine", "Uniformly refine a mesh with a subdivision scheme");
  cmd->add_option("input", opt->input, "Mesh to refine (.obj, .ply or .off)")->required();
  cmd->add_option("-o,--output", opt->output, "Where to write the result (format from the extension)")->required();
  cmd->add_option("-s,--scheme", opt->scheme, "Scheme (see 'subdiv schemes')")->capture_default_str();
  cmd->add_option("-l,--levels", opt->levels, "Refinement steps")->capture_default_str()->check(CLI::Range(0, 12));
  cmd->add_option("--boundary", opt->boundary,
                  "Boundary interpolation, overriding the file's tag (default: the tag, else edge-and-corner)")
      ->check(CLI::IsMember({"edge-only", "edge-and-corner"}));
  cmd->add_option("--crease-method", opt->crease_method,
                  "Semi-sharp crease rule, overriding the file's creasemethod tag (default: the tag, else uniform)")
      ->check(CLI::IsMember({"uniform", "chaikin"}));
  cmd->add_option("--threads", opt->threads, "Worker threads (0 = all cores); results do not depend on it")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  cmd->add_flag("--stats", opt->stats, "Print counts and timings per level");
  cmd->add_flag("--allow-non-manifold", opt->allow_non_manifold,
                "Refine non-manifold or inconsistently oriented meshes, treating those elements as sharp");
  cmd->add_flag("--triangulate", opt->triangulate, "Triangulate polygons first (for triangle schemes such as loop)");
  add_rule_options(*cmd, opt->rules);
  cmd->add_flag("--ascii", opt->ascii, "ASCII PLY output instead of binary");
  cmd->add_flag("-q,--quiet", opt->quiet, "No progress lines on stderr");
  cmd->footer(
      "Vertex data (colours, any per-vertex channel) is refined with the scheme's\n"
      "masks; face-varying data (UVs) linearly within faces.\n"
      "Examples:\n"
      "  subdiv refine data/meshes/spot_control_mesh.obj -s catmull-clark -l 3 -o /tmp/spot3.obj\n"
      "  subdiv refine data/meshes/cube.obj -s loop --triangulate -l 4 -o /tmp/cube_loop.ply --stats");
  return [opt] { return run_refine(*opt); };
}

Command add_schemes_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("schemes", "List the subdivision schemes with their rules and sources");
  cmd->footer("Example:\n  subdiv schemes");
  return [] { return run_schemes(); };
}

}  // namespace subdiv::cli
