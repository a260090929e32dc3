"""GeodesicSolver distances against known geodesics: a plane, a sphere, CGAL's exact values."""
import subprocess

import numpy as np
import pytest

import gsp
from conftest import BIN_DIR, DATA_DIR, grid, shared_mesh


def test_plane_is_euclidean(plane):
    V, F = plane
    d = gsp.GeodesicSolver(V, F).distance(0)
    assert d.dtype == np.float64 and d.shape == (len(V),)
    exact = np.linalg.norm(V - V[0], axis=1)
    # Vertex sources on a flat mesh: exact up to float rounding (single precision lengths).
    np.testing.assert_allclose(d, exact, rtol=1e-5, atol=1e-6)


def test_plane_surface_point_and_mixed_sources(plane):
    V, F = plane
    solver = gsp.GeodesicSolver(V, F)
    bary = (0.2, 0.3, 0.5)
    p = bary[0] * V[F[100, 0]] + bary[1] * V[F[100, 1]] + bary[2] * V[F[100, 2]]
    d = solver.distance(gsp.SurfacePoint(100, bary))
    np.testing.assert_allclose(d, np.linalg.norm(V - p, axis=1), rtol=1e-5, atol=1e-6)
    # Mixed list: the distance to the nearer of the two, and labels say which.
    d2, label = solver.distance([gsp.SurfacePoint(100, bary), 1680], labels=True)
    exact = np.minimum(np.linalg.norm(V - p, axis=1), np.linalg.norm(V - V[1680], axis=1))
    np.testing.assert_allclose(d2, exact, rtol=1e-5, atol=1e-6)
    nearer = np.where(np.linalg.norm(V - p, axis=1) < np.linalg.norm(V - V[1680], axis=1), 0, 1)
    clear = np.abs(np.linalg.norm(V - p, axis=1) - np.linalg.norm(V - V[1680], axis=1)) > 1e-3
    assert label.dtype == np.int64
    np.testing.assert_array_equal(label[clear], nearer[clear])
    # Index arrays and numpy integers are sources too.
    np.testing.assert_array_equal(solver.distance(np.array([5, 9])), solver.distance([5, 9]))
    np.testing.assert_array_equal(solver.distance(np.int64(5)), solver.distance(5))


def test_sphere_against_great_circles(sphere):
    V, F = sphere
    d = gsp.GeodesicSolver(V, F).distance(0)
    exact = np.arccos(np.clip(V @ V[0], -1, 1))
    # The polyhedron is shorter than the sphere: chords of ~0.08 rad edges; GSP is exact on
    # the polyhedron up to its own error, so the relative error stays below 1.5%.
    rel = np.abs(d - exact)[1:] / exact[1:]
    assert rel.mean() < 0.005 and rel.max() < 0.015
    # Physics: never below the straight line.
    assert np.all(d >= np.linalg.norm(V - V[0], axis=1) * (1 - 1e-6))


def exact_distances(path, source, tmp_path):
    tool = BIN_DIR / "gsp-exact"
    if not tool.exists():
        pytest.skip("gsp-exact not built (GSP_WITH_CGAL=OFF)")
    out = tmp_path / "exact.txt"
    subprocess.run([str(tool), str(path), "--source-vertex", str(source), "-o", str(out)], check=True)
    return np.loadtxt(out)


@pytest.mark.parametrize("name", ["fertility.off", "camelhead.off"])
def test_shared_mesh_against_cgal_exact(name, tmp_path):
    path = shared_mesh(name)
    V, F = gsp.read_mesh(path)
    exact = exact_distances(path, 7, tmp_path)
    d = gsp.GeodesicSolver(V, F).distance(7)
    mask = exact > 0
    rel = np.abs(d[mask] - exact[mask]) / exact[mask]
    # The corpus figure for benign scans is a mean relative error of 0.17% (docs/benchmarks.md).
    assert rel.mean() < 0.005, rel.mean()
    assert rel.max() < 0.05, rel.max()


def test_one_off_and_options(plane):
    V, F = plane
    a = gsp.geodesic_distance(V, F, 3)
    b = gsp.geodesic_distance(V, F, 3, intrinsic_delaunay=False, strategy="priority_queue", precision="double")
    np.testing.assert_allclose(a, b, rtol=1e-5, atol=1e-6)
    bounded = gsp.geodesic_distance(V, F, 3, max_distance=0.5)
    assert np.all(np.isinf(bounded[a > 0.5 + 1e-9]))
    np.testing.assert_allclose(bounded[a < 0.5], a[a < 0.5], rtol=1e-5, atol=1e-6)


def test_layout_auto_sorts_faces_stored_in_blocks():
    """A grid of 2^19 faces stored in four blocks (libigl's upsample writes a split face's
    children so): the vertices are coherent, the faces scattered, and "auto" sorts the faces
    (from gsp's kSortFacesFrom faces); the distances are the plane's, in the arrays' order."""
    V, F = grid(513)
    assert len(F) == 2**19
    Fb = np.concatenate([F[r::4] for r in range(4)])
    solver = gsp.GeodesicSolver(V, Fb, optimize_layout="auto")
    assert solver.optimize_layout is True
    assert gsp.GeodesicSolver(V, F[np.argsort(F.min(axis=1), kind="stable")], optimize_layout="auto").optimize_layout is False
    # One thread: on two, GSP's order effects reach 2e-5 at a few vertices of this plane
    # whatever the layout (measured with the faces as stored, too).
    d = solver.distance(0, threads=1)
    np.testing.assert_allclose(d, np.linalg.norm(V - V[0], axis=1), rtol=1e-5, atol=1e-6)


def test_layout_auto_follows_the_arrays_order(plane):
    """optimize_layout="auto" (gsp.geodesic_distance's default) skips the cache layout for arrays
    whose own order is coherent (the row-major grid, its faces by their smallest vertex) and
    keeps it for a shuffled copy; the solver's default stays True (many queries); the distances
    agree on the plane."""
    V, F = plane
    Fc = F[np.argsort(F.min(axis=1), kind="stable")]
    assert gsp.GeodesicSolver(V, F).optimize_layout is True
    assert gsp.GeodesicSolver(V, Fc, optimize_layout="auto").optimize_layout is False
    # The fixture's faces come as two blocks (each cell's lower triangles, then its upper
    # ones): its vertices are coherent, its faces not, but too few for the order to matter.
    assert gsp.GeodesicSolver(V, F, optimize_layout="auto").optimize_layout is False
    assert gsp.GeodesicSolver(V, F, optimize_layout=False).optimize_layout is False
    perm = np.random.default_rng(5).permutation(len(V))
    rank = np.empty_like(perm)
    rank[perm] = np.arange(len(V))
    Vs, Fs = V[perm], rank[F]
    assert gsp.GeodesicSolver(Vs, Fs, optimize_layout="auto").optimize_layout is True

    a = gsp.geodesic_distance(V, F, 3)
    b = gsp.GeodesicSolver(V, F).distance(3)
    np.testing.assert_allclose(a, b, rtol=1e-5, atol=1e-6)
    np.testing.assert_allclose(gsp.geodesic_distance(Vs, Fs, int(rank[3])), a[perm], rtol=1e-5, atol=1e-6)
    with pytest.raises(ValueError):
        gsp.GeodesicSolver(V, F, optimize_layout="sometimes")
    with pytest.raises(TypeError):
        gsp.GeodesicSolver(V, F, optimize_layout=1)


def test_unreachable_is_inf():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 0, 0], [6, 0, 0], [5, 1, 0]], float)
    F = np.array([[0, 1, 2], [3, 4, 5]])
    d, label = gsp.GeodesicSolver(V, F).distance(0, labels=True)
    assert np.all(np.isfinite(d[:3])) and np.all(np.isinf(d[3:]))
    np.testing.assert_array_equal(label, [0, 0, 0, -1, -1, -1])


def test_distance_at_uses_face_sources(plane):
    V, F = plane
    solver = gsp.GeodesicSolver(V, F)
    solver.distance(0)
    faces = np.array([10, 200, 1500])
    bary = np.array([[0.2, 0.3, 0.5], [1 / 3, 1 / 3, 1 / 3], [0.6, 0.2, 0.2]])
    at = solver.distance_at(faces, bary)
    p = np.einsum("kj,kjd->kd", bary, V[F[faces]])
    np.testing.assert_allclose(at, np.linalg.norm(p - V[0], axis=1), rtol=1e-5, atol=1e-6)
    # The same with explicit sources, and another source.
    np.testing.assert_allclose(solver.distance_at(faces, bary, sources=0), at)
    np.testing.assert_allclose(solver.distance_at(faces, bary, sources=40), np.linalg.norm(p - V[40], axis=1),
                               rtol=1e-5, atol=1e-6)


def plate_with_hole(a=10.0, r=3.0, n=48):
    """A flat square with a round hole written as CAD exporters write it: a fan of slivers from
    each corner over its quarter of the rim."""
    ang = 2 * np.pi * np.arange(n) / n + 0.1
    V = [[r * np.cos(t), r * np.sin(t), 0.0] for t in ang] + [[a, a, 0], [-a, a, 0], [-a, -a, 0], [a, -a, 0]]
    quarter = (np.floor(np.mod(ang, 2 * np.pi) / (np.pi / 2)).astype(int)) % 4
    F = []
    for i in range(n):
        j = (i + 1) % n
        F.append([n + quarter[i], i, j])
        if quarter[j] != quarter[i]:
            F.append([n + quarter[i], j, n + quarter[j]])
    return np.array(V), np.array(F)


def test_distance_at_follows_distance_on_cad_slivers():
    # distance_at reads sources fitted to distance()'s values (fitted_face_sources): at every
    # face's corners within 1.1% of them on average (the input faces' own sources: 1.2-1.8%),
    # and never below the straight line from the source (a flat plate: the line is exact
    # wherever the hole does not hide it).
    V, F = plate_with_hole()
    solver = gsp.GeodesicSolver(V, F)
    faces = np.repeat(np.arange(len(F)), 3)
    bary = np.tile(np.eye(3), (len(F), 1))
    for source in (0, 20, 48):
        d = solver.distance(source)
        at = solver.distance_at(faces, bary)
        ref = d[F.reshape(-1)]
        ok = ref > 0
        assert np.mean(np.abs(at[ok] - ref[ok]) / ref[ok]) < 0.011, source
        line = np.linalg.norm(V[F.reshape(-1)] - V[source], axis=1)
        assert np.all(at >= line * (1 - 1e-5)), source


def test_distance_matrix(plane):
    V, F = plane
    solver = gsp.GeodesicSolver(V, F)
    pts = [0, 40, 820, gsp.SurfacePoint(700, (0.5, 0.25, 0.25))]
    D = solver.distance_matrix(pts)
    assert D.shape == (4, 4)
    P = np.array([V[0], V[40], V[820], 0.5 * V[F[700, 0]] + 0.25 * V[F[700, 1]] + 0.25 * V[F[700, 2]]])
    exact = np.linalg.norm(P[:, None] - P[None], axis=2)
    np.testing.assert_allclose(D, exact, rtol=1e-5, atol=1e-5)
    full = solver.distance_matrix([0, 40], targets="vertices", threads=2)
    assert full.shape == (2, len(V))
    np.testing.assert_allclose(full[1], solver.distance(40), rtol=1e-6)
    calls = []
    solver.distance_matrix(list(range(0, 1600, 50)), progress=calls.append)
    assert calls and calls[-1] == 1.0 and calls == sorted(calls)


def test_matrix_of_a_scan_is_nearly_symmetric(fertility):
    V, F = fertility
    solver = gsp.GeodesicSolver(V, F)
    idx = np.random.default_rng(3).choice(len(V), 12, replace=False)
    D = solver.distance_matrix(idx)
    assert np.all(np.diag(D) == 0)
    off = ~np.eye(12, dtype=bool)
    asym = np.abs(D - D.T)[off] / D[off]
    assert asym.max() < 0.01
    # Bounds: at least the straight line between the vertices.
    straight = np.linalg.norm(V[idx][:, None] - V[idx][None], axis=2)
    assert np.all(D[off] >= straight[off] * (1 - 1e-6))


def test_metric_direction_on_plane(plane):
    V, F = plane
    m = gsp.metric.direction(V, F, (1, 0, 0), 3.0)
    assert m.location == "per_face" and m.tensors.shape == (len(F), 3, 3)
    d = gsp.GeodesicSolver(V, F, metric=m).distance(840)   # the centre vertex
    delta = V - V[840]
    exact = np.sqrt((3 * delta[:, 0]) ** 2 + delta[:, 1] ** 2)
    rel = np.abs(d - exact)[exact > 0] / exact[exact > 0]
    # A constant metric on a plane is a flat metric: exact up to the visibility decisions of a
    # few vertices (measured: mean 1e-6, max 3.1e-4 on this jittered grid).
    assert rel.mean() < 1e-5 and rel.max() < 1e-3
    # A constant tensor does the same.
    T = np.diag([9.0, 1.0, 1.0])
    np.testing.assert_allclose(gsp.GeodesicSolver(V, F, metric=T).distance(840), d, rtol=1e-6)
    lengths = gsp.metric.edge_lengths(V, F, gsp.metric.constant(T))
    assert lengths.shape == (len(F), 3)


def test_curvature_metric_runs_on_a_scan(fertility):
    V, F = fertility
    m = gsp.metric.curvature(V, F, 2.0)
    assert m.location == "per_vertex" and m.tensors.shape == (len(V), 3, 3)
    d = gsp.GeodesicSolver(V, F, metric=m).distance(0)
    iso = gsp.GeodesicSolver(V, F).distance(0)
    # Steps cost 1x to 2x their 3D length, so d >= iso up to GSP's error in either field
    # (measured: one vertex next to the source 1.4% below, every other one above 0.999).
    assert np.all(np.isfinite(d))
    assert np.mean(d < iso * 0.99) < 0.001 and np.all(d >= iso * 0.97)
    assert np.mean(d) > np.mean(iso) * 1.05


def test_window_distance_on_plane_and_against_exact(plane, tmp_path):
    V, F = plane
    d, label = gsp.window_distance(V, F, [0, len(V) - 1], labels=True)
    e0, e1 = np.linalg.norm(V - V[0], axis=1), np.linalg.norm(V - V[-1], axis=1)
    np.testing.assert_allclose(d, np.minimum(e0, e1), rtol=1e-9, atol=1e-12)
    assert np.all(label[e0 < e1 - 1e-9] == 0) and np.all(label[e1 < e0 - 1e-9] == 1)
    path = shared_mesh("camelhead.off")
    V, F = gsp.read_mesh(path)
    exact = exact_distances(path, 7, tmp_path)
    w = gsp.window_distance(V, F, 7)
    g = gsp.GeodesicSolver(V, F).distance(7)
    mask = exact > 0
    rel_w = (w[mask] - exact[mask]) / exact[mask]
    rel_g = np.abs(g[mask] - exact[mask]) / exact[mask]
    # Paths on the surface: never below the exact distance; more accurate than GSP here.
    assert rel_w.min() > -1e-6, rel_w.min()
    assert np.abs(rel_w).mean() < rel_g.mean(), (np.abs(rel_w).mean(), rel_g.mean())
    with pytest.raises(ValueError):
        gsp.window_distance(V, F, len(V))
    with pytest.raises(ValueError):
        gsp.window_distance(V, F, 0, windows=0)
    with pytest.raises(ValueError):
        gsp.window_distance(V, F, 0, max_distance=-1)


def test_window_distance_from_face_points_with_a_limit(plane):
    V, F = plane
    p = gsp.SurfacePoint(7, (0.2, 0.5, 0.3))
    x = 0.2 * V[F[7, 0]] + 0.5 * V[F[7, 1]] + 0.3 * V[F[7, 2]]
    euclid = np.linalg.norm(V - x, axis=1)
    d, label = gsp.window_distance(V, F, [p, 0], labels=True)
    np.testing.assert_allclose(d, np.minimum(euclid, np.linalg.norm(V - V[0], axis=1)), rtol=1e-9, atol=1e-12)
    limit = float(np.median(euclid))
    cut = gsp.window_distance(V, F, p, max_distance=limit)
    near = euclid <= limit * (1 - 1e-9)
    np.testing.assert_allclose(cut[near], euclid[near], rtol=1e-9, atol=1e-12)
    assert np.all(np.isinf(cut[euclid > limit * (1 + 1e-9)]))
