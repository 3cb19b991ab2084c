"""A scheme's subdominant eigenvalues and C1 verdict at every valence: the
table of the survey's section 5, from the scheme's own rules.

    python3 examples/python/spectrum_table.py loop
"""

import sys

import subdiv


def main(scheme):
    print(f"{scheme}: interior vertices")
    print("   k   lambda_1   lambda_2  |lambda_3|  verdict")
    for c in subdiv.analyze(scheme, k=range(3, 11), characteristic_map=True)["configurations"]:
        lam = c["leading_eigenvalues"]
        print(f"{c['k']:4d} {lam[1].real:10.6f} {lam[2].real:10.6f} {abs(lam[3]):10.6f}  {c['verdict']}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
