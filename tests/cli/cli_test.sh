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

# SUBDIV_CLI_QUICK=1 (the sanitizer build) leaves out the few commands
# whose numerics take 10 s or more under the sanitizers (analyses over many
# valences, adaptive refinement of interpolating schemes); the release build
# runs them.
full=1
if [ "${SUBDIV_CLI_QUICK:-0}" = 1 ]; then full=0; fi

# A hang guard, not a speed check: SUBDIV_CLI_TIMEOUT seconds per command
# (tests/CMakeLists.txt: longer under the sanitizers, which run the analysis
# 10-20x slower).
limit_s=${SUBDIV_CLI_TIMEOUT:-20}

# run NAME EXPECTED_EXIT ARGS...: runs subdiv, keeps stdout/stderr in $work.
# SUBDIV_CLI_TIMES=FILE appends each command's wall time and name to FILE.
run() {
  local name=$1 expected=$2 start=$EPOCHREALTIME
  shift 2
  timeout "$limit_s" "$SUBDIV" "$@" >"$work/out" 2>"$work/err"
  local code=$?
  if [ -n "${SUBDIV_CLI_TIMES:-}" ]; then echo "$start $EPOCHREALTIME $name" >>"$SUBDIV_CLI_TIMES"; fi
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
run convert-help 0 convert --help && stdout_has convert-help "Examples:"
run version 0 --version && stdout_has version "subdiv $(sed -n 's/^project(subdiv VERSION \([0-9.]*\).*/\1/p' "$project_dir/CMakeLists.txt")"

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
run info-isolated 0 info "$data/isolated_vertex.obj" && stdout_has info-isolated "0 errors, 1 warning"

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
run convert-badext 1 convert "$work/in.obj" "$work/out.fbx"
[ ! -e "$work/out.fbx" ] && pass || fail "convert-badext left a file"
run convert-invalid 1 convert "$data/nonmanifold_edge.obj" "$work/nm.obj" --validate
[ ! -e "$work/nm.obj" ] && pass || fail "convert --validate wrote an invalid mesh"
run convert-nodir 1 convert "$work/in.obj" "$work/no/such/dir/x.obj" && stderr_one_line convert-nodir
# Every pair of formats: the rook (quads and 12-gons) goes through each one and
# into each other. STL holds triangles, so what passed through it has 284 triangles;
# every other route keeps the 134 polygons (glTF through subdiv's extras).
for from in obj ply off gltf glb stl; do
  run "convert-to-$from" 0 convert "$meshes/rook.obj" "$work/pair.$from" || continue
  for to in obj ply off gltf glb stl; do
    [ "$from" = "$to" ] && continue
    run "convert-$from-$to" 0 convert "$work/pair.$from" "$work/pair_$from.$to" || continue
    faces=134; { [ "$from" = stl ] || [ "$to" = stl ]; } && faces=284
    run "info-$from-$to" 0 info --json "$work/pair_$from.$to" || continue
    python3 -c 'import json,sys; d=json.load(sys.stdin); sys.exit(0 if (d["vertices"], d["faces"]) == (144, int(sys.argv[1])) else 1)' \
      "$faces" <"$work/out" && pass || fail "convert $from -> $to: not 144 vertices and $faces faces"
  done
done
run convert-stl-ascii 0 convert "$meshes/cube.obj" "$work/cube_ascii.stl" --ascii
head -c 12 "$work/cube_ascii.stl" | grep -q "^solid" && pass || fail "convert --ascii: not ASCII STL"
run convert-glb-ascii 1 convert "$meshes/cube.obj" "$work/cube.glb" --ascii && stderr_has convert-glb-ascii ".gltf is its text form"
run convert-gltf-tags 0 convert "$data/tagged_octagon.obj" "$work/octagon.glb" && stderr_has convert-gltf-tags "kept in the extras"
run convert-gltf-tags-back 0 convert "$work/octagon.glb" "$work/octagon_back.obj"
[ "$(grep -c '^t ' "$work/octagon_back.obj")" = "$(grep -c '^t ' "$data/tagged_octagon.obj")" ] && pass || fail "glTF: tags not kept"
# STL welding: without it every triangle keeps its three corners.
run convert-stl-apart 0 convert "$work/pair.stl" "$work/apart.obj" --weld-tolerance -1 && stdout_has convert-stl-apart "852 vertices, 284 faces"
run convert-stl-welded 0 convert "$work/pair.stl" "$work/welded.obj" --weld-tolerance 1e-6 && stdout_has convert-stl-welded "144 vertices, 284 faces"
run refine-from-glb 0 refine "$work/pair.glb" -s catmull-clark -l 1 -o "$work/rook_cc.glb" && stdout_has refine-from-glb "552 faces"
printf 'solid x\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 nan\n' >"$work/bad.stl"
run stl-bad 1 info "$work/bad.stl" && stderr_one_line stl-bad && stderr_has stl-bad "bad.stl:5"
printf '{"asset": {"version": "2.0"}, "buffers": [{"uri": "/dev/zero", "byteLength": 16}]}' >"$work/bad.gltf"
run gltf-bad 1 info "$work/bad.gltf" && stderr_one_line gltf-bad && stderr_has gltf-bad "bad.gltf: "
# Catmull-Clark's edge rule next to triangles: the option changes the output, and applies to catmull-clark only.
printf 'v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 1 1 1.5\nf 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n' >"$work/pyramid.obj"
run triangle-rule-catmark 0 refine "$work/pyramid.obj" -o "$work/pyramid_catmark.obj" --triangle-rule catmark
run triangle-rule-smooth 0 refine "$work/pyramid.obj" -o "$work/pyramid_smooth.obj" --triangle-rule smooth
cmp -s "$work/pyramid_catmark.obj" "$work/pyramid_smooth.obj" && fail "--triangle-rule smooth changed nothing" || pass
grep -q "^t smoothtriangles 0/0/1 smooth" "$work/pyramid_smooth.obj" && pass || fail "--triangle-rule: the output's tag does not name the rule"
run triangle-rule-loop 1 refine "$work/pyramid.obj" -s loop -o "$work/x.obj" --triangle-rule smooth &&
  stderr_has triangle-rule-loop "--triangle-rule applies to catmull-clark"
# Face-varying channels: --face-varying smooths Spot's UVs (the default is linear), names the option in
# the output's tags, and applies to the schemes that refine them smoothly.
spot="$meshes/spot_control_mesh.obj"
run face-varying-all 0 refine "$spot" -l 2 -o "$work/spot_uv_all.obj"
run face-varying-none 0 refine "$spot" -l 2 -o "$work/spot_uv_none.obj" --face-varying none
[ "$(grep '^v ' "$work/spot_uv_all.obj")" = "$(grep '^v ' "$work/spot_uv_none.obj")" ] && pass ||
  fail "--face-varying changed the positions"
[ "$(grep '^vt ' "$work/spot_uv_all.obj")" != "$(grep '^vt ' "$work/spot_uv_none.obj")" ] && pass ||
  fail "--face-varying none did not change the UVs"
grep -q "^t facevaryinginterpolateboundary 1/0/0 0" "$work/spot_uv_none.obj" && pass ||
  fail "--face-varying: the output's tag does not name the option"
run face-varying-butterfly 1 refine "$spot" -s butterfly --triangulate -o "$work/x.obj" --face-varying none &&
  stderr_has face-varying-butterfly "--face-varying applies to the schemes that refine face-varying channels smoothly"
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
# Butterfly's tension: w = 0 is the linear scheme on a closed mesh.
run refine-butterfly-w0 0 refine "$meshes/cube.obj" -s butterfly --triangulate --tension 0 -l 2 -o "$work/bw0.obj"
run refine-linear 0 refine "$meshes/cube.obj" -s linear --triangulate -l 2 -o "$work/lin.obj"
cmp -s "$work/bw0.obj" "$work/lin.obj" && pass || fail "butterfly --tension 0 differs from linear"
run refine-tension-loop 1 refine "$meshes/cube.obj" -s loop --triangulate --tension 0.1 -o "$work/x.obj" &&
  stderr_one_line refine-tension-loop && stderr_has refine-tension-loop "--tension applies to butterfly"
run analyze-butterfly-tension 0 analyze -s butterfly -k 6 --tension 0.04 --no-charmap &&
  stdout_has analyze-butterfly-tension "0.500000  0.500000    0.400000"
run refine-doo-sabin 0 refine "$meshes/cube.obj" -s doo-sabin -l 2 -o "$work/ds.obj" --stats
stdout_has refine-doo-sabin "level 1: 24 vertices, 26 faces" && stdout_has refine-doo-sabin "level 2: 96 vertices, 98 faces"
run refine-doo-sabin-info 0 info "$work/ds.obj" && stdout_has refine-doo-sabin-info "validation      ok"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nt crease 2/1/0 0 1 3\n' > "$work/ds_crease.obj"
run refine-doo-sabin-crease 1 refine "$work/ds_crease.obj" -s doo-sabin -o "$work/x.obj"
stderr_one_line refine-doo-sabin-crease && stderr_has refine-doo-sabin-crease "ds_crease.obj:6: doo-sabin has no crease rules"
run limit-doo-sabin 0 limit "$meshes/cube.obj" -s doo-sabin -o "$work/ds_limit.obj" &&
  stdout_has limit-doo-sabin "8 vertices at their doo-sabin limit positions (generic masks)"
# The sqrt3 and sqrt2 splits' limits: generic masks; quasi 4-8 has none (one line).
run limit-sqrt3 0 limit "$meshes/l_shape.obj" -s sqrt3 --triangulate --normals -o "$work/s3_limit.obj" &&
  stdout_has limit-sqrt3 "21 vertices at their sqrt3 limit positions (generic masks), with limit normals"
run limit-four-eight 0 limit "$meshes/cube.obj" -s four-eight -o "$work/48_limit.obj" &&
  stdout_has limit-four-eight "8 vertices at their four-eight limit positions (generic masks)"
[ ! -s "$work/err" ] && pass || fail "limit four-eight: unexpected warnings: $(cat "$work/err")"
run limit-quasi 1 limit "$meshes/tetrahedron.obj" -s quasi-4-8 -o "$work/x.obj" && stderr_one_line limit-quasi &&
  stderr_has limit-quasi "its steps are not stationary"
# limit names the file and line of what it cannot refine, as refine does.
run limit-nonmanifold 1 limit "$data/nonmanifold_edge.obj" -o "$work/x.obj" && stderr_one_line limit-nonmanifold &&
  stderr_has limit-nonmanifold "nonmanifold_edge.obj:9: edge 0-1 is shared by 3 faces"
run limit-quads-for-loop 1 limit "$meshes/cube.obj" -s loop -o "$work/x.obj" && stderr_one_line limit-quads-for-loop &&
  stderr_has limit-quads-for-loop "cube.obj:11: loop needs a triangle mesh"

# The exact limit surface: eval, tessellate, project.
printf '# face u v\n0 0 0\n0 0.5 0.5\n\n5 1 1\n' > "$work/at.txt"
run eval-cube 0 eval "$meshes/cube.obj" -s catmull-clark --at "$work/at.txt" --derivatives &&
  [ "$(wc -l <"$work/out")" -eq 3 ] && [ "$(awk '{print NF}' "$work/out" | sort -u)" = "12" ] && pass ||
  fail "eval-cube: expected 3 lines of 12 numbers: $(cat "$work/out")"
# Ptex face 0's corner (0, 0) is the limit of the cube's vertex there, as 'limit' writes it.
eval_point=$(head -1 "$work/out" | awk '{print $1, $2, $3}')
run limit-cube-for-eval 0 limit "$meshes/cube.obj" -s catmull-clark -o "$work/cube_limit.obj"
first_vertex=$(awk '$1 == "f" {split($2, a, "/"); print a[1]; exit}' "$meshes/cube.obj")
limit_point=$(awk -v n="$first_vertex" '$1 == "v" {i++; if (i == n) {print $2, $3, $4; exit}}' "$work/cube_limit.obj")
awk -v a="$limit_point" -v b="$eval_point" 'BEGIN {split(a, x); split(b, y); d = 0;
  for (i = 1; i <= 3; i++) d += (x[i] - y[i])^2; exit !(d < 1e-20)}' && pass ||
  fail "eval-cube: corner (0, 0) of ptex face 0 is $eval_point, the vertex limit $limit_point"
run eval-output 0 eval "$meshes/cube.obj" --at "$work/at.txt" -o "$work/eval.txt" &&
  stdout_has eval-output "wrote $work/eval.txt: 3 limit points" && [ "$(wc -l <"$work/eval.txt")" -eq 3 ] && pass ||
  fail "eval-output: $work/eval.txt"
printf '0 0.5\n' > "$work/at_short.txt"
run eval-short-line 1 eval "$meshes/cube.obj" --at "$work/at_short.txt" && stderr_one_line eval-short-line &&
  stderr_has eval-short-line "at_short.txt:1: expected three finite numbers per line (face u v)"
printf '0 0.5 0.5\n6 0.5 0.5\n' > "$work/at_face.txt"
run eval-face-range 1 eval "$meshes/cube.obj" --at "$work/at_face.txt" && stderr_one_line eval-face-range &&
  stderr_has eval-face-range "point 2: face 6 is not a ptex face"
printf '0 1.5 0.5\n' > "$work/at_outside.txt"
run eval-outside 1 eval "$meshes/cube.obj" --at "$work/at_outside.txt" && stderr_one_line eval-outside &&
  stderr_has eval-outside "is outside ptex face 0"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n' > "$work/one_quad.obj"
printf '0 0 0\n0 0.5 0.5\n' > "$work/at_quad.txt"
# A lone quad: four corners (the corner rule), the surface their bilinear patch.
run eval-boundary 0 eval "$work/one_quad.obj" --at "$work/at_quad.txt" && stdout_has eval-boundary "0 0 0 0 0 1" &&
  awk 'NR == 2 {exit !(($1 - 0.5)^2 + ($2 - 0.5)^2 + $3^2 < 1e-24 && $4 == 0 && $5 == 0 && $6 == 1)}' "$work/out" && pass ||
  fail "eval-boundary: the quad's centre is not (0.5, 0.5, 0) with normal (0, 0, 1): $(cat "$work/out")"
# A concave corner of three faces (its own model); a crease too sharp to isolate.
run eval-l-shape 0 eval "$meshes/l_shape.obj" --at "$work/at_quad.txt" && [ "$(wc -l <"$work/out")" -eq 2 ] && pass ||
  fail "eval-l-shape: expected 2 lines: $(cat "$work/out")"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2 5 6 3\nt crease 2/1/0 1 2 5\n' > "$work/sharp5.obj"
run eval-semi-sharp 1 eval "$work/sharp5.obj" --exact --at "$work/at_quad.txt" && stderr_one_line eval-semi-sharp &&
  stderr_has eval-semi-sharp "sharp5.obj: limit evaluation: edge 1-2 has sharpness 5.000000; exact evaluation isolates semi-sharp features up to sharpness 4"
# Without --exact: evaluation by refinement, with a warning saying why and what was measured.
run eval-semi-sharp-approximate 0 eval "$work/sharp5.obj" --at "$work/at_quad.txt" &&
  stderr_one_line eval-semi-sharp-approximate &&
  stderr_has eval-semi-sharp-approximate "sharp5.obj: approximate evaluation: edge 1-2 has sharpness 5.000000" &&
  stderr_has eval-semi-sharp-approximate "the limit moved at most" &&
  [ "$(wc -l <"$work/out")" -eq 2 ] && pass || fail "eval-semi-sharp-approximate: expected 2 lines: $(cat "$work/out")"
run eval-into-input 1 eval "$meshes/cube.obj" --at "$work/at.txt" -o "$work/at.txt" && stderr_one_line eval-into-input &&
  stderr_has eval-into-input "output is the input file"
run eval-scheme 1 eval "$meshes/cube.obj" -s doo-sabin --exact --at "$work/at.txt" && stderr_one_line eval-scheme &&
  stderr_has eval-scheme "doo-sabin has no exact evaluator"
run eval-scheme-split 1 eval "$meshes/cube.obj" -s doo-sabin --at "$work/at.txt" && stderr_one_line eval-scheme-split &&
  stderr_has eval-scheme-split "doo-sabin: evaluation at (face, u, v) needs a split that divides each face into sub-faces"
run eval-kobbelt 0 eval "$meshes/cube.obj" -s kobbelt --accuracy 0.01 --at "$work/at.txt" --json &&
  stdout_has eval-kobbelt '"exact": false' && stdout_has eval-kobbelt '"points": 3'
run tessellate-butterfly 0 tessellate "$meshes/tetrahedron.obj" -s butterfly --accuracy 0.01 --rate 4 -o "$work/tetrahedron_b.obj" &&
  stderr_has tessellate-butterfly "approximate evaluation: butterfly has no exact evaluator" &&
  run tessellate-butterfly-closed 0 info "$work/tetrahedron_b.obj" &&
  stdout_has tessellate-butterfly-closed "(boundary 0, non-manifold 0)"
run tessellate-cube 0 tessellate "$meshes/cube.obj" --rate 4 -o "$work/cube_t.obj" &&
  stdout_has tessellate-cube "wrote $work/cube_t.obj: 98 vertices, 96 faces"
run tessellate-closed 0 info "$work/cube_t.obj" && stdout_has tessellate-closed "edges           192  (boundary 0, non-manifold 0)"
run tessellate-loop 0 tessellate "$meshes/elephant.obj" -s loop --rate 2 -o "$work/elephant_t.obj" &&
  run tessellate-loop-closed 0 info "$work/elephant_t.obj" && stdout_has tessellate-loop-closed "(boundary 0, non-manifold 0)"
run tessellate-ngons 0 tessellate "$meshes/rook.obj" --rate 4 -o "$work/rook_t.obj" &&
  run tessellate-ngons-closed 0 info "$work/rook_t.obj" && stdout_has tessellate-ngons-closed "(boundary 0, non-manifold 0)"
run tessellate-valence-3 0 tessellate "$meshes/tetrahedron.obj" -s loop --rate 2 -o "$work/tetrahedron_t.obj" &&
  run tessellate-valence-3-closed 0 info "$work/tetrahedron_t.obj" &&
  stdout_has tessellate-valence-3-closed "(boundary 0, non-manifold 0)"
run tessellate-odd 1 tessellate "$meshes/spot_control_mesh.obj" --rate 3 -o "$work/x.obj" &&
  stderr_one_line tessellate-odd && stderr_has tessellate-odd "give an even rate"
[ ! -e "$work/x.obj" ] && pass || fail "tessellate-odd: wrote $work/x.obj"
printf '0.5 0.5 2\n0.5 0.5 0.5\n' > "$work/points.txt"
run project-cube 0 project "$meshes/cube.obj" --points "$work/points.txt" &&
  [ "$(wc -l <"$work/out")" -eq 2 ] && [ "$(awk '{print NF}' "$work/out" | sort -u)" = "7" ] && pass ||
  fail "project-cube: expected 2 lines of 7 numbers: $(cat "$work/out")"
printf '0.5 nan 2\n' > "$work/points_nan.txt"
run project-nan 1 project "$meshes/cube.obj" --points "$work/points_nan.txt" && stderr_one_line project-nan &&
  stderr_has project-nan "points_nan.txt:1: expected three finite numbers"
run depth-nonmanifold 1 depth "$data/nonmanifold_edge.obj" -s catmull-clark --eps 0.01 &&
  stderr_one_line depth-nonmanifold && stderr_has depth-nonmanifold "nonmanifold_edge.obj:9: edge 0-1 is shared by 3 faces"
run adaptive-quads-for-loop 1 adaptive "$meshes/cube.obj" -s loop --eps 0.01 -o "$work/x.obj" &&
  stderr_one_line adaptive-quads-for-loop && stderr_has adaptive-quads-for-loop "cube.obj:11: loop needs a triangle mesh"
run analyze-doo-sabin 0 analyze -s doo-sabin -k 3..8 && stdout_has analyze-doo-sabin "extraordinary face of k sides"
for k in 3 5 8; do
  grep -qE "^interior k=$k +$((4 * k)) +1 +0.500000 +0.500000 +0.250000 .* C1 " "$work/out" && pass ||
    fail "analyze doo-sabin: no C1 row with 1/2, 1/2, 1/4 for k=$k"
done
run analyze-doo-sabin-boundary 1 analyze -s doo-sabin --boundary -k 2 && stderr_one_line analyze-doo-sabin-boundary &&
  stderr_has analyze-doo-sabin-boundary "extraordinary faces only"
# The dual split: half E-faces and fan polygons join the levels.
run adaptive-doo-sabin 0 adaptive "$meshes/cube.obj" -s doo-sabin --eps 0.003 -o "$work/ads.obj" &&
  stdout_has adaptive-doo-sabin "(120 transition faces)"
run adaptive-doo-sabin-info 0 info "$work/ads.obj" && stdout_has adaptive-doo-sabin-info "(boundary 0, non-manifold 0)" &&
  stdout_has adaptive-doo-sabin-info "validation      ok"
run adaptive-doo-sabin-open 1 adaptive "$meshes/l_shape.obj" -s doo-sabin --eps 0.003 -o "$work/x.obj" &&
  stderr_one_line adaptive-doo-sabin-open
run refine-midedge 0 refine "$meshes/cube.obj" -s midedge -l 2 -o "$work/me.obj" --stats
stdout_has refine-midedge "level 1: 12 vertices, 14 faces" && stdout_has refine-midedge "level 2: 24 vertices, 26 faces"
run refine-midedge-open 1 refine "$meshes/l_shape.obj" -s midedge -o "$work/x.obj" && stderr_one_line refine-midedge-open
run analyze-midedge 0 analyze -s midedge -k 3..6 && stdout_has analyze-midedge "period 2" &&
  stdout_has analyze-midedge "extraordinary face of k sides"
grep -qE "^interior k=6 +24 +1 +0.750000 +0.750000 +0.250000 .* C1 " "$work/out" && pass || fail "analyze midedge: k=6 row"
# Generalized Catmull-Clark and midpoint schemes (Chen-Prautzsch).
run refine-gcc 0 refine "$meshes/cube.obj" -s gcc -l 2 -o "$work/gcc.obj" --stats
stdout_has refine-gcc "level 2: 98 vertices, 96 faces"
run refine-gcc-cc 0 refine "$meshes/cube.obj" -s catmull-clark -l 2 -o "$work/cc.obj"
paste <(grep '^v ' "$work/gcc.obj") <(grep '^v ' "$work/cc.obj") |
  awk '{for (i = 2; i <= 4; ++i) { d = $i - $(i + 4); if (d < 0) d = -d; if (d > m) m = d } } END { exit !(NR == 98 && m < 1e-14) }' &&
  pass || fail "refine gcc: not Catmull-Clark's vertices on the cube"
run refine-gcc-5 0 refine "$meshes/cube.obj" -s gcc --degree 5 --alpha 0.2,0.3 --beta 0.5,0.4 -l 2 -o "$work/gcc5.obj" --stats
stdout_has refine-gcc-5 "level 2: 98 vertices, 96 faces"
run refine-midpoint-4 0 refine "$meshes/cube.obj" -s midpoint --degree 4 -l 2 -o "$work/m4.obj" --stats
stdout_has refine-midpoint-4 "level 1: 24 vertices, 26 faces"
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 1\nv 2 1 0\nf 1 2 5 4\nf 2 3 6 5\n' >"$work/open.obj"
run refine-midpoint-open 0 refine "$work/open.obj" -s midpoint --degree 3 -l 1 -o "$work/open3.obj"
run refine-midpoint-tagged 1 refine "$meshes/l_shape.obj" -s midpoint -o "$work/x.obj" &&
  stderr_one_line refine-midpoint-tagged && stderr_has refine-midpoint-tagged "midpoint has no corner rules"
run refine-gcc-range 1 refine "$meshes/cube.obj" -s gcc --alpha 0.7 --beta 0.5 -o "$work/x.obj" &&
  stderr_one_line refine-gcc-range && stderr_has refine-gcc-range "outside the paper's range"
run refine-gcc-count 1 refine "$meshes/cube.obj" -s gcc --degree 7 --alpha 0.2,0.3 --beta 0.5,0.4 -o "$work/x.obj" &&
  stderr_one_line refine-gcc-count && stderr_has refine-gcc-count "degree 7 has 3 smoothing operators"
run refine-gcc-alpha-only 1 refine "$meshes/cube.obj" -s gcc --alpha 0.2 -o "$work/x.obj" && stderr_one_line refine-gcc-alpha-only
run refine-degree-cc 1 refine "$meshes/cube.obj" -s catmull-clark --degree 5 -o "$work/x.obj" &&
  stderr_has refine-degree-cc "--degree applies to gcc and midpoint"
run refine-midpoint-alpha 1 refine "$meshes/cube.obj" -s midpoint --alpha 0.2 --beta 0.3 -o "$work/x.obj" &&
  stderr_has refine-midpoint-alpha "give other weights to gcc"
run analyze-gcc 0 analyze -s gcc -k 3..6 && stdout_has analyze-gcc "Chen-Prautzsch (n=3, B_1: alpha=1-3/m beta=2/m)"
grep -qE "^interior k=3 +0.166667 +0.410097 +0.410097 +yes +yes +C1: Remark 5.7: \(5.1\) holds +C1$" "$work/out" && pass ||
  fail "analyze gcc: k=3 closed-form row"
stdout_has analyze-gcc "|U_dd| = 0.25 from the stencils"
run analyze-gcc-52 0 analyze -s gcc --valence-weights 5:0.9:0.05 -k 5 &&
  stdout_has analyze-gcc-52 "open: (5.2) fails" && stdout_has analyze-gcc-52 "not tangent-plane continuous"
run analyze-gcc-json 0 analyze -s gcc --alpha 0.3 --beta 0.4 -k 5 --json && stdout_has analyze-gcc-json '"chen_prautzsch"'
if [ "$full" = 1 ]; then  # 22 s under the sanitizers
  run analyze-midpoint-6 0 analyze -s midpoint --degree 6 -k 3..5 && stdout_has analyze-midpoint-6 "extraordinary face of k sides"
fi
run analyze-gcc-boundary 1 analyze -s gcc --boundary -k 2 && stderr_one_line analyze-gcc-boundary &&
  stderr_has analyze-gcc-boundary "interior configurations only"
run limit-gcc 0 limit "$meshes/cube.obj" -s gcc --degree 5 -o "$work/gcc_limit.obj" &&
  stdout_has limit-gcc "8 vertices at their gcc limit positions (generic masks)"
run limit-gcc-even 0 limit "$meshes/cube.obj" -s gcc --degree 4 -o "$work/gcc4_limit.obj" &&
  stdout_has limit-gcc-even "8 vertices at their gcc limit positions (generic masks)"
run limit-midedge 0 limit "$meshes/cube.obj" -s midedge -o "$work/midedge_limit.obj" &&
  stdout_has limit-midedge "8 vertices at their midedge limit positions (generic masks)"
run refine-sqrt3 0 refine "$meshes/cube.obj" -s sqrt3 --triangulate -l 3 -o "$work/s3.obj" --stats
stdout_has refine-sqrt3 "level 1: 20 vertices, 36 faces" && stdout_has refine-sqrt3 "level 3: 164 vertices, 324 faces"
run refine-sqrt3-open 0 refine "$meshes/l_shape.obj" -s sqrt3 --triangulate -l 2 -o "$work/s3l.obj"
run refine-sqrt3-open-info 0 info "$work/s3l.obj" && stdout_has refine-sqrt3-open-info "validation      ok"
run refine-sqrt3-quads 1 refine "$meshes/cube.obj" -s sqrt3 -o "$work/x.obj" && stderr_one_line refine-sqrt3-quads &&
  stderr_has refine-sqrt3-quads "needs a triangle mesh"
if [ "$full" = 1 ]; then  # 12 s under the sanitizers
  run analyze-sqrt3 0 analyze -s sqrt3 -k 3..12 && stdout_has analyze-sqrt3 "period 2"
  grep -qE "^interior k=6 +7 +1 +0.333333 +0.333333 +0.111111 .* C1 " "$work/out" && pass || fail "analyze sqrt3: k=6 row"
  [ "$(grep -cE "^interior k=[0-9]+ .* C1 " "$work/out")" = 10 ] && pass || fail "analyze sqrt3: not C1 at every valence"
fi
run analyze-sqrt3-boundary 0 analyze -s sqrt3 --boundary -k 3 && stdout_has analyze-sqrt3-boundary "0.333333  0.333333"
run refine-isqrt3 0 refine "$meshes/tetrahedron.obj" -s interpolatory-sqrt3 -l 2 -o "$work/is3.obj" --stats
stdout_has refine-isqrt3 "level 2: 20 vertices, 36 faces"
run refine-isqrt3-open 0 refine "$meshes/l_shape.obj" -s interpolatory-sqrt3 --triangulate -l 3 -o "$work/is3l.obj"
run refine-isqrt3-open-info 0 info "$work/is3l.obj" && stdout_has refine-isqrt3-open-info "validation      ok"
if [ "$full" = 1 ]; then  # 55 s under the sanitizers
  run analyze-isqrt3-boundary 0 analyze -s interpolatory-sqrt3 --boundary -k 1..5
  # Reif holds at every sector; the regular boundary test does not apply to these rules.
  [ "$(grep -cE "^boundary k=[0-9]+ .* yes +yes +yes +inconclusive " "$work/out")" = 5 ] && pass ||
    fail "analyze interpolatory-sqrt3: boundary rows"
  stdout_has analyze-isqrt3-boundary "boundary regular rules not read"
  run analyze-isqrt3 0 analyze -s interpolatory-sqrt3 -k 3..8 --no-charmap &&
    grep -qE "^interior k=6 +37 +3 +0.333333 +0.333333 " "$work/out" && pass || fail "analyze interpolatory-sqrt3: k=6 row"
fi
# Two steps at once (a quad split), then one: levels 2 and 3 are reported.
run refine-four-eight 0 refine "$meshes/cube.obj" -s four-eight -l 3 -o "$work/48.obj" --stats
stdout_has refine-four-eight "level 2: 26 vertices, 24 faces" && stdout_has refine-four-eight "level 3: 50 vertices, 48 faces"
if grep -q "^level 1:" "$work/out"; then fail "refine four-eight: level 1 reported"; else pass; fi
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n' > "$work/quad.obj"
run refine-four-eight-open 1 refine "$work/quad.obj" -s four-eight -o "$work/x.obj" &&
  stderr_one_line refine-four-eight-open && stderr_has refine-four-eight-open "needs a closed mesh"
if [ "$full" = 1 ]; then  # 19 s under the sanitizers
  run analyze-four-eight 0 analyze -s four-eight -k 3..8 && stdout_has analyze-four-eight "period 2"
  grep -qE "^interior k=4 +25 +2 +0.500000 +0.500000 +0.250000 .* C1 " "$work/out" && pass || fail "analyze four-eight: k=4 row"
fi
run refine-kobbelt 0 refine "$meshes/cube.obj" -s kobbelt -l 2 -o "$work/kob.obj" --stats
stdout_has refine-kobbelt "level 1: 26 vertices, 24 faces" && stdout_has refine-kobbelt "level 2: 98 vertices, 96 faces"
run refine-kobbelt-open 0 refine "$work/quad.obj" -s kobbelt -l 2 -o "$work/kobq.obj"
run refine-kobbelt-triangles 1 refine "$meshes/tetrahedron.obj" -s kobbelt -o "$work/x.obj" &&
  stderr_one_line refine-kobbelt-triangles && stderr_has refine-kobbelt-triangles "tetrahedron.obj:7: kobbelt needs a quad mesh"
run refine-kobbelt-tension 1 refine "$meshes/cube.obj" -s kobbelt --tension -0.5 -o "$work/x.obj" &&
  stderr_one_line refine-kobbelt-tension && stderr_has refine-kobbelt-tension "kobbelt needs w > -1/2"
# Interpolating schemes: faces refined by their next level's displacements.
if [ "$full" = 1 ]; then  # 12 s under the sanitizers
  run adaptive-kobbelt 0 adaptive "$meshes/cube.obj" -s kobbelt --eps 0.01 -o "$work/ak.obj" &&
    stdout_has adaptive-kobbelt "every vertex on the limit; largest distance of a face's next-level vertices" &&
    stdout_has adaptive-kobbelt "within eps (1 - r)"
fi
run adaptive-butterfly 0 adaptive "$meshes/tetrahedron.obj" -s butterfly --eps 0.01 -o "$work/ab.obj" --json &&
  stdout_has adaptive-butterfly '"measure": "surface-to-limit"'
if [ "$full" = 1 ]; then
  run adaptive-interpolatory-sqrt3 0 adaptive "$meshes/tetrahedron.obj" -s interpolatory-sqrt3 --eps 0.01 -o "$work/ai3.obj" &&
    stdout_has adaptive-interpolatory-sqrt3 " of two steps, every vertex on the limit"
fi
# The rate's joint spectral radius bound of the sqrt2 rules takes about 6 s
# on its own (regular_smoothness_of): a longer limit, so that a loaded
# machine does not turn it into a failure.
if [ "$full" = 1 ]; then  # 6 s in a release build: its rate bound
  limit_s=$((limit_s * 3)) run adaptive-interpolating-sqrt2 0 adaptive "$meshes/cube.obj" -s interpolating-sqrt2 --eps 0.01 -o "$work/ai2.obj" &&
    stdout_has adaptive-interpolating-sqrt2 " of two steps, every vertex on the limit"
fi
# The regular rules' own test: four-point's and Kobbelt's tension sweeps.
for w in 0.2 0.24 0.3; do
  run "analyze-four-point-$w" 0 analyze -s four-point --tension "$w" &&
    stdout_has "analyze-four-point-$w" "verdict: not C1 (regular rules not C1"
done
run analyze-four-point-default 0 analyze -s four-point && stdout_has analyze-four-point-default "verdict: C1 (regular rules C1"
run analyze-four-point-json 0 analyze -s four-point --tension 0.3 --json &&
  stdout_has analyze-four-point-json '"verdict": "not C1"' && stdout_has analyze-four-point-json '"lower_length"'
if [ "$full" = 1 ]; then  # 13 s under the sanitizers
  run analyze-kobbelt-tension 0 analyze -s kobbelt --tension 0.3 -k 4
  grep -qE "^interior k=4 .* yes +yes +yes +not C1 " "$work/out" && pass || fail "analyze kobbelt 0.3: k=4 row"
  stdout_has analyze-kobbelt-tension "regular rules not C1"
fi
run analyze-loop-regular 0 analyze -s loop -k 6 && stdout_has analyze-loop-regular "regular rules C1"
run analyze-bilinear 0 analyze -s bilinear -k 4 && grep -qE "^interior k=4 .* not C1 " "$work/out" && pass ||
  fail "analyze bilinear: k=4 not C1"
run analyze-loop-boundary-regular 0 analyze -s loop --boundary -k 2 && stdout_has analyze-loop-boundary-regular "boundary regular rules C1"
run analyze-kobbelt 0 analyze -s kobbelt -k 3..12
grep -qE "^interior k=4 +25 +2 +0.500000 +0.500000 +0.250000 .* C1 " "$work/out" && pass || fail "analyze kobbelt: k=4 row"
[ "$(grep -cE "^interior k=[0-9]+ .* C1 " "$work/out")" = 10 ] && pass || fail "analyze kobbelt: not C1 at every valence"
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
# Loop's printed numbers against its closed forms (the full check against
# independently written matrices is tests/analysis/independent_spectra_test).
run analyze-loop-json 0 analyze -s loop -k 3..12 --json --no-charmap && stdout_has analyze-loop-json '"period": 1'
if command -v python3 >/dev/null 2>&1; then
  python3 -c '
import json, math, sys
doc = json.load(sys.stdin)
assert [c["k"] for c in doc["configurations"]] == list(range(3, 13))
for c in doc["configurations"]:
    k = c["k"]
    lam = 3 / 8 + math.cos(2 * math.pi / k) / 4
    beta = (5 / 8 - lam * lam) / k
    chi = 8 * beta / (3 + 8 * k * beta)
    assert c["period"] == 1 and c["matrix_size"] == k + 1, c["name"]
    assert abs(c["leading_eigenvalues"][1]["re"] - lam) < 1e-10, c["name"]
    assert abs(c["leading_eigenvalues"][2]["re"] - lam) < 1e-10, c["name"]
    assert abs(c["limit_mask"][0] - (1 - k * chi)) < 1e-10, c["name"]
    assert all(abs(w - chi) < 1e-10 for w in c["limit_mask"][1:]), c["name"]
    assert c["eigenvalue_condition"], c["name"]
' <"$work/out" && pass || fail "analyze -s loop --json: lambda_1 or the limit mask differ from Loop's closed forms"
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

# Curve schemes refine polylines (OBJ l lines): a closed square (last index =
# first) and an open polyline of 5 points. Points per level: closed 2n; open
# 2n - 1 (cubic-bspline, four-point) or 2n (chaikin, which keeps both ends).
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nl 1 2 3 4 1\nv 0 0 1\nv 1 0 1\nv 2 1 1\nv 3 1 1\nv 4 0 1\nl 5 6 7 8 9\n' \
  >"$work/curves.obj"
for case in cubic-bspline:33 chaikin:36 four-point:33; do
  scheme=${case%%:*}
  run "refine-curve-$scheme" 0 refine "$work/curves.obj" -s "$scheme" -l 2 -o "$work/curve_$scheme.obj" --stats
  stdout_has "refine-curve-$scheme" "wrote $work/curve_$scheme.obj: ${case##*:} vertices, 2 polylines"
  stdout_has "refine-curve-$scheme" "level 2: ${case##*:} points, 2 polylines"
  [ "$(grep -c '^l ' "$work/curve_$scheme.obj")" -eq 2 ] && grep -qE '^l 1( [0-9]+){15} 1$' "$work/curve_$scheme.obj" &&
    pass || fail "refine -s $scheme: not one closed l line of 16 points and one more l line"
done
for p in "0 0 0" "1 1 0" "2 1 1" "4 0 1"; do  # four-point interpolates: the coarse points are kept
  grep -qx "v $p" "$work/curve_four-point.obj" && pass || fail "refine -s four-point: lost the point $p"
done
run refine-curve-tension 0 refine "$work/curves.obj" -s four-point --tension 0.1 -l 2 -o "$work/curve_w.obj"
cmp -s "$work/curve_w.obj" "$work/curve_four-point.obj" && fail "refine --tension 0.1: same as 1/16" || pass
run refine-curve-tension-default 0 refine "$work/curves.obj" -s four-point --tension 0.0625 -l 2 -o "$work/curve_w16.obj"
cmp -s "$work/curve_w16.obj" "$work/curve_four-point.obj" && pass || fail "refine --tension 1/16 is not the default"
run refine-curve-tension-bad 1 refine "$work/curves.obj" -s cubic-bspline --tension 0.1 -o "$work/x.obj" &&
  stderr_one_line refine-curve-tension-bad && stderr_has refine-curve-tension-bad "has no tension"
run refine-surface-tension 1 refine "$meshes/cube.obj" --tension 0.1 -o "$work/x.obj" && stderr_one_line refine-surface-tension
run refine-curve-faces 1 refine "$meshes/cube.obj" -s chaikin -o "$work/x.obj" && stderr_one_line refine-curve-faces &&
  stderr_has refine-curve-faces "chaikin is a curve scheme and refines polylines, but the file has 6 faces"
printf 'v 0 0 0\nv 1 0 0\n' >"$work/points.obj"
run refine-curve-none 1 refine "$work/points.obj" -s cubic-bspline -o "$work/x.obj" && stderr_one_line refine-curve-none &&
  stderr_has refine-curve-none "no polylines"
printf 'v 0 0 0\nv 1 0 0\nv 2 1 0\nl 1 2 3\n' >"$work/short.obj"
run refine-curve-short 1 refine "$work/short.obj" -s four-point -o "$work/x.obj" && stderr_one_line refine-curve-short &&
  stderr_has refine-curve-short "short.obj:4: polyline 0: curve scheme 'four-point': an open polyline needs at least 4 points"
run refine-curve-surface 1 refine "$work/curves.obj" -s catmull-clark -o "$work/x.obj" &&
  stderr_one_line refine-curve-surface && stderr_has refine-curve-surface "need a curve scheme"
run refine-curve-option 1 refine "$work/curves.obj" -s chaikin --triangulate -o "$work/x.obj" &&
  stderr_one_line refine-curve-option
printf 'v 0 0 0\nv 1 0 0\nl 1 3\n' >"$work/bad_l.obj"
run refine-curve-badindex 1 refine "$work/bad_l.obj" -s chaikin -o "$work/x.obj" && stderr_one_line refine-curve-badindex &&
  stderr_has refine-curve-badindex "bad_l.obj:3: polyline 0 refers to vertex 3 but the file has 2 vertices"
printf 'v 0 0 0\nl 1\n' >"$work/one_l.obj"
run info-curve-onepoint 1 info "$work/one_l.obj" && stderr_one_line info-curve-onepoint && stderr_has info-curve-onepoint "one_l.obj:2:"
[ ! -e "$work/x.obj" ] && pass || fail "refine with a curve scheme wrote a file after an error"
run info-curves 0 info "$work/curves.obj" && stdout_has info-curves "polylines       2  (closed 1, points 9)" &&
  stdout_has info-curves "validation      ok"
run convert-curves 0 convert "$work/curves.obj" "$work/curves_copy.obj"
[ "$(grep '^l ' "$work/curves_copy.obj")" = "$(printf 'l 1 2 3 4 1\nl 5 6 7 8 9')" ] && pass ||
  fail "convert: polylines not kept"
run convert-curves-ply 0 convert "$work/curves.obj" "$work/curves.ply" && stderr_has convert-curves-ply "no place for polylines"
run schemes-curves 0 schemes
for scheme in cubic-bspline chaikin four-point; do
  grep -qE "^$scheme " "$work/out" && pass || fail "schemes: $scheme not listed"
done
[ "$(grep -c 'curve scheme (polylines' "$work/out")" -eq 3 ] && pass || fail "schemes: curve schemes not marked"

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
  stderr_has ps-limit-fold "warning: 1 vertex has no limit normal"

# Every shared mesh: exit 0 or 1, never a crash, and a failure is one line.
if [ -d "$shared" ]; then
  while IFS= read -r -d '' mesh; do
    timeout "$limit_s" "$SUBDIV" info "$mesh" >"$work/out" 2>"$work/err"
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
run depth-doo-sabin 0 depth "$meshes/cube.obj" -s doo-sabin --eps 0.01 --verify &&
  stdout_has depth-doo-sabin "bound (paper (regular) + local subdivision matrix (extraordinary)): distance to the limit after k >= 2 steps" &&
  stdout_has depth-doo-sabin "(worst at a face of 3 sides)" && stdout_has depth-doo-sabin "     4           1536           1538" &&
  stdout_has depth-doo-sabin "verify: after 4 steps" && stdout_has depth-doo-sabin ": within"
# four-eight: levels of two steps (its two-step quad split), verified with its own steps and limits.
run depth-four-eight 0 depth "$meshes/cube.obj" -s four-eight --eps 0.01 --verify &&
  stdout_has depth-four-eight "depth for accuracy 0.01: 5" && stdout_has depth-four-eight "refine -l 10" &&
  stdout_has depth-four-eight "     5           6146           6144" && stdout_has depth-four-eight "verify: after 10 steps" &&
  stdout_has depth-four-eight ": within"
run depth-butterfly 0 depth "$meshes/tetrahedron.obj" -s butterfly --eps 0.01 --verify &&
  stdout_has depth-butterfly "distance of the level's linear surface to the limit" && stdout_has depth-butterfly ": within"
# The rotating splits' interpolating schemes: levels of two steps (after two the faces nest).
run depth-interpolatory-sqrt3 0 depth "$meshes/tetrahedron.obj" -s interpolatory-sqrt3 --eps 0.01 --verify &&
  stdout_has depth-interpolatory-sqrt3 "distance of the level's linear surface to the limit" &&
  stdout_has depth-interpolatory-sqrt3 "refine -l 8" && stdout_has depth-interpolatory-sqrt3 "verify: after 8 steps" &&
  stdout_has depth-interpolatory-sqrt3 ": within"
run depth-interpolatory-sqrt3-open 1 depth "$meshes/l_shape.obj" -s interpolatory-sqrt3 --triangulate --eps 0.01 &&
  stderr_one_line depth-interpolatory-sqrt3-open &&
  stderr_has depth-interpolatory-sqrt3-open "no depth bound on a mesh with a boundary"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n' > "$work/square.obj"
run depth-doo-sabin-corner 0 depth "$work/square.obj" -s doo-sabin --eps 0.01 --verify &&
  stdout_has depth-doo-sabin-corner "after k >= 3 steps" && stdout_has depth-doo-sabin-corner ": within"
run depth-verify-budget 1 depth "$meshes/cube.obj" -s loop --triangulate --eps 1e-8 --verify &&
  stderr_one_line depth-verify-budget && stderr_has depth-verify-budget "--verify: level 23 has" &&
  stderr_has depth-verify-budget "over the verification budget of 2^28 faces"
run depth-bad-eps 1 depth "$meshes/cube.obj" -s loop --eps -1 && stderr_one_line depth-bad-eps &&
  stderr_has depth-bad-eps "--eps: must be a positive number, not -1" &&
  { [ "$(wc -c <"$work/err")" -lt 120 ] && pass || fail "depth-bad-eps: message too long: $(cat "$work/err")"; }
run depth-bad-file 1 depth "$data/index_out_of_range.obj" -s catmull-clark --eps 0.1 && stderr_one_line depth-bad-file

# adaptive: fewer faces than uniform refinement, a closed output.
run adaptive-cc 0 adaptive "$meshes/spot_control_mesh.obj" -s catmull-clark --eps 0.004 -o "$work/spot_adaptive.obj" &&
  stdout_has adaptive-cc "uniform refinement to the same accuracy"
run adaptive-info 0 info "$work/spot_adaptive.obj" && stdout_has adaptive-info "(boundary 0, non-manifold 0)" &&
  stdout_has adaptive-info "validation      ok"
run adaptive-bad-out 1 adaptive "$meshes/cube.obj" -s catmull-clark --eps 0.01 -o "$work/out.xyz" &&
  stderr_one_line adaptive-bad-out
# four-eight: its two-step quad split's hierarchy, levels of two steps.
run adaptive-four-eight 0 adaptive "$meshes/cube.obj" -s four-eight --eps 0.01 -o "$work/48_adaptive.obj" &&
  stdout_has adaptive-four-eight " of two steps, largest vertex-to-limit distance" &&
  stdout_has adaptive-four-eight "uniform refinement to the same accuracy: 6 steps"

# quasi 4-8: binary steps, --full-steps, tags from OBJ lines, the refusals.
run refine-q48 0 refine "$data/tagged_octagon.obj" -s quasi-4-8 -l 4 --quasi-boundary smoothed -o "$work/q48.obj" --stats &&
  stdout_has refine-q48 "level 1: 13 vertices, 16 faces" && stdout_has refine-q48 "level 4: 81 vertices, 128 faces"
# The tagged vertices (0 and 1 on the crease, corner 5) have not moved.
for v in "v 0 0 0" "v 1 0 0.2" "v -1 0 0.2"; do
  grep -qxF "$v" "$work/q48.obj" && pass || fail "refine-q48: tagged vertex '$v' moved"
done
grep -qF "t crease 2/1/0" "$work/q48.obj" && pass || fail "refine-q48: crease tags not written"
run refine-q48-full 0 refine "$data/tagged_octagon.obj" -s quasi-4-8 -l 2 --full-steps -o "$work/q48f.obj" --stats &&
  stdout_has refine-q48-full "scheme quasi-4-8, 4 levels" && stdout_has refine-q48-full "level 4: 81 vertices, 128 faces"
run refine-q48-crease 0 refine "$meshes/tetrahedron.obj" -s quasi-4-8 -l 3 --crease 0,1 --corner 2 -o "$work/q48t.obj" &&
  stdout_has refine-q48-crease "wrote"
run refine-q48-quads 1 refine "$meshes/cube.obj" -s quasi-4-8 -o "$work/x.obj" && stderr_one_line refine-q48-quads &&
  stderr_has refine-q48-quads "quasi-4-8 needs a triangle mesh"
run refine-q48-bad-crease 1 refine "$meshes/tetrahedron.obj" -s quasi-4-8 --crease 0,x -o "$work/x.obj" &&
  stderr_one_line refine-q48-bad-crease
run refine-full-steps-loop 1 refine "$meshes/tetrahedron.obj" -s loop --full-steps -o "$work/x.obj" &&
  stderr_one_line refine-full-steps-loop && stderr_has refine-full-steps-loop "--full-steps applies to quasi-4-8"
run limit-q48 1 limit "$meshes/tetrahedron.obj" -s quasi-4-8 -o "$work/x.obj" && stderr_one_line limit-q48

run analyze-q48 0 analyze -s quasi-4-8 -k 3..6 &&
  grep -qE "^3 +6 +3 +37 +0\.405113 +0\.405113 +0\.250000 .*Reif holds +regular: 1350 faces alike, winds once" "$work/out" &&
  pass || fail "analyze quasi-4-8: n=3 row"
run analyze-q48-json 1 analyze -s quasi-4-8 --json && stderr_one_line analyze-q48-json
run analyze-warmup-loop 1 analyze -s loop --warmup 2 && stderr_one_line analyze-warmup-loop

# sqrt3 on an open mesh: an odd level warns, and --start-level continues it
# exactly as refining both levels at once.
run sqrt3-level1 0 refine "$meshes/l_shape.obj" -s sqrt3 --triangulate -l 1 -o "$work/s1.obj" &&
  stderr_one_line sqrt3-level1 && stderr_has sqrt3-level1 "s1.obj is at level 1 of sqrt3" &&
  stderr_has sqrt3-level1 "--start-level 1"
run sqrt3-continue 0 refine "$work/s1.obj" -s sqrt3 -l 1 --start-level 1 -o "$work/s2.obj" && [ ! -s "$work/err" ] && pass ||
  fail "sqrt3-continue: warned at an even level"
run sqrt3-at-once 0 refine "$meshes/l_shape.obj" -s sqrt3 --triangulate -l 2 -o "$work/s2b.obj"
cmp -s <(grep '^v ' "$work/s2.obj") <(grep '^v ' "$work/s2b.obj") && pass || fail "sqrt3: 1 + 1 levels with --start-level differ from 2"
run sqrt3-closed 0 refine "$meshes/tetrahedron.obj" -s sqrt3 -l 1 -o "$work/s3.obj" && [ ! -s "$work/err" ] && pass ||
  fail "sqrt3-closed: warned on a closed mesh"
run start-level-quad 1 refine "$meshes/cube.obj" -l 1 --start-level 1 -o "$work/x.obj" &&
  stderr_one_line start-level-quad && stderr_has start-level-quad "--start-level applies to the sqrt3 split"

# Hierarchical edits: convert keeps them; refine and limit -l apply those
# within the levels made and say what they drop; adaptive drops them all.
edits=$data/hierarchical_edits.obj
run convert-edits 0 convert "$edits" "$work/e.obj" && [ ! -s "$work/err" ] && pass || fail "convert-edits: warned"
[ "$(grep -c '^t vertexedit\|^t faceedit' "$work/e.obj")" -eq 3 ] && pass || fail "convert-edits: edits not written back"
for cmd in "refine -l 1" "limit -l 1"; do
  name="edits-${cmd%% *}"
  run "$name" 0 $cmd "$edits" -s catmull-clark -o "$work/e.obj" && stderr_one_line "$name" &&
    stderr_has "$name" "hierarchical_edits.obj: 1 tags not applied dropped from the refined mesh (1 faceedit): their edits lie below the 1 levels made"
  grep -q '^t .*edit' "$work/e.obj" && fail "$name: edits written to the refined mesh" || pass
done
run edits-adaptive 0 adaptive --eps 0.1 "$edits" -s catmull-clark -o "$work/e.obj" && stderr_one_line edits-adaptive &&
  stderr_has edits-adaptive "hierarchical_edits.obj: 3 tags not applied dropped from the refined mesh (2 vertexedit, 1 faceedit): their indices name"
# Two levels apply all three; the hole is written as a hole tag.
run edits-refine-2 0 refine "$edits" -s catmull-clark -l 2 -o "$work/e2.obj" && [ ! -s "$work/err" ] && pass ||
  fail "edits-refine-2: warned: $(cat "$work/err")"
[ "$(grep -c '^t hole' "$work/e2.obj")" -ge 1 ] && pass || fail "edits-refine-2: no hole written"
run edits-loop 0 refine "$edits" -s loop --triangulate -l 1 -o "$work/e.obj" && stderr_has edits-loop "3 tags not applied"
# The second tag is malformed: the error names it by its rank in the file.
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nt vertexedit 3/3/3 2 0 1 0 0 1 add P value\nt vertexedit 3/3/3 2 0 7 0 0 1 add P value\n' > "$work/bad_edit.obj"
run edits-bad 1 refine "$work/bad_edit.obj" -s catmull-clark -o "$work/e.obj" && stderr_one_line edits-bad &&
  stderr_has edits-bad "bad_edit.obj: vertexedit tag 2: corner 7 on face 0's path is not in 0..3"
run edits-limit-0 0 limit "$edits" -s catmull-clark -o "$work/e.obj" && [ ! -s "$work/err" ] && pass || fail "edits-limit-0: warned"

# ---- Issue 22 (wrong answers): interior valence-2 vertices in limit, depth
# and adaptive; semi-sharp features in limit; hierarchical edits on
# refinement. Shared meshes: skipped with a note when absent.
val2=$shared/opensubdiv/catmark_val2_interior.obj
suzanne=$shared/common3d/suzanne.obj
creases1=$shared/opensubdiv/catmark_cube_creases1.obj
if [ -f "$val2" ] && [ -f "$suzanne" ] && [ -f "$creases1" ]; then
  # Catmull-Clark keeps a valence-2 vertex at valence 2; limit, depth and
  # adaptive handle it wherever refine does.
  for m in "$val2" "$suzanne"; do
    n=$(basename "$m" .obj)
    run "limit-val2-$n" 0 limit "$m" -s catmull-clark -o "$work/v2.obj" &&
      stdout_has "limit-val2-$n" "vertices at their catmull-clark limit positions (closed-form masks)"
    [ ! -s "$work/err" ] && pass || fail "limit-val2-$n: unexpected warnings: $(cat "$work/err")"
    run "limit-val2-generic-$n" 0 limit "$m" -s catmull-clark --masks generic --isolation-levels 5 -o "$work/v2.obj"
    run "depth-val2-$n" 0 depth "$m" -s catmull-clark --eps 0.01 --verify && stdout_has "depth-val2-$n" ": within"
    run "adaptive-val2-$n" 0 adaptive "$m" -s catmull-clark --eps 0.01 -o "$work/v2a.obj" &&
      stdout_has "adaptive-val2-$n" "(accuracy 0.01)"
  done
  # Two triangles around a vertex have no configuration: depth names the
  # vertex and its line; limit and adaptive need no bound.
  run depth-val2-loop 1 depth "$suzanne" -s loop --triangulate --allow-non-manifold --eps 0.01 &&
    stderr_one_line depth-val2-loop && stderr_has depth-val2-loop "suzanne.obj:289: vertex 137: no depth bound"
  run limit-val2-loop 0 limit "$suzanne" -s loop --triangulate --allow-non-manifold -o "$work/v2l.obj" &&
    stdout_has limit-val2-loop "507 vertices at their loop limit positions (closed-form masks)"
  # Level 1's two vertices at the merged edges match no configuration: said.
  run adaptive-val2-loop 0 adaptive "$suzanne" -s loop --triangulate --allow-non-manifold --eps 0.01 -o "$work/v2la.obj" &&
    stderr_has adaptive-val2-loop "only approximated, and the accuracy is not established there"

  # catmark_cube_creases1: sharpness 5 needs 5 levels. The default resolves
  # it; the semi-sharp corners are not kept where they are (their limit is
  # inside the cube, as the generic masks after 6 levels give).
  run limit-creases1 0 limit "$creases1" -o "$work/c1.obj" &&
    stdout_has limit-creases1 "8 vertices at their catmull-clark limit positions (closed-form masks)"
  [ ! -s "$work/err" ] && pass || fail "limit-creases1: unexpected warnings: $(cat "$work/err")"
  run limit-creases1-generic6 0 limit "$creases1" --masks generic --isolation-levels 6 -o "$work/c1g.obj"
  paste -d' ' <(grep '^v ' "$work/c1.obj") <(grep '^v ' "$work/c1g.obj") |
    awk '{d = ($2 - $6)^2 + ($3 - $7)^2 + ($4 - $8)^2; if (d > 1e-20) bad = 1; if (NR == 1 && ($4 > 0.99 || $4 < 0.98)) bad = 1}
         END{exit bad || NR != 8}' && pass || fail "limit-creases1: closed-form and generic limits differ, or a corner was kept"
  # Too few generic levels: the warning says why and what resolves them, and
  # the summary counts the same vertices; its suggestion then works.
  run limit-creases1-generic 0 limit "$creases1" --masks generic -o "$work/c1g.obj" &&
    stdout_has limit-creases1-generic "8 vertices, 0 at their catmull-clark limit positions (generic masks), 8 at their positions after 2 levels" &&
    stderr_one_line limit-creases1-generic &&
    stderr_has limit-creases1-generic "8 vertices are at or next to semi-sharp features still unresolved after 2 levels (sharpness up to 3 left: --isolation-levels 5 resolves them)"
  run limit-creases1-generic5 0 limit "$creases1" --masks generic --isolation-levels 5 -o "$work/c1g.obj" &&
    stdout_has limit-creases1-generic5 "8 vertices at their catmull-clark limit positions (generic masks)"
  [ ! -s "$work/err" ] && pass || fail "limit-creases1-generic5: unexpected warnings: $(cat "$work/err")"
else
  echo "cli: issue 22 checks skipped: shared meshes absent ($shared)"
fi

# No silent losses: what a command cannot carry it says, or it refuses.
run convert-invalid 0 convert "$data/nan_coordinate.obj" "$work/nan.obj" &&
  stderr_one_line convert-invalid && stderr_has convert-invalid "nan_coordinate.obj: the mesh is not valid and is written as it is: line" &&
  stdout_has convert-invalid "1 face"
run convert-invalid-refused 1 convert "$data/nan_coordinate.obj" "$work/nan2.obj" --validate &&
  stderr_one_line convert-invalid-refused
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2 5 6 3\nt hole 1/0/0 1\n' >"$work/hole.obj"
run convert-hole-ply 0 convert "$work/hole.obj" "$work/hole.ply" --ascii &&
  stderr_has convert-hole-ply "1 hole face left out" && grep -q "^element face 1$" "$work/hole.ply" && pass ||
  fail "convert-hole-ply: the hole face was written"
run convert-hole-kept 0 convert "$work/hole.obj" "$work/hole_kept.ply" --ascii --keep-hole-faces &&
  grep -q "^element face 2$" "$work/hole_kept.ply" && pass || fail "convert --keep-hole-faces: the hole face was left out"
run convert-hole-obj 0 convert "$work/hole.obj" "$work/hole_copy.obj" && [ "$(grep -c '^f ' "$work/hole_copy.obj")" -eq 2 ] &&
  pass || fail "convert-hole-obj: OBJ keeps hole faces with their tag"
run adaptive-hole 1 adaptive "$work/hole.obj" --eps 0.01 -o "$work/x.obj" && stderr_one_line adaptive-hole &&
  stderr_has adaptive-hole "hole.obj: face 1 is tagged as a hole"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\nt crease 2/1/0 0 1 10\n' >"$work/normals.obj"
run refine-normals 0 refine "$work/normals.obj" -l 1 -o "$work/n1.obj" && stderr_one_line refine-normals &&
  stderr_has refine-normals "input normals dropped" && ! grep -q '^vn ' "$work/n1.obj" && pass ||
  fail "refine-normals: input normals carried into the refined mesh"
run adaptive-losses 0 adaptive "$work/normals.obj" --eps 0.001 -o "$work/na.obj" &&
  stderr_has adaptive-losses "input normals dropped" && stderr_has adaptive-losses "does not carry 1 crease tag"
run refine-curve-ply 1 refine "$work/curves.obj" -s chaikin -o "$work/curve.ply" && stderr_one_line refine-curve-ply &&
  stderr_has refine-curve-ply "has no place for polylines"
[ ! -e "$work/curve.ply" ] && pass || fail "refine-curve-ply: wrote a file"

# Work that cannot fit is refused before it starts, with the estimate.
run refine-memory 1 refine "$meshes/spot_control_mesh.obj" -l 12 -o "$work/huge.obj" && stderr_one_line refine-memory &&
  stderr_has refine-memory "refine to level 12 needs about" && stderr_has refine-memory "--no-memory-check"
[ ! -e "$work/huge.obj" ] && pass || fail "refine-memory: wrote a file"
run limit-memory 1 limit "$meshes/spot_control_mesh.obj" -l 12 -o "$work/huge.obj" && stderr_one_line limit-memory

# One program: typos get suggestions, ranges their syntax, -q silences all but errors.
run typo-scheme 1 refine "$meshes/cube.obj" -s catmul-clark -o "$work/x.obj" && stderr_one_line typo-scheme &&
  stderr_has typo-scheme "did you mean 'catmull-clark'?"
run typo-command 1 refne "$meshes/cube.obj" && stderr_one_line typo-command && stderr_has typo-command "did you mean 'refine'?"
run k-dash 1 analyze -s loop -k 3-8 && stderr_one_line k-dash && stderr_has k-dash "a range is written 3..8"
run eps-inf 1 depth "$meshes/cube.obj" --eps inf && stderr_one_line eps-inf && stderr_has eps-inf "not inf" &&
  stderr_has eps-inf "finite"
run quiet-refine 0 refine "$work/normals.obj" -l 1 -o "$work/nq.obj" -q && [ ! -s "$work/err" ] && pass ||
  fail "refine -q: printed on stderr: $(cat "$work/err")"
run quiet-first 0 -q convert "$data/nan_coordinate.obj" "$work/nanq.obj" && [ ! -s "$work/err" ] && pass ||
  fail "-q convert: printed on stderr: $(cat "$work/err")"
run quiet-limit 0 limit "$meshes/cube.obj" -o "$work/lq.obj" -q

# One support matrix, from the library's own checks: what it says no to, the command refuses with the same reason.
run schemes-matrix 0 schemes --matrix &&
  grep -qE '^catmull-clark +yes +yes +yes +yes +yes +yes$' "$work/out" && pass || fail "schemes --matrix: catmull-clark row"
grep -qE '^midedge +yes +yes +no \([0-9]+\) ' "$work/out" && grep -q "no depth bound for the midedge split" "$work/out" && pass ||
  fail "schemes --matrix: midedge's depth"
sed -n '/<!-- schemes-matrix -->/,/<!-- \/schemes-matrix -->/p' "$project_dir/README.md" | sed '1,2d;$d' | sed '$d' \
  >"$work/readme_matrix" && diff -q "$work/out" "$work/readme_matrix" >/dev/null && pass ||
  fail "README.md's support matrix differs from 'subdiv schemes --matrix' (paste the command's output)"
run depth-midedge-refused 1 depth "$meshes/cube.obj" -s midedge --eps 0.01 &&
  stderr_one_line depth-midedge-refused && stderr_has depth-midedge-refused "no depth bound for the midedge split"
run depth-sqrt3 0 depth "$meshes/cube.obj" -s sqrt3 --triangulate --eps 0.01 --verify &&
  stdout_has depth-sqrt3 "of a period of 2 steps" && stdout_has depth-sqrt3 ": within"
# The sqrt3 split's faces nest every two steps: adaptive refinement walks those levels.
run adaptive-sqrt3 0 adaptive "$meshes/l_shape.obj" -s sqrt3 --triangulate --eps 0.002 -o "$work/a3.obj" &&
  stdout_has adaptive-sqrt3 " of two steps, largest vertex-to-limit distance" &&
  stdout_has adaptive-sqrt3 "uniform refinement to the same accuracy: 8 steps"
run adaptive-sqrt3-info 0 info "$work/a3.obj" && stdout_has adaptive-sqrt3-info "validation      ok" &&
  stdout_has adaptive-sqrt3-info "boundary loops  1"
run adaptive-midedge 0 adaptive "$meshes/cube.obj" -s midedge --eps 0.005 -o "$work/ame.obj" &&
  stdout_has adaptive-midedge " of two steps, largest vertex-to-limit distance"
# Piecewise-smooth rules at an edge-only boundary: the generic masks give
# every limit (one-face boundary vertices included), so the bound holds.
run limit-edge-only-piecewise 0 limit "$meshes/l_shape.obj" -o "$work/x.obj" --boundary edge-only \
  --boundary-rules piecewise-smooth && stdout_has limit-edge-only-piecewise "21 vertices at their catmull-clark limit positions"
run depth-edge-only-piecewise 0 depth "$meshes/l_shape.obj" --eps 0.01 --boundary edge-only \
  --boundary-rules piecewise-smooth --verify && stdout_has depth-edge-only-piecewise ": within"

# One program: the options of every command that refines, the same everywhere.
for command in "limit -o $work/ro_limit.obj" "depth --eps 0.01" "adaptive --eps 0.05 --max-level 3 -o $work/ro_adaptive.obj"; do
  set -- $command
  name=$1
  shift
  run "$name-rule-options" 0 "$name" "$meshes/l_shape.obj" "$@" -s catmull-clark --boundary edge-only \
    --crease-method chaikin --boundary-rules piecewise-smooth --corner 0:convex --crease 0,1 --threads 1
  run "$name-triangulate" 0 "$name" "$meshes/cube.obj" "$@" -s loop --triangulate
  run "$name-tension" 1 "$name" "$meshes/cube.obj" "$@" --tension 0.1 && stderr_one_line "$name-tension" &&
    stderr_has "$name-tension" "--tension applies to"
  run "$name-quasi-boundary" 1 "$name" "$meshes/cube.obj" "$@" --quasi-boundary smoothed &&
    stderr_has "$name-quasi-boundary" "--quasi-boundary applies to quasi-4-8, not to catmull-clark"
  run "$name-flatness" 1 "$name" "$meshes/cube.obj" "$@" --flatness 0.5 &&
    stderr_has "$name-flatness" "--flatness applies to --boundary-rules piecewise-smooth"
  run "$name-crease-range" 1 "$name" "$meshes/cube.obj" "$@" --crease 0,99 &&
    stderr_has "$name-crease-range" "vertex 99 is not in the mesh (8 vertices)"
  run "$name-stats" 0 "$name" "$meshes/cube.obj" "$@" --stats && stdout_has "$name-stats" "read " &&
    grep -qE '[0-9]\.[0-9]{3} s' "$work/out" && pass || fail "$name --stats: no phase times"
done
# A rule option changes the answer where it applies: edge-only moves the
# L-shape's boundary away from its control polygon, so the bound differs.
run depth-edge-and-corner 0 depth "$meshes/l_shape.obj" --eps 0.001 --json && cp "$work/out" "$work/depth_eac.json"
run depth-edge-only 0 depth "$meshes/l_shape.obj" --eps 0.001 --json --boundary edge-only
cmp -s "$work/out" "$work/depth_eac.json" && fail "depth --boundary edge-only: the same document as edge-and-corner" ||
  pass

# Options that do not apply are refused in one line, never ignored.
run ascii-obj 1 refine "$meshes/cube.obj" -o "$work/x.obj" --ascii && stderr_one_line ascii-obj &&
  stderr_has ascii-obj "--ascii applies to PLY and STL output"
run big-endian-obj 1 convert "$meshes/cube.obj" "$work/x.obj" --big-endian && stderr_has big-endian-obj "applies to PLY"
run no-tags-ply 1 convert "$meshes/cube.obj" "$work/x.ply" --no-tags && stderr_has no-tags-ply "applies to OBJ and glTF output"
run hole-faces-obj 1 convert "$meshes/cube.obj" "$work/x.obj" --keep-hole-faces &&
  stderr_has hole-faces-obj "applies to PLY, OFF and STL output"
run isolation-closed-form 1 limit "$meshes/cube.obj" -o "$work/x.obj" --isolation-levels 3 &&
  stderr_has isolation-closed-form "--isolation-levels applies to the generic masks" &&
  run isolation-generic 0 limit "$meshes/cube.obj" -o "$work/x.obj" --isolation-levels 3 --masks generic
run closed-form-butterfly 1 limit "$meshes/cube.obj" -s butterfly --triangulate --masks closed-form -o "$work/x.obj" &&
  stderr_has closed-form-butterfly "butterfly has no closed-form limit masks"
run corner-angles-standard 1 refine "$meshes/cube.obj" -o "$work/x.obj" --corner-angles measured &&
  stderr_has corner-angles-standard "--corner-angles applies to --boundary-rules piecewise-smooth"
run analyze-flatness 1 analyze -s loop --flatness 0.5 && stderr_has analyze-flatness "--flatness applies to"
run triangulate-quads 1 refine "$meshes/cube.obj" -s catmull-clark --triangulate -o "$work/x.obj" &&
  stderr_one_line triangulate-quads && stderr_has triangulate-quads "--triangulate applies to the schemes that read triangles (loop"

# adaptive refuses at once what cannot fit, with the a-priori bound's depth.
run adaptive-memory 1 adaptive "$meshes/spot_control_mesh.obj" --eps 1e-9 --max-level 12 -o "$work/huge.obj" &&
  stderr_one_line adaptive-memory && stderr_has adaptive-memory "adaptive refinement over 12 uniform levels" &&
  stderr_has adaptive-memory "the a-priori bound for accuracy 1e-09 needs" && stderr_has adaptive-memory "--no-memory-check"
[ ! -e "$work/huge.obj" ] && pass || fail "adaptive-memory: wrote a file"

# Plurals: one of a thing is singular.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$work/one_triangle.obj"
run plural-refine 0 refine "$work/one_triangle.obj" -s loop -l 0 -o "$work/one.obj" --stats &&
  stdout_has plural-refine "3 vertices, 1 face" && stdout_has plural-refine "0 levels"

# --json: one document on stdout, with the keys docs/cli.md lists.
json_keys() {  # NAME KEY...: the document in $work/out has these top-level keys
  local name=$1
  shift
  command -v python3 >/dev/null 2>&1 || return 0
  python3 -c '
import json, sys
doc = json.load(open(sys.argv[1]))
missing = [k for k in sys.argv[2:] if k not in doc]
sys.exit("missing: " + ", ".join(missing) if missing else 0)' "$work/out" "$@" && pass || fail "$name --json: not JSON with $*"
}
run json-info 0 info "$meshes/cube.obj" --json &&
  json_keys json-info command input format vertices faces edges face_sizes valences tags valid errors warnings issues
run json-info-invalid 1 info "$data/nonmanifold_edge.obj" --json && stderr_one_line json-info-invalid &&
  json_keys json-info-invalid valid issues
run json-refine 0 refine "$meshes/cube.obj" -l 2 -o "$work/j.obj" --json &&
  json_keys json-refine command input output scheme threads levels seconds
run json-refine-curve 0 refine "$work/curves.obj" -s chaikin -l 2 -o "$work/jc.obj" --json &&
  json_keys json-refine-curve command scheme levels seconds
run json-limit 0 limit "$meshes/cube.obj" -o "$work/j.obj" --json --normals &&
  json_keys json-limit command scheme masks vertices at_limit no_normal seconds
run json-depth 0 depth "$meshes/cube.obj" --eps 0.01 --verify --json &&
  json_keys json-depth command scheme eps bound depth bound_at_depth levels trade_off verify seconds
run json-adaptive 0 adaptive "$meshes/cube.obj" --eps 0.01 -o "$work/j.obj" --json &&
  json_keys json-adaptive command scheme eps vertices faces transition_faces largest_distance bound_steps uniform seconds
if command -v python3 >/dev/null 2>&1; then
  python3 -c '
import json, sys
doc = json.load(sys.stdin)
assert doc["largest_distance"] <= doc["eps"], doc
assert doc["bound_steps"] >= doc["uniform"]["steps"], doc
' <"$work/out" && pass || fail "adaptive --json: a distance over eps, or the bound below the measured depth"
fi

# render: a PNG of the asked size; the same command twice gives the same
# bytes; two schemes give different pictures; bad options are one line.
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{printf "%dx%d", $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}'; }
if run render-cube 0 render "$meshes/cube.obj" -s catmull-clark -l 3 --size 320x240 -o "$work/cube_a.png"; then
  stdout_has render-cube "wrote $work/cube_a.png: 320x240, catmull-clark, 3 levels"
  stdout_has render-cube "shaded by limit normals"
  [ "$(png_size "$work/cube_a.png")" = 320x240 ] && pass || fail "render-cube: PNG size $(png_size "$work/cube_a.png")"
fi
run render-cube-again 0 render "$meshes/cube.obj" -s catmull-clark -l 3 --size 320x240 -o "$work/cube_b.png" &&
  { cmp -s "$work/cube_a.png" "$work/cube_b.png" && pass || fail "render: the same command gave different bytes"; }
run render-cube-doo-sabin 0 render "$meshes/cube.obj" -s doo-sabin -l 3 --size 320x240 -o "$work/cube_ds.png" &&
  { cmp -s "$work/cube_a.png" "$work/cube_ds.png" && fail "render: doo-sabin and catmull-clark gave the same picture" || pass; }
run render-as-given 0 render "$meshes/l_shape.obj" --cage --wireframe --view -30,60 --background black -o "$work/l.png" &&
  stdout_has render-as-given "the mesh as given"
run render-json 0 render "$meshes/tetrahedron.obj" -s loop --json -o "$work/t.png" &&
  python3 -c 'import json,sys; d=json.load(sys.stdin); assert d["command"]=="render" and d["levels"]==3 and d["faces"]==256, d' <"$work/out" &&
  pass || fail "render --json: unexpected document"
for bad in "--size 0x10" "--size 12" "--view 10" "--view 0,95" "--background #12345" "--samples 9"; do
  # shellcheck disable=SC2086
  run "render $bad" 1 render "$meshes/cube.obj" $bad -o "$work/bad.png" && stderr_one_line "render $bad"
done
run render-not-png 1 render "$meshes/cube.obj" -o "$work/cube.jpg" && stderr_has render-not-png "render writes PNG images"
[ ! -e "$work/bad.png" ] && [ ! -e "$work/cube.jpg" ] && pass || fail "render: a refused command wrote a file"
run render-nonmanifold 1 render "$data/nonmanifold_edge.obj" -s loop -o "$work/nm.png" && stderr_one_line render-nonmanifold

# compare: a self-contained page (three.js inlined: no external script or
# module address), a PNG grid, the schemes asked for, and one-line errors.
if run compare-tetra 0 compare "$meshes/tetrahedron.obj" -s loop,butterfly,catmull-clark -l 2 -o "$work/t.html" --png "$work/t.png" --size 120x100 --columns 2; then
  stdout_has compare-tetra "the control mesh and 3 schemes at level 2"
  grep -q 'src="http\|from "http\|import(.http' "$work/t.html" && fail "compare: the page loads something from the network" || pass
  [ "$(grep -c '"title":"butterfly"' "$work/t.html")" = 1 ] && pass || fail "compare: no butterfly panel in the page"
  # Two columns of 120 px (8 px gaps) for four pictures: 264 px wide.
  [ "$(png_size "$work/t.png" | cut -dx -f1)" = 264 ] && pass || fail "compare --png: grid size $(png_size "$work/t.png")"
fi
run compare-all-tetra 0 compare "$meshes/tetrahedron.obj" -l 1 -o "$work/all.html" &&
  { grep -q "kobbelt left out" "$work/err" && pass || fail "compare -s all: no warning for kobbelt on triangles"; }
run compare-kobbelt-tetra 1 compare "$meshes/tetrahedron.obj" -s kobbelt -o "$work/k.html" &&
  stderr_one_line compare-kobbelt-tetra
run compare-triangulated 0 compare "$meshes/rook.obj" -s catmull-clark,catmull-clark/triangulated -l 1 --json -o "$work/r.html" &&
  python3 -c 'import json,sys; p=json.load(sys.stdin)["panels"]; assert [x["scheme"] for x in p]==["catmull-clark","catmull-clark/triangulated"] and p[1]["faces"]>p[0]["faces"], p' <"$work/out" &&
  pass || fail "compare /triangulated: unexpected panels"
run compare-bad-suffix 1 compare "$meshes/cube.obj" -s loop/quads -o "$work/u.html" && stderr_has compare-bad-suffix "the only suffix is /triangulated"
run compare-unknown 1 compare "$meshes/cube.obj" -s loop,lop -o "$work/u.html" && stderr_has compare-unknown "unknown scheme 'lop'"
run compare-twice 1 compare "$meshes/cube.obj" -s loop,loop -o "$work/u.html" && stderr_has compare-twice "listed twice"
run compare-not-html 1 compare "$meshes/cube.obj" -o "$work/u.htm" && stderr_one_line compare-not-html
run compare-bad-png 1 compare "$meshes/cube.obj" -o "$work/u.html" --png "$work/u.jpg" && stderr_one_line compare-bad-png
[ ! -e "$work/u.html" ] && [ ! -e "$work/k.html" ] && pass || fail "compare: a refused command wrote a page"

# Every command on every shared mesh that refine accepts (meshes under
# 200 kB, one level), with -q: success, or one stderr line and exit 1; never
# exit 2, a crash or a run past 30 s (tessellate exact only: by refinement
# at the default accuracy, catmark_rook's sharpness 7.9 takes 27 s to refuse). Release builds only (SUBDIV_CLI_SWEEP:
# under the sanitizers it would take most of CI's time).
if [ -d "$shared" ] && [ "${SUBDIV_CLI_SWEEP:-0}" = 1 ]; then
  while IFS= read -r -d '' mesh; do
    timeout 30 "$SUBDIV" refine "$mesh" -o "$work/sweep.obj" -q >/dev/null 2>"$work/err" || continue
    for args in "limit -o $work/sweep_limit.obj" "depth --eps 0.01" "adaptive --eps 0.05 --max-level 3 -o $work/sweep_adaptive.obj" \
                "convert $work/sweep.ply" "info" "render -l 1 --size 64x48 -o $work/sweep.png" \
                "tessellate --rate 2 --exact -o $work/sweep_tessellation.obj"; do
      set -- $args
      command=$1
      shift
      timeout 30 "$SUBDIV" "$command" "$mesh" "$@" -q >/dev/null 2>"$work/err"
      code=$?
      if [ "$code" -ne 0 ] && [ "$code" -ne 1 ]; then
        fail "$command $mesh: exit $code: $(head -c 300 "$work/err")"
      elif [ "$code" -eq 1 ] && [ "$(wc -l <"$work/err")" -ne 1 ]; then
        fail "$command $mesh: exit 1 without exactly one stderr line: $(head -c 300 "$work/err")"
      else
        pass
      fi
    done
  done < <(find "$shared" -name '*.obj' -size -200k -print0 | sort -z)
fi

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
