#pragma once
// A counting sort's two passes (count the items per key, then place each
// item in its key's bucket) in parallel, with the serial result: the keys
// are split into one range per part, and each part scans every item in
// order, keeping those whose key falls in its range. Every bucket is then
// filled in item order, whatever the number of threads. Scanning all items
// once per part is cheap next to the scattered writes it shares out; the
// parts are capped so that it stays so.

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <type_traits>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "subdiv/core/types.h"

namespace subdiv::detail {

// for_each_key(item, emit) calls emit(key) for each of the item's keys
// (any number, in a fixed order), keys in [0, keys).
class ParallelBuckets {
 public:
  explicit ParallelBuckets(Index keys)
      : keys_(keys), parts_(std::clamp(tbb::this_task_arena::max_concurrency(), 1, 8)) {}

  // offsets[k] .. offsets[k + 1]: key k's bucket; offsets has keys + 1 entries.
  template <typename ForEachKey>
  void count(Index items, ForEachKey&& for_each_key, std::vector<Index>& offsets) const {
    offsets.assign(static_cast<std::size_t>(keys_) + 1, 0);
    for_each_part([&](Index low, Index high, auto every_key) {
      for (Index i = 0; i < items; ++i)
        for_each_key(i, [&](Index key) {
          if (every_key || (key >= low && key < high)) ++offsets[static_cast<std::size_t>(key) + 1];
        });
    });
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  }

  // place(slot, item) for each (item, key) pair, slot in key's bucket, items
  // of one bucket in increasing order.
  template <typename ForEachKey, typename Place>
  void fill(Index items, ForEachKey&& for_each_key, const std::vector<Index>& offsets, Place&& place) const {
    std::vector<Index> next(offsets.begin(), offsets.end() - 1);
    for_each_part([&](Index low, Index high, auto every_key) {
      for (Index i = 0; i < items; ++i)
        for_each_key(i, [&](Index key) {
          if (every_key || (key >= low && key < high)) place(next[static_cast<std::size_t>(key)]++, i);
        });
    });
  }

 private:
  // body(low, high, every_key): the part's keys, and whether they are all
  // keys (one part: the serial loop, without the range test).
  template <typename Body>
  void for_each_part(Body&& body) const {
    if (parts_ == 1) return body(Index{0}, keys_, std::true_type{});
    tbb::parallel_for(0, parts_, [&](int p) {
      const auto low = static_cast<Index>(static_cast<std::int64_t>(keys_) * p / parts_);
      const auto high = static_cast<Index>(static_cast<std::int64_t>(keys_) * (p + 1) / parts_);
      body(low, high, std::false_type{});
    });
  }

  Index keys_;
  int parts_;
};

}  // namespace subdiv::detail
