"""Result rows (one per mesh: the app's --stats or the callable's figures) and the tables
results.csv and results.json."""
import csv
import io
import json
import os

from .jsonable import _json_default
from .outdir import RESULTS_CSV, RESULTS_JSON, _write_atomic

#: The leading columns of the results table, in this order; the job's figures follow.
COLUMNS = ["input", "output", "status", "error", "vertices", "faces", "output_vertices", "output_faces",
           "seconds", "worker"]

# Sections of an app's --stats that are the job's figures (the rest: input, settings, timings ...).
_NOT_FIGURES = {"app", "version", "input", "settings", "operations", "timings", "memory", "output"}


def _flatten(prefix, value, into):
    if isinstance(value, dict):
        for k, v in value.items():
            _flatten(f"{prefix}.{k}" if prefix else str(k), v, into)
    else:
        into[prefix] = value


def _bench_figures(report):
    figures, counts = {}, {}
    meshes = (report or {}).get("meshes") or []
    if meshes:
        m = meshes[0]
        counts = {"vertices": m.get("vertices"), "faces": m.get("faces")}
        for method in m.get("methods") or []:
            name = method.get("method", "?")
            for key in ("status", "precompute_s", "query_s", "vertices_per_s", "cycles_per_vertex",
                        "update_steps_per_triangle", "mre", "max_re", "unreached"):
                if key in method:
                    figures[f"{name}.{key}"] = method[key]
    return counts, figures


def _make_row(task, res):
    row = {c: None for c in COLUMNS}
    row.update(input=task["input"], output=None, status="error", error="")
    if res is None:
        return row
    row["seconds"] = res.get("seconds")
    row["worker"] = res.get("worker")
    row["error"] = res.get("error") or ""
    figures, timings = {}, {}
    stats = res.get("stats")
    if stats:
        inp = stats.get("input") or {}
        row["vertices"] = inp.get("vertices")
        row["faces"] = inp.get("triangles", inp.get("file_faces"))
        outp = stats.get("output") or {}
        if isinstance(outp, dict):
            row["output_vertices"] = outp.get("vertices")
            row["output_faces"] = outp.get("faces")
        if task["job"] == "remesh":
            remesh = stats.get("remesh") or {}
            row["output_vertices"] = remesh.get("vertices", row["output_vertices"])
            row["output_faces"] = remesh.get("triangles", row["output_faces"])
        timings = stats.get("timings") or {}
        for section, value in stats.items():
            if section not in _NOT_FIGURES:
                _flatten(section, value, figures)
    if task["job"] == "bench" and res.get("report"):
        counts, figures = _bench_figures(res["report"])
        row.update({k: v for k, v in counts.items() if v is not None})
    result = res.get("result")
    if result:
        row["vertices"] = result.get("vertices")
        row["faces"] = result.get("faces")
        timings = result.get("timings") or {}
        _flatten("", result.get("figures") or {}, figures)
    for k, v in timings.items():
        row[f"time_{k}"] = v
    for k, v in figures.items():
        row[k if k not in row else f"figure.{k}"] = v
    ok = res.get("returncode") == 0 and not row["error"]
    row["status"] = "ok" if ok else "error"
    # A failed app leaves no new file; gsp-path writes the paths it found (exit 3, some unreachable).
    if (ok or res.get("returncode") == 3) and os.path.exists(task["output"]):
        row["output"] = task["output_name"]
    return row


def _write_tables(outdir, rows, meta):
    columns = list(COLUMNS)
    for row in rows:
        for k in row:
            if k not in columns:
                columns.append(k)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(columns)
    for row in rows:
        cells = []
        for c in columns:
            v = row.get(c)
            if v is None:
                cells.append("")
            elif isinstance(v, bool):
                cells.append("true" if v else "false")
            elif isinstance(v, (list, dict)):
                cells.append(json.dumps(v, default=_json_default))
            else:
                cells.append(v)
        w.writerow(cells)
    _write_atomic(outdir / RESULTS_CSV, buf.getvalue())
    doc = dict(meta, columns=columns, rows=rows)
    _write_atomic(outdir / RESULTS_JSON, json.dumps(doc, indent=1, default=_json_default) + "\n")
