#include "fuzz_checks.h"

#include <array>
#include <optional>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

#include "subdiv/core/error.h"
#include "subdiv/eval/limit_evaluator.h"
#include "subdiv/io/gltf.h"
#include "subdiv/io/obj.h"
#include "subdiv/io/off.h"
#include "subdiv/io/ply.h"
#include "subdiv/io/stl.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::fuzz {
namespace {

// Refinement grows a mesh about fourfold a level: these keep every input's
// work to milliseconds, so the fuzzer spends its time on new shapes.
constexpr Index kMaxFaces = 64;
constexpr Index kMaxVertices = 256;
constexpr Index kMaxFacesForTwoLevels = 16;
// Exact evaluation isolates semi-sharp features up to six levels: small
// meshes only, so that a run stays fast.
constexpr Index kMaxFacesForEvaluation = 16;

/// A finding: prints why and aborts, so that libFuzzer keeps the input.
[[noreturn]] void fail(const std::string& why) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", why.c_str());
  std::abort();
}

std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Through a volatile: GCC 12 at -O2 can drop a float round trip's rounding.
float to_float(double x) {
  volatile float f = static_cast<float>(x);
  return f;
}

bool same_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

/// A mesh the reader accepted must survive its own format's writer: the
/// points and faces come back unchanged (the writers print shortest
/// round-trip numbers). A typed error from the second read is a finding: the
/// writer wrote what the reader refuses.
template <class Format, class Parse>
void check_round_trip(const MeshFile& first, Format format, Parse parse, const char* what) {
  std::string text;
  try {
    text = format(first.mesh);
  } catch (const InvalidInputError&) {
    return;  // the writer's documented refusal of arrays it cannot represent
  }
  MeshFile second;
  try {
    second = parse(std::string_view(text));
  } catch (const Error& e) {
    fail(std::string(what) + ": the writer's output does not parse: " + e.what());
  }
  const PolygonMesh& a = first.mesh;
  const PolygonMesh& b = second.mesh;
  if (a.vertex_count() != b.vertex_count() || a.face_offsets != b.face_offsets || a.face_indices != b.face_indices)
    fail(std::string(what) + ": faces or the vertex count changed by a write and a read");
  for (Index v = 0; v < a.vertex_count(); ++v)
    for (int c = 0; c < 3; ++c)
      if (!same_number(a.positions[v][c], b.positions[v][c]))
        fail(std::string(what) + ": a position changed by a write and a read, vertex " + std::to_string(v));
}

template <class Parse>
bool try_parse(Parse parse, MeshFile& file) {
  try {
    file = parse();
    return true;
  } catch (const ParseError&) {
    return false;
  }
}

/// Binary STL holds float32: the mesh written in binary and read back must
/// equal the mesh with its positions rounded to float written in ASCII and
/// read back (rounding may weld vertices and collapse triangles, the same
/// way in both).
void check_stl_binary_round_trip(const PolygonMesh& mesh) {
  std::string binary;
  try {
    binary = format_stl(mesh, StlEncoding::binary);
  } catch (const InvalidInputError&) {
    return;  // positions beyond float's range
  }
  PolygonMesh rounded = mesh;
  for (Vec3& p : rounded.positions)
    for (int c = 0; c < 3; ++c) {
      if (!(std::abs(p[c]) <= static_cast<double>(std::numeric_limits<float>::max()))) return;  // an unused vertex
      p[c] = static_cast<double>(static_cast<float>(p[c]));
    }
  MeshFile expected, actual;
  try {
    actual = parse_stl(binary, "round-trip.stl");
    expected = parse_stl(format_stl(rounded, StlEncoding::ascii), "rounded.stl");
  } catch (const Error& e) {
    fail(std::string("STL binary: the writer's output does not parse: ") + e.what());
  }
  const PolygonMesh& a = expected.mesh;
  const PolygonMesh& b = actual.mesh;
  if (a.positions != b.positions || a.face_offsets != b.face_offsets || a.face_indices != b.face_indices)
    fail("STL binary: a write and a read differ from rounding the positions to float");
}

}  // namespace

void check_obj_input(const std::uint8_t* data, std::size_t size) {
  MeshFile file;
  if (!try_parse([&] { return parse_obj(as_text(data, size), "fuzz.obj"); }, file)) return;
  (void)validate(file.mesh, &file.lines);
  WriteOptions options;
  options.threads = 1;
  check_round_trip(
      file, [&](const PolygonMesh& m) { return format_obj(m, options); },
      [](std::string_view t) { return parse_obj(t, "round-trip.obj"); }, "OBJ");
}

void check_ply_input(const std::uint8_t* data, std::size_t size) {
  MeshFile file;
  if (!try_parse([&] { return parse_ply(as_text(data, size), "fuzz.ply"); }, file)) return;
  (void)validate(file.mesh, &file.lines);
  const auto read_back = [](std::string_view t) { return parse_ply(t, "round-trip.ply"); };
  check_round_trip(
      file, [](const PolygonMesh& m) { return format_ply(m, PlyEncoding::ascii, nullptr, 1); }, read_back,
      "PLY ascii");
  check_round_trip(
      file, [](const PolygonMesh& m) { return format_ply(m, PlyEncoding::binary_big_endian, nullptr, 1); },
      read_back, "PLY binary");
}

void check_off_input(const std::uint8_t* data, std::size_t size) {
  MeshFile file;
  if (!try_parse([&] { return parse_off(as_text(data, size), "fuzz.off"); }, file)) return;
  (void)validate(file.mesh, &file.lines);
  check_round_trip(
      file, [](const PolygonMesh& m) { return format_off(m, nullptr, 1); },
      [](std::string_view t) { return parse_off(t, "round-trip.off"); }, "OFF");
}

void check_gltf_input(const std::uint8_t* data, std::size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  MeshFile file;
  if (!try_parse([&] { return parse_gltf(as_text(data, size), "fuzz.gltf", binary); }, file)) return;
  (void)validate(file.mesh, &file.lines);
  std::string text;
  try {
    text = format_gltf(file.mesh, false);
  } catch (const InvalidInputError&) {
    return;  // no triangle, or a position beyond float32: the writer's documented refusals
  }
  MeshFile second;
  try {
    second = parse_gltf(text, "round-trip.gltf", false);
  } catch (const Error& e) {
    fail(std::string("glTF: the writer's output does not parse: ") + e.what());
  }
  const PolygonMesh& a = file.mesh;
  const PolygonMesh& b = second.mesh;
  if (a.vertex_count() != b.vertex_count() || a.face_offsets != b.face_offsets || a.face_indices != b.face_indices)
    fail("glTF: faces or the vertex count changed by a write and a read");
  for (Index v = 0; v < a.vertex_count(); ++v)
    for (int c = 0; c < 3; ++c)
      if (static_cast<double>(to_float(a.positions[v][c])) != b.positions[v][c])
        fail("glTF: a position changed beyond float rounding by a write and a read, vertex " + std::to_string(v));
}

void check_stl_input(const std::uint8_t* data, std::size_t size) {
  MeshFile file;
  if (!try_parse([&] { return parse_stl(as_text(data, size), "fuzz.stl"); }, file)) return;
  (void)validate(file.mesh, &file.lines);
  const auto read_back = [](std::string_view t) { return parse_stl(t, "round-trip.stl"); };
  check_round_trip(
      file, [](const PolygonMesh& m) { return format_stl(m, StlEncoding::ascii); }, read_back, "STL ascii");
  check_stl_binary_round_trip(file.mesh);
  // Welding with a tolerance takes another path (a grid of cells).
  MeshFile welded;
  if (!try_parse([&] { return parse_stl(as_text(data, size), "fuzz.stl", {.weld_tolerance = 0.5}); }, welded))
    fail("STL: a file read without a weld tolerance is refused with one");
  (void)validate(welded.mesh, &welded.lines);
}

namespace {

// Exact evaluation of a valid mesh: refused with a message, or finite
// points at the corners and inside every ptex face.
void check_evaluation(const PolygonMesh& mesh) {
  // Exact evaluation, and evaluation by refinement (a coarse accuracy, few
  // levels: a refusal is fine, a crash or a non-finite point is not).
  for (const char* name : {"catmull-clark", "loop", "bilinear", "butterfly"}) {
    const Scheme* scheme = find_scheme(name);
    const bool exact = std::string_view(name) == "catmull-clark" || std::string_view(name) == "loop";
    std::optional<LimitEvaluator> evaluator;
    RefineOptions one_thread;
    one_thread.threads = 1;
    try {
      if (exact) evaluator.emplace(mesh, *scheme, one_thread);
      else evaluator.emplace(LimitEvaluator::by_refinement(mesh, *scheme, 1e-1, one_thread, 3));
    } catch (const Error&) {
      continue;  // not covered, with a message
    }
    const bool triangles = evaluator->triangles();
    for (Index f = 0; f < evaluator->ptex_face_count(); ++f) {
      for (const auto& [u, v] : {std::array<double, 2>{0, 0}, {1, 0}, {0, 1}, {0.25, 0.25}, {triangles ? 0.5 : 1.0, 0.5}}) {
        const LimitPoint p = evaluator->evaluate(f, u, v);
        if (!std::isfinite(p.position.x) || !std::isfinite(p.position.y) || !std::isfinite(p.position.z))
          fail(std::string(name) + " evaluated a non-finite point of a valid mesh");
      }
    }
  }
}

}  // namespace

void check_pipeline_input(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return;
  const std::uint8_t selector = data[0];
  const std::string_view bytes = as_text(data + 1, size - 1);
  MeshFile file;
  const bool parsed = try_parse(
      [&] {
        switch (selector % 3) {
          case 0: return parse_obj(bytes, "fuzz.obj");
          case 1: return parse_ply(bytes, "fuzz.ply");
          default: return parse_off(bytes, "fuzz.off");
        }
      },
      file);
  if (!parsed) return;
  const PolygonMesh& mesh = file.mesh;
  if (mesh.face_count() == 0 || mesh.face_count() > kMaxFaces || mesh.vertex_count() > kMaxVertices) return;
  if (!validate(mesh, &file.lines).ok()) return;

  RefineOptions options;
  options.threads = 1;
  options.levels = (selector / 3) % 2 == 1 && mesh.face_count() <= kMaxFacesForTwoLevels ? 2 : 1;
  for (const Scheme* scheme : all_schemes()) {
    PolygonMesh refined;
    try {
      refined = refine(mesh, *scheme, options, &file.lines);
    } catch (const Error&) {
      continue;  // the scheme refuses this mesh, with a message
    }
    const ValidationReport report = validate(refined);
    if (!report.ok())
      fail(std::string(scheme->name) + " made an invalid mesh from a valid one: " + report.first_error());
  }
  if (mesh.face_count() <= kMaxFacesForEvaluation) check_evaluation(mesh);
}

}  // namespace subdiv::fuzz
