#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite.
# Usage: scripts/test.sh [--sanitize]   (--sanitize: under ASan + UBSan, less
# the long numerical sweeps of tests/sanitize_skip.txt)
set -euo pipefail
cd "$(dirname "$0")/.."

setup=(--browser)
if [ "${1:-}" = "--sanitize" ]; then setup+=(--fuzz); fi  # clang and its sanitizer runtimes
bash scripts/setup.sh "${setup[@]}"
# The browser test's driver (playwright-core) and the three.js the page
# inlines, as viewer/package-lock.json pins them.
if [ ! -f viewer/node_modules/.package-lock.json ] || [ viewer/package-lock.json -nt viewer/node_modules/.package-lock.json ]; then
  (cd viewer && npm ci --ignore-scripts --no-audit --no-fund)
fi
bash scripts/build.sh "$@"
build_dir=build
if [ "${1:-}" = "--sanitize" ]; then build_dir=build-asan; fi
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
skip=()
if [ "$build_dir" = build-asan ]; then
  # The long numerical sweeps run in the release build only (the list says why).
  skip=(-E "^($(grep -v '^#' tests/sanitize_skip.txt | paste -sd'|'))\$")
fi
ctest --test-dir "$build_dir" --output-on-failure --parallel "$(nproc)" "${skip[@]}"
