#!/usr/bin/env bash
# Installs what is missing, builds, and runs subdiv on the bundled meshes:
# inspects each one, converts it to PLY, OFF, glTF and STL, refines it with
# Catmull-Clark (and the triangle meshes with Loop), and moves its vertices
# to their limit positions; then subdivides the cube and the tetrahedron with
# every surface scheme (the survey's comparison), analyses Loop,
# Catmull-Clark, the Butterfly schemes and Doo-Sabin with pictures, refines
# the L-shaped patch with the standard and the piecewise-smooth boundary
# rules, and refines Spot to an accuracy (a priori depth, adaptive
# refinement), and runs one Python example. Pictures (PNG) of the refined
# surfaces, and the survey's comparison figures as web pages and PNG grids.
# Results under out/.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
bash scripts/build.sh --tool  # the program and the Python module: no tests or benchmarks compiled
subdiv=build/tools/subdiv/subdiv
mkdir -p out
for mesh in data/meshes/*.obj; do
  name=$(basename "$mesh" .obj)
  echo "== $mesh"
  "$subdiv" info "$mesh"
  "$subdiv" convert "$mesh" "out/$name.ply"
  "$subdiv" convert "$mesh" "out/$name.off"
  "$subdiv" -q convert "$mesh" "out/$name.glb"  # polygons kept in subdiv's extras; viewers see triangles
  "$subdiv" -q convert "$mesh" "out/$name.stl"
  if [ "$name" = "elephant" ] || [ "$name" = "tetrahedron" ]; then
    "$subdiv" refine "$mesh" -s loop -l 2 -o "out/${name}_loop2.obj"
  fi
  "$subdiv" refine "$mesh" -s catmull-clark -l 2 -o "out/${name}_catmull_clark2.obj"
  "$subdiv" -q refine "out/$name.glb" -s catmull-clark -l 2 -o "out/${name}_catmull_clark2.glb"
  "$subdiv" limit "$mesh" -s catmull-clark --normals -o "out/${name}_catmull_clark_limit.obj"
  "$subdiv" render "$mesh" -s catmull-clark -l 3 --cage -o "out/${name}_catmull_clark3.png"
done
echo "== the cube and the tetrahedron with every surface scheme (4 levels)"
for mesh in cube tetrahedron; do
  for scheme in catmull-clark loop butterfly modified-butterfly doo-sabin midedge sqrt3 interpolatory-sqrt3 \
                four-eight gcc midpoint quasi-4-8; do
    triangulate=()  # the schemes that read triangles get the triangulated mesh
    case "$scheme" in loop | butterfly | modified-butterfly | sqrt3 | interpolatory-sqrt3 | quasi-4-8) triangulate=(--triangulate) ;; esac
    "$subdiv" refine "data/meshes/$mesh.obj" -s "$scheme" "${triangulate[@]}" -l 4 -o "out/${mesh}_${scheme}4.obj"
  done
done
echo "== the survey's comparison figures: every surface scheme on the cube and the tetrahedron, and a rook"
echo "   under Loop, Catmull-Clark and Catmull-Clark on its triangulation (web pages and PNG grids)"
for mesh in cube tetrahedron; do
  "$subdiv" compare "data/meshes/$mesh.obj" -l 3 -q -o "out/survey_$mesh.html" --png "out/survey_$mesh.png" --size 300x300 --columns 6
done
"$subdiv" compare data/meshes/rook.obj -s catmull-clark,loop,catmull-clark/triangulated -l 3 --view 30,25 \
  -o out/survey_rook.html --png out/survey_rook.png --size 360x400
# Kobbelt's interpolatory scheme reads quads: the cube, and the L (open, with corners).
"$subdiv" refine data/meshes/cube.obj -s kobbelt -l 4 -o out/cube_kobbelt4.obj
"$subdiv" refine data/meshes/l_shape.obj -s kobbelt -l 4 -o out/l_shape_kobbelt4.obj
# Interpolatory sqrt3 on the open L: ternary four-point boundaries.
"$subdiv" refine data/meshes/l_shape.obj -s interpolatory-sqrt3 --triangulate -l 4 -o out/l_shape_interpolatory-sqrt34.obj
# Limits of the arity sqrt 3 and sqrt 2 schemes (eigenvector masks of their two-step matrices).
"$subdiv" limit data/meshes/l_shape.obj -s sqrt3 --triangulate --normals -o out/l_shape_sqrt3_limit.obj
"$subdiv" limit data/meshes/spot_control_mesh.obj -s four-eight --normals -o out/spot_control_mesh_four-eight_limit.obj
for scheme in loop catmull-clark butterfly modified-butterfly doo-sabin; do
  echo "== subdiv analyze -s $scheme -k 3..8"
  "$subdiv" analyze -s "$scheme" -k 3..8 --plot-spectrum "out/${scheme}_spectrum.svg" \
    --plot-charmap 5 "out/${scheme}_charmap5.png"
done
echo "== subdiv analyze -s sqrt3 -k 3..8 (two steps), kobbelt, and the generalized Catmull-Clark scheme's closed forms"
"$subdiv" analyze -s sqrt3 -k 3..8
"$subdiv" analyze -s kobbelt -k 3..8
"$subdiv" analyze -s gcc -k 3..8
echo "== a composite scheme written as averaging operators (Loop's, spelled out), the two-cycle sqrt3, interpolating sqrt2"
"$subdiv" refine data/meshes/tetrahedron.obj -s 'composite:Tvv4,VdE,EVc(loop),VdE,EVc(loop)' -l 4 \
  -o out/tetrahedron_composite_loop4.obj
"$subdiv" analyze -s composite-sqrt3 -k 3..6 --no-charmap
"$subdiv" refine data/meshes/cube.obj -s interpolating-sqrt2 -l 6 -o out/cube_interpolating-sqrt26.obj
echo "== the L's concave corner: standard and piecewise-smooth rules"
"$subdiv" refine data/meshes/l_shape.obj -s catmull-clark -l 4 -o out/l_shape_standard4.obj
"$subdiv" refine data/meshes/l_shape.obj -s catmull-clark -l 4 --boundary-rules piecewise-smooth \
  -o out/l_shape_piecewise_smooth4.obj
echo "== subdiv analyze -s catmull-clark --boundary -k 1..6 (standard, then piecewise-smooth rules)"
"$subdiv" analyze -s catmull-clark --boundary -k 1..6
"$subdiv" analyze -s catmull-clark --boundary -k 1..6 --boundary-rules piecewise-smooth
echo "== a priori depth and adaptive refinement of Spot to 0.005"
"$subdiv" depth data/meshes/spot_control_mesh.obj -s catmull-clark --eps 0.005 --verify
"$subdiv" adaptive data/meshes/spot_control_mesh.obj -s catmull-clark --eps 0.005 -o out/spot_adaptive.obj
echo "== from Python: stencils built once, three poses, each checked against refining again"
PYTHONPATH=build/python /usr/bin/python3 examples/python/animate_with_stencils.py data/meshes/spot_control_mesh.obj
echo "demo: results in out/"
