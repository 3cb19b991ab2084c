// subdiv render MESH [-s SCHEME -l N] -o OUT.png: a picture of the surface,
// shaded by its normals (the scheme's limit normals where it has closed-form
// limit masks), with boundaries and creases in colour, optionally the
// wireframe and the control cage. Headless (Mesa's off-screen renderer).

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "command_report.h"
#include "commands.h"
#include "read_options.h"
#include "memory_guard.h"
#include "output_checks.h"
#include "picture_options.h"
#include "refinement_options.h"
#include "surface_normals.h"
#include "wording.h"
#include "../render/png.h"
#include "../render/rasterizer.h"
#include "../render/render_scene.h"
#include "subdiv/core/error.h"
#include "subdiv/io/file_io.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"

namespace subdiv::cli {

namespace {

struct RenderCommandOptions {
  ReadOptions read;  ///< --weld-tolerance
  std::string input;
  std::string output;
  int levels = 3;
  RefinementOptionValues refinement;
  ReportOptionValues report;
  PictureOptionValues picture;
  bool wireframe = false;
  bool cage = false;
  bool no_features = false;
  bool flat = false;
  bool no_memory_check = false;
  bool scheme_given = false;
  bool levels_given = false;
};

int run_render(RenderCommandOptions& opt) {
  const render::RenderStyle style = picture_style(opt.picture);
  const int width = style.width, height = style.height;
  const render::ViewDirection view = style.view;
  std::string extension = std::filesystem::path(opt.output).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension != ".png") throw InvalidInputError(opt.output + ": render writes PNG images (.png)");

  PhaseClock clock;
  MeshFile file = read_mesh(opt.input, opt.read);
  print_warnings(opt.input, file.warnings);
  const int levels = opt.levels_given ? opt.levels : (opt.scheme_given ? 3 : 0);
  const Scheme scheme = chosen_scheme(opt.refinement);
  RefineOptions options;
  apply_refinement_options(opt.refinement, scheme, file, options);
  options.levels = levels;
  clock.lap("read");

  PolygonMesh surface;
  std::vector<Vec3> normals;
  const char* shading = opt.flat ? "each face's own normal" : "face normals";
  if (levels > 0) {
    check_refinable(file.mesh, scheme, options, &file.lines);
    check_fits_in_memory(file.mesh, scheme, levels, opt.no_memory_check, "render");
    surface = refine(file.mesh, scheme, options, &file.lines);
    clock.lap("refine");
    if (!opt.flat) normals = limit_normals_for_picture(surface, scheme, options);
    if (!normals.empty()) shading = "limit normals";
    clock.lap("normals");
  } else {
    surface = file.mesh;
  }
  render::Scene scene =
      render::surface_scene(surface, normals, render::EdgeStyle{.wireframe = opt.wireframe, .features = !opt.no_features, .flat = opt.flat});
  if (opt.cage) render::add_cage(scene, file.mesh);
  const render::Image image = render::rasterize(scene, style);
  clock.lap("draw");
  write_file_atomically(opt.output, render::encode_png(image));
  clock.lap("write");

  const std::string described = levels > 0 ? fmt::format("{}, {}", std::string(scheme.name), count_of(levels, "level", "levels"))
                                           : std::string("the mesh as given");
  if (opt.report.json) {
    print_json({{"command", "render"}, {"input", opt.input}, {"output", opt.output},
                {"scheme", levels > 0 ? nlohmann::ordered_json(std::string(scheme.name)) : nlohmann::ordered_json()},
                {"levels", levels}, {"width", width}, {"height", height},
                {"view", {view.azimuth, view.elevation}}, {"vertices", surface.vertex_count()},
                {"faces", surface.face_count()}, {"triangles", scene.triangles.size() / 3}, {"shading", shading},
                {"seconds", clock.json()}});
    return kExitOk;
  }
  if (opt.report.stats) std::printf("%s\n", clock.text().c_str());
  std::printf("wrote %s: %dx%d, %s: %s, %s, shaded by %s\n", opt.output.c_str(), width, height, described.c_str(),
              count_of(surface.vertex_count(), "vertex", "vertices").c_str(),
              count_of(surface.face_count(), "face", "faces").c_str(), shading);
  return kExitOk;
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto opt = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Draw a picture of the subdivision surface (PNG, no display needed)");
  add_read_options(cmd, opt->read);
  cmd->add_option("input", opt->input, "Mesh to draw (.obj, .ply, .off, .gltf, .glb or .stl)")->required();
  cmd->add_option("-o,--output", opt->output, "The PNG image to write")->required();
  add_refinement_options(*cmd, opt->refinement, "Scheme to refine with before drawing (see 'subdiv schemes')");
  cmd->add_option("-l,--levels", opt->levels,
                  "Refinement steps before drawing (default: 3 with -s, else 0: the mesh as given)")
      ->check(CLI::Range(0, 12));
  add_picture_options(*cmd, opt->picture, "800x600");
  cmd->add_flag("--wireframe", opt->wireframe, "Draw every edge of the drawn surface");
  cmd->add_flag("--cage", opt->cage, "Draw the control mesh's edges over the surface (green)");
  cmd->add_flag("--no-features", opt->no_features, "Do not draw boundaries and creases in colour");
  cmd->add_flag("--flat", opt->flat, "Shade each face by its own normal (facets; default: smooth)");
  add_report_options(*cmd, opt->report, "Print the time of each phase");
  cmd->add_flag("--no-memory-check", opt->no_memory_check,
                "Refine even when the estimated peak memory exceeds what the machine has available");
  cmd->footer(
      "Colours: boundaries blue, infinitely sharp creases red, semi-sharp creases\n"
      "orange (while their sharpness lasts at the drawn level), the cage green;\n"
      "faces seen from behind (inside-out) are drawn in a reddish tone.\n"
      "Examples:\n"
      "  subdiv render data/meshes/cube.obj -s catmull-clark -l 4 -o /tmp/cube.png\n"
      "  subdiv render data/meshes/tetrahedron.obj -s loop --cage --view 45,30 --size 640x480 -o /tmp/t.png");
  return [opt, cmd] {
    opt->scheme_given = cmd->get_option("--scheme")->count() > 0;
    opt->levels_given = cmd->get_option("--levels")->count() > 0;
    return run_render(*opt);
  };
}

}  // namespace subdiv::cli
