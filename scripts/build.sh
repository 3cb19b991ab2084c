#!/usr/bin/env bash
# Configures and builds subdiv. Usage: scripts/build.sh [--sanitize | --tool] [extra cmake args]
#   default:     build/       Release, tests + examples + benchmarks
#   --tool:      build/       Release, the subdiv program and the Python module (the demo: no tests or
#                             benchmarks compiled)
#   --sanitize:  build-asan/  -O1 with line tables, AddressSanitizer + UBSan, tests only
# With CI=true, compiler warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=build
targets=()
args=(-DCMAKE_BUILD_TYPE=Release -DSUBDIV_BUILD_TESTS=ON -DSUBDIV_BUILD_EXAMPLES=ON -DSUBDIV_BUILD_BENCHMARKS=ON)
if [ "${1:-}" = "--tool" ]; then
  shift
  targets=(--target subdiv subdiv_python)
elif [ "${1:-}" = "--sanitize" ]; then
  shift
  build_dir=build-asan
  # -O1 -g1: line tables for the sanitizers' stack traces at half the
  # compile time of -O2 -g (the sanitizer build dominates CI).
  args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" -DSUBDIV_SANITIZE=ON
        -DSUBDIV_BUILD_TESTS=ON -DSUBDIV_BUILD_EXAMPLES=OFF -DSUBDIV_BUILD_BENCHMARKS=OFF)
fi
if [ "${CI:-}" = "true" ]; then args+=(-DSUBDIV_WARNINGS_AS_ERRORS=ON); fi

generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S . -B "$build_dir" "${generator[@]}" "${args[@]}" "$@"
else
  cmake -S . -B "$build_dir" "${args[@]}" "$@" >/dev/null
fi
cmake --build "$build_dir" --parallel "$(nproc)" "${targets[@]}"
