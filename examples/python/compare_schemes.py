"""Refines one mesh with several schemes and prints what each makes: the
survey's comparison, as numbers. Writes each result next to the output
prefix when one is given.

    python3 examples/python/compare_schemes.py data/meshes/cube.obj [OUT_PREFIX]
"""

import sys

import numpy as np

import subdiv


def main(path, prefix=None):
    mesh = subdiv.read(path)
    print(f"{path}: {mesh.vertex_count} vertices, {mesh.face_count} faces")
    for scheme in subdiv.schemes():
        name = scheme["name"]
        try:
            fine = subdiv.refine(mesh, name, levels=3).mesh
        except subdiv.Error as e:  # a scheme that does not take this mesh says why
            print(f"  {name:20s} refused: {e}")
            continue
        radius = np.linalg.norm(fine.points - fine.points.mean(axis=0), axis=1)
        print(f"  {name:20s} {fine.vertex_count:7d} vertices {fine.face_count:7d} faces, "
              f"radius {radius.min():.4f}..{radius.max():.4f}")
        if prefix:
            subdiv.write(fine, f"{prefix}_{name}.obj")


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(*sys.argv[1:])
