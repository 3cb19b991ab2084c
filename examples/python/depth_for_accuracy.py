"""How many uniform steps an accuracy needs, known before refining, checked
by refining; then adaptive refinement to the same accuracy.

    python3 examples/python/depth_for_accuracy.py data/meshes/tetrahedron.obj loop 1e-3
"""

import sys

import subdiv


def main(path, scheme, eps):
    mesh = subdiv.read(path)
    d = subdiv.depth(mesh, scheme, eps, verify=True)
    measured = d["verified"]["measured"]
    print(f"a priori depth for eps {eps:g}: {d['depth']} (bound {d['bound']:.3g}, {d['source']})")
    print(f"refined to depth {d['depth']}: largest vertex-to-limit distance {measured:.3g}")
    a = subdiv.adaptive(mesh, scheme, eps)
    print(f"adaptive: {a.mesh.face_count} faces; uniform to depth {a.uniform_depth}: {a.uniform_faces} faces")
    if measured > eps:
        sys.exit("the depth bound did not hold")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], float(sys.argv[3]))
