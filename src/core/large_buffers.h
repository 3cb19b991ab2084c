#pragma once
// Sizing the big per-level arrays. A refined level is hundreds of megabytes
// written once right after allocation, and with 4 KiB pages the kernel's
// page-fault handling costs more than the refinement arithmetic (400 MB:
// 250 ms touched with 4 KiB pages, 67 ms with transparent huge pages, on the
// development VM). So large vectors ask for huge pages before their first
// touch. Where the kernel offers none (or on other systems) this is a plain
// assign.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include <tbb/parallel_for.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace subdiv::detail {

inline constexpr std::size_t kHugePage = std::size_t{2} << 20;

/// Marks the whole 2 MiB pages inside [data, data + bytes) for transparent
/// huge pages. Only a hint: failures are ignored.
inline void advise_huge_pages([[maybe_unused]] void* data, [[maybe_unused]] std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHugePage - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#endif
}

/// Faults in the pages of [data, data + bytes) in parallel, so that the
/// kernel's zeroing of new pages is spread over the threads instead of
/// happening in the serial first write. Only a hint: failures are ignored.
inline void populate_in_parallel([[maybe_unused]] void* data, [[maybe_unused]] std::size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  const auto begin = reinterpret_cast<std::uintptr_t>(data) & ~(std::uintptr_t{4095});
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(data) + bytes;
  const std::uintptr_t chunks = (end - begin + kHugePage - 1) / kHugePage;
  tbb::parallel_for(std::uintptr_t{0}, chunks, [&](std::uintptr_t i) {
    const std::uintptr_t from = begin + i * kHugePage;
    const std::uintptr_t to = std::min(end, from + kHugePage);
    madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
  });
#endif
}

/// v.reserve(n), with huge pages for a large new allocation.
template <typename T>
void reserve_large(std::vector<T>& v, std::size_t n) {
  if (n <= v.capacity()) return;
  if (n * sizeof(T) < 2 * kHugePage) return v.reserve(n);
  std::vector<T> bigger;
  bigger.reserve(n);
  advise_huge_pages(bigger.data(), n * sizeof(T));
  bigger.insert(bigger.end(), v.begin(), v.end());
  v.swap(bigger);
}

/// v = n copies of value, with huge pages for large new allocations.
template <typename T>
void assign_large(std::vector<T>& v, std::size_t n, const std::type_identity_t<T>& value = T{}) {
  if (n * sizeof(T) >= 2 * kHugePage && v.capacity() < n) {
    std::vector<T>().swap(v);  // nothing to keep: allocate fresh, untouched memory
    v.reserve(n);
    advise_huge_pages(v.data(), n * sizeof(T));
    populate_in_parallel(v.data(), n * sizeof(T));
  }
  v.assign(n, value);
}

}  // namespace subdiv::detail
