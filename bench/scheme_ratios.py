#!/usr/bin/env python3
"""Per-output-face cost of each scheme against Loop and Catmull-Clark.

Runs the scheme benchmarks of subdiv_bench (BM_Refine_QuadScheme,
BM_Refine_TriangleScheme) in several rounds, takes each scheme's rate of
output faces against Loop's and Catmull-Clark's *of the same round* (the
machine is noisy; within a round the load is alike), and prints the median
and range of those ratios over the rounds.

  python3 bench/scheme_ratios.py [--bench build/bench/subdiv_bench] [--rounds 7]
                                 [--schemes loop,catmull_clark,kobbelt,...]
"""

import argparse
import json
import statistics
import subprocess
import sys

DEFAULT_SCHEMES = "loop,catmull_clark,sqrt3,interpolatory_sqrt3,four_eight,kobbelt"


def one_round(bench, schemes, min_time):
    run = subprocess.run(
        [bench, f"--benchmark_filter=Scheme/({'|'.join(schemes)})/", f"--benchmark_min_time={min_time}",
         "--benchmark_format=json"],
        check=True, capture_output=True, text=True)
    rates = {}
    for b in json.loads(run.stdout)["benchmarks"]:
        scheme = b["name"].split("/")[1]
        rates[scheme] = b["items_per_second"]  # output faces per second
    return rates


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bench", default="build/bench/subdiv_bench")
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--min-time", default="0.5")
    parser.add_argument("--schemes", default=DEFAULT_SCHEMES)
    args = parser.parse_args()
    schemes = args.schemes.split(",")
    for reference in ("loop", "catmull_clark"):
        if reference not in schemes:
            schemes.append(reference)
    rounds = []
    for r in range(args.rounds):
        rounds.append(one_round(args.bench, schemes, args.min_time))
        print(f"round {r + 1}/{args.rounds}: " +
              ", ".join(f"{s} {rounds[-1][s] / 1e6:.2f}M faces/s" for s in schemes), file=sys.stderr)
    print("| scheme | output faces/s (median) | per face against Loop | against Catmull-Clark |")
    print("| --- | --: | --: | --: |")
    for s in schemes:
        cells = [f"{statistics.median(r[s] for r in rounds) / 1e6:.2f}M"]
        for reference in ("loop", "catmull_clark"):
            ratios = sorted(r[reference] / r[s] for r in rounds)  # > 1: slower per face
            cells.append(f"{statistics.median(ratios):.2f}x ({ratios[0]:.2f}-{ratios[-1]:.2f})")
        print(f"| {s} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
