// libFuzzer's entry point for the stl checks (fuzz_checks.h).
#include <cstddef>
#include <cstdint>

#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  subdiv::fuzz::check_stl_input(data, size);
  return 0;
}
