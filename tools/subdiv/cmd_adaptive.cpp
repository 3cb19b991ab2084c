// subdiv adaptive IN -s SCHEME --eps E -o OUT: refine only where the control
// mesh is further than E from the limit surface, without cracks, and compare
// the face count with uniform refinement to the same accuracy.

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "input_mesh.h"
#include "output_checks.h"
#include "wording.h"
#include "scheme_option.h"
#include "subdiv/core/error.h"
#include "subdiv/depth/adaptive.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"

namespace subdiv::cli {

namespace {

// What the input holds that the adaptive mesh does not carry, one warning
// line listing each kind (the positions already follow the tags' rules).
void warn_not_carried(const std::string& path, const PolygonMesh& input, const PolygonMesh& output) {
  std::vector<std::string> kinds;
  for (const VertexChannel& c : input.vertex_channels)
    if (!output.find_vertex_channel(c.name)) kinds.push_back("vertex channel '" + c.name + "'");
  for (const FaceVaryingChannel& c : input.face_varying_channels)
    if (!output.find_face_varying_channel(c.name)) kinds.push_back("face-varying channel '" + c.name + "'");
  if (!input.tags.creases.empty() && output.tags.creases.empty())
    kinds.push_back(count_of(static_cast<std::int64_t>(input.tags.creases.size()), "crease tag", "crease tags"));
  if (!input.tags.corners.empty() && output.tags.corners.empty())
    kinds.push_back(count_of(static_cast<std::int64_t>(input.tags.corners.size()), "corner tag", "corner tags"));
  if (kinds.empty()) return;
  std::string list;
  for (const std::string& k : kinds) list += (list.empty() ? "" : ", ") + k;
  warnf(
               "subdiv: warning: %s: the adaptive mesh does not carry %s (positions follow the tags' rules; "
               "'subdiv refine' carries them)\n",
               path.c_str(), list.c_str());
}

struct AdaptiveCommandOptions {
  std::string input;
  std::string output;
  std::string scheme = std::string(default_scheme().name);
  double eps = 0.0;
  int max_level = 8;
  bool triangulate = false;
  bool allow_non_manifold = false;
  bool ascii = false;
};

int run_adaptive(const AdaptiveCommandOptions& opt) {
  const Scheme& scheme = scheme_named(opt.scheme);
  check_output_path(opt.input, opt.output);
  MeshFile file = read_mesh(opt.input);
  print_warnings(opt.input, file.warnings);
  triangulate_if_asked(scheme, opt.triangulate, file);
  if (!file.mesh.tags.holes.empty())
    throw InvalidInputError(opt.input + ": face " + std::to_string(file.mesh.tags.holes.front()) +
                            " is tagged as a hole, and adaptive refinement has no rule for holes (it would fill them); "
                            "'subdiv refine' keeps them");
  drop_input_normals(opt.input, file.mesh);

  AdaptiveOptions options;
  options.max_level = opt.max_level;
  options.depth.refine.allow_non_manifold = opt.allow_non_manifold;
  check_refinable(file.mesh, scheme, options.depth.refine, &file.lines);  // errors with the file's lines
  const AdaptiveResult result = adaptive_refine(file.mesh, scheme, opt.eps, options);
  warn_dropped_tags(opt.input, file.mesh.tags);
  warn_not_carried(opt.input, file.mesh, result.mesh);

  WriteOptions wopt;
  wopt.ply_encoding = opt.ascii ? PlyEncoding::ascii : PlyEncoding::binary_little_endian;
  print_warnings(opt.output, write_mesh(result.mesh, opt.output, wopt));
  const double worst = result.distances.empty() ? 0.0 : *std::max_element(result.distances.begin(), result.distances.end());
  std::printf("wrote %s: %d vertices, %d faces (%lld transition faces), levels 0..%d, largest vertex-to-limit "
              "distance %.6g (accuracy %g)\n",
              opt.output.c_str(), result.mesh.vertex_count(), result.mesh.face_count(),
              static_cast<long long>(result.transition_faces), result.leaves_per_level_max, worst, opt.eps);
  std::printf("uniform refinement to the same accuracy: %d steps, %lld faces: %.2fx the adaptive faces\n",
              result.uniform_depth, static_cast<long long>(result.uniform_faces),
              static_cast<double>(result.uniform_faces) / std::max(1, result.mesh.face_count()));
  return kExitOk;
}

}  // namespace

Command add_adaptive_command(CLI::App& app) {
  auto opt = std::make_shared<AdaptiveCommandOptions>();
  CLI::App* cmd = app.add_subcommand("adaptive", "Refine only where the mesh is further than an accuracy from the limit");
  cmd->add_option("input", opt->input, "Mesh (.obj, .ply or .off)")->required();
  cmd->add_option("-o,--output", opt->output, "Where to write the result (format from the extension)")->required();
  cmd->add_option("-s,--scheme", opt->scheme, "Scheme: loop or catmull-clark (any in 'subdiv schemes' works)")
      ->capture_default_str();
  cmd->add_option("--eps", opt->eps, "Accuracy: largest allowed distance of an output vertex to its limit position")
      ->required()
      ->check(positive_number());
  cmd->add_option("--max-level", opt->max_level, "Refuse accuracies that need more uniform levels than this")
      ->capture_default_str()
      ->check(CLI::Range(0, 12));
  cmd->add_flag("--triangulate", opt->triangulate, "Triangulate polygons first (for triangle schemes such as loop)");
  cmd->add_flag("--allow-non-manifold", opt->allow_non_manifold, "Treat non-manifold elements as sharp");
  cmd->add_flag("--ascii", opt->ascii, "ASCII PLY output instead of binary");
  cmd->footer(
      "Faces are refined where a corner is further than the accuracy from its limit position\n"
      "(the paper's mobile vertices); neighbouring levels are joined by transition faces, so the\n"
      "output has no cracks and no T-junctions. Levels are computed uniformly first.\n"
      "Example:\n"
      "  subdiv adaptive data/meshes/spot_control_mesh.obj -s catmull-clark --eps 0.002 -o /tmp/spot_adaptive.obj");
  return [opt] { return run_adaptive(*opt); };
}

}  // namespace subdiv::cli
