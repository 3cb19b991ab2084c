// subdiv compare MESH -s loop,butterfly,... -l N -o compare.html [--png grid.png]:
// the control mesh and each scheme's refinement side by side, as one
// self-contained web page (three.js inlined; one camera for every panel;
// wireframe and cage toggles) and, on request, as a grid of pictures drawn
// as `subdiv render` draws them.

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "command_report.h"
#include "commands.h"
#include "read_options.h"
#include "memory_guard.h"
#include "output_checks.h"
#include "picture_options.h"
#include "plots.h"
#include "refinement_options.h"
#include "scheme_option.h"
#include "surface_normals.h"
#include "wording.h"
#include "../compare/compare_page.h"
#include "../render/picture_grid.h"
#include "../render/render_scene.h"
#include "subdiv/core/error.h"
#include "subdiv/io/file_io.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/refine/refine.h"

namespace subdiv::cli {

namespace {

struct CompareCommandOptions {
  ReadOptions read;  ///< --weld-tolerance
  std::string input;
  std::string output;
  std::string png;
  int levels = 3;
  int columns = 4;
  RefinementOptionValues refinement;
  ReportOptionValues report;
  PictureOptionValues picture;
  bool no_memory_check = false;
  bool schemes_given = false;
};

// One scheme's panel, with what the picture grid needs to shade it.
struct Refined {
  compare::Panel panel;
  std::vector<Vec3> normals;
  std::string counts;  // "level 3: 386 vertices, 384 faces"
  bool triangulated = false;
};

// A listed scheme with this suffix refines the triangulated mesh.
constexpr std::string_view kTriangulated = "/triangulated";

std::vector<std::string> scheme_list(const CompareCommandOptions& opt) {
  std::vector<std::string> names;
  if (!opt.schemes_given || opt.refinement.scheme == "all") {
    for (const Scheme* s : all_schemes()) names.emplace_back(s->name);
    return names;
  }
  std::stringstream list(opt.refinement.scheme);
  for (std::string name; std::getline(list, name, ',');) {
    if (name.empty()) throw InvalidInputError("-s: an empty scheme name in '" + opt.refinement.scheme + "'");
    if (std::find(names.begin(), names.end(), name) != names.end())
      throw InvalidInputError("-s: " + name + " is listed twice");
    const std::size_t slash = name.find('/');
    if (slash != std::string::npos && name.substr(slash) != kTriangulated)
      throw InvalidInputError("-s: '" + name + "': the only suffix is " + std::string(kTriangulated));
    scheme_named(name.substr(0, slash));  // unknown names: the known ones, and the closest
    names.push_back(name);
  }
  return names;
}

bool has_non_triangles(const PolygonMesh& mesh) {
  for (Index f = 0; f < mesh.face_count(); ++f)
    if (mesh.face_size(f) != 3) return true;
  return false;
}

Refined refine_for_panel(const CompareCommandOptions& opt, const std::string& name, const MeshFile& input) {
  const std::size_t slash = name.find('/');
  RefinementOptionValues values = opt.refinement;
  values.scheme = name.substr(0, slash);
  const Scheme scheme = chosen_scheme(values);
  MeshFile file = input;
  const bool asked = slash != std::string::npos;
  if (asked) {
    file.mesh = triangulate(file.mesh);
    file.lines.face_lines.clear();
    file.lines.hole_lines.clear();
  }
  values.triangulate = !asked && scheme.traits.needs_triangles && has_non_triangles(input.mesh);
  RefineOptions options;
  apply_refinement_options(values, scheme, file, options);
  options.levels = opt.levels;
  check_refinable(file.mesh, scheme, options, &file.lines);
  check_fits_in_memory(file.mesh, scheme, opt.levels, opt.no_memory_check, "compare (" + name + ")");
  Refined out;
  out.panel.title = name;
  out.panel.mesh = refine(file.mesh, scheme, options, &file.lines);
  out.counts = fmt::format("level {}: {}, {}", opt.levels, count_of(out.panel.mesh.vertex_count(), "vertex", "vertices"),
                           count_of(out.panel.mesh.face_count(), "face", "faces"));
  out.triangulated = asked || values.triangulate;
  out.panel.caption = out.counts + (out.triangulated ? ", of the triangulated mesh" : "");
  if (!opt.png.empty()) out.normals = limit_normals_for_picture(out.panel.mesh, scheme, options);
  return out;
}

std::string lower_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension;
}

std::string grid_png(const MeshFile& input, const std::vector<Refined>& refined, const CompareCommandOptions& opt) {
  const render::RenderStyle style = picture_style(opt.picture);
  // The control mesh faceted, with its edges; each refinement with the cage
  // over it; every picture framing the same sphere.
  std::vector<render::Scene> scenes;
  scenes.push_back(render::surface_scene(input.mesh, {}, {.wireframe = true, .features = true, .flat = true}));
  for (const Refined& r : refined) {
    scenes.push_back(render::surface_scene(r.panel.mesh, r.normals, {}));
    render::add_cage(scenes.back(), input.mesh);
  }
  std::vector<render::Scene*> framed;
  for (render::Scene& scene : scenes) framed.push_back(&scene);
  render::frame_together(framed);
  std::vector<render::Captioned> pictures;
  pictures.push_back({render::rasterize(scenes.front(), style),
                      {"control mesh", fmt::format("{}, {}", count_of(input.mesh.vertex_count(), "vertex", "vertices"),
                                                   count_of(input.mesh.face_count(), "face", "faces"))}});
  for (std::size_t i = 0; i < refined.size(); ++i) {
    std::vector<std::string> lines{refined[i].panel.title, refined[i].counts};
    if (refined[i].triangulated) lines.emplace_back("of the triangulated mesh");
    pictures.push_back({render::rasterize(scenes[i + 1], style), std::move(lines)});
  }
  return render::picture_grid_png(pictures, opt.columns);
}

int run_compare(const CompareCommandOptions& opt) {
  if (lower_extension(opt.output) != ".html")
    throw InvalidInputError(opt.output + ": compare writes a web page (.html); --png adds a grid of pictures");
  if (!opt.png.empty() && lower_extension(opt.png) != ".png")
    throw InvalidInputError(opt.png + ": --png writes a PNG image (.png)");
  if (!opt.png.empty()) picture_style(opt.picture);  // a malformed --size or --view fails before the work
  const std::vector<std::string> names = scheme_list(opt);
  PhaseClock clock;
  const MeshFile input = read_mesh(opt.input, opt.read);
  print_warnings(opt.input, input.warnings);
  clock.lap("read");

  std::vector<Refined> refined;
  for (const std::string& name : names) {
    try {
      refined.push_back(refine_for_panel(opt, name, input));
    } catch (const InvalidInputError& e) {
      if (opt.schemes_given && opt.refinement.scheme != "all") throw;
      warnf("subdiv: warning: %s: %s left out: %s\n", opt.input.c_str(), name.c_str(), e.what());
    }
  }
  if (refined.empty()) throw InvalidInputError(opt.input + ": no scheme refines this mesh");
  clock.lap("refine");

  std::vector<compare::Panel> panels;
  panels.push_back({"control mesh",
                    fmt::format("{}, {}", count_of(input.mesh.vertex_count(), "vertex", "vertices"),
                                count_of(input.mesh.face_count(), "face", "faces")),
                    input.mesh});
  for (const Refined& r : refined) panels.push_back(r.panel);
  const std::string title = std::filesystem::path(opt.input).filename().string() + ": " +
                            count_of(static_cast<std::int64_t>(refined.size()), "scheme", "schemes") + ", " +
                            count_of(opt.levels, "level", "levels");
  write_file_atomically(opt.output, compare::comparison_page(title, input.mesh, panels));
  clock.lap("page");
  if (!opt.png.empty()) {
    struct ReleaseCaches {
      ~ReleaseCaches() { release_text_caches(); }  // the captions' fonts, on every path
    } release_caches_on_exit;
    write_file_atomically(opt.png, grid_png(input, refined, opt));
    clock.lap("pictures");
  }

  if (opt.report.json) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const Refined& r : refined)
      list.push_back({{"scheme", r.panel.title}, {"vertices", r.panel.mesh.vertex_count()},
                      {"faces", r.panel.mesh.face_count()}});
    print_json({{"command", "compare"}, {"input", opt.input}, {"output", opt.output},
                {"png", opt.png.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(opt.png)},
                {"levels", opt.levels}, {"panels", list}, {"seconds", clock.json()}});
    return kExitOk;
  }
  if (opt.report.stats) std::printf("%s\n", clock.text().c_str());
  std::printf("wrote %s: the control mesh and %s at level %d\n", opt.output.c_str(),
              count_of(static_cast<std::int64_t>(refined.size()), "scheme", "schemes").c_str(), opt.levels);
  if (!opt.png.empty()) std::printf("wrote %s\n", opt.png.c_str());
  return kExitOk;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto opt = std::make_shared<CompareCommandOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Show several schemes' refinements of a mesh side by side (web page, PNG)");
  add_read_options(cmd, opt->read);
  cmd->add_option("input", opt->input, "Mesh to refine (.obj, .ply, .off, .gltf, .glb or .stl)")->required();
  cmd->add_option("-o,--output", opt->output, "The web page to write (.html, self-contained)")->required();
  add_refinement_options(*cmd, opt->refinement,
                         "Schemes, comma-separated, or 'all' (the default: every surface scheme that takes the mesh)");
  cmd->add_option("-l,--levels", opt->levels, "Refinement steps of every scheme")->capture_default_str()->check(CLI::Range(0, 8));
  cmd->add_option("--png", opt->png, "Also write the panels as a grid of pictures (PNG)");
  cmd->add_option("--columns", opt->columns, "Pictures per row of the --png grid")->capture_default_str()->check(CLI::Range(1, 32));
  add_picture_options(*cmd, opt->picture, "400x400");
  add_report_options(*cmd, opt->report, "Print the time of each phase");
  cmd->add_flag("--no-memory-check", opt->no_memory_check,
                "Refine even when the estimated peak memory exceeds what the machine has available");
  cmd->footer(
      "Schemes that read triangles refine the triangulated mesh (the caption says so);\n"
      "a listed name with the suffix /triangulated (catmull-clark/triangulated) does too.\n"
      "With -s all, schemes that refuse the mesh are left out with a warning; a\n"
      "listed scheme that refuses it is an error. Scheme parameters (--tension,\n"
      "--degree, ...) apply to every listed scheme. --size, --view, --background\n"
      "and --samples are those of each picture of the --png grid.\n"
      "Examples:\n"
      "  subdiv compare data/meshes/cube.obj -o /tmp/cube.html --png /tmp/cube.png\n"
      "  subdiv compare data/meshes/tetrahedron.obj -s loop,butterfly,sqrt3 -l 4 -o /tmp/t.html");
  return [opt, cmd] {
    opt->schemes_given = cmd->get_option("--scheme")->count() > 0;
    return run_compare(*opt);
  };
}

}  // namespace subdiv::cli
