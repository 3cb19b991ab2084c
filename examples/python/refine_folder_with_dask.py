"""Refines every mesh of a folder on a Dask cluster: one task per mesh,
meshes and results travelling between processes by pickling. Here the
cluster is local (two worker processes); pass a scheduler address to use an
existing one. Each refined mesh comes back to the client, which writes it.

    python3 examples/python/refine_folder_with_dask.py data/meshes catmull-clark 2 out/dask [SCHEDULER]
"""

import pathlib
import sys

from dask.distributed import Client, LocalCluster

import subdiv


def refine_one(mesh, scheme, levels):
    """Runs on a worker: the mesh arrives pickled, the hierarchy returns pickled."""
    return subdiv.refine(mesh, scheme, levels, threads=1)


def main(folder, scheme, levels, out, scheduler=None):
    paths = sorted(p for p in pathlib.Path(folder).iterdir() if p.suffix in (".obj", ".ply", ".off"))
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    cluster = None if scheduler else LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                                  dashboard_address=None)
    with Client(scheduler or cluster) as client:
        meshes = [subdiv.read(p) for p in paths]
        futures = client.map(refine_one, meshes, scheme=scheme, levels=int(levels), pure=False)
        for path, future in zip(paths, futures):
            try:
                hierarchy = future.result()
            except subdiv.Error as e:  # the worker's exception, re-raised here with its message
                print(f"{path.name}: refused: {e}")
                continue
            target = out / f"{path.stem}_{scheme}{levels}.obj"
            subdiv.write(hierarchy.mesh, target)
            print(f"{path.name}: {hierarchy.mesh.face_count} faces -> {target}")
    if cluster is not None:
        cluster.close()


if __name__ == "__main__":
    if len(sys.argv) not in (5, 6):
        sys.exit(__doc__)
    main(*sys.argv[1:])
