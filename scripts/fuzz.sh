#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang with AddressSanitizer and
# UndefinedBehaviorSanitizer) and runs each one for a while.
#
# Usage: scripts/fuzz.sh [--seconds N | --runs N] [--max-len B] [--targets "obj ply off pipeline"]
#   --seconds N   per target, one after the other (default 60: CI's short run)
#   --runs N      instead: N executions per target (the long campaign)
#   --max-len B   the largest input tried, in bytes (default 16384)
#   --targets T   which targets (default all six); they run side by side,
#                 one per core
#
# Seeds are fuzz/seeds (PLY and OFF in every encoding the readers take), the
# small bundled meshes, tests/data and, where present, the shared meshes (../shared/data/meshes); each target's growing corpus lives in
# build-asan/corpus/<target>, so a long campaign can be resumed. A finding
# (crash, sanitizer report, broken invariant, timeout, out of memory) stops
# the run with a non-zero exit and leaves the input in build-asan/findings/:
# minimize it (fuzz_<target> -minimize_crash=1 INPUT), keep it under
# tests/data/fuzz/<target>/ and the test suite checks it on every build.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=60
runs=-1
max_len=16384
targets="obj ply off gltf stl pipeline"
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    --runs) runs="$2"; seconds=0; shift 2 ;;
    --max-len) max_len="$2"; shift 2 ;;
    --targets) targets="$2"; shift 2 ;;
    *) echo "fuzz.sh: unknown option $1 (see the comment at the top)" >&2; exit 2 ;;
  esac
done

bash scripts/setup.sh --fuzz

# The fuzz targets live in the sanitizer build (scripts/build.sh --sanitize
# builds them with the suite; here only they are built).
build_dir=build-asan
bash scripts/build.sh --fuzz

# Seeds: small files of each format (under 64 KiB keeps the runs fast).
seed_files() {  # extension
  # Only the folders that exist: find fails on a missing one, and under
  # pipefail that would end the script (../shared is absent outside the team's machines).
  local dirs=() dir
  for dir in fuzz/seeds data/meshes tests/data ../shared/data/meshes; do
    if [ -d "$dir" ]; then dirs+=("$dir"); fi
  done
  find "${dirs[@]}" -type f -iname "*.$1" -size -64k | sort
}
seeds="$(mktemp -d)"  # one per run, so that two runs side by side do not share it
trap 'rm -rf "$seeds"' EXIT
for format in obj ply off gltf glb stl; do
  target="$format"; [ "$format" = glb ] && target=gltf  # one target reads both glTF forms
  mkdir -p "$seeds/$target"
  seed_files "$format" | while read -r f; do cp "$f" "$seeds/$target/$(echo "${f#../}" | tr '/' '_')"; done
done
# The pipeline's first byte picks the format (byte % 3) and one or two levels ((byte / 3) odd).
mkdir -p "$seeds/pipeline"
selector=0
for format in obj ply off; do
  for f in "$seeds/$format"/*; do
    [ -e "$f" ] || continue
    for levels in 0 1; do
      byte=$((selector + 3 * levels))
      { printf "\\$(printf '%03o' "$byte")"; cat "$f"; } > "$seeds/pipeline/${levels}_$(basename "$f")"
    done
  done
  selector=$((selector + 1))
done
if [ ! -d ../shared/data/meshes ]; then
  echo "fuzz.sh: ../shared/data/meshes is absent: seeding from the bundled meshes only"
fi

findings="$build_dir/findings"
mkdir -p "$findings"
cat fuzz/dict/{obj,ply,off}.dict > "$seeds/pipeline.dict"
# One target's run: its summary in build-asan/fuzz_<target>.summary, and
# "found" in build-asan/fuzz_<target>.status where it found something.
run_target() {
  local target=$1 corpus="$build_dir/corpus/$1" log="$build_dir/fuzz_$1.log" dict
  mkdir -p "$corpus" "$findings/$target"
  case "$target" in
    pipeline) dict="$seeds/pipeline.dict" ;;
    *) dict="fuzz/dict/$target.dict" ;;
  esac
  if ! "$build_dir/fuzz/fuzz_$target" "$corpus" "$seeds/$target" -dict="$dict" \
        -max_total_time="$seconds" -runs="$runs" -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" \
        -print_final_stats=1 \
        -artifact_prefix="$findings/$target/" > "$log" 2>&1; then
    { echo "fuzz.sh: FINDING in $target: see $log and $findings/$target/"; tail -40 "$log"; } > "$build_dir/fuzz_$target.summary"
    echo found > "$build_dir/fuzz_$target.status"
    return 0
  fi
  grep -E "^stat::|DONE|cov: " "$log" | tail -7 > "$build_dir/fuzz_$target.summary" || true
}
# The targets run side by side, one per core; their summaries follow.
budget="${seconds} s"; [ "$runs" -ge 0 ] && budget="$runs runs"
for target in $targets; do
  rm -f "$build_dir/fuzz_$target.status" "$build_dir/fuzz_$target.summary"
  while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do wait -n || true; done
  echo "fuzz.sh: $target for $budget ($(ls "$seeds/$target" | wc -l) seeds)"
  run_target "$target" &
done
wait
status=0
for target in $targets; do
  cat "$build_dir/fuzz_$target.summary" 2>/dev/null || echo "fuzz.sh: $target left no summary"
  if [ -f "$build_dir/fuzz_$target.status" ] || [ ! -f "$build_dir/fuzz_$target.summary" ]; then status=1; fi
done
exit $status
