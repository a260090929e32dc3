"""Geodesic Source Propagation: geodesic distances, paths, sampling and remeshing.

Meshes are numpy arrays: V float (n, 3), F int (m, 3). Results are numpy arrays in the
input's vertex order. Errors: ValueError (bad input), OSError (files), gsp.NoPathError.
See docs/python.md.

    import gsp
    V, F = gsp.read_mesh("bunny.obj")
    solver = gsp.GeodesicSolver(V, F)
    d = solver.distance(0)                      # from vertex 0
    p = solver.path(0, 1234)                    # p.points, p.length
"""
from ._gsp import (
    Cvt,
    Error,
    GeodesicSolver,
    NoPathError,
    Path,
    PointCloudSolver,
    RemeshWarning,
    Samples,
    SurfacePoint,
    __version__,
    cvt,
    line_distance,
    read_mesh,
    read_points,
    remesh,
    sample,
    window_distance,
    write_mesh,
)
from . import metric

__all__ = [
    "Cvt", "Error", "GeodesicSolver", "NoPathError", "Path", "PointCloudSolver", "RemeshWarning", "Samples", "SurfacePoint",
    "cvt", "geodesic_distance", "line_distance", "metric", "read_mesh", "read_points", "remesh", "sample",
    "window_distance", "write_mesh", "__version__",
]

_SOLVER_KEYWORDS = ("intrinsic_delaunay", "metric", "optimize_layout")


def geodesic_distance(V, F, sources, **options):
    """One-off geodesic distance from `sources` to every vertex: an (n,) float64 array.

    Takes GeodesicSolver's keywords (intrinsic_delaunay, metric, optimize_layout: "auto" here,
    the cache layout only where the arrays' own order is scattered, which is what pays for one
    query) and GeodesicSolver.distance's (max_distance, strategy, threads, labels, precision,
    relax). For several queries on one mesh, build a GeodesicSolver once instead.
    """
    solver_options = {k: options.pop(k) for k in _SOLVER_KEYWORDS if k in options}
    solver_options.setdefault("optimize_layout", "auto")
    return GeodesicSolver(V, F, **solver_options).distance(sources, **options)
