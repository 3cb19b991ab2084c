#pragma once
/// \file
/// Whole-file reads and crash-safe whole-file writes (what mesh_io.h writes
/// meshes with; programs writing other files use the same guarantee).

#include <filesystem>
#include <string>
#include <string_view>

namespace subdiv {

/// Reads a whole file (also a pipe or other non-regular file).
/// \param path the file to read.
/// \return the file's bytes, unchanged.
/// \throws IoError naming the path (and the system's reason where there is
///         one) when it is a directory, cannot be opened, or a read fails.
/// \throws std::bad_alloc if memory runs out.
std::string read_file(const std::filesystem::path& path);

/// Writes \p data to a temporary file in the target's directory, syncs it
/// and renames it over \p path, so readers see the old file or the new one,
/// never a partial one. The new file gets the usual permissions (0666 less
/// the umask). On failure the temporary file is removed and the target is
/// left as it was.
/// \param path the file to write; its directory must exist.
/// \param data the bytes to write.
/// \throws IoError naming the path and the system's reason when \p path is
///         a directory, or the temporary file cannot be created, written,
///         synced, closed or renamed into place.
/// \throws std::bad_alloc if memory runs out.
void write_file_atomically(const std::filesystem::path& path, std::string_view data);

}  // namespace subdiv
