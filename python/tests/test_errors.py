"""Every error path raises the documented exception with a message, never crashes."""
import numpy as np
import pytest

import gsp
from conftest import grid


@pytest.fixture(scope="module")
def small():
    return grid(5)


def test_bad_meshes():
    V, F = grid(3)
    with pytest.raises(ValueError, match="shape"):
        gsp.GeodesicSolver(V[:, :2], F)
    with pytest.raises(ValueError, match="shape"):
        gsp.GeodesicSolver(V, F[:, :2])
    with pytest.raises(ValueError, match="vertex 99"):
        gsp.GeodesicSolver(V, np.array([[0, 1, 99]]))
    with pytest.raises(ValueError, match="vertex -1"):
        gsp.GeodesicSolver(V, np.array([[0, 1, -1]]))
    W = V.copy()
    W[1, 0] = np.nan
    with pytest.raises(ValueError, match="finite"):
        gsp.GeodesicSolver(W, F)
    with pytest.raises(ValueError, match="integers"):
        gsp.GeodesicSolver(V, F.astype(float))
    with pytest.raises(ValueError, match="faces"):
        gsp.GeodesicSolver(V, np.zeros((0, 3), int))
    with pytest.raises(ValueError):
        gsp.GeodesicSolver("not an array", F)


def test_bad_sources(small):
    solver = gsp.GeodesicSolver(*small)
    for bad in [25, -1, [], [0, 99], "3", 1.5, None, [0, "x"], gsp.SurfacePoint(999, (1, 0, 0))]:
        with pytest.raises(ValueError):
            solver.distance(bad)
    with pytest.raises(ValueError, match="sum to 1"):
        gsp.SurfacePoint(0, (0.5, 0.5, 0.5))
    with pytest.raises(ValueError, match=">= 0"):
        gsp.SurfacePoint(0, (-0.5, 1.0, 0.5))
    with pytest.raises(ValueError):
        gsp.SurfacePoint(-1, (1, 0, 0))


def test_bad_options(small):
    solver = gsp.GeodesicSolver(*small)
    with pytest.raises(ValueError, match="strategy"):
        solver.distance(0, strategy="fastest")
    with pytest.raises(ValueError, match="precision"):
        solver.distance(0, precision="half")
    with pytest.raises(ValueError, match="max_distance"):
        solver.distance(0, max_distance=-1)
    with pytest.raises(TypeError):   # keyword-only after the data arguments
        solver.distance(0, 1.0)
    with pytest.raises(TypeError):
        gsp.GeodesicSolver(*small, False)
    with pytest.raises(ValueError, match="first"):
        gsp.GeodesicSolver(*small).distance_at([0], [[1, 0, 0]])
    with pytest.raises(ValueError, match="targets"):
        solver.distance_matrix([0, 1], targets="all")
    with pytest.raises(ValueError, match="method"):
        solver.path(0, 3, method="teleport")


def test_bad_extension_arguments(small):
    V, F = small
    with pytest.raises(ValueError, match="exactly one"):
        gsp.sample(V, F)
    with pytest.raises(ValueError, match="exactly one"):
        gsp.sample(V, F, count=5, radius=0.1)
    with pytest.raises(ValueError, match="mode"):
        gsp.sample(V, F, count=5, mode="blue")
    with pytest.raises(ValueError, match="count"):
        gsp.sample(V, F, count=0)
    with pytest.raises(ValueError, match="exactly one"):
        gsp.remesh(V, F)
    with pytest.raises(ValueError, match="line_distance needs"):
        gsp.line_distance(V, F)
    with pytest.raises(ValueError):
        gsp.line_distance(V, F, edges=[[0, 24]])   # not an edge
    with pytest.raises(ValueError, match="boundary"):
        Vs, Fs = __import__("conftest").icosphere(1)
        gsp.line_distance(Vs, Fs, boundary=True)
    with pytest.raises(ValueError, match="positive definite"):
        gsp.metric.constant(-np.eye(3))
    with pytest.raises(ValueError, match="symmetric"):
        gsp.metric.constant([[1, 2, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(ValueError, match="tensors"):
        gsp.GeodesicSolver(V, F, metric=np.tile(np.eye(3), (7, 1, 1)))
    m = gsp.metric.direction(V, F, (1, 0, 0), 2.0)
    with pytest.raises(ValueError, match="3D metric"):
        gsp.GeodesicSolver(V, F, metric=m).path(0, 3)
    with pytest.raises(ValueError):
        gsp.PointCloudSolver(V).distance()
    with pytest.raises(ValueError, match="out of range"):
        gsp.PointCloudSolver(V).distance(100)
    with pytest.raises(TypeError, match="progress"):
        gsp.sample(V, F, count=3, progress=5)


def test_progress_exceptions_stop_the_call(fertility):
    V, F = fertility

    class Stop(Exception):
        pass

    def stop(fraction):
        raise Stop()

    with pytest.raises(Stop):
        gsp.sample(V, F, count=200, progress=stop)
    with pytest.raises(Stop):
        gsp.remesh(V, F, vertices=300, progress=stop)
    with pytest.raises(Stop):
        gsp.GeodesicSolver(V, F).distance_matrix(list(range(40)), progress=stop)
