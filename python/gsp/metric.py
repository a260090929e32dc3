"""Riemannian metrics for GeodesicSolver(..., metric=...): a tensor for the mesh, per face or per vertex.

    m = gsp.metric.direction(V, F, (1, 0, 0), 3.0)     # steps along x cost 3x
    d = gsp.GeodesicSolver(V, F, metric=m).distance(0)
"""
from ._gsp import metric as _native

Metric = _native.Metric
constant = _native.constant
per_face = _native.per_face
per_vertex = _native.per_vertex
direction = _native.direction
curvature = _native.curvature
read = _native.read
edge_lengths = _native.edge_lengths

__all__ = ["Metric", "constant", "per_face", "per_vertex", "direction", "curvature", "read", "edge_lengths"]
