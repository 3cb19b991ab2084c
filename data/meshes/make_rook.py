#!/usr/bin/env python3
"""Writes rook.obj: a chess rook modelled for subdiv as a quad control mesh
(CC0). A surface of revolution (12 segments) from a profile of a base, a
waist and a tower, with six crenellations raised from the rim at the top;
both ends closed by 12-gons. Closed, manifold, every face a quad but the two
caps. Usage: make_rook.py > rook.obj"""
import math

SEGMENTS = 12
# The profile, bottom to top: (radius, height). The last two points are the
# rim at the top, outer then inner, and the tower's floor inside it.
PROFILE = [(1.00, 0.00), (1.00, 0.18), (0.85, 0.28), (0.62, 0.40), (0.52, 0.80),
           (0.55, 1.25), (0.72, 1.40), (0.74, 1.58), (0.50, 1.58), (0.48, 1.42)]
CRENEL_HEIGHT = 0.24
RIM_OUTER, RIM_INNER = 7, 8  # profile indices of the rim's two rings

positions = []
def vertex(r, y, angle):
    positions.append((r * math.cos(angle), y, -r * math.sin(angle)))
    return len(positions)  # OBJ numbering

rings = [[vertex(r, y, 2 * math.pi * s / SEGMENTS) for s in range(SEGMENTS)] for r, y in PROFILE]
faces = []
faces.append([rings[0][s] for s in reversed(range(SEGMENTS))])  # the base, seen from below
for k in range(len(PROFILE) - 1):
    lower, upper = rings[k], rings[k + 1]
    for s in range(SEGMENTS):
        t = (s + 1) % SEGMENTS
        if k == RIM_OUTER and s % 2 == 0:
            # A crenellation: the rim's quad raised into a block.
            a, b, c, d = lower[s], lower[t], upper[t], upper[s]
            lift = [vertex(math.hypot(positions[v - 1][0], positions[v - 1][2]),
                           positions[v - 1][1] + CRENEL_HEIGHT,
                           math.atan2(-positions[v - 1][2], positions[v - 1][0])) for v in (a, b, c, d)]
            A, B, C, D = lift
            faces += [[A, B, C, D], [a, b, B, A], [b, c, C, B], [c, d, D, C], [d, a, A, D]]
        else:
            faces.append([lower[s], lower[t], upper[t], upper[s]])
faces.append([rings[-1][s] for s in range(SEGMENTS)])  # the tower's floor, seen from above

print("# A chess rook as a quad control mesh, modelled for subdiv by data/meshes/make_rook.py; CC0.")
for p in positions:
    print("v %.6f %.6f %.6f" % p)
for f in faces:
    print("f " + " ".join(map(str, f)))
