#!/usr/bin/env bash
# Configures and builds subdiv. Usage: scripts/build.sh [--sanitize] [extra cmake args]
#   default:     build/       Release, tests + examples + benchmarks
#   --sanitize:  build-asan/  Debug info, AddressSanitizer + UBSan, tests only
# With CI=true, compiler warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=build
args=(-DCMAKE_BUILD_TYPE=Release -DSUBDIV_BUILD_TESTS=ON -DSUBDIV_BUILD_EXAMPLES=ON -DSUBDIV_BUILD_BENCHMARKS=ON)
if [ "${1:-}" = "--sanitize" ]; then
  shift
  build_dir=build-asan
  args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DSUBDIV_SANITIZE=ON -DSUBDIV_BUILD_TESTS=ON
        -DSUBDIV_BUILD_EXAMPLES=OFF -DSUBDIV_BUILD_BENCHMARKS=OFF)
fi
if [ "${CI:-}" = "true" ]; then args+=(-DSUBDIV_WARNINGS_AS_ERRORS=ON); fi

generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S . -B "$build_dir" "${generator[@]}" "${args[@]}" "$@"
else
  cmake -S . -B "$build_dir" "${args[@]}" "$@" >/dev/null
fi
cmake --build "$build_dir" --parallel "$(nproc)"
