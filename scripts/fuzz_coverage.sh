#!/usr/bin/env bash
# Line coverage of the fuzz corpora (build-asan/corpus/<target>, grown by
# scripts/fuzz.sh): rebuilds the targets with clang's source-based coverage in
# build-fuzz-cov/, runs every corpus input once through its target and prints
# llvm-cov's summary for the source files that target is about.
# Usage: scripts/fuzz_coverage.sh [--targets "obj ply off pipeline"]
set -euo pipefail
cd "$(dirname "$0")/.."

targets="obj ply off pipeline"
if [ "${1:-}" = "--targets" ]; then targets="$2"; fi

bash scripts/setup.sh --fuzz
build_dir=build-fuzz-cov
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  CXX=clang++-14 cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -fprofile-instr-generate -fcoverage-mapping" \
    -DCMAKE_EXE_LINKER_FLAGS=-fprofile-instr-generate -DSUBDIV_BUILD_FUZZERS=ON -DSUBDIV_BUILD_TOOLS=OFF \
    -DSUBDIV_BUILD_TESTS=OFF -DSUBDIV_BUILD_EXAMPLES=OFF -DSUBDIV_BUILD_BENCHMARKS=OFF
fi
cmake --build "$build_dir" --parallel "$(nproc)"

for target in $targets; do
  corpus=build-asan/corpus/$target
  if [ ! -d "$corpus" ]; then echo "fuzz_coverage.sh: no corpus for $target (run scripts/fuzz.sh first)"; continue; fi
  case "$target" in
    obj) sources=(src/io/obj_reader.cpp src/io/obj_writer.cpp src/io/text_scan.h) ;;
    ply) sources=(src/io/ply_reader.cpp src/io/ply_writer.cpp) ;;
    off) sources=(src/io/off_reader.cpp src/io/off_writer.cpp) ;;
    pipeline) sources=(src/mesh/validation.cpp src/mesh/topology.cpp src/refine src/topology src/rules) ;;
  esac
  rm -f "$build_dir"/$target-*.profraw
  LLVM_PROFILE_FILE="$build_dir/$target-%p.profraw" "$build_dir/fuzz/fuzz_$target" -runs=0 "$corpus" >/dev/null 2>&1
  llvm-profdata-14 merge -sparse "$build_dir"/$target-*.profraw -o "$build_dir/$target.profdata"
  echo "== $target: $(ls "$corpus" | wc -l) corpus inputs"
  llvm-cov-14 report "$build_dir/fuzz/fuzz_$target" -instr-profile="$build_dir/$target.profdata" "${sources[@]}" \
    | awk 'NR == 1 || /^TOTAL/ || /\.(cpp|h) /'
done
