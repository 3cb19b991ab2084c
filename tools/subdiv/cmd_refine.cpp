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
#include "read_options.h"
#include "input_mesh.h"
#include "memory_guard.h"
#include "output_checks.h"
#include "command_report.h"
#include "refinement_options.h"
#include "wording.h"
#include "subdiv/core/error.h"
#include "subdiv/curves/curve_scheme.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::cli {

namespace {

struct RefineCommandOptions {
  ReadOptions read;  ///< --weld-tolerance
  std::string input;
  std::string output;
  int levels = 1;
  RefinementOptionValues refinement;
  ReportOptionValues report;
  bool ascii = false;
  bool no_memory_check = false;
  bool full_steps = false;  // quasi-4-8: -l counts 4-8 steps (two binary steps each)
  int start_level = 0;      // the level the input is at (splits whose steps alternate)
};

// Every polyline of the file refined on its own; the output holds the refined
// points of each polyline in turn and one `l` line per polyline.
int run_curve_refine(const CurveScheme& registered, const RefineCommandOptions& opt) {
  PhaseClock clock;
  const std::string name(registered.name);
  const char* option = surface_option_given(opt.refinement);
  if (!option && opt.full_steps) option = "--full-steps";
  if (!option && opt.start_level != 0) option = "--start-level";
  if (option)
    throw InvalidInputError(std::string(option) + " applies to surface schemes, not to the curve scheme " + name);
  const CurveScheme scheme = with_tension(registered, opt.refinement.tension);
  check_output_path(opt.input, opt.output);
  check_ascii_applies(opt.ascii, opt.output);
  if (format_from_path(opt.output) != FileFormat::obj)
    throw InvalidInputError(opt.output + ": " + to_string(format_from_path(opt.output)) +
                            " has no place for polylines; write the refined curves to an .obj file");

  const MeshFile file = read_mesh(opt.input, opt.read);
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

  clock.lap("read");
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
  clock.lap("refine");
  WriteOptions wopt;
  wopt.ply_encoding = opt.ascii ? PlyEncoding::ascii : PlyEncoding::binary_little_endian;
  wopt.stl_encoding = opt.ascii ? StlEncoding::ascii : StlEncoding::binary;
  wopt.threads = opt.refinement.threads;
  print_warnings(opt.output, write_mesh(result, opt.output, wopt));
  clock.lap("write");
  std::vector<long long> points(static_cast<std::size_t>(opt.levels) + 1, 0);
  for (int level = 0; level <= opt.levels; ++level)
    for (const MeshPolyline& p : mesh.polylines)
      points[static_cast<std::size_t>(level)] +=
          refined_point_count(scheme, static_cast<Index>(p.vertices.size()), p.closed, level);
  if (opt.report.json) {
    nlohmann::ordered_json levels = nlohmann::ordered_json::array();
    for (int level = 0; level <= opt.levels; ++level)
      levels.push_back({{"level", level}, {"points", points[static_cast<std::size_t>(level)]},
                        {"polylines", mesh.polylines.size()}});
    print_json({{"command", "refine"}, {"input", opt.input}, {"output", opt.output}, {"scheme", name},
                {"tension", scheme.tension}, {"levels", levels}, {"seconds", clock.json()}});
    return kExitOk;
  }
  if (opt.report.stats) {
    std::printf("curve scheme %s, %s", name.c_str(), count_of(opt.levels, "level", "levels").c_str());
    if (scheme.tension != 0.0) std::printf(", tension %g", scheme.tension);
    std::printf("\n");
    for (int level = 0; level <= opt.levels; ++level)
      std::printf("level %d: %s, %s\n", level, count_of(points[static_cast<std::size_t>(level)], "point", "points").c_str(),
                  count_of(static_cast<std::int64_t>(mesh.polylines.size()), "polyline", "polylines").c_str());
    std::printf("%s\n", clock.text().c_str());
  }
  std::printf("wrote %s: %s, %s\n", opt.output.c_str(), count_of(result.vertex_count(), "vertex", "vertices").c_str(),
              count_of(static_cast<std::int64_t>(result.polylines.size()), "polyline", "polylines").c_str());
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
  if (!find_scheme(opt.refinement.scheme)) {
    if (const CurveScheme* curve = find_curve_scheme(opt.refinement.scheme)) return run_curve_refine(*curve, opt);
    throw_unknown_scheme(opt.refinement.scheme, true);
  }
  const Scheme scheme = chosen_scheme(opt.refinement);
  const std::string name(scheme.name);
  check_output_path(opt.input, opt.output);
  check_ascii_applies(opt.ascii, opt.output);
  const bool quasi = scheme.split == SplitRule::quasi_4_8;
  if (!quasi && opt.full_steps) throw InvalidInputError("--full-steps applies to quasi-4-8, not to " + name);
  if (opt.start_level != 0 && !steps_alternate(scheme.split))
    throw InvalidInputError(fmt::format("--start-level applies to the {}, whose steps alternate with the level, not "
                                        "to the {} of {}",
                                        to_string(SplitRule::sqrt3), to_string(scheme.split), name));

  PhaseClock clock;
  MeshFile file = read_mesh(opt.input, opt.read);
  print_warnings(opt.input, file.warnings);
  if (!file.mesh.polylines.empty()) {
    if (file.mesh.face_count() == 0)
      throw InvalidInputError(opt.input + ": no faces for the surface scheme " + name + " to refine; its " +
                              count_of(static_cast<std::int64_t>(file.mesh.polylines.size()), "polyline", "polylines") +
                              " need a curve scheme (" + curve_scheme_names() + ")");
    warnf("subdiv: warning: %s: %s not refined by a surface scheme: not written\n", opt.input.c_str(),
          count_of(static_cast<std::int64_t>(file.mesh.polylines.size()), "polyline is", "polylines are").c_str());
  }
  RefineOptions options;
  apply_refinement_options(opt.refinement, scheme, file, options);
  options.levels = opt.full_steps ? 2 * opt.levels : opt.levels;
  options.start_level = opt.start_level;
  if (options.levels > 0) {
    warn_dropped_tags(opt.input, file.mesh, options.start_level == 0 ? &scheme : nullptr, options.levels);
    drop_input_normals(opt.input, file.mesh);
  }
  clock.lap("read");

  using steady = std::chrono::steady_clock;
  const auto start = steady::now();
  auto last = start;
  nlohmann::ordered_json levels = nlohmann::ordered_json::array();
  levels.push_back({{"level", 0}, {"vertices", file.mesh.vertex_count()}, {"faces", file.mesh.face_count()},
                    {"seconds", 0.0}});
  options.on_level = [&](int level, const PolygonMesh& mesh) {
    const auto now = steady::now();
    const double seconds = std::chrono::duration<double>(now - last).count();
    last = now;
    levels.push_back({{"level", level}, {"vertices", mesh.vertex_count()}, {"faces", mesh.face_count()},
                      {"seconds", seconds}});
    // Progress for long runs only, so that quick runs stay quiet.
    if (std::chrono::duration<double>(now - start).count() > 1.0)
      progressf("subdiv: level %d: %s, %s, %.3f s\n", level, count_of(mesh.vertex_count(), "vertex", "vertices").c_str(),
                count_of(mesh.face_count(), "face", "faces").c_str(), seconds);
  };
  check_refinable(file.mesh, scheme, options, &file.lines);  // bad input first, then its size
  check_fits_in_memory(file.mesh, scheme, options.levels, opt.no_memory_check, "refine");
  const PolygonMesh result = refine(file.mesh, scheme, options, &file.lines);
  clock.lap("refine");

  WriteOptions wopt;
  wopt.ply_encoding = opt.ascii ? PlyEncoding::ascii : PlyEncoding::binary_little_endian;
  wopt.stl_encoding = opt.ascii ? StlEncoding::ascii : StlEncoding::binary;
  wopt.threads = opt.refinement.threads;
  print_warnings(opt.output, write_mesh(result, opt.output, wopt));
  clock.lap("write");
  warn_if_level_matters(scheme, file.mesh, options, opt.output);
  if (opt.report.json) {
    print_json({{"command", "refine"}, {"input", opt.input}, {"output", opt.output}, {"scheme", name},
                {"threads", opt.refinement.threads}, {"levels", levels}, {"seconds", clock.json()}});
    return kExitOk;
  }
  if (opt.report.stats) {
    std::printf("scheme %s, %s, threads %s\n", name.c_str(), count_of(options.levels, "level", "levels").c_str(),
                opt.refinement.threads > 0 ? std::to_string(opt.refinement.threads).c_str() : "all");
    for (const nlohmann::ordered_json& level : levels) {
      std::printf("level %d: %s, %s", level["level"].get<int>(),
                  count_of(level["vertices"].get<std::int64_t>(), "vertex", "vertices").c_str(),
                  count_of(level["faces"].get<std::int64_t>(), "face", "faces").c_str());
      if (level["level"].get<int>() > 0) std::printf(", %.3f s", level["seconds"].get<double>());
      std::printf("\n");
    }
    std::printf("%s\n", clock.text().c_str());
  }
  std::printf("wrote %s: %s, %s\n", opt.output.c_str(), count_of(result.vertex_count(), "vertex", "vertices").c_str(),
              count_of(result.face_count(), "face", "faces").c_str());
  return kExitOk;
}

}  // namespace

Command add_refine_command(CLI::App& app) {
  auto opt = std::make_shared<RefineCommandOptions>();
  CLI::App* cmd = app.add_subcommand("refine", "Uniformly refine a mesh with a subdivision scheme");
  add_read_options(cmd, opt->read);
  cmd->add_option("input", opt->input, "Mesh to refine (.obj, .ply, .off, .gltf, .glb or .stl)")->required();
  cmd->add_option("-o,--output", opt->output, "Where to write the result (format from the extension)")->required();
  add_refinement_options(*cmd, opt->refinement, "Scheme, surface or curve (see 'subdiv schemes')");
  cmd->add_option("-l,--levels", opt->levels, "Refinement steps (quasi-4-8: binary steps, see --full-steps)")
      ->capture_default_str()
      ->check(CLI::Range(0, 12));
  add_report_options(*cmd, opt->report, "Print counts and timings per level");
  cmd->add_option("--start-level", opt->start_level,
                  "The level the input is at (default 0, a control mesh); the sqrt3 split's boundary rule "
                  "alternates with the level, so a mesh refined to an odd level continues with this")
      ->check(CLI::Range(0, 64));
  cmd->add_flag("--full-steps", opt->full_steps,
                "quasi-4-8: -l counts 4-8 steps, two binary steps each (default: binary steps)");
  cmd->add_flag("--ascii", opt->ascii, "ASCII PLY or STL output instead of binary");
  cmd->add_flag("--no-memory-check", opt->no_memory_check,
                "Refine even when the estimated peak memory exceeds what the machine has available");
  cmd->footer(
      "Vertex data (colours, any per-vertex channel) is refined with the scheme's\n"
      "masks; face-varying data (UVs) as --face-varying says (catmull-clark,\n"
      "loop, loop-warren), else linearly within faces. Curve schemes\n"
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
