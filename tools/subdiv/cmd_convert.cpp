// subdiv convert IN OUT: change format (by extension). The input is never
// modified; the output appears complete or not at all.

#include <cstdio>

#include <fmt/format.h>

#include "commands.h"
#include "output_checks.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/validation.h"

namespace subdiv::cli {

namespace {

struct ConvertOptions {
  std::string input;
  std::string output;
  bool ascii = false;
  bool big_endian = false;
  bool validate = false;
  bool no_tags = false;
};

int run_convert(const ConvertOptions& opt) {
  check_output_path(opt.input, opt.output);
  const MeshFile file = read_mesh(opt.input);
  if (opt.validate) require_valid(validate(file.mesh, &file.lines), opt.input);
  print_warnings(opt.input, file.warnings);

  WriteOptions wopt;
  wopt.ply_encoding = opt.ascii ? PlyEncoding::ascii
                      : opt.big_endian ? PlyEncoding::binary_big_endian : PlyEncoding::binary_little_endian;
  wopt.write_tags = !opt.no_tags;
  print_warnings(opt.output, write_mesh(file.mesh, opt.output, wopt));
  std::printf("%s", fmt::format("wrote {}: {} vertices, {} faces\n", opt.output, file.mesh.vertex_count(),
                                file.mesh.face_count()).c_str());
  return kExitOk;
}

}  // namespace

Command add_convert_command(CLI::App& app) {
  auto opt = std::make_shared<ConvertOptions>();
  CLI::App* cmd = app.add_subcommand("convert", "Convert a mesh between OBJ, PLY and OFF (format from the extension)");
  cmd->add_option("input", opt->input, "Mesh to read")->required();
  cmd->add_option("output", opt->output, "Mesh to write (written to a temporary file, then renamed)")->required();
  cmd->add_flag("--ascii", opt->ascii, "PLY output in ASCII instead of binary little-endian");
  cmd->add_flag("--big-endian", opt->big_endian, "PLY output in binary big-endian");
  cmd->add_flag("--validate", opt->validate, "Refuse to convert a mesh that fails validation");
  cmd->add_flag("--no-tags", opt->no_tags, "Do not write OBJ tag lines");
  cmd->footer(
      "Example:\n"
      "  subdiv convert data/meshes/cube.obj /tmp/cube.ply --ascii");
  return [opt] { return run_convert(*opt); };
}

}  // namespace subdiv::cli
