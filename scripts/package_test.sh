#!/usr/bin/env bash
# The package as users get it (CI runs this after scripts/test.sh, which
# leaves the static release build in build/):
#   1. `cmake --install build` into a temporary prefix, then the examples
#      configured and built as an outside project with find_package(subdiv)
#      only, and run; and one example built by hand with pkg-config.
#   2. A project that embeds subdiv with add_subdirectory, as a shared library
#      (BUILD_SHARED_LIBS): it must get the library alone and keep its build
#      type; the shared library must export nothing of TBB or {fmt}; then the
#      same install and outside build against it.
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir="$PWD"

if [ ! -f build/CMakeCache.txt ]; then
  echo "package_test.sh: build/ is missing: run scripts/test.sh (or scripts/build.sh) first" >&2
  exit 2
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi

fail() { echo "package_test.sh: FAILED: $*" >&2; exit 1; }

# Runs the examples built in $1 and checks what they print.
run_examples() {
  local dir="$1" out
  out="$("$dir/inspect_mesh" data/meshes/cube.obj)"
  [[ "$out" == "8 vertices, 6 faces, 12 edges; 0 errors, 0 warnings"* ]] || fail "inspect_mesh printed: $out"
  out="$("$dir/refine_mesh" data/meshes/l_shape.obj catmull-clark 2 "$work/l_shape2.obj")"
  [[ "$out" == *"faces -> "*" faces (catmull-clark, 2 levels), 0 creases and 1 corners tagged" ]] ||
    fail "refine_mesh printed: $out"
  [ -s "$work/l_shape2.obj" ] || fail "refine_mesh wrote no file"
  # A typed error thrown inside the library is caught by the example's
  # handler (type information across the library boundary).
  if out="$("$dir/refine_mesh" "$work/missing.obj" loop 1 "$work/x.obj" 2>&1)"; then fail "a missing file succeeded"; fi
  [[ "$out" == "refine_mesh: "*"missing.obj"* ]] || fail "refine_mesh reported a missing file as: $out"
  # The table re-evaluates three poses; the example itself fails if refining
  # again differs by more than 1e-12.
  out="$("$dir/animate_with_stencils" data/meshes/spot_control_mesh.obj catmull-clark 2)"
  [ "$(grep -c "^frame [123]: largest difference" <<< "$out")" = 3 ] || fail "animate_with_stencils printed: $out"
  # Loop's limit of a tetrahedron's vertex (1,1,1): valence 3, beta = 3/16,
  # chi = 1/(3/(8 beta) + 3) = 1/5, so 2/5 (1,1,1) + 1/5 of its three
  # neighbours' sum (-1,-1,-1) = (0.2, 0.2, 0.2), normal along (1,1,1).
  out="$("$dir/limit_points" data/meshes/tetrahedron.obj loop)"
  [[ "$out" == "vertex 0: limit (0.200000, 0.200000, 0.200000), normal (0.577350, 0.577350, 0.577350), closed form"* ]] ||
    fail "limit_points printed: $out"
  # Loop at an interior vertex of valence 5: beta = (5/8 - (3/8 + cos(72 deg)/4)^2) / 5
  # = 0.0840932..., each neighbour's limit weight 1/(3/(8 beta) + 5) = 0.1057156...
  # The document must parse as JSON.
  out="$("$dir/analyze_scheme" loop 5)"
  python3 -c 'import json, sys; d = json.loads(sys.argv[1]); assert d["verdict"] == "C1", d["verdict"];
assert abs(d["limit_mask"][1] - 0.1057156546251194) < 1e-12, d["limit_mask"]' "$out" ||
    fail "analyze_scheme printed: $out"
  # The example itself fails when refining to the a priori depth is not within eps.
  out="$("$dir/depth_and_adaptive" data/meshes/tetrahedron.obj loop 0.001)" || fail "depth_and_adaptive: $out"
  [[ "$out" == *"within eps"*"adaptive: "*" faces"* ]] || fail "depth_and_adaptive printed: $out"
  # The four-point scheme interpolates the square's corners and puts each
  # edge's new point at (1/2 + 1/16) * 2 + 1/16 * 2 = 1.25 from the centre.
  out="$("$dir/refine_curve" four-point 1)"
  [[ "$out" == *"point 0: (1.000000, 1.000000, 0.000000)"*"point 1: (0.000000, 1.250000, 0.000000)"* ]] ||
    fail "refine_curve printed: $out"
}

# Configures and builds examples/ against the prefix $1 into $2, then runs them.
outside_build() {
  cmake -S examples -B "$2" "${generator[@]}" -DCMAKE_PREFIX_PATH="$1" -DCMAKE_BUILD_TYPE=Release >/dev/null
  grep -q "subdiv_DIR:PATH=$1/" "$2/CMakeCache.txt" || fail "the examples did not find subdiv in $1"
  cmake --build "$2" >/dev/null
  run_examples "$2"
}

echo "package_test.sh: static library, installed"
cmake --install build --prefix "$work/static" >/dev/null
for f in include/subdiv/subdiv.h include/subdiv/version.h lib/libsubdiv.a lib/cmake/subdiv/subdivConfig.cmake \
         lib/cmake/subdiv/subdivConfigVersion.cmake lib/pkgconfig/subdiv.pc bin/subdiv share/doc/subdiv/LICENSE \
         share/doc/subdiv/refinement.md; do
  [ -e "$work/static/$f" ] || fail "the install has no $f"
done
version="$(sed -n 's/^project(subdiv VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)"
[ "$("$work/static/bin/subdiv" --version)" = "subdiv $version" ] || fail "subdiv --version is not $version"
outside_build "$work/static" "$work/examples-static"
# The Python module, where the build has it: imported from the install alone.
if grep -q "^SUBDIV_BUILD_PYTHON:BOOL=ON" build/CMakeCache.txt; then
  python_dir="$(sed -n 's/^SUBDIV_PYTHON_INSTALL_DIR:STRING=//p' build/CMakeCache.txt)"
  [ -f "$work/static/$python_dir/subdiv/__init__.py" ] || fail "the install has no Python package in $python_dir"
  out="$(cd "$work" && PYTHONPATH="$work/static/$python_dir" /usr/bin/python3 -c '
import subdiv
mesh = subdiv.read("'"$source_dir"'/data/meshes/tetrahedron.obj")
print(subdiv.__version__, subdiv.refine(mesh, "loop", 2).mesh.face_count, subdiv.__file__)')"
  [[ "$out" == "$version 64 $work/static/"* ]] || fail "the installed Python module printed: $out"
fi
# pkg-config, static: the private requirements (TBB, {fmt}) join the link.
PKG_CONFIG_PATH="$work/static/lib/pkgconfig" c++ examples/refine_mesh.cpp -o "$work/refine_mesh_pc" \
  $(PKG_CONFIG_PATH="$work/static/lib/pkgconfig" pkg-config --cflags --libs --static subdiv)
"$work/refine_mesh_pc" data/meshes/cube.obj loop 1 "$work/cube_pc.obj" >/dev/null 2>&1 &&
  fail "loop refined a quad cube" || true
out="$("$work/refine_mesh_pc" data/meshes/tetrahedron.obj loop 1 "$work/tet_pc.obj")"
[[ "$out" == *"4 faces -> 16 faces"* ]] || fail "the pkg-config build did not refine: $out"

echo "package_test.sh: shared library, embedded with add_subdirectory"
# -O0: this build checks packaging, not speed, and compiles fastest.
cmake -S tests/package/embed -B "$work/embed" "${generator[@]}" -DSUBDIV_SOURCE_DIR="$source_dir" \
  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0 -DBUILD_SHARED_LIBS=ON -DSUBDIV_INSTALL=ON >/dev/null
for dependency in CLI11 GTest benchmark nlohmann_json; do
  if grep -q "^${dependency}_DIR:PATH=/" "$work/embed/CMakeCache.txt"; then
    fail "embedding subdiv looked for $dependency, which only its program, tests or benchmarks need"
  fi
done
cmake --build "$work/embed" --parallel "$(nproc)" >/dev/null
library="$(find "$work/embed" -name 'libsubdiv.so.*' -type f -print -quit)"
[ -n "$library" ] || fail "no libsubdiv.so was built"
# Mangled names: _ZN3tbb, _ZN3fmt, _ZNSt... are those namespaces' functions,
# whatever type they return.
leaked="$(nm -D --defined-only "$library" | awk '{print $3}' | grep -cE '^_Z(N|NK|TI|TS|TV)?(3tbb|3fmt|St|NSt)' || true)"
[ "$leaked" = 0 ] || fail "libsubdiv.so exports $leaked symbols of TBB, {fmt} or std"
# The symbol tables are captured before matching: `nm | grep -q` fails under
# pipefail whenever grep exits before nm has written everything (SIGPIPE).
exported="$(nm -DC --defined-only "$library")"
[[ "$exported" == *" subdiv::refine("* ]] || fail "libsubdiv.so does not export subdiv::refine"
out="$("$work/embed/embedded_refine_mesh" data/meshes/tetrahedron.obj loop 2 "$work/tet2.obj")"
[[ "$out" == *"4 faces -> 64 faces"* ]] || fail "the embedding project's program did not refine: $out"
cmake --install "$work/embed" --prefix "$work/shared" >/dev/null
[ -e "$work/shared/lib/libsubdiv.so" ] || fail "the shared install has no lib/libsubdiv.so"
outside_build "$work/shared" "$work/examples-shared"
linked="$(ldd "$work/examples-shared/refine_mesh")"
[[ "$linked" == *"$work/shared/lib/libsubdiv.so"* ]] ||
  fail "the outside build did not link the installed libsubdiv.so"
echo "package_test.sh: passed"
