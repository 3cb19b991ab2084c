#!/usr/bin/env bash
# The comparison page as a user opens it: `subdiv compare` writes it, then
# Debian's chromium loads it from the file (viewer/tests/compare_page_test.mjs:
# no console errors, every panel drawn, the toggles change the picture).
# Also checks that the three.js compiled into the page is the npm package
# viewer/package-lock.json pins. Usage: compare_page_test.sh PROJECT_DIR,
# with $SUBDIV the program; needs `npm ci` in viewer/ (scripts/test.sh).
set -euo pipefail
project_dir=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

three=$project_dir/viewer/node_modules/three
if [ ! -d "$three" ] || [ ! -d "$project_dir/viewer/node_modules/playwright-core" ]; then
  echo "FAIL: viewer/node_modules is missing: run 'npm ci' in viewer/ (scripts/test.sh does)"
  exit 1
fi
cmp "$project_dir/tools/compare/vendor/three.module.min.js" "$three/build/three.module.min.js"
cmp "$project_dir/tools/compare/vendor/OrbitControls.js" "$three/examples/jsm/controls/OrbitControls.js"

"$SUBDIV" compare "$project_dir/data/meshes/cube.obj" -l 3 --json -o "$work/cube.html" --png "$work/cube.png" \
  >"$work/summary.json"
panels=$(python3 -c 'import json,sys; print(1 + len(json.load(sys.stdin)["panels"]))' <"$work/summary.json")
node "$project_dir/viewer/tests/compare_page_test.mjs" "$work/cube.html" "$panels"
