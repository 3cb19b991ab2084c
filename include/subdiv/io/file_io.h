#pragma once
// Whole-file reads and crash-safe whole-file writes (what mesh_io.h writes
// meshes with; programs writing other files use the same guarantee).

#include <filesystem>
#include <string>
#include <string_view>

namespace subdiv {

/// The file's bytes. Throws IoError (naming the path and the reason) when it
/// does not exist, is a directory, or cannot be read.
std::string read_file(const std::filesystem::path& path);

/// Writes `data` to a temporary file in the target's directory and renames it
/// over `path`. On failure the temporary file is removed, the target is left
/// as it was, and IoError is thrown.
void write_file_atomically(const std::filesystem::path& path, std::string_view data);

}  // namespace subdiv
