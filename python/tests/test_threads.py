"""Compute calls release the GIL: other Python threads run while a query is in C++.

(The speed-up of threads is measured by python/benchmarks/threads.py, which prints ratios;
timed assertions do not belong in unit tests.)"""
import threading

import numpy as np

import gsp
from conftest import icosphere


def test_queries_release_the_gil():
    V, F = icosphere(6)   # 40,962 vertices: each query takes milliseconds
    solver = gsp.GeodesicSolver(V, F)
    started, done = threading.Event(), threading.Event()
    ticks = 0

    def work():
        started.set()
        solver.distance_matrix(list(range(40)), threads=1)   # one call of about half a second
        done.set()

    t = threading.Thread(target=work)
    t.start()
    started.wait()
    while not done.is_set():
        ticks += 1   # runs only while the worker's call has released the GIL
    t.join()
    # Holding the GIL, the call would leave this loop a handful of iterations at most.
    assert ticks > 10000


def test_threads_give_the_same_results():
    V, F = icosphere(5)
    solver = gsp.GeodesicSolver(V, F)
    sources = [0, 100, 2000, 5000]
    expected = [solver.distance(s, threads=1) for s in sources]
    results = [None] * 4

    def work(i):
        results[i] = solver.distance(sources[i], threads=1)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for got, want in zip(results, expected):
        np.testing.assert_array_equal(got, want)


def test_more_threads_than_cores_all_finish_with_the_same_results():
    # Queries beyond one per core wait for a free core (docs/python.md, "Threads"): every one
    # still runs, on two solvers at once, with failing calls among them.
    V, F = icosphere(4)
    solvers = [gsp.GeodesicSolver(V, F), gsp.GeodesicSolver(V, F, intrinsic_delaunay=False)]
    sources = list(range(0, 2400, 150))
    expected = [[s.distance(v, threads=1) for v in sources] for s in solvers]
    results, errors = {}, []

    def work(k, i):
        try:
            results[k, i] = solvers[k].distance(sources[i])
        except Exception as e:   # noqa: BLE001 - collected and asserted below
            errors.append(e)

    def fail():
        try:
            solvers[0].distance(0, strategy="no-such-strategy")
        except ValueError:
            pass

    threads = [threading.Thread(target=fail) for _ in range(4)]
    threads += [threading.Thread(target=work, args=(k, i)) for k in range(2) for i in range(len(sources))]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=60)
    assert not any(t.is_alive() for t in threads)
    assert errors == []
    for k in range(2):
        for i in range(len(sources)):
            np.testing.assert_array_equal(results[k, i], expected[k][i])
