"""Batch processing of mesh collections on Dask distributed: one task per mesh.

    python3 -m gsp.batch JOB INPUT... -o OUTDIR [--workers N | --scheduler ADDRESS] [-- JOB OPTIONS]
    gsp-batch remesh scans/ -o remeshed --workers 2 -- --vertices 5000

JOB is an app (`geodesic`, `sample`, `remesh`, `path`, `bench`: gsp-geodesic, gsp-sample,
gsp-cvt, gsp-path, gsp-bench run as a subprocess on the worker with the job options) or a
Python callable `module:function` called as `function(V, F, path)` with the mesh's arrays and
the path to write the mesh's output to (it returns a dict of figures, or None). Inputs are
files, folders (their mesh files) or globs. Each mesh's output is OUTDIR/<input stem><ext>;
OUTDIR also gets results.csv and results.json (one row per mesh) and manifest.jsonl (what a
second run skips). See docs/batch.md.

From Python:

    import gsp.batch
    rows = gsp.batch.run("geodesic", ["scans/"], "out", workers=2, options=["--source-vertex", "0"])

The library does not print; `main()` (the command line) does.
"""
# gsp.batch was one module; its public names stay here (the gsp-batch entry point is
# gsp.batch:main), with the two helpers tests/test_batch.py calls. One concept per module:
# apps, inputs, outdir, manifest, callables, child, task, rows, cluster, runner, progress, cli.
from .apps import DEFAULT_EXT, JOBS, find_app   # noqa: F401
from .cli import _split_argv, main   # noqa: F401
from .cluster import connect, dashboard_link
from .errors import UsageError
from .inputs import MESH_EXTENSIONS, _output_names   # noqa: F401
from .outdir import MANIFEST, RESULTS_CSV, RESULTS_JSON   # noqa: F401
from .rows import COLUMNS   # noqa: F401
from .runner import run

__all__ = ["JOBS", "UsageError", "connect", "dashboard_link", "find_app", "main", "run"]
