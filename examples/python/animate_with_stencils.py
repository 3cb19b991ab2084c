"""Stencils for animation: the table from control points to refined points
is built once, then each pose is one sparse matrix product, checked against
refining the posed mesh again.

    python3 examples/python/animate_with_stencils.py data/meshes/spot_control_mesh.obj
"""

import sys

import numpy as np

import subdiv


def main(path, scheme="catmull-clark", levels=2):
    mesh = subdiv.read(path)
    S = subdiv.stencils(mesh, scheme, levels)  # scipy.sparse.csr_matrix
    print(f"{S.shape[0]} refined points from {S.shape[1]} control points, {S.nnz} weights")
    rest = mesh.points.copy()
    for frame in range(1, 4):
        # A twist about the vertical axis, growing with height and frame.
        angle = 0.3 * frame * (rest[:, 1] - rest[:, 1].min())
        posed = rest.copy()
        posed[:, 0] = np.cos(angle) * rest[:, 0] - np.sin(angle) * rest[:, 2]
        posed[:, 2] = np.sin(angle) * rest[:, 0] + np.cos(angle) * rest[:, 2]
        refined = S @ posed
        mesh.points[:] = posed  # the mesh's own memory: re-posed in place
        again = subdiv.refine(mesh, scheme, levels).mesh.points
        difference = np.abs(refined - again).max()
        print(f"frame {frame}: largest difference from refining again {difference:.2e}")
        if difference > 1e-12:
            sys.exit("the stencils disagree with refinement")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
