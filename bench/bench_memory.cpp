// This machine's memory bandwidth on one core, for the roofline of
// refinement (BENCHMARKS.md): how many bytes a second a loop can write to
// memory that is already mapped (write), and copy from one buffer to
// another (read + write). 512 MiB buffers, far past every cache.

#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace {

constexpr std::size_t kBytes = std::size_t{512} << 20;

void BM_Memory_Write(benchmark::State& state) {
  std::vector<char> buffer(kBytes, 1);  // touched: no page faults in the loop
  char value = 0;
  for (auto _ : state) {
    std::memset(buffer.data(), ++value, kBytes);
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(kBytes));
}
BENCHMARK(BM_Memory_Write)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Memory_Copy(benchmark::State& state) {
  std::vector<char> from(kBytes, 1), to(kBytes, 2);
  for (auto _ : state) {
    std::memcpy(to.data(), from.data(), kBytes);
    benchmark::ClobberMemory();
  }
  // Bytes moved: each one read once and written once.
  state.SetBytesProcessed(2 * static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(kBytes));
}
BENCHMARK(BM_Memory_Copy)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
