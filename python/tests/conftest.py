"""Shared fixtures: built meshes with known geodesics (plane, sphere) and the shared meshes.

Environment (set by ctest, see tests/python.cmake): PYTHONPATH with the built package,
GSP_DATA_DIR (shared meshes), GSP_BIN_DIR (the apps, for gsp-exact), GSP_SOURCE_DIR.
"""
import os
import pathlib

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("GSP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
DATA_DIR = pathlib.Path(os.environ.get("GSP_DATA_DIR", SOURCE_DIR.parent / "shared" / "data" / "meshes"))
BIN_DIR = pathlib.Path(os.environ.get("GSP_BIN_DIR", SOURCE_DIR / "build" / "bin"))


def grid(n=41, size=2.0, jitter=0.0, seed=0):
    """A square [-size/2, size/2]^2 in the z = 0 plane, n x n vertices, two triangles per cell."""
    t = np.linspace(-size / 2, size / 2, n)
    x, y = np.meshgrid(t, t, indexing="ij")
    V = np.stack([x.ravel(), y.ravel(), np.zeros(n * n)], axis=1)
    if jitter:
        inner = (np.abs(V[:, 0]) < size / 2 - 1e-9) & (np.abs(V[:, 1]) < size / 2 - 1e-9)
        V[inner, :2] += np.random.default_rng(seed).uniform(-jitter, jitter, (inner.sum(), 2)) * size / (n - 1)
    i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="ij")
    a = (i * n + j).ravel()
    b, c, d = a + n, a + n + 1, a + 1
    F = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])
    return V, F.astype(np.int64)


def icosphere(levels=4):
    """A unit sphere: an icosahedron split 1-to-4 `levels` times, projected onto the sphere."""
    p = (1 + 5 ** 0.5) / 2
    V = [(-1, p, 0), (1, p, 0), (-1, -p, 0), (1, -p, 0), (0, -1, p), (0, 1, p), (0, -1, -p), (0, 1, -p),
         (p, 0, -1), (p, 0, 1), (-p, 0, -1), (-p, 0, 1)]
    F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
         (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
         (8, 6, 7), (9, 8, 1)]
    V = [np.array(v, float) / np.linalg.norm(v) for v in V]
    for _ in range(levels):
        mid, G = {}, []

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                v = V[a] + V[b]
                V.append(v / np.linalg.norm(v))
                mid[key] = len(V) - 1
            return mid[key]

        for a, b, c in F:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            G += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        F = G
    return np.array(V), np.array(F, dtype=np.int64)


@pytest.fixture(scope="session")
def plane():
    return grid(41, jitter=0.3)


@pytest.fixture(scope="session")
def sphere():
    return icosphere(4)


def shared_mesh(name):
    path = DATA_DIR / name
    if not path.exists():
        pytest.skip(f"shared mesh {path} not present")
    return path


@pytest.fixture(scope="session")
def fertility():
    import gsp
    return gsp.read_mesh(SOURCE_DIR / "data" / "samples" / "fertility.off")
