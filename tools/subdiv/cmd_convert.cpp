// subdiv convert IN OUT: change format (by extension). The input is never
// modified; the output appears complete or not at all.

#include <cstdio>

#include <fmt/format.h>

#include "commands.h"
#include "read_options.h"
#include "output_checks.h"
#include "wording.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/validation.h"

namespace subdiv::cli {

namespace {

struct ConvertOptions {
  ReadOptions read;  ///< --weld-tolerance
  std::string input;
  std::string output;
  bool ascii = false;
  bool big_endian = false;
  bool validate = false;
  bool no_tags = false;
  bool keep_hole_faces = false;
};

// The writer options that one output format alone reads: refused for the
// others rather than ignored.
void check_format_options(const ConvertOptions& opt) {
  check_ascii_applies(opt.ascii, opt.output);
  const FileFormat format = format_from_path(opt.output);
  if (opt.ascii && opt.big_endian) throw InvalidInputError("--ascii and --big-endian exclude each other");
  if (opt.big_endian && format != FileFormat::ply)
    throw InvalidInputError("--big-endian applies to PLY output, not to " + opt.output);
  const bool keeps_tags = format == FileFormat::obj || format == FileFormat::gltf || format == FileFormat::glb;
  if (opt.no_tags && !keeps_tags)
    throw InvalidInputError("--no-tags applies to OBJ and glTF output (the formats that keep tags), not to " + opt.output);
  if (opt.keep_hole_faces && keeps_tags)
    throw InvalidInputError("--keep-hole-faces applies to PLY, OFF and STL output; OBJ and glTF keep hole faces with "
                            "their tags");
}

int run_convert(const ConvertOptions& opt) {
  check_output_path(opt.input, opt.output);
  check_format_options(opt);
  const MeshFile file = read_mesh(opt.input, opt.read);
  const ValidationReport report = validate(file.mesh, &file.lines);
  if (opt.validate) require_valid(report, opt.input);
  print_warnings(opt.input, file.warnings);
  if (!report.ok()) {
    // A converter writes what it reads, but never silently: the first error
    // with its line, and how many more `subdiv info` lists.
    const std::size_t more = report.error_count() - 1;
    std::string note = "the mesh is not valid and is written as it is: " + report.first_error();
    if (more > 0) note += fmt::format(" (and {} more {}; subdiv info lists them)", more, more == 1 ? "error" : "errors");
    else note += " (--validate refuses such a mesh)";
    print_warnings(opt.input, {note});
  }

  WriteOptions wopt;
  wopt.ply_encoding = opt.ascii ? PlyEncoding::ascii
                      : opt.big_endian ? PlyEncoding::binary_big_endian : PlyEncoding::binary_little_endian;
  wopt.stl_encoding = opt.ascii ? StlEncoding::ascii : StlEncoding::binary;
  wopt.write_tags = !opt.no_tags;
  wopt.hole_faces_as_faces = opt.keep_hole_faces;
  print_warnings(opt.output, write_mesh(file.mesh, opt.output, wopt));
  std::printf("%s", fmt::format("wrote {}: {}, {}\n", opt.output, count_of(file.mesh.vertex_count(), "vertex", "vertices"),
                                count_of(file.mesh.face_count(), "face", "faces")).c_str());
  return kExitOk;
}

}  // namespace

Command add_convert_command(CLI::App& app) {
  auto opt = std::make_shared<ConvertOptions>();
  CLI::App* cmd = app.add_subcommand("convert", "Convert a mesh between OBJ, PLY, OFF, glTF and STL (format from the extension)");
  add_read_options(cmd, opt->read);
  cmd->add_option("input", opt->input, "Mesh to read")->required();
  cmd->add_option("output", opt->output, "Mesh to write (written to a temporary file, then renamed)")->required();
  cmd->add_flag("--ascii", opt->ascii, "PLY or STL output in ASCII instead of binary (little-endian)");
  cmd->add_flag("--big-endian", opt->big_endian, "PLY output in binary big-endian");
  cmd->add_flag("--validate", opt->validate,
                "Refuse to convert a mesh that fails validation (without it: converted, with a warning)");
  cmd->add_flag("--no-tags", opt->no_tags, "Do not write tags (OBJ tag lines, glTF extras)");
  cmd->add_flag("--keep-hole-faces", opt->keep_hole_faces,
                "PLY, OFF and STL: write faces tagged as holes as ordinary faces (by default they are left "
                "out, with a warning: those formats have no hole tags)");
  cmd->footer(
      "glTF (.gltf, .glb) holds triangles: subdiv keeps the polygons, the vertices split at seams\n"
      "and the tags in the primitive's extras and reads them back; other programs see triangles.\n"
      "STL holds triangles, each with its own corners: they are welded into shared vertices on\n"
      "reading (--weld-tolerance).\n"
      "Examples:\n"
      "  subdiv convert data/meshes/cube.obj /tmp/cube.ply --ascii\n"
      "  subdiv convert data/meshes/cube.obj /tmp/cube.glb\n"
      "  subdiv convert scan.stl /tmp/scan.obj --weld-tolerance 1e-6");
  return [opt] { return run_convert(*opt); };
}

}  // namespace subdiv::cli
