#pragma once
/// \file
/// Typed exceptions. Every message says what went wrong and where (element
/// index, or file and line), so the CLI can print it as one line.

#include <cstdint>
#include <stdexcept>
#include <string>

namespace subdiv {

/// Base of every error the library throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The caller passed something unusable: bad arguments, a malformed mesh.
class InvalidInputError : public Error {
 public:
  using Error::Error;
};

/// A scheme's parameter lies outside its family's valid range; the message
/// names the scheme, the parameter and the range.
class ParameterError : public InvalidInputError {
 public:
  using InvalidInputError::InvalidInputError;
};

/// The mesh's connectivity cannot support the requested operation
/// (non-manifold where manifold is required, out-of-range indices...).
class TopologyError : public InvalidInputError {
 public:
  using InvalidInputError::InvalidInputError;
};

/// A file could not be opened, read or written.
class IoError : public Error {
 public:
  using Error::Error;
};

/// A file's contents are malformed. line() is 1-based; 0 when the problem
/// has no line (binary formats, a missing header).
class ParseError : public IoError {
 public:
  /// An error at \p line of \p path. The message (what()) is
  /// "path:line: what", with "<input>" for an empty path and no ":line"
  /// when \p line is 0.
  /// \param path the file's path as given to the reader; may be empty.
  /// \param line 1-based line number, 0 when unknown or not applicable.
  /// \param what the problem, without location.
  /// \throws std::bad_alloc if memory runs out.
  ParseError(const std::string& path, std::uint64_t line, const std::string& what);
  /// The file's path as given to the constructor (possibly empty).
  /// \return the path, valid as long as the error.
  const std::string& path() const noexcept { return path_; }
  /// The 1-based line of the problem.
  /// \return the line number, or 0 when the problem has no line.
  std::uint64_t line() const noexcept { return line_; }

 private:
  std::string path_;
  std::uint64_t line_;
};

}  // namespace subdiv
