#pragma once
// The checks each fuzz target runs on one input. libFuzzer's entry points
// (fuzz_*.cpp) call them, and so does the ordinary test suite on every
// input kept in tests/data/fuzz/ (tests/io/fuzz_regression_test.cpp), so a
// finding, once minimized and kept, is checked on every build. A check
// returns normally for an input that is parsed or refused with a typed
// error, and aborts with a message on a broken invariant.

#include <cstddef>
#include <cstdint>

namespace subdiv::fuzz {

/// OBJ with OpenSubdiv's tag lines: parses or throws ParseError; a parsed
/// mesh validates without throwing and survives a write and a read.
void check_obj_input(const std::uint8_t* data, std::size_t size);
/// PLY, ASCII and binary: the same, written back in ASCII and in binary.
void check_ply_input(const std::uint8_t* data, std::size_t size);
/// OFF: the same.
void check_off_input(const std::uint8_t* data, std::size_t size);
/// glTF 2.0: read as a GLB container when it starts with the "glTF" magic,
/// else as JSON; a parsed mesh validates without throwing and survives a
/// glTF write and read (positions to float precision).
void check_gltf_input(const std::uint8_t* data, std::size_t size);
/// STL, ASCII or binary: parses or throws ParseError; a parsed mesh
/// validates without throwing and survives an ASCII and a binary write and
/// read (binary: positions to float precision).
void check_stl_input(const std::uint8_t* data, std::size_t size);
/// The first byte picks the format (byte % 3: OBJ, PLY, OFF) and, for
/// meshes of at most 16 faces, two levels instead of one ((byte / 3) odd);
/// the rest is the file. A valid mesh of at most 64 faces and 256 vertices
/// is refined with every surface scheme: a typed error is a refusal, and a
/// refined mesh must validate.
void check_pipeline_input(const std::uint8_t* data, std::size_t size);

}  // namespace subdiv::fuzz
