#!/usr/bin/env bash
# Builds the API reference into BUILD/docs/api/html (BUILD defaults to build/)
# and checks it: Doxygen fails on any warning (an undocumented public symbol,
# parameter or return value, a malformed command), then
# scripts/check_api_docs.py fails on a public function that neither is
# noexcept nor documents what it throws.
# Usage: scripts/docs.sh [BUILD]      then open BUILD/docs/api/html/index.html
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"

bash scripts/setup.sh --docs
generator=()
if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
# Configuring (again) finds doxygen even when the build was configured first
# without it, and generates subdiv/version.h, which the reference includes.
cmake -S . -B "$build" "${generator[@]}" >/dev/null
rm -rf "$build/docs/api"
cmake --build "$build" --target subdiv_docs
python3 scripts/check_api_docs.py "$build/docs/api/xml"
echo "docs.sh: $build/docs/api/html/index.html"
