#pragma once
// Appending numbers to text output without locale or iostreams: doubles in
// the shortest form that reads back to the same value.

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "subdiv/core/types.h"

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

/// Appends "x y z", each coordinate as append_number() writes it.
inline void append_point(std::string& out, Vec3 p) {
  append_number(out, p.x);
  out += ' ';
  append_number(out, p.y);
  out += ' ';
  append_number(out, p.z);
}

/// Appends the lines of elements [0, count) to `out`, `append_line(text, i)`
/// writing element i's. Blocks of elements are formatted on up to `threads`
/// workers (0: all cores) and joined in order, so the text is the same for
/// every thread count: each block's text depends on its elements alone.
template <typename AppendLine>
void append_lines(std::string& out, std::size_t count, int threads, const AppendLine& append_line) {
  constexpr std::size_t kBlock = 16384;  // elements per block: ~0.5 MB of text
  if (threads == 1 || count <= kBlock) {
    for (std::size_t i = 0; i < count; ++i) append_line(out, i);
    return;
  }
  std::vector<std::string> blocks((count + kBlock - 1) / kBlock);
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t b = r.begin(); b < r.end(); ++b) {
        std::string& text = blocks[b];
        const std::size_t begin = b * kBlock, end = std::min(count, (b + 1) * kBlock);
        append_line(text, begin);
        // Room for the block at a quarter more than its first line's length
        // per line: one allocation instead of a doubling series of copies.
        text.reserve(text.size() * (end - begin) * 5 / 4);
        for (std::size_t i = begin + 1; i < end; ++i) append_line(text, i);
      }
    });
  });
  std::size_t size = out.size();
  for (const std::string& text : blocks) size += text.size();
  out.reserve(size);
  for (std::string& text : blocks) {
    out += text;
    std::string().swap(text);  // release each block once copied
  }
}

}  // namespace subdiv::detail
