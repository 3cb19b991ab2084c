#!/usr/bin/env bash
# Configures and builds subdiv. Usage: scripts/build.sh [--sanitize | --fuzz | --tool] [extra cmake args]
#   default:     build/       Release, tests + examples + benchmarks
#   --tool:      build/       Release, the subdiv program and the Python module (the demo: no tests or
#                             benchmarks compiled)
#   --sanitize:  build-asan/  clang, -O1 with line tables: the library and programs under AddressSanitizer
#                             + UBSan (and libFuzzer's coverage), the tests, and the fuzz targets
#   --fuzz:      build-asan/  the same build, the fuzz targets only (scripts/fuzz.sh)
# With CI=true, compiler warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=build
targets=()
compiler=()
args=(-DCMAKE_BUILD_TYPE=Release -DSUBDIV_BUILD_TESTS=ON -DSUBDIV_BUILD_EXAMPLES=ON -DSUBDIV_BUILD_BENCHMARKS=ON)
mode="${1:-}"
if [ "$mode" = "--tool" ]; then
  shift
  targets=(--target subdiv subdiv_python)
elif [ "$mode" = "--sanitize" ] || [ "$mode" = "--fuzz" ]; then
  shift
  build_dir=build-asan
  # One instrumented build for the suite and the fuzzers: clang, which
  # libFuzzer needs, also compiles the instrumented units faster than GCC.
  # -O1 -g1: line tables for the sanitizers' stack traces at half the
  # compile time of -O2 -g (the instrumented build dominates CI).
  compiler=(-DCMAKE_CXX_COMPILER=clang++-14)
  args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" -DSUBDIV_SANITIZE=ON
        -DSUBDIV_BUILD_FUZZERS=ON -DSUBDIV_BUILD_TESTS=ON -DSUBDIV_BUILD_EXAMPLES=OFF -DSUBDIV_BUILD_BENCHMARKS=OFF)
  if [ "$mode" = "--fuzz" ]; then
    targets=(--target fuzz_obj fuzz_ply fuzz_off fuzz_gltf fuzz_stl fuzz_pipeline)
  fi
  # CMake cannot switch an existing build directory's compiler: one
  # configured with another is a build product, made again.
  if [ -f "$build_dir/CMakeCache.txt" ] && ! grep -q "^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++-14$" "$build_dir/CMakeCache.txt"; then
    echo "build.sh: $build_dir/ was configured with another compiler: configuring it again with clang++-14"
    rm -rf "$build_dir"
  fi
fi
if [ "${CI:-}" = "true" ]; then args+=(-DSUBDIV_WARNINGS_AS_ERRORS=ON); fi

generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S . -B "$build_dir" "${generator[@]}" "${compiler[@]}" "${args[@]}" "$@"
else
  cmake -S . -B "$build_dir" "${args[@]}" "$@" >/dev/null
fi
cmake --build "$build_dir" --parallel "$(nproc)" "${targets[@]}"
