#!/usr/bin/env bash
# Runs the subdiv program the way a user does and checks exit codes, output
# and the one-line error contract. Usage: cli_test.sh TESTS_DIR PROJECT_DIR
# with $SUBDIV pointing at the program.
set -uo pipefail

tests_dir=$1
project_dir=$2
data=$tests_dir/data
meshes=$project_dir/data/meshes
shared=$project_dir/../shared/data/meshes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

passed=0
failed=0
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
pass() { passed=$((passed + 1)); }

# run NAME EXPECTED_EXIT ARGS...: runs subdiv, keeps stdout/stderr in $work.
run() {
  local name=$1 expected=$2
  shift 2
  timeout 20 "$SUBDIV" "$@" >"$work/out" 2>"$work/err"
  local code=$?
  if [ "$code" -ne "$expected" ]; then
    fail "$name: exit $code, expected $expected; stderr: $(head -c 300 "$work/err")"
    return 1
  fi
  pass
}
stdout_has() { grep -qF -- "$2" "$work/out" && pass || fail "$1: stdout lacks '$2'"; }
stderr_has() { grep -qF -- "$2" "$work/err" && pass || fail "$1: stderr lacks '$2': $(cat "$work/err")"; }
stderr_one_line() {
  local n
  n=$(wc -l <"$work/err")
  [ "$n" -eq 1 ] && pass || fail "$1: stderr has $n lines, expected exactly one: $(cat "$work/err")"
}

run help 0 --help && stdout_has help "subdiv info data/meshes/cube.obj"
run info-help 0 info --help && stdout_has info-help "Example:"
run convert-help 0 convert --help && stdout_has convert-help "Example:"
run version 0 --version && stdout_has version "subdiv 0.1.0"

run info-cube 0 info "$meshes/cube.obj"
stdout_has info-cube "vertices        8"
stdout_has info-cube "face sizes      4:6"
stdout_has info-cube "valences        3:8"
stdout_has info-cube "validation      ok"
run info-spot 0 info "$meshes/spot_control_mesh.obj" && stdout_has info-spot "uv (face-varying, 2 components"
run info-elephant 0 info "$meshes/elephant.obj" && stdout_has info-elephant "euler char.     -4"

run info-nonmanifold 1 info "$data/nonmanifold_edge.obj"
stderr_one_line info-nonmanifold
stderr_has info-nonmanifold "nonmanifold_edge.obj:9: edge 0-1 is shared by 3 faces"
stdout_has info-nonmanifold "non-manifold edge"
run info-isolated 0 info "$data/isolated_vertex.obj" && stdout_has info-isolated "0 errors, 1 warnings"

for bad in zero_index.obj index_out_of_range.obj truncated_vertex.obj garbage.obj lying_header.ply \
           index_out_of_range.off missing_file.obj; do
  run "bad-$bad" 1 info "$data/$bad" && stderr_one_line "bad-$bad"
done
run bad-extension 1 info "$data/README.md" && stderr_has bad-extension "unknown mesh format"
run bad-command 1 frobnicate && stderr_one_line bad-command
run missing-argument 1 info && stderr_one_line missing-argument
run no-command 1 && stderr_one_line no-command

# convert: formats round-trip, the input is never touched, no partial output.
cp "$meshes/spot_control_mesh.obj" "$work/in.obj"
before=$(sha256sum "$work/in.obj")
run convert-ply 0 convert "$work/in.obj" "$work/out.ply"
stderr_has convert-ply "face-varying channel 'uv'"
run convert-off 0 convert "$work/out.ply" "$work/out.off" --validate
run convert-back 0 convert "$work/out.off" "$work/back.obj"
run info-back 0 info "$work/back.obj" && stdout_has info-back "faces           180"
run convert-ascii 0 convert "$work/in.obj" "$work/ascii.ply" --ascii
head -c 200 "$work/ascii.ply" | grep -q "format ascii 1.0" && pass || fail "convert --ascii: not ASCII PLY"
run convert-self 1 convert "$work/in.obj" "$work/in.obj" && stderr_has convert-self "output is the input file"
run convert-badext 1 convert "$work/in.obj" "$work/out.stl"
[ ! -e "$work/out.stl" ] && pass || fail "convert-badext left a file"
run convert-invalid 1 convert "$data/nonmanifold_edge.obj" "$work/nm.obj" --validate
[ ! -e "$work/nm.obj" ] && pass || fail "convert --validate wrote an invalid mesh"
run convert-nodir 1 convert "$work/in.obj" "$work/no/such/dir/x.obj" && stderr_one_line convert-nodir
[ "$(sha256sum "$work/in.obj")" = "$before" ] && pass || fail "the input file changed"
leftovers=$(find "$work" -name '*.tmp-*' | wc -l)
[ "$leftovers" -eq 0 ] && pass || fail "temporary files left behind"

# refine and schemes
run schemes 0 schemes && stdout_has schemes "catmull-clark" && stdout_has schemes "loop-warren"
run refine-cc 0 refine "$meshes/cube.obj" -s catmull-clark -l 2 -o "$work/cc.obj"
stdout_has refine-cc "wrote $work/cc.obj: 98 vertices, 96 faces"
run refine-cc-info 0 info "$work/cc.obj" && stdout_has refine-cc-info "valences        3:8  4:90"
run refine-loop-quads 1 refine "$meshes/cube.obj" -s loop -o "$work/loop.obj"
stderr_one_line refine-loop-quads && stderr_has refine-loop-quads "needs a triangle mesh"
run refine-loop-tri 0 refine "$meshes/cube.obj" -s loop --triangulate -l 3 -o "$work/loop.ply" --stats
stdout_has refine-loop-tri "level 3: 386 vertices, 768 faces"
run refine-unknown 1 refine "$meshes/cube.obj" -s butterfly-x -o "$work/x.obj" && stderr_has refine-unknown "unknown scheme"
run refine-nonmanifold 1 refine "$data/nonmanifold_edge.obj" -o "$work/nm.obj" && stderr_has refine-nonmanifold "--allow-non-manifold"
run refine-allow 0 refine "$data/nonmanifold_edge.obj" -o "$work/nm.obj" --allow-non-manifold
run refine-t1 0 refine "$meshes/spot_control_mesh.obj" -l 3 -o "$work/t1.ply" --threads 1
run refine-t2 0 refine "$meshes/spot_control_mesh.obj" -l 3 -o "$work/t2.ply" --threads 2
cmp -s "$work/t1.ply" "$work/t2.ply" && pass || fail "refine output depends on the thread count"
run refine-self 1 refine "$work/cc.obj" -o "$work/cc.obj" && stderr_has refine-self "output is the input file"
run refine-levels 1 refine "$meshes/cube.obj" -l 40 -o "$work/x.obj" && stderr_one_line refine-levels

# Every shared mesh: exit 0 or 1, never a crash, and a failure is one line.
if [ -d "$shared" ]; then
  while IFS= read -r -d '' mesh; do
    timeout 20 "$SUBDIV" info "$mesh" >"$work/out" 2>"$work/err"
    code=$?
    if [ "$code" -ne 0 ] && [ "$code" -ne 1 ]; then
      fail "info $mesh: exit $code"
    elif [ "$code" -eq 1 ] && [ "$(wc -l <"$work/err")" -ne 1 ]; then
      fail "info $mesh: exit 1 without exactly one stderr line"
    else
      pass
    fi
  done < <(find "$shared" -name '*.obj' -print0 | sort -z)
else
  echo "note: $shared not found; shared-mesh checks skipped"
fi

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
