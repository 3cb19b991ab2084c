#!/usr/bin/env bash
# Installs what is missing, builds, and runs subdiv on the bundled meshes:
# inspects each one and converts it to PLY and OFF under out/.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
bash scripts/build.sh
subdiv=build/tools/subdiv/subdiv
mkdir -p out
for mesh in data/meshes/*.obj; do
  name=$(basename "$mesh" .obj)
  echo "== $mesh"
  "$subdiv" info "$mesh"
  "$subdiv" convert "$mesh" "out/$name.ply"
  "$subdiv" convert "$mesh" "out/$name.off"
done
echo "demo: results in out/"
