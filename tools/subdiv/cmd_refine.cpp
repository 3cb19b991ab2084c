// subdiv refine IN -s SCHEME -l N -o OUT: uniform refinement with any scheme
// of the registry, carrying vertex and face-varying data through; with a
// curve scheme, refinement of the file's polylines (OBJ `l` lines).

#include <charconv>
#include <chrono>
#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "commands.h"
#include "input_mesh.h"
#include "memory_guard.h"
#include "output_checks.h"
#include "rule_options.h"
#include "scheme_option.h"
#include "subdiv/core/error.h"
#include "subdiv/curves/curve_scheme.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::cli {

namespace {

struct RefineCommandOptions {
  std::string input;
  std::string output;
  std::string scheme = std::string(default_scheme().name);
  int levels = 1;
  std::string boundary;
  std::string crease_method;
  int threads = 0;
  bool stats = false;
  bool allow_non_manifold = false;
  bool triangulate = false;
  bool ascii = false;
  bool no_memory_check = false;
  std::optional<double> tension;
  RuleOptionValues rules;
  DegreeOptionValues degree;
  bool full_steps = false;            // quasi-4-8: -l counts 4-8 steps (two binary steps each)
  int start_level = 0;                // the level the input is at (splits whose steps alternate)
  std::string quasi_boundary;         // quasi-4-8: fixed or smoothed
  std::vector<std::string> creases;  // --crease A,B: infinitely sharp edge tags
};

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

/// The options only surface schemes read; a curve scheme refuses them
/// rather than ignore them.
const char* surface_option_given(const RefineCommandOptions& opt) {
  if (!opt.boundary.empty()) return "--boundary";
  if (!opt.crease_method.empty()) return "--crease-method";
  if (opt.allow_non_manifold) return "--allow-non-manifold";
  if (opt.triangulate) return "--triangulate";
  if (opt.rules.boundary_rules != "standard") return "--boundary-rules";
  if (opt.rules.corner_angles != "fixed") return "--corner-angles";
  if (opt.rules.flatness) return "--flatness";
  if (!opt.rules.corners.empty()) return "--corner";
  if (opt.degree.degree) return "--degree";
  if (!opt.degree.alpha.empty() || !opt.degree.beta.empty()) return "--alpha/--beta";
  if (!opt.degree.valence_weights.empty()) return "--valence-weights";
  if (!opt.creases.empty()) return "--crease";
  if (opt.full_steps) return "--full-steps";
  if (opt.start_level != 0) return "--start-level";
  if (!opt.quasi_boundary.empty()) return "--quasi-boundary";
  return nullptr;
}

// Every polyline of the file refined on its own; the output holds the refined
// points of each polyline in turn and one `l` line per polyline.
int run_curve_refine(const CurveScheme& registered, const RefineCommandOptions& opt) {
  const std::string name(registered.name);
  if (const char* option = surface_option_given(opt))
    throw InvalidInputError(std::string(option) + " applies to surface schemes, not to the curve scheme " + name);
  const CurveScheme scheme = with_tension(registered, opt.tension);
  check_output_path(opt.input, opt.output);
  if (format_from_path(opt.output) != FileFormat::obj)
    throw InvalidInputError(opt.output + ": " + to_string(format_from_path(opt.output)) +
                            " has no place for polylines; write the refined curves to an .obj file");

  const MeshFile file = read_mesh(opt.input);
  print_warnings(opt.input, file.warnings);
  const PolygonMesh& mesh = file.mesh;
  if (mesh.face_count() > 0)
    throw InvalidInputError(opt.input + ": " + name + " is a curve scheme and refines polylines, but the file has " +
                            std::to_string(mesh.face_count()) + " faces (surface schemes: see 'subdiv schemes')");
  if (mesh.polylines.empty())
    throw InvalidInputError(opt.input + ": no polylines ('l' lines) for the curve scheme " + name + " to refine");
  if (!mesh.vertex_channels.empty() || !mesh.tags.empty())
    warnf("subdiv: warning: %s: vertex channels and tags are not carried through curve refinement\n",
                 opt.input.c_str());

  const auto start = std::chrono::steady_clock::now();
  PolygonMesh result;
  for (std::size_t l = 0; l < mesh.polylines.size(); ++l) {
    const MeshPolyline& in = mesh.polylines[l];
    Polyline coarse{{}, in.closed};
    coarse.points.reserve(in.vertices.size());
    for (const Index v : in.vertices) coarse.points.push_back(mesh.positions[static_cast<std::size_t>(v)]);
    Polyline fine;
    try {
      fine = refine(coarse, scheme, opt.levels);
    } catch (const InvalidInputError& e) {
      throw ParseError(opt.input, SourceLines::at(file.lines.polyline_lines, static_cast<Index>(l)),
                       "polyline " + std::to_string(l) + ": " + e.what());
    }
    if (fine.points.size() > static_cast<std::size_t>(kMaxElements) - result.positions.size())
      throw InvalidInputError(opt.input + ": the refined polylines have more points than an Index can count");
    MeshPolyline out{{}, fine.closed};
    out.vertices.reserve(fine.points.size());
    for (const Vec3& p : fine.points) {
      out.vertices.push_back(result.vertex_count());
      result.positions.push_back(p);
    }
    result.polylines.push_back(std::move(out));
  }
  const auto write_start = std::chrono::steady_clock::now();
  WriteOptions wopt;
  wopt.ply_encoding = opt.ascii ? PlyEncoding::ascii : PlyEncoding::binary_little_endian;
  print_warnings(opt.output, write_mesh(result, opt.output, wopt));
  if (opt.stats) {
    std::printf("curve scheme %s, %d levels", name.c_str(), opt.levels);
    if (scheme.tension != 0.0) std::printf(", tension %g", scheme.tension);
    std::printf("\n");
    for (int level = 0; level <= opt.levels; ++level) {
      long long points = 0;
      for (const MeshPolyline& p : mesh.polylines)
        points += refined_point_count(scheme, static_cast<Index>(p.vertices.size()), p.closed, level);
      std::printf("level %d: %lld points, %zu polylines\n", level, points, mesh.polylines.size());
    }
    std::printf("refine %.3f s, write %.3f s\n", std::chrono::duration<double>(write_start - start).count(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count());
  }
  std::printf("wrote %s: %d vertices, %zu polylines\n", opt.output.c_str(), result.vertex_count(),
              result.polylines.size());
  return kExitOk;
}

// A split whose steps alternate leaves an open mesh at an odd level in a
// state the file does not record: refining the file again from level 0
// would not continue the same surface.
void warn_if_level_matters(const Scheme& scheme, const PolygonMesh& input, const RefineOptions& options,
                           const std::string& output) {
  const int level = options.start_level + options.levels;
  if (!steps_alternate(scheme.split) || level % 2 == 0 || options.levels == 0) return;
  const MeshTopology topology(input);
  bool open = false;
  for (Index e = 0; e < topology.edge_count() && !open; ++e) open = topology.is_boundary_edge(e);
  if (!open) return;
  warnf(
               "subdiv: warning: %s is at level %d of %s, whose boundary rule alternates with the level: refine it "
               "further with --start-level %d to continue the same surface\n",
               output.c_str(), level, std::string(scheme.name).c_str(), level);
}

int run_refine(const RefineCommandOptions& opt) {
  const Scheme* registered = find_scheme(opt.scheme);
  if (!registered) {
    if (const CurveScheme* curve = find_curve_scheme(opt.scheme)) return run_curve_refine(*curve, opt);
    throw_unknown_scheme(opt.scheme, true);
  }
  Scheme chosen = with_degree_options(with_tension(*registered, opt.tension), opt.degree);
  const Scheme* scheme = &chosen;
  check_output_path(opt.input, opt.output);

  MeshFile file = read_mesh(opt.input);
  print_warnings(opt.input, file.warnings);
  if (!file.mesh.polylines.empty()) {
    if (file.mesh.face_count() == 0)
      throw InvalidInputError(opt.input + ": no faces for the surface scheme " + opt.scheme + " to refine; its " +
                              std::to_string(file.mesh.polylines.size()) + " polylines need a curve scheme (" +
                              curve_scheme_names() + ")");
    warnf("subdiv: warning: %s: %zu polylines are not refined by a surface scheme: not written\n",
                 opt.input.c_str(), file.mesh.polylines.size());
  }
  triangulate_if_asked(*scheme, opt.triangulate, file);

  const bool quasi = scheme->split == SplitRule::quasi_4_8;
  if (!quasi && opt.full_steps) throw InvalidInputError("--full-steps applies to quasi-4-8, not to " + opt.scheme);
  if (!quasi && !opt.quasi_boundary.empty())
    throw InvalidInputError("--quasi-boundary applies to quasi-4-8, not to " + opt.scheme);
  RefineOptions options;
  apply_rule_options(opt.rules, file.mesh, options);
  for (const std::string& text : opt.creases)
    file.mesh.tags.creases.push_back(parse_crease(text, file.mesh.vertex_count()));
  options.levels = opt.full_steps ? 2 * opt.levels : opt.levels;
  if (opt.start_level != 0 && !steps_alternate(scheme->split))
    throw InvalidInputError(fmt::format("--start-level applies to the {}, whose steps alternate with the level, not "
                                        "to the {} of {}",
                                        to_string(SplitRule::sqrt3), to_string(scheme->split), opt.scheme));
  options.start_level = opt.start_level;
  if (options.levels > 0) {
    warn_dropped_tags(opt.input, file.mesh.tags);
    drop_input_normals(opt.input, file.mesh);
  }
  if (opt.quasi_boundary == "smoothed") std::get<Quasi48Parameters>(chosen.parameters).boundary = Quasi48Boundary::smoothed;
  options.allow_non_manifold = opt.allow_non_manifold;
  options.threads = opt.threads;
  if (opt.boundary == "edge-only") options.boundary = BoundaryInterpolation::edge_only;
  else if (opt.boundary == "edge-and-corner") options.boundary = BoundaryInterpolation::edge_and_corner;
  if (const auto method = crease_method_named(opt.crease_method)) options.crease_method = *method;

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
    if (std::chrono::duration<double>(now - start).count() > 1.0) progressf("subdiv: %s\n", line.c_str());
  };
  check_refinable(file.mesh, *scheme, options, &file.lines);  // bad input first, then its size
  check_fits_in_memory(file.mesh, *scheme, options.levels, opt.no_memory_check, "refine");
  const PolygonMesh result = refine(file.mesh, *scheme, options, &file.lines);

  WriteOptions wopt;
  wopt.ply_encoding = opt.ascii ? PlyEncoding::ascii : PlyEncoding::binary_little_endian;
  const auto write_start = clock::now();
  print_warnings(opt.output, write_mesh(result, opt.output, wopt));
  warn_if_level_matters(*scheme, file.mesh, options, opt.output);
  if (opt.stats) {
    std::printf("scheme %s, %d levels, threads %s\n", std::string(scheme->name).c_str(), options.levels,
                opt.threads > 0 ? std::to_string(opt.threads).c_str() : "all");
    std::printf("level 0: %d vertices, %d faces\n", file.mesh.vertex_count(), file.mesh.face_count());
    for (const auto& s : stats) std::printf("%s\n", s.c_str());
    std::printf("refine %.3f s, write %.3f s\n", std::chrono::duration<double>(write_start - start).count(),
                std::chrono::duration<double>(clock::now() - write_start).count());
  }
  std::printf("wrote %s: %d vertices, %d faces\n", opt.output.c_str(), result.vertex_count(), result.face_count());
  return kExitOk;
}


}  // namespace

Command add_refine_command(CLI::App& app) {
  auto opt = std::make_shared<RefineCommandOptions>();
  CLI::App* cmd = app.add_subcommand("refine", "Uniformly refine a mesh with a subdivision scheme");
  cmd->add_option("input", opt->input, "Mesh to refine (.obj, .ply or .off)")->required();
  cmd->add_option("-o,--output", opt->output, "Where to write the result (format from the extension)")->required();
  cmd->add_option("-s,--scheme", opt->scheme, "Scheme, surface or curve (see 'subdiv schemes')")->capture_default_str();
  cmd->add_option("--tension", opt->tension, "butterfly and the four-point curve scheme: the tension w (default 1/16)");
  add_degree_options(*cmd, opt->degree);
  cmd->add_option("-l,--levels", opt->levels, "Refinement steps (quasi-4-8: binary steps, see --full-steps)")
      ->capture_default_str()
      ->check(CLI::Range(0, 12));
  cmd->add_option("--boundary", opt->boundary,
                  "Boundary interpolation, overriding the file's tag (default: the tag, else edge-and-corner)")
      ->check(CLI::IsMember({"edge-only", "edge-and-corner"}));
  cmd->add_option("--crease-method", opt->crease_method,
                  "Semi-sharp crease rule, overriding the file's creasemethod tag (default: the tag, else uniform)")
      ->check(CLI::IsMember(crease_method_names()));
  cmd->add_option("--threads", opt->threads, "Worker threads (0 = all cores); results do not depend on it")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  cmd->add_flag("--stats", opt->stats, "Print counts and timings per level");
  cmd->add_flag("--allow-non-manifold", opt->allow_non_manifold,
                "Refine non-manifold or inconsistently oriented meshes, treating those elements as sharp");
  cmd->add_flag("--triangulate", opt->triangulate, "Triangulate polygons first (for triangle schemes such as loop)");
  add_rule_options(*cmd, opt->rules);
  cmd->add_option("--crease", opt->creases,
                  "Tag edge A,B (0-based vertices) as infinitely sharp (repeatable); quasi-4-8 does not smooth it")
      ->type_name("A,B");
  cmd->add_option("--start-level", opt->start_level,
                  "The level the input is at (default 0, a control mesh); the sqrt3 split's boundary rule "
                  "alternates with the level, so a mesh refined to an odd level continues with this")
      ->check(CLI::Range(0, 64));
  cmd->add_flag("--full-steps", opt->full_steps,
                "quasi-4-8: -l counts 4-8 steps, two binary steps each (default: binary steps)");
  cmd->add_option("--quasi-boundary", opt->quasi_boundary,
                  "quasi-4-8: boundary vertices fixed (default) or the boundary polygon smoothed")
      ->check(CLI::IsMember({"fixed", "smoothed"}));
  cmd->add_flag("--ascii", opt->ascii, "ASCII PLY output instead of binary");
  cmd->add_flag("--no-memory-check", opt->no_memory_check,
                "Refine even when the estimated peak memory exceeds what the machine has available");
  cmd->footer(
      "Vertex data (colours, any per-vertex channel) is refined with the scheme's\n"
      "masks; face-varying data (UVs) linearly within faces. Curve schemes\n"
      "(cubic-bspline, chaikin, four-point) refine the polylines of a file\n"
      "without faces (OBJ 'l' lines; closed when the last index is the first).\n"
      "Examples:\n"
      "  subdiv refine data/meshes/spot_control_mesh.obj -s catmull-clark -l 3 -o /tmp/spot3.obj\n"
      "  subdiv refine data/meshes/cube.obj -s loop --triangulate -l 4 -o /tmp/cube_loop.ply --stats\n"
      "  subdiv refine curve.obj -s four-point --tension 0.08 -l 4 -o /tmp/curve4.obj\n"
      "  subdiv refine data/meshes/cube.obj -s gcc --degree 5 --alpha 0.2,0.3 --beta 0.5,0.4 -l 3 -o /tmp/gcc5.obj\n"
      "  subdiv refine data/meshes/cube.obj -s midpoint --degree 4 -l 3 -o /tmp/m4.obj\n"
      "  subdiv refine data/meshes/tetrahedron.obj -s quasi-4-8 -l 3 --full-steps -o /tmp/tetra_q48.obj");
  return [opt] { return run_refine(*opt); };
}

}  // namespace subdiv::cli
