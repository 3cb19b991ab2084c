#pragma once
// Appending numbers to text output without locale or iostreams: doubles in
// the shortest form that reads back to the same value.

#include <charconv>
#include <string>

namespace subdiv::detail {

inline void append_number(std::string& out, double value) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, result.ptr);
}

inline void append_number(std::string& out, long long value) {
  char buf[24];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, result.ptr);
}

inline void append_number(std::string& out, int value) { append_number(out, static_cast<long long>(value)); }

}  // namespace subdiv::detail
