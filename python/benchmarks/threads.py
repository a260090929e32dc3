"""Four geodesic queries one after another against four Python threads in parallel, on one solver.

    PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/threads.py [MESH] [--queries 4] [--repeat 5]

Prints the median wall times and their ratio (sequential / threads): the speed-up the GIL
release gives on this machine's cores. Each query runs with threads=1 so the library does not
also split it.
"""
import argparse
import pathlib
import statistics
import threading
import time

import numpy as np

import gsp

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("mesh", nargs="?", default=ROOT.parent / "shared" / "data" / "meshes" / "nefertiti_lowres.obj")
    ap.add_argument("--queries", type=int, default=4)
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    V, F = gsp.read_mesh(args.mesh)
    solver = gsp.GeodesicSolver(V, F)
    sources = np.random.default_rng(1).choice(len(V), args.queries, replace=False).tolist()
    solver.distance(sources[0], threads=1)   # warm-up

    def sequential():
        for s in sources:
            solver.distance(s, threads=1)

    def parallel():
        threads = [threading.Thread(target=solver.distance, args=(s,), kwargs={"threads": 1}) for s in sources]
        for t in threads:
            t.start()
        for t in threads:
            t.join()

    def timed(fn):
        times = []
        for _ in range(args.repeat):
            t0 = time.perf_counter()
            fn()
            times.append(time.perf_counter() - t0)
        return statistics.median(times)

    seq, par = timed(sequential), timed(parallel)
    print(f"{pathlib.Path(args.mesh).name}: {len(V)} vertices, {args.queries} queries")
    print(f"one after another {seq * 1e3:.1f} ms, {args.queries} threads {par * 1e3:.1f} ms, "
          f"speed-up {seq / par:.2f}x")


if __name__ == "__main__":
    main()
