// subdiv adaptive IN -s SCHEME --eps E -o OUT: refine only where the control
// mesh is further than E from the limit surface, without cracks, and compare
// the face count with uniform refinement to the same accuracy.

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <string>
#include <vector>

#include "commands.h"
#include "read_options.h"
#include "input_mesh.h"
#include "output_checks.h"
#include "wording.h"
#include "command_report.h"
#include "memory_guard.h"
#include "refinement_options.h"
#include "subdiv/core/error.h"
#include "subdiv/depth/adaptive.h"
#include "subdiv/depth/depth.h"
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
  ReadOptions read;  ///< --weld-tolerance
  std::string input;
  std::string output;
  double eps = 0.0;
  int max_level = 8;
  bool ascii = false;
  bool no_memory_check = false;
  RefinementOptionValues refinement;
  ReportOptionValues report;
};

// The uniform steps adaptive refinement may take: up to --max-level, and no
// further than the a-priori bound's depth, at which every vertex is within
// eps. Nothing tighter than --max-level where the scheme or the mesh has no
// bound (the measured distances decide then).
// --max-level counts the levels adaptive refinement walks (4-8's, the sqrt3
// and sqrt2 splits' and midedge's of two steps each). Interpolating schemes read their faces'
// displacements one level further down, and refine one level more.
int steps_needed_at_most(const PolygonMesh& mesh, const Scheme& scheme, double eps, const AdaptiveOptions& options,
                         std::optional<int>& bound_steps) {
  const int max_steps = options.max_level * adaptive_steps_per_level(scheme);
  if (depth_bound_unavailable(scheme, options.depth)) return max_steps;
  int extra = 0;
  try {
    const DepthBound bound = depth_bound(mesh, scheme, options.depth);
    bound_steps = bound.depth_for(eps) * bound.steps_per_level;
    if (bound.measure == DepthMeasure::surface_to_limit) extra = 2 * bound.steps_per_level;
  } catch (const InvalidInputError&) {
    return max_steps;  // a configuration without a rate: no bound
  }
  return std::min(*bound_steps + extra, max_steps);
}

int run_adaptive(const AdaptiveCommandOptions& opt) {
  const Scheme scheme = chosen_scheme(opt.refinement);
  const std::string name(scheme.name);
  check_output_path(opt.input, opt.output);
  check_ascii_applies(opt.ascii, opt.output);
  PhaseClock clock;
  MeshFile file = read_mesh(opt.input, opt.read);
  print_warnings(opt.input, file.warnings);
  AdaptiveOptions options;
  options.max_level = opt.max_level;
  apply_refinement_options(opt.refinement, scheme, file, options.depth.refine);
  if (!file.mesh.tags.holes.empty())
    throw InvalidInputError(opt.input + ": face " + std::to_string(file.mesh.tags.holes.front()) +
                            " is tagged as a hole, and adaptive refinement has no rule for holes (it would fill them); "
                            "'subdiv refine' keeps them");
  drop_input_normals(opt.input, file.mesh);
  clock.lap("read");

  check_refinable(file.mesh, scheme, options.depth.refine, &file.lines);  // errors with the file's lines
  std::optional<int> bound_steps;
  const int steps = steps_needed_at_most(file.mesh, scheme, opt.eps, options, bound_steps);
  const std::string why = bound_steps ? fmt::format("the a-priori bound for accuracy {:g} needs {}, --max-level is {}",
                                                    opt.eps, count_of(*bound_steps, "step", "steps"), opt.max_level)
                                      : fmt::format("--max-level {}", opt.max_level);
  check_fits_in_memory(estimated_adaptive_peak_bytes(file.mesh, scheme, steps), opt.no_memory_check,
                       fmt::format("adaptive refinement over {} uniform levels ({})", steps, why));
  clock.lap("bound");
  const AdaptiveResult result = adaptive_refine(file.mesh, scheme, opt.eps, options);
  clock.lap("adaptive");
  warn_dropped_tags(opt.input, file.mesh);
  warn_not_carried(opt.input, file.mesh, result.mesh);
  if (result.approximated > 0)
    warnf("subdiv: warning: %s no configuration's masks after four isolation levels: %s only approximated, and "
          "the accuracy is not established there\n",
          count_of(result.approximated, "output vertex matches", "output vertices match").c_str(),
          result.approximated == 1 ? "its limit is" : "their limits are");

  WriteOptions wopt;
  wopt.ply_encoding = opt.ascii ? PlyEncoding::ascii : PlyEncoding::binary_little_endian;
  wopt.stl_encoding = opt.ascii ? StlEncoding::ascii : StlEncoding::binary;
  wopt.threads = opt.refinement.threads;
  print_warnings(opt.output, write_mesh(result.mesh, opt.output, wopt));
  clock.lap("write");
  const double worst = result.distances.empty() ? 0.0 : *std::max_element(result.distances.begin(), result.distances.end());
  const double ratio = static_cast<double>(result.uniform_faces) / std::max(1, result.mesh.face_count());
  if (opt.report.json) {
    print_json({{"command", "adaptive"},
                {"input", opt.input},
                {"output", opt.output},
                {"scheme", name},
                {"eps", opt.eps},
                {"vertices", result.mesh.vertex_count()},
                {"faces", result.mesh.face_count()},
                {"transition_faces", result.transition_faces},
                {"deepest_level", result.leaves_per_level_max},
                {"largest_distance", worst},
                {"measure", to_string(result.measure)},
                {"largest_displacement", result.largest_displacement},
                {"displacement_threshold", result.displacement_threshold},
                {"approximated", result.approximated},
                {"bound_steps", bound_steps ? nlohmann::ordered_json(*bound_steps) : nlohmann::ordered_json(nullptr)},
                {"uniform", {{"steps", result.uniform_depth * result.steps_per_level}, {"faces", result.uniform_faces}}},
                {"uniform_to_adaptive_faces", ratio},
                {"seconds", clock.json()}});
    return kExitOk;
  }
  if (opt.report.stats) std::printf("%s\n", clock.text().c_str());
  const std::string accuracy =
      result.measure == DepthMeasure::surface_to_limit
          ? fmt::format("every vertex on the limit; largest distance of a face's next-level vertices from its linear "
                        "surface {:.6g}, within eps (1 - r) = {:.6g}, r the depth bound's rate (accuracy {:g})",
                        result.largest_displacement, result.displacement_threshold, opt.eps)
          : fmt::format("largest vertex-to-limit distance {:.6g} (accuracy {:g})", worst, opt.eps);
  std::printf("wrote %s: %s, %s (%lld transition faces), levels 0..%d%s, %s\n", opt.output.c_str(),
              count_of(result.mesh.vertex_count(), "vertex", "vertices").c_str(),
              count_of(result.mesh.face_count(), "face", "faces").c_str(),
              static_cast<long long>(result.transition_faces), result.leaves_per_level_max,
              result.steps_per_level > 1 ? " of two steps" : "", accuracy.c_str());
  std::printf("uniform refinement to the same accuracy: %s, %s: %.2fx the adaptive faces\n",
              count_of(result.uniform_depth * result.steps_per_level, "step", "steps").c_str(),
              count_of(result.uniform_faces, "face", "faces").c_str(), ratio);
  return kExitOk;
}

}  // namespace

Command add_adaptive_command(CLI::App& app) {
  auto opt = std::make_shared<AdaptiveCommandOptions>();
  CLI::App* cmd = app.add_subcommand("adaptive", "Refine only where the mesh is further than an accuracy from the limit");
  add_read_options(cmd, opt->read);
  cmd->add_option("input", opt->input, "Mesh (.obj, .ply, .off, .gltf, .glb or .stl)")->required();
  cmd->add_option("-o,--output", opt->output, "Where to write the result (format from the extension)")->required();
  add_refinement_options(*cmd, opt->refinement, "Scheme (see 'subdiv schemes'; 'subdiv schemes --matrix' says which refine adaptively)");
  cmd->add_option("--eps", opt->eps, "Accuracy: largest allowed distance of an output vertex to its limit position")
      ->required()
      ->check(positive_number());
  cmd->add_option("--max-level", opt->max_level, "Refuse accuracies that need more uniform levels than this")
      ->capture_default_str()
      ->check(CLI::Range(0, 12));
  add_report_options(*cmd, opt->report, "Print the time of each phase");
  cmd->add_flag("--ascii", opt->ascii, "ASCII PLY or STL output instead of binary");
  cmd->add_flag("--no-memory-check", opt->no_memory_check,
                "Refine even when the estimated peak memory exceeds what the machine has available");
  cmd->footer(
      "Faces are refined where a corner is further than the accuracy from its limit position\n"
      "(the paper's mobile vertices); neighbouring levels are joined by transition faces, so the\n"
      "output has no cracks and no T-junctions. Levels are computed uniformly first.\n"
      "Example:\n"
      "  subdiv adaptive data/meshes/spot_control_mesh.obj -s catmull-clark --eps 0.002 -o /tmp/spot_adaptive.obj");
  return [opt] { return run_adaptive(*opt); };
}

}  // namespace subdiv::cli
