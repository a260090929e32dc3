"""Geodesic paths: straight on a plane, close to exact on a scan, NoPathError across components."""
import numpy as np
import pytest

import gsp
from conftest import shared_mesh
from test_geodesic import exact_distances


def test_path_on_a_plane_is_the_segment(plane):
    V, F = plane
    solver = gsp.GeodesicSolver(V, F)
    p = solver.path(0, 1680)
    assert isinstance(p, gsp.Path)
    assert p.points.shape == (len(p), 3) and p.faces.shape == (len(p),) and p.barycentric.shape == (len(p), 3)
    np.testing.assert_allclose(p.points[0], V[0], atol=1e-9)
    np.testing.assert_allclose(p.points[-1], V[1680], atol=1e-9)
    assert p.length == pytest.approx(np.linalg.norm(V[1680] - V[0]), rel=1e-6)
    # Every point lies in its face: barycentric weights reproduce the position.
    recon = np.einsum("kj,kjd->kd", p.barycentric, V[F[p.faces]])
    np.testing.assert_allclose(recon, p.points, atol=1e-9)


def test_path_between_surface_points(plane):
    V, F = plane
    solver = gsp.GeodesicSolver(V, F)
    a, b = gsp.SurfacePoint(3, (0.2, 0.3, 0.5)), gsp.SurfacePoint(3000, (0.1, 0.1, 0.8))
    p = solver.path(a, b)
    pa = np.dot(a.barycentric, V[F[3]])
    pb = np.dot(b.barycentric, V[F[3000]])
    assert p.length == pytest.approx(np.linalg.norm(pa - pb), rel=1e-6)


@pytest.mark.parametrize("method", ["astar", "settle", "full"])
def test_paths_within_half_a_percent_of_exact(method, tmp_path):
    path = shared_mesh("fertility.off")
    V, F = gsp.read_mesh(path)
    exact = exact_distances(path, 11, tmp_path)
    solver = gsp.GeodesicSolver(V, F)
    ends = np.random.default_rng(5).choice(len(V), 8, replace=False)
    paths = solver.paths(11, ends, method=method)
    assert len(paths) == len(ends)
    for e, p in zip(ends, paths):
        assert p.length == pytest.approx(exact[e], rel=0.005)
        # A path is never shorter than the geodesic (it is a curve on the surface).
        assert p.length >= exact[e] * (1 - 1e-6)


def test_edge_paths_are_longer(fertility):
    V, F = fertility
    solver = gsp.GeodesicSolver(V, F)
    a = solver.path(0, 2000)
    b = solver.path(0, 2000, method="dijkstra_edges")
    assert b.length >= a.length


def test_no_path_between_components():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 0, 0], [6, 0, 0], [5, 1, 0]], float)
    F = np.array([[0, 1, 2], [3, 4, 5]])
    solver = gsp.GeodesicSolver(V, F)
    with pytest.raises(gsp.NoPathError, match="not reached"):
        solver.path(0, 4)
    with pytest.raises(gsp.NoPathError):
        solver.paths(0, [1, 4])
    assert issubclass(gsp.NoPathError, gsp.Error) and issubclass(gsp.Error, RuntimeError)
    assert solver.path(0, 1).length == pytest.approx(1.0)
