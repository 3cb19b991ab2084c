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
stdout_has schemes "butterfly" && stdout_has schemes "modified-butterfly"
run refine-cc 0 refine "$meshes/cube.obj" -s catmull-clark -l 2 -o "$work/cc.obj"
stdout_has refine-cc "wrote $work/cc.obj: 98 vertices, 96 faces"
run refine-cc-info 0 info "$work/cc.obj" && stdout_has refine-cc-info "valences        3:8  4:90"
run refine-loop-quads 1 refine "$meshes/cube.obj" -s loop -o "$work/loop.obj"
stderr_one_line refine-loop-quads && stderr_has refine-loop-quads "needs a triangle mesh"
run refine-loop-tri 0 refine "$meshes/cube.obj" -s loop --triangulate -l 3 -o "$work/loop.ply" --stats
stdout_has refine-loop-tri "level 3: 386 vertices, 768 faces"
for scheme in butterfly modified-butterfly; do
  run "refine-$scheme" 0 refine "$meshes/cube.obj" -s "$scheme" --triangulate -l 2 -o "$work/$scheme.obj" --stats
  stdout_has "refine-$scheme" "level 2: 98 vertices, 192 faces"
  run "refine-$scheme-quads" 1 refine "$meshes/cube.obj" -s "$scheme" -o "$work/$scheme.obj"
  stderr_one_line "refine-$scheme-quads" && stderr_has "refine-$scheme-quads" "needs a triangle mesh"
done
run refine-doo-sabin 0 refine "$meshes/cube.obj" -s doo-sabin -l 2 -o "$work/ds.obj" --stats
stdout_has refine-doo-sabin "level 1: 24 vertices, 26 faces" && stdout_has refine-doo-sabin "level 2: 96 vertices, 98 faces"
run refine-doo-sabin-info 0 info "$work/ds.obj" && stdout_has refine-doo-sabin-info "validation      ok"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nt crease 2/1/0 0 1 3\n' > "$work/ds_crease.obj"
run refine-doo-sabin-crease 1 refine "$work/ds_crease.obj" -s doo-sabin -o "$work/x.obj"
stderr_one_line refine-doo-sabin-crease && stderr_has refine-doo-sabin-crease "ds_crease.obj:6: doo-sabin has no crease rules"
run limit-doo-sabin 1 limit "$meshes/cube.obj" -s doo-sabin -o "$work/x.obj" && stderr_one_line limit-doo-sabin
run analyze-doo-sabin 0 analyze -s doo-sabin -k 3..8 && stdout_has analyze-doo-sabin "extraordinary face of k sides"
for k in 3 5 8; do
  grep -qE "^interior k=$k +$((4 * k)) +1 +0.500000 +0.500000 +0.250000 .* C1 " "$work/out" && pass ||
    fail "analyze doo-sabin: no C1 row with 1/2, 1/2, 1/4 for k=$k"
done
run analyze-doo-sabin-boundary 1 analyze -s doo-sabin --boundary -k 2 && stderr_one_line analyze-doo-sabin-boundary &&
  stderr_has analyze-doo-sabin-boundary "extraordinary faces only"
run adaptive-doo-sabin 1 adaptive "$meshes/cube.obj" -s doo-sabin --eps 0.1 -o "$work/x.obj" && stderr_one_line adaptive-doo-sabin
run refine-midedge 0 refine "$meshes/cube.obj" -s midedge -l 2 -o "$work/me.obj" --stats
stdout_has refine-midedge "level 1: 12 vertices, 14 faces" && stdout_has refine-midedge "level 2: 24 vertices, 26 faces"
run refine-midedge-open 1 refine "$meshes/l_shape.obj" -s midedge -o "$work/x.obj" && stderr_one_line refine-midedge-open
run analyze-midedge 1 analyze -s midedge -k 4 && stderr_one_line analyze-midedge && stderr_has analyze-midedge "every two steps"
run refine-unknown 1 refine "$meshes/cube.obj" -s butterfly-x -o "$work/x.obj" && stderr_has refine-unknown "unknown scheme"
run refine-nonmanifold 1 refine "$data/nonmanifold_edge.obj" -o "$work/nm.obj" && stderr_has refine-nonmanifold "--allow-non-manifold"
run refine-allow 0 refine "$data/nonmanifold_edge.obj" -o "$work/nm.obj" --allow-non-manifold
run refine-t1 0 refine "$meshes/spot_control_mesh.obj" -l 3 -o "$work/t1.ply" --threads 1
run refine-t2 0 refine "$meshes/spot_control_mesh.obj" -l 3 -o "$work/t2.ply" --threads 2
cmp -s "$work/t1.ply" "$work/t2.ply" && pass || fail "refine output depends on the thread count"
run refine-self 1 refine "$work/cc.obj" -o "$work/cc.obj" && stderr_has refine-self "output is the input file"
run refine-levels 1 refine "$meshes/cube.obj" -l 40 -o "$work/x.obj" && stderr_one_line refine-levels

# Chaikin creasing: a 4 x 2 grid with the crease 6 - 7 - 8 of sharpness 2 and 3;
# at vertex 7 the halves get 3/4 * 2 + 1/4 * 3 - 1 = 1.25 and 1.75.
{
  for j in 0 1 2; do for i in 0 1 2 3 4; do echo "v $i $j 0"; done; done
  for j in 0 1; do for i in 0 1 2 3; do
    a=$((j * 5 + i + 1)); echo "f $a $((a + 1)) $((a + 6)) $((a + 5))"
  done; done
  echo "t crease 2/1/0 6 7 2"
  echo "t crease 2/1/0 7 8 3"
  echo "t creasemethod 0/0/1 chaikin"
} >"$work/chaikin.obj"
run refine-chaikin 0 refine "$work/chaikin.obj" -o "$work/chaikin_1.obj"
grep -q '^t crease 2/1/0 [0-9]* [0-9]* 1.25$' "$work/chaikin_1.obj" &&
  grep -q '^t crease 2/1/0 [0-9]* [0-9]* 1.75$' "$work/chaikin_1.obj" && pass ||
  fail "refine: Chaikin halves 1.25 and 1.75 not in the refined tags"
run refine-chaikin-uniform 0 refine "$work/chaikin.obj" --crease-method uniform -o "$work/uniform_1.obj"
grep -q ' 1.25$' "$work/uniform_1.obj" && fail "refine --crease-method uniform: Chaikin sharpness" || pass
grep -q '^t creasemethod 0/0/1 normal$' "$work/uniform_1.obj" && pass ||
  fail "refine --crease-method uniform: the output's tag does not name the method used"
run refine-crease-method-bad 1 refine "$work/chaikin.obj" --crease-method normal -o "$work/x.obj" &&
  stderr_one_line refine-crease-method-bad
run limit-chaikin 0 limit "$work/chaikin.obj" -o "$work/chaikin_limit.obj"

# analyze: tables, JSON, plots and the error contract.
run analyze-help 0 analyze --help && stdout_has analyze-help "Example" && stdout_has analyze-help "tangent masks"
for scheme in loop catmull-clark; do
  run "analyze-$scheme" 0 analyze -s "$scheme" -k 3..8 && stdout_has "analyze-$scheme" "lambda_1^2"
  for k in 3 4 5 6; do
    grep -qE "^interior k=$k .* C1 " "$work/out" && pass || fail "analyze $scheme: no C1 row for k=$k"
  done
done
run analyze-butterfly 0 analyze -s butterfly -k 3..10
grep -qE "^interior k=3 .* inconclusive" "$work/out" && grep -qE "^interior k=9 .* inconclusive" "$work/out" &&
  grep -qE "^interior k=5 .* C1 " "$work/out" && pass || fail "analyze butterfly: verdicts at k = 3, 5, 9"
run analyze-modified-butterfly 0 analyze -s modified-butterfly -k 3..16
for k in 3 4 9 16; do
  grep -qE "^interior k=$k .* C1 " "$work/out" && pass || fail "analyze modified-butterfly: no C1 row for k=$k"
done
run analyze-boundary 0 analyze -s catmull-clark --boundary -k 1..5 && stdout_has analyze-boundary "boundary k=5"
run analyze-corner 0 analyze -s loop --corner concave -k 1..3 && stdout_has analyze-corner "concave corner k=2"
run analyze-json 0 analyze -s catmull-clark -k 3..5 --json
for key in '"scheme": "catmull-clark"' '"limit_mask"' '"tangent_masks"' '"layout"' '"spectrum"' '"verdict": "C1"'; do
  stdout_has analyze-json "$key"
done
if command -v python3 >/dev/null 2>&1; then
  python3 -c 'import json, sys; assert len(json.load(sys.stdin)["configurations"]) == 3' <"$work/out" &&
    pass || fail "analyze --json: not valid JSON with 3 configurations"
fi
run analyze-plots 0 analyze -s loop -k 3..6 --plot-spectrum "$work/spectrum.png" --plot-charmap 5 "$work/charmap.svg"
[ "$(head -c 8 "$work/spectrum.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] && pass ||
  fail "analyze --plot-spectrum: not a PNG"
head -c 200 "$work/charmap.svg" | grep -qE '<\?xml|<svg' && pass || fail "analyze --plot-charmap: not an SVG"
run analyze-plots2 0 analyze -s catmull-clark --plot-spectrum "$work/spectrum.svg" --plot-charmap 3 "$work/charmap.png"
[ -s "$work/spectrum.svg" ] && [ -s "$work/charmap.png" ] && pass || fail "analyze: empty plot files"
for bad in "-s butterfly-x" "-s loop -k 2" "-s loop -k 8..3" "-s loop -k 3..65" "-s loop -k x" \
           "-s loop --boundary -k 0" "-s loop --plot-spectrum $work/plot.pdf" \
           "-s loop --plot-charmap 5 $work/no/such/dir/c.svg" "-s bilinear --plot-charmap 5 $work/bilinear.svg"; do
  # shellcheck disable=SC2086
  run "analyze $bad" 1 analyze $bad && stderr_one_line "analyze $bad"
done
run analyze-unknown 1 analyze -s butterfly-x && stderr_has analyze-unknown "unknown scheme 'butterfly-x' (known: catmull-clark"
[ ! -e "$work/plot.pdf" ] && [ ! -e "$work/bilinear.svg" ] && pass || fail "analyze left a plot after an error"
leftovers=$(find "$work" -name '*.tmp-*' | wc -l)
[ "$leftovers" -eq 0 ] && pass || fail "analyze left temporary files behind"

# Curve schemes: the survey's cubic B-spline example.
run analyze-curve 0 analyze -s cubic-bspline && stdout_has analyze-curve "0.125000 0.125000" &&
  stdout_has analyze-curve "limit mask: 0.166667 0.666667 0.166667" && stdout_has analyze-curve "verdict: C1"
run analyze-curve-json 0 analyze -s four-point --json && stdout_has analyze-curve-json '"tangent_mask"'
run analyze-curve-k 1 analyze -s chaikin -k 3 && stderr_one_line analyze-curve-k

# limit: every vertex at its limit position, normals as vn lines; inputs untouched.
cp "$meshes/cube.obj" "$work/cube_in.obj"
run limit-cc 0 limit "$work/cube_in.obj" -s catmull-clark --normals -o "$work/cube_limit.obj" &&
  stdout_has limit-cc "8 vertices at their catmull-clark limit positions (closed-form masks), with limit normals"
[ "$(grep -c '^v ' "$work/cube_limit.obj")" -eq 8 ] && [ "$(grep -c '^vn ' "$work/cube_limit.obj")" -eq 8 ] && pass ||
  fail "limit: expected 8 v and 8 vn lines"
# The unit cube's Catmull-Clark corner limit (n^2 v + 4 sum e + sum f) / (n (n + 5)), n = 3: (1/4, 1/4, 1/4) at the origin.
awk '/^v /{ok = ($2 - 0.25)^2 + ($3 - 0.25)^2 + ($4 - 0.25)^2 < 1e-24; exit} END{exit !ok}' "$work/cube_limit.obj" &&
  pass || fail "limit: the first cube corner is not at (1/4, 1/4, 1/4)"
cmp -s "$meshes/cube.obj" "$work/cube_in.obj" && pass || fail "limit modified its input"
run limit-loop-quads 1 limit "$meshes/cube.obj" -s loop -o "$work/loop_limit.obj" && stderr_one_line limit-loop-quads
run limit-loop 0 limit "$meshes/cube.obj" -s loop --triangulate -o "$work/loop_limit.obj"
# The Butterfly schemes' masks reach past the one-ring; they interpolate, so
# the limit positions are the input's (to the file's digits) and every
# vertex gets a unit normal.
run limit-modified-butterfly 0 limit "$meshes/cube.obj" -s modified-butterfly --triangulate --normals \
  -o "$work/mb_limit.obj" && stdout_has limit-modified-butterfly "8 vertices at their modified-butterfly limit positions"
[ "$(grep -c '^vn ' "$work/mb_limit.obj")" -eq 8 ] && pass || fail "limit modified-butterfly: expected 8 vn lines"
paste <(grep '^v ' "$work/mb_limit.obj") <(grep '^v ' "$meshes/cube.obj") <(grep '^vn ' "$work/mb_limit.obj") |
  awk '{if (($2-$6)^2 + ($3-$7)^2 + ($4-$8)^2 != 0) bad = 1; l = $10*$10 + $11*$11 + $12*$12; if ((l - 1)^2 > 1e-20) bad = 1}
       END{exit bad}' && pass || fail "limit modified-butterfly: moved a vertex or wrote a non-unit normal"
[ -s "$work/err" ] && fail "limit modified-butterfly: warned: $(cat "$work/err")" || pass
run limit-butterfly 0 limit "$meshes/cube.obj" -s butterfly --triangulate -o "$work/b_limit.obj"
run limit-same-file 1 limit "$work/cube_in.obj" -o "$work/cube_in.obj" && stderr_one_line limit-same-file
# The generic masks give the same cube corner.
run limit-generic 0 limit "$meshes/cube.obj" --masks generic -o "$work/cube_generic.obj" &&
  stdout_has limit-generic "(generic masks)"
awk '/^v /{ok = ($2 - 0.25)^2 + ($3 - 0.25)^2 + ($4 - 0.25)^2 < 1e-24; exit} END{exit !ok}' "$work/cube_generic.obj" &&
  pass || fail "limit --masks generic: the first cube corner is not at (1/4, 1/4, 1/4)"
# -l N: the refined mesh, every vertex at its limit, one vn per vertex.
run limit-levels 0 limit "$meshes/cube.obj" -l 2 --normals -o "$work/cube_limit_l2.obj" &&
  stdout_has limit-levels "98 vertices at their catmull-clark limit positions"
[ "$(grep -c '^v ' "$work/cube_limit_l2.obj")" -eq 98 ] && [ "$(grep -c '^vn ' "$work/cube_limit_l2.obj")" -eq 98 ] &&
  [ "$(grep -c '^f ' "$work/cube_limit_l2.obj")" -eq 96 ] && pass || fail "limit -l 2: expected 98 v, 98 vn and 96 f lines"
# The limit masks are convex combinations: every limit point lies inside the
# unit cube; and the cube's symmetry x -> 1 - x holds for the point set.
awk '/^v /{for (i = 2; i <= 4; ++i) { if ($i <= 0 || $i >= 1) bad = 1; if (!n++ || $i < lo) lo = $i; if ($i > hi) hi = $i } }
     END{exit bad || (lo + hi - 1)^2 > 1e-24}' "$work/cube_limit_l2.obj" &&
  pass || fail "limit -l 2: a limit point outside the unit cube, or the set not symmetric"
# Unit normals, pointing away from the cube's centre.
paste <(grep '^v ' "$work/cube_limit_l2.obj") <(grep '^vn ' "$work/cube_limit_l2.obj") |
  awk '{l = $6*$6 + $7*$7 + $8*$8; d = ($2-0.5)*$6 + ($3-0.5)*$7 + ($4-0.5)*$8; if ((l - 1)^2 > 1e-20 || d <= 0) bad = 1} END{exit bad}' &&
  pass || fail "limit -l 2: normals not unit or not outward"
run limit-bad-masks 1 limit "$meshes/cube.obj" --masks eigen -o "$work/x.obj" && stderr_one_line limit-bad-masks
run limit-bad-levels 1 limit "$meshes/cube.obj" -l -1 -o "$work/x.obj" && stderr_one_line limit-bad-levels

# Piecewise-smooth rules: an L of three quads with a concave corner at vertex 4.
cat >"$work/l.obj" <<'OBJ'
v 0 0 0
v 1 0 0
v 2 0 0
v 0 1 0
v 1 1 0
v 2 1 0
v 0 2 0
v 1 2 0
f 1 2 5 4
f 2 3 6 5
f 4 5 8 7
OBJ
cp "$work/l.obj" "$work/l_in.obj"
run ps-refine 0 refine "$work/l_in.obj" -s catmull-clark -l 3 --boundary-rules piecewise-smooth --corner 4:concave \
  -o "$work/l_ps.obj"
run ps-standard 0 refine "$work/l_in.obj" -s catmull-clark -l 3 --corner 4:concave -o "$work/l_std.obj"
cmp -s "$work/l_ps.obj" "$work/l_std.obj" && fail "piecewise-smooth refine: same output as standard" || pass
cmp -s "$work/l.obj" "$work/l_in.obj" && pass || fail "refine --corner modified its input"
run ps-measured 0 refine "$work/l_in.obj" -l 2 --boundary-rules piecewise-smooth --corner 4:concave \
  --corner-angles measured --flatness 0.5 -o "$work/l_m.obj"
for bad in "--corner 99:concave" "--corner 4:sideways" "--corner 4:concave:90" "--corner x" \
           "--boundary-rules smooth" "--flatness 1.5" "--corner 4:convex:400"; do
  # shellcheck disable=SC2086
  run "refine $bad" 1 refine "$work/l_in.obj" -o "$work/l_bad.obj" $bad && stderr_one_line "refine $bad"
done
[ ! -e "$work/l_bad.obj" ] && pass || fail "refine wrote output after a bad rule option"
run ps-analyze 0 analyze -s loop --boundary -k 4..9 --boundary-rules piecewise-smooth
[ "$(grep -cE '^boundary k=[4-9] .* C1 ' "$work/out")" -eq 6 ] && pass || fail "analyze piecewise-smooth: not C1 for k = 4..9"
run ps-analyze-corner 0 analyze -s catmull-clark --corner concave --angle 240 -k 2..4 --boundary-rules piecewise-smooth
stdout_has ps-analyze-corner "concave corner k=3 alpha=240deg"
run ps-limit 0 limit "$work/l_in.obj" -s catmull-clark --boundary-rules piecewise-smooth --normals -o "$work/l_limit.obj"
# The bundled L mesh (convex corners and a tagged concave one): every vertex
# gets a unit normal, and no warning; without flatness the concave corner
# folds, has no normal, and one warning line counts it.
run ps-limit-l 0 limit "$meshes/l_shape.obj" -s catmull-clark --boundary-rules piecewise-smooth --normals \
  -o "$work/l_shape_limit.obj" && [ ! -s "$work/err" ] && pass || fail "limit piecewise-smooth L: $(cat "$work/err")"
[ "$(grep -c '^vn ' "$work/l_shape_limit.obj")" -eq 21 ] &&
  awk '/^vn /{ if (($2^2 + $3^2 + $4^2 - 1)^2 > 1e-12) bad = 1 } END{exit bad}' "$work/l_shape_limit.obj" &&
  pass || fail "limit piecewise-smooth L: expected 21 unit vn lines"
run ps-limit-fold 0 limit "$meshes/l_shape.obj" -s catmull-clark --boundary-rules piecewise-smooth --flatness 0 \
  --normals -o "$work/l_shape_fold.obj" && stderr_one_line ps-limit-fold &&
  stderr_has ps-limit-fold "warning: 1 vertices have no limit normal"

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

# depth: the bound, the costs, the trade-off and a verification that passes.
run depth-cc 0 depth "$meshes/cube.obj" -s catmull-clark --eps 0.01 --verify &&
  stdout_has depth-cc "depth for accuracy 0.01: 5" && stdout_has depth-cc "     5           6146           6144" &&
  stdout_has depth-cc "verify: after 5 steps" && stdout_has depth-cc ": within"
run depth-loop 0 depth "$meshes/tetrahedron.obj" -s loop --eps 0.01 --verify &&
  stdout_has depth-loop "bound (paper (regular) + analysis (extraordinary))" && stdout_has depth-loop "depth 3 would not have been enough"
run depth-doo-sabin 1 depth "$meshes/cube.obj" -s doo-sabin --eps 0.01 && stderr_one_line depth-doo-sabin &&
  stderr_has depth-doo-sabin "doo-sabin: the depth needs vertex-to-limit distances"
run depth-bad-eps 1 depth "$meshes/cube.obj" -s loop --eps -1 && stderr_one_line depth-bad-eps
run depth-bad-file 1 depth "$data/index_out_of_range.obj" -s catmull-clark --eps 0.1 && stderr_one_line depth-bad-file

# adaptive: fewer faces than uniform refinement, a closed output.
run adaptive-cc 0 adaptive "$meshes/spot_control_mesh.obj" -s catmull-clark --eps 0.004 -o "$work/spot_adaptive.obj" &&
  stdout_has adaptive-cc "uniform refinement to the same accuracy"
run adaptive-info 0 info "$work/spot_adaptive.obj" && stdout_has adaptive-info "(boundary 0, non-manifold 0)" &&
  stdout_has adaptive-info "validation      ok"
run adaptive-bad-out 1 adaptive "$meshes/cube.obj" -s catmull-clark --eps 0.01 -o "$work/out.xyz" &&
  stderr_one_line adaptive-bad-out

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
