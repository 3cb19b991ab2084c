#!/usr/bin/env bash
# glTF written by subdiv, checked by the Khronos glTF Validator (npm
# gltf-validator, pinned in viewer/package-lock.json): the bundled meshes
# (polygons, UV seams, tags) converted to .gltf and .glb, and refined ones.
# No error and no warning may be reported. Usage: gltf_validator_test.sh
# PROJECT_DIR, with $SUBDIV the program; needs `npm ci` in viewer/.
set -euo pipefail
project_dir=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if [ ! -d "$project_dir/viewer/node_modules/gltf-validator" ]; then
  echo "FAIL: viewer/node_modules is missing: run 'npm ci' in viewer/ (scripts/test.sh does)"
  exit 1
fi
meshes=$project_dir/data/meshes
files=()
for mesh in cube rook spot_control_mesh l_shape; do
  "$SUBDIV" -q convert "$meshes/$mesh.obj" "$work/$mesh.gltf" >/dev/null
  "$SUBDIV" -q convert "$meshes/$mesh.obj" "$work/$mesh.glb" >/dev/null
  files+=("$work/$mesh.gltf" "$work/$mesh.glb")
done
"$SUBDIV" -q convert "$project_dir/tests/data/tagged_octagon.obj" "$work/octagon.glb" >/dev/null
"$SUBDIV" -q refine "$meshes/spot_control_mesh.obj" -s catmull-clark -l 2 -o "$work/spot_cc.glb" >/dev/null
"$SUBDIV" -q refine "$meshes/spot_control_mesh.obj" -s loop --triangulate -l 1 -o "$work/spot_loop.gltf" >/dev/null
"$SUBDIV" -q limit "$meshes/cube.obj" -s catmull-clark -o "$work/cube_limit.gltf" >/dev/null
files+=("$work/octagon.glb" "$work/spot_cc.glb" "$work/spot_loop.gltf" "$work/cube_limit.gltf")
node "$project_dir/viewer/tests/validate_gltf.mjs" "${files[@]}"
