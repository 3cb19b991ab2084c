"""The Python module's overhead: subdiv.refine on the 1M-quad torus to level
2, one thread, against the C++ benchmark of the same refinement
(BM_Refine_CatmullClark/1000/2/1 of subdiv_bench), alternating, in one run.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_refine.py [build/bench/subdiv_bench] [repetitions]

Prints each repetition's times and the ratio of the medians (Python / C++).
Both sides refine once untimed first, as Google Benchmark does.
"""

import json
import statistics
import subprocess
import sys
import time

import numpy as np

import subdiv


def torus(n):
    """bench/bench_meshes.cpp's torus(n): n x n quads, the same positions."""
    i, j = np.meshgrid(np.arange(n), np.arange(n))
    u, v = 2 * np.pi * i / n, 2 * np.pi * j / n
    r = 1.0 + 0.3 * np.cos(v) + 1e-3 * np.sin(7.0 * i + 3.0 * j)
    points = np.stack([r * np.cos(u), r * np.sin(u), 0.3 * np.sin(v)], axis=-1).reshape(-1, 3)

    def vid(a, b):
        return ((b + n) % n) * n + (a + n) % n

    faces = np.stack([vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)], axis=-1).reshape(-1, 4)
    return subdiv.Mesh(points, faces)


def cpp_milliseconds(bench):
    out = subprocess.run([bench, "--benchmark_filter=^BM_Refine_CatmullClark/1000/2/1/", "--benchmark_format=json",
                          "--benchmark_repetitions=1"], check=True, capture_output=True, text=True).stdout
    runs = [b for b in json.loads(out)["benchmarks"] if b.get("run_type") == "iteration"]
    return runs[0]["real_time"]


def main(bench="build/bench/subdiv_bench", repetitions=3):
    mesh = torus(1000)
    # Google Benchmark runs the refinement once untimed before it measures
    # (to choose the iteration count); so does this side, so that neither
    # counts the process's first touch of the output's memory.
    subdiv.refine(mesh, "catmull-clark", 2, threads=1)
    python, cpp = [], []
    for _ in range(int(repetitions)):
        start = time.perf_counter()
        fine = subdiv.refine(mesh, "catmull-clark", 2, threads=1).mesh
        python.append(1e3 * (time.perf_counter() - start))
        assert fine.face_count == 16_000_000
        del fine
        cpp.append(cpp_milliseconds(bench))
        print(f"python {python[-1]:8.1f} ms   c++ {cpp[-1]:8.1f} ms")
    ratio = statistics.median(python) / statistics.median(cpp)
    print(f"median python / median c++: {ratio:.2f}")


if __name__ == "__main__":
    main(*sys.argv[1:])
