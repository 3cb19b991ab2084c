#pragma once
// Small helpers for the program's messages.

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>
#include <string>
#include <string_view>

namespace subdiv::cli {

/// "1 vertex", "8 vertices": the count with the noun in the right number.
inline std::string count_of(std::int64_t n, std::string_view one, std::string_view many) {
  return std::to_string(n) + " " + std::string(n == 1 ? one : many);
}

/// The candidate closest to `typed` by edit distance, when it is close
/// enough to be a typo (at most 2 edits, and fewer than half the letters),
/// for "did you mean ...?"; empty otherwise.
inline std::string closest_name(std::string_view typed, std::span<const std::string> candidates) {
  std::string best;
  std::size_t best_distance = 3;
  for (const std::string& c : candidates) {
    // Levenshtein distance, one row at a time.
    std::vector<std::size_t> row(c.size() + 1);
    for (std::size_t j = 0; j <= c.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= typed.size(); ++i) {
      std::size_t diagonal = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= c.size(); ++j) {
        const std::size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (typed[i - 1] == c[j - 1] ? 0 : 1)});
        diagonal = up;
      }
    }
    const std::size_t d = row[c.size()];
    if (d < best_distance && 2 * d < std::max(typed.size(), c.size())) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

}  // namespace subdiv::cli
