"""Python callables for test_batch.py's `module:function` jobs (gsp-batch runs them on the workers).

A job is called as fn(V, F, path): the mesh's arrays and the file to write its output to; it
returns a dict of figures for the results table (or None).
"""
import pathlib

import numpy as np

import gsp


def surface(V, F):
    """Total area and Euler characteristic V - E + F of a triangle mesh."""
    V, F = np.asarray(V, float), np.asarray(F, np.int64)
    area = 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1).sum()
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    n_edges = len(np.unique(edges, axis=0))
    return float(area), int(len(V) - n_edges + len(F))


def area(V, F, path):
    """Writes the mesh as read (with gsp.write_mesh) and returns its area and Euler characteristic."""
    a, euler = surface(V, F)
    gsp.write_mesh(path, V, F)
    return {"area": a, "euler": euler, "max_x": np.float64(V[:, 0].max())}


def name_only(V, F, path, *, input):
    """Writes nothing; returns the input's file name (the `input=` keyword) and the face count."""
    return {"name": pathlib.Path(input).name, "triangles": len(F)}


def not_a_dict(V, F, path):
    return [len(V), len(F)]


def refuse_small(V, F, path):
    """Fails on meshes under 3000 vertices, as a job's own error."""
    if len(V) < 3000:
        raise ValueError(f"only {len(V)} vertices\nsecond line that must not reach the table")
    return {"vertices_seen": len(V)}
