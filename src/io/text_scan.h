#pragma once
// A cursor over one line of text: whitespace-separated tokens, integers and
// doubles (fast_float), without allocation.

#include <charconv>
#include <cstring>
#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include <fast_float/fast_float.h>

namespace subdiv::detail {

/// At most 40 characters of `s` for an error message, unprintable bytes as '?'.
inline std::string printable(std::string_view s) {
  std::string out(s.substr(0, 40));
  for (char& c : out)
    if (c < ' ' || c > '~') c = '?';
  if (s.size() > 40) out += "...";
  return out;
}

/// Line numbers are stored in 32 bits; later lines saturate.
inline std::uint32_t clamp_line(std::uint64_t line) {
  return static_cast<std::uint32_t>(std::min<std::uint64_t>(line, std::numeric_limits<std::uint32_t>::max()));
}

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

class LineScanner {
 public:
  LineScanner(const char* begin, const char* end) : p_(begin), end_(end) {}
  explicit LineScanner(std::string_view s) : p_(s.data()), end_(s.data() + s.size()) {}

  void skip_spaces() {
    while (p_ != end_ && is_space(*p_)) ++p_;
  }
  bool at_end() {
    skip_spaces();
    return p_ == end_;
  }
  /// The next whitespace-delimited token ("" at the end of the line).
  std::string_view token() {
    skip_spaces();
    const char* start = p_;
    while (p_ != end_ && !is_space(*p_)) ++p_;
    return {start, static_cast<std::size_t>(p_ - start)};
  }
  /// Parses a double token; false (cursor unchanged past spaces) if the next
  /// token is not exactly one number.
  bool number(double& value) {
    skip_spaces();
    const char* start = p_;
    if (start != end_ && *start == '+') ++start;  // fast_float rejects a leading '+'
    const auto result = fast_float::from_chars(start, end_, value);
    if (result.ec != std::errc() || (result.ptr != end_ && !is_space(*result.ptr))) return false;
    p_ = result.ptr;
    return true;
  }
  /// Parses a decimal integer that may be followed by `stop` (e.g. '/') as
  /// well as by whitespace. False on overflow or if no digits are there.
  /// Hand-written: std::from_chars was a quarter of OBJ parsing time.
  bool integer(long long& value, char stop = ' ') {
    skip_spaces();
    const char* q = p_;
    bool negative = false;
    if (q != end_ && (*q == '-' || *q == '+')) negative = *q++ == '-';
    const char* digits = q;
    unsigned long long magnitude = 0;
    while (q != end_ && static_cast<unsigned char>(*q - '0') < 10) {
      if (q - digits == 19) return false;  // 19 digits fit in 64 unsigned bits; refuse longer
      magnitude = magnitude * 10 + static_cast<unsigned>(*q - '0');
      ++q;
    }
    if (q == digits) return false;
    if (q != end_ && !is_space(*q) && *q != stop) return false;
    constexpr auto max = static_cast<unsigned long long>(std::numeric_limits<long long>::max());
    if (magnitude > max + (negative ? 1 : 0)) return false;
    value = negative && magnitude == max + 1 ? std::numeric_limits<long long>::min()
          : negative ? -static_cast<long long>(magnitude) : static_cast<long long>(magnitude);
    p_ = q;
    return true;
  }
  bool consume(char c) {
    if (p_ != end_ && *p_ == c) {
      ++p_;
      return true;
    }
    return false;
  }
  char peek() const { return p_ != end_ ? *p_ : '\0'; }
  const char* position() const { return p_; }
  std::string_view rest() const { return {p_, static_cast<std::size_t>(end_ - p_)}; }

 private:
  const char* p_;
  const char* end_;
};

/// Iterates over the lines of a buffer ('\n' separated, '\r' left to the
/// scanner, which treats it as space), counting them from 1.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}
  bool next(std::string_view& line) {
    if (p_ == end_) return false;
    const char* nl = static_cast<const char*>(std::memchr(p_, '\n', static_cast<std::size_t>(end_ - p_)));
    const char* stop = nl ? nl : end_;
    line = {p_, static_cast<std::size_t>(stop - p_)};
    p_ = nl ? nl + 1 : end_;
    ++line_;
    return true;
  }
  std::uint64_t line_number() const { return line_; }
  std::size_t bytes_left() const { return static_cast<std::size_t>(end_ - p_); }

 private:
  const char* p_;
  const char* end_;
  std::uint64_t line_ = 0;
};

}  // namespace subdiv::detail
