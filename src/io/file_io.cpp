#include "subdiv/io/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "subdiv/core/error.h"

namespace subdiv {

namespace {
std::string reason() { return std::strerror(errno); }
}  // namespace

std::string read_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw IoError(path.string() + ": is a directory, not a mesh file");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw IoError(path.string() + ": cannot open: " + reason());
  std::string data;
  // Read in one go when the size is known; grow by chunks otherwise (pipes).
  struct stat info {};
  if (::fstat(::fileno(file), &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0) {
    data.resize(static_cast<std::size_t>(info.st_size));
    data.resize(std::fread(data.data(), 1, data.size(), file));
  }
  char buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) data.append(buffer, n);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) throw IoError(path.string() + ": read error");
  return data;
}

void write_file_atomically(const std::filesystem::path& path, std::string_view data) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw IoError(path.string() + ": is a directory");
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::string temp = (dir / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) throw IoError(path.string() + ": cannot create a temporary file in " + dir.string() + ": " + reason());

  auto fail = [&](const std::string& what) {
    const std::string why = reason();
    ::close(fd);
    ::unlink(temp.c_str());
    throw IoError(path.string() + ": " + what + ": " + why);
  };
  const char* p = data.data();
  std::size_t left = data.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, p, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      fail("write failed");
    }
    p += written;
    left -= static_cast<std::size_t>(written);
  }
  // Readable by others like any file the user writes (mkstemp makes it 0600).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  if (::fsync(fd) != 0 && errno != EINVAL) fail("sync failed");
  if (::close(fd) != 0) {
    const std::string why = reason();
    ::unlink(temp.c_str());
    throw IoError(path.string() + ": close failed: " + why);
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const std::string why = reason();
    ::unlink(temp.c_str());
    throw IoError(path.string() + ": cannot rename the temporary file into place: " + why);
  }
}

}  // namespace subdiv
