"""Random arrays into every entry point that takes arrays: shapes, dtypes,
index ranges, NaN and infinities. Only subdiv's exceptions (or a result)
may come out; a crash ends the test run and fails it."""

import numpy as np
import pytest

import subdiv

DTYPES = [np.float64, np.float32, np.int32, np.int64, np.uint8, np.bool_, np.complex128, object]


def random_array(rng, max_rows=12):
    shape = tuple(int(d) for d in rng.integers(0, max_rows, size=rng.integers(0, 4)))
    dtype = DTYPES[rng.integers(len(DTYPES))]
    values = rng.normal(size=shape) * 10 ** rng.integers(0, 12)
    if values.size and rng.random() < 0.3:
        values.flat[rng.integers(values.size)] = rng.choice([np.nan, np.inf, -np.inf])
    try:
        with np.errstate(invalid="ignore", over="ignore"):
            return values.astype(dtype)
    except (ValueError, OverflowError):
        return values


def plausible_mesh(rng):
    n = int(rng.integers(0, 10))
    points = rng.normal(size=(n, 3))
    if n and rng.random() < 0.2:
        points[rng.integers(n), rng.integers(3)] = np.nan
    k = int(rng.integers(1, 6))
    faces = rng.integers(-2, n + 3, size=(int(rng.integers(0, 6)), k))
    return points, faces


@pytest.mark.parametrize("seed", range(40))
def test_random_meshes(seed):
    rng = np.random.default_rng(seed)
    for _ in range(25):
        if rng.random() < 0.5:
            points, faces = random_array(rng), random_array(rng)
        else:
            points, faces = plausible_mesh(rng)
        keywords = {}
        if rng.random() < 0.3:
            keywords["creases"] = random_array(rng)
        if rng.random() < 0.3:
            keywords["corners"] = random_array(rng)
        if rng.random() < 0.3:
            keywords["holes"] = random_array(rng)
        try:
            mesh = subdiv.Mesh(points, faces, **keywords)
        except subdiv.Error:
            continue
        for scheme in ("catmull-clark", "loop", "doo-sabin", "sqrt3"):
            try:
                fine = subdiv.refine(mesh, scheme, 1).mesh
                assert np.all(np.isfinite(fine.points))
                subdiv.stencils(mesh, scheme, 1)
            except subdiv.Error:
                pass


@pytest.mark.parametrize("seed", range(10))
def test_random_polylines(seed):
    rng = np.random.default_rng(seed)
    for _ in range(30):
        points = random_array(rng)
        try:
            out = subdiv.refine_curve(points, ["chaikin", "cubic-bspline", "four-point"][seed % 3],
                                      int(rng.integers(0, 4)), closed=bool(rng.random() < 0.5))
            assert np.all(np.isfinite(out))
        except subdiv.Error:
            pass
