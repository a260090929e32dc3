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
from __future__ import annotations

import argparse
import csv
import glob
import hashlib
import inspect
import io
import json
import os
import pathlib
import pickle
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import uuid

__all__ = ["JOBS", "UsageError", "connect", "dashboard_link", "find_app", "main", "run"]

#: Job name -> the app that runs it.
JOBS = {"geodesic": "gsp-geodesic", "sample": "gsp-sample", "remesh": "gsp-cvt", "path": "gsp-path",
        "bench": "gsp-bench"}
#: Default output extension per job (callables: .ply).
DEFAULT_EXT = {"geodesic": ".ply", "sample": ".ply", "remesh": ".ply", "path": ".ply", "bench": ".json"}
#: The files a folder input contributes.
MESH_EXTENSIONS = (".ply", ".obj", ".off", ".stl", ".gltf", ".glb")

MANIFEST = "manifest.jsonl"
RESULTS_CSV = "results.csv"
RESULTS_JSON = "results.json"
_RESERVED = {MANIFEST, RESULTS_CSV, RESULTS_JSON}

#: The leading columns of the results table, in this order; the job's figures follow.
COLUMNS = ["input", "output", "status", "error", "vertices", "faces", "output_vertices", "output_faces",
           "seconds", "worker"]

# Options gsp-batch sets itself for every app.
_RESERVED_OPTIONS = {"-o", "--output", "--stats", "--json", "-h", "--help", "--version"}
# Sections of an app's --stats that are the job's figures (the rest: input, settings, timings ...).
_NOT_FIGURES = {"app", "version", "input", "settings", "operations", "timings", "memory", "output"}


class UsageError(ValueError):
    """A batch that cannot start: unknown job, no inputs, bad options (the command line exits 2)."""


# ---------------------------------------------------------------------------------------------
# Finding the apps


def find_app(job, bin_dir=None):
    """The absolute path of JOB's app: in `bin_dir` when given (only there), else in $GSP_BIN_DIR,
    on PATH, or in the checkout's build/bin beside the package.

    Raises FileNotFoundError naming the places searched.
    """
    name = JOBS[job]
    if bin_dir:
        folders = [pathlib.Path(bin_dir)]
    else:
        here = pathlib.Path(__file__).resolve().parent   # build/python/gsp or python/gsp
        folders = [pathlib.Path(os.environ["GSP_BIN_DIR"])] if os.environ.get("GSP_BIN_DIR") else []
        folders += [None, here.parent.parent / "bin", here.parent.parent / "build" / "bin"]
    for d in folders:
        if d is None:
            found = shutil.which(name)
            if found:
                return str(pathlib.Path(found).resolve())
            continue
        p = d / name
        if p.is_file() and os.access(p, os.X_OK):
            return str(p.resolve())
    places = ", ".join("PATH" if d is None else str(d) for d in folders)
    raise FileNotFoundError(f"{name} not found (looked in {places}; use --bin DIR or GSP_BIN_DIR)")


def _app_version(app):
    try:
        out = subprocess.run([app, "--version"], capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired) as e:
        raise FileNotFoundError(f"{app}: cannot run: {e}") from None
    if out.returncode != 0:
        raise FileNotFoundError(f"{app} --version failed (exit {out.returncode})")
    return out.stdout.strip()


# ---------------------------------------------------------------------------------------------
# Inputs and output names


def _expand_inputs(inputs):
    """Files, folders (their mesh files, sorted) and globs -> resolved paths, in order, no repeats."""
    if isinstance(inputs, (str, os.PathLike)):
        inputs = [inputs]
    paths, seen = [], set()

    def add(p):
        p = pathlib.Path(p).resolve()
        if p not in seen:
            seen.add(p)
            paths.append(p)

    for item in inputs:
        item = os.fspath(item)
        p = pathlib.Path(item)
        if p.is_dir():
            for q in sorted(p.iterdir()):
                if q.is_file() and q.suffix.lower() in MESH_EXTENSIONS:
                    add(q)
        elif p.is_file():
            add(p)
        elif glob.has_magic(item):
            matches = sorted(glob.glob(item, recursive=True))
            if not matches:
                raise UsageError(f"{item}: no file matches")
            for m in matches:
                if pathlib.Path(m).is_file():
                    add(m)
        else:
            raise UsageError(f"{item}: no such file or folder")
    if not paths:
        raise UsageError("no input meshes (the folders hold no .ply .obj .off .stl .gltf .glb file)")
    return paths


def _output_names(paths, ext):
    """Unique output names: the input's stem, then its whole name, then parent folders prefixed."""
    level = [0] * len(paths)

    def candidate(i):
        p = paths[i]
        if level[i] == 0:
            base = p.stem
        elif level[i] == 1:
            base = p.name
        else:
            parts = p.parts[-level[i]:]
            base = "_".join(parts)
        return base + ext

    for _ in range(64):
        names = [candidate(i) for i in range(len(paths))]
        groups = {}
        for i, n in enumerate(names):
            groups.setdefault(n.lower(), []).append(i)
        bumped = False
        for n, idx in groups.items():
            if len(idx) > 1 or n in _RESERVED:
                for i in idx:
                    if level[i] < len(paths[i].parts):
                        level[i] += 1
                        bumped = True
        if not bumped:
            break
    names = [candidate(i) for i in range(len(paths))]
    seen = {}
    for i, n in enumerate(names):   # whatever is left (cannot happen for distinct paths): number it
        key = n.lower()
        if key in seen or key in _RESERVED:
            stem = n[: -len(ext)] if ext else n
            k = 2
            while f"{stem}-{k}{ext}".lower() in seen:
                k += 1
            n = f"{stem}-{k}{ext}"
            names[i] = n
        seen[n.lower()] = i
    return names


def _sha256_file(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


# ---------------------------------------------------------------------------------------------
# Manifest: one JSON line per complete output, the last line for an output wins.


def _read_manifest(outdir):
    entries = {}
    path = outdir / MANIFEST
    try:
        with open(path, encoding="utf-8") as f:
            for line in f:
                try:
                    e = json.loads(line)
                except ValueError:
                    continue        # a line cut short by a killed run
                if isinstance(e, dict) and isinstance(e.get("output_name"), str):
                    entries[e["output_name"]] = e
    except FileNotFoundError:
        pass
    return entries


def _write_atomic(path, text):
    path = pathlib.Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as f:
            f.write(text)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def _complete(entry, settings_hash, outdir):
    """Whether a manifest entry says the output is there and was made with these settings."""
    if not entry or entry.get("settings_hash") != settings_hash:
        return False
    for name, size in (entry.get("files") or {}).items():
        try:
            if (outdir / name).stat().st_size != size:
                return False
        except OSError:
            return False
    return True


# ---------------------------------------------------------------------------------------------
# Callables


def _load_callable(spec):
    """'module:function' -> the function (the module imported from the current folder or sys.path)."""
    module_name, _, attr = spec.partition(":")
    if not module_name or not attr:
        raise UsageError(f"{spec}: a job is one of {', '.join(JOBS)} or module:function")
    import importlib
    if "" not in sys.path and os.getcwd() not in sys.path:
        sys.path.insert(0, os.getcwd())
    try:
        obj = importlib.import_module(module_name)
    except ImportError as e:
        raise UsageError(f"{spec}: cannot import {module_name}: {e}") from None
    for part in attr.split("."):
        try:
            obj = getattr(obj, part)
        except AttributeError:
            raise UsageError(f"{spec}: {module_name} has no {attr}") from None
    if not callable(obj):
        raise UsageError(f"{spec}: not callable")
    return obj


def _callable_identity(fn):
    """What a callable's outputs depend on besides the mesh: its name and its module's source."""
    h = hashlib.sha256()
    name = f"{getattr(fn, '__module__', '?')}:{getattr(fn, '__qualname__', repr(fn))}"
    h.update(name.encode())
    try:
        source_file = inspect.getsourcefile(fn)
        h.update(pathlib.Path(source_file).read_bytes())
    except (TypeError, OSError):
        code = getattr(fn, "__code__", None)
        if code is not None:
            h.update(code.co_code)
            h.update(repr(code.co_consts).encode())
    import gsp
    return f"{name} sha256:{h.hexdigest()[:16]} gsp {gsp.__version__}"


def _callable_pythonpath(fn):
    """Folders the child process needs on sys.path to unpickle `fn` (its top-level package's)."""
    module = sys.modules.get(getattr(fn, "__module__", None) or "")
    paths = []
    f = getattr(module, "__file__", None)
    if f and module.__name__ != "__main__":
        p = pathlib.Path(f).resolve().parent
        for _ in range(module.__name__.count(".") + (1 if f.endswith("__init__.py") else 0)):
            p = p.parent
        paths.append(str(p))
    import gsp
    paths.append(str(pathlib.Path(gsp.__file__).resolve().parent.parent))
    return paths


# The child process of a callable job (so that a crash or an out-of-memory stays with it).
_CHILD = "import sys\nfrom gsp.batch import _child_main\nsys.exit(_child_main(sys.argv[1:]))\n"


def _json_default(x):
    try:
        import numpy as np
        if isinstance(x, np.generic):
            return x.item()
        if isinstance(x, np.ndarray):
            return x.tolist()
    except ImportError:
        pass
    if isinstance(x, os.PathLike):
        return os.fspath(x)
    raise TypeError(f"{type(x).__name__} is not JSON serializable")


def _one_line(e):
    lines = str(e).strip().splitlines()
    return f"{type(e).__name__}: {lines[0]}" if lines else type(e).__name__


def _child_main(argv):
    """Runs in a fresh interpreter on the worker: read the mesh, call the function, write a JSON."""
    func_file, input_path, output_path, result_file = argv
    t0 = time.perf_counter()
    try:
        with open(func_file, "rb") as f:
            fn = pickle.load(f)
        import gsp
        t_read = time.perf_counter()
        V, F = gsp.read_mesh(input_path)
        t_call = time.perf_counter()
        kwargs = {}
        try:
            params = inspect.signature(fn).parameters
            if "input" in params or any(p.kind is p.VAR_KEYWORD for p in params.values()):
                kwargs["input"] = input_path
        except (TypeError, ValueError):
            pass
        figures = fn(V, F, pathlib.Path(output_path), **kwargs)
        t_end = time.perf_counter()
        if figures is not None and not isinstance(figures, dict):
            raise TypeError(f"the job returned a {type(figures).__name__}, not a dict of figures or None")
        result = {"vertices": int(len(V)), "faces": int(len(F)),
                  "timings": {"read": t_call - t_read, "compute": t_end - t_call, "total": t_end - t0},
                  "figures": figures or {}}
        text = json.dumps(result, default=_json_default, allow_nan=True)
    except MemoryError:
        print(f"error: {input_path}: out of memory", file=sys.stderr)
        return 1
    except BaseException as e:   # noqa: BLE001 - every failure is the mesh's one-line error
        print(f"error: {_one_line(e)}", file=sys.stderr)
        return 1
    with open(result_file, "w", encoding="utf-8") as f:
        f.write(text)
    return 0


# ---------------------------------------------------------------------------------------------
# The task (runs on a worker)

# The apps die with their worker (no orphans computing for nobody when a worker is killed):
# setpriv --pdeathsig sets PR_SET_PDEATHSIG and execs the app. A wrapper, not preexec_fn, so that
# Python can still vfork (forking a Dask worker's address space costs ~20 ms per mesh).
_SETPRIV = shutil.which("setpriv") if sys.platform.startswith("linux") else None


def _wrap(argv, max_memory):
    """The command line that runs argv with the parent-death signal and the memory limit, if any."""
    if max_memory:
        prlimit = shutil.which("prlimit")
        if prlimit:
            argv = [prlimit, f"--as={int(max_memory)}", "--", *argv]
    if _SETPRIV:
        argv = [_SETPRIV, "--pdeathsig", "KILL", "--", *argv]
    return argv


def _limit_memory(max_memory):
    """preexec_fn fallback for the memory limit where prlimit(1) is missing."""
    if not max_memory or shutil.which("prlimit"):
        return None

    def setup():
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (max_memory, max_memory))
    return setup


def _signal_name(n):
    try:
        return signal.Signals(n).name
    except ValueError:
        return f"signal {n}"


def _nanny_environ():
    """The variables Dask's nanny sets in its worker processes (distributed.nanny.pre-spawn-environ)."""
    try:
        import dask
        return dict(dask.config.get("distributed.nanny.pre-spawn-environ", {}) or {})
    except ImportError:
        return {}


def _worker_address():
    try:
        from distributed import get_worker
        return get_worker().address
    except (ImportError, ValueError):
        return ""


def _run_task(spec):
    """One mesh: run the app (or the callable's child) and report what happened. Never raises
    for the mesh's own failures: they are the returned error."""
    t0 = time.perf_counter()
    out = {"returncode": None, "error": "", "stats": None, "report": None, "result": None,
           "worker": _worker_address()}
    tmpdir = tempfile.mkdtemp(prefix="gsp-batch-")
    output = spec["output"]
    tmp_output = None
    try:
        if spec["kind"] == "app":
            app = spec["app"]
            if not os.path.exists(app):      # another machine: the same app on its PATH
                app = shutil.which(os.path.basename(app)) or app
            stats = os.path.join(tmpdir, "stats.json")
            argv = [app, spec["input"], *spec["options"], spec["output_flag"], output, "--stats", stats, "-q"]
            argv += spec.get("extra", [])
        else:
            func_file = os.path.join(tmpdir, "function.pkl")
            with open(func_file, "wb") as f:
                f.write(spec["function"])
            stats = os.path.join(tmpdir, "result.json")
            ext = spec["ext"]
            tmp_output = os.path.join(os.path.dirname(output),
                                      f".{os.path.basename(output)}.{uuid.uuid4().hex[:8]}.tmp{ext}")
            argv = [sys.executable, "-c", _CHILD, func_file, spec["input"], tmp_output, stats]
        env = dict(os.environ)
        # Dask's nanny sets MALLOC_TRIM_THRESHOLD_=65536 for its Python worker; inherited, it makes
        # the apps' allocations trim memory all the time (gsp-cvt 25% slower).
        if env.get("MALLOC_TRIM_THRESHOLD_") == str(_nanny_environ().get("MALLOC_TRIM_THRESHOLD_")):
            del env["MALLOC_TRIM_THRESHOLD_"]
        if spec.get("pythonpath"):
            env["PYTHONPATH"] = os.pathsep.join([*spec["pythonpath"], env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
        name = os.path.basename(argv[0]) if spec["kind"] == "app" else spec["job"]
        try:
            proc = subprocess.Popen(_wrap(argv, spec.get("max_memory")), stdin=subprocess.DEVNULL,
                                    stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env, cwd=tmpdir,
                                    preexec_fn=_limit_memory(spec.get("max_memory")))
        except OSError as e:
            out["error"] = f"{name}: cannot run: {e}"
            return out
        try:
            _, err = proc.communicate(timeout=spec.get("timeout"))
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
            out["error"] = f"{name}: timed out after {spec['timeout']:g} s"
            out["returncode"] = proc.returncode
            return out
        rc = out["returncode"] = proc.returncode
        err_lines = [line.strip() for line in err.decode("utf-8", "replace").splitlines() if line.strip()]
        if rc < 0:
            out["error"] = f"{name}: killed by {_signal_name(-rc)}"
            if -rc == signal.SIGKILL:
                out["error"] += " (out of memory?)"
        elif rc != 0:
            errors = [line for line in err_lines if "error:" in line]
            line = (errors or err_lines or [f"exited with code {rc}"])[-1]
            if spec["kind"] != "app":
                line = f"{name}: {line}"
            out["error"] = line
        if os.path.exists(stats):
            try:
                with open(stats, encoding="utf-8") as f:
                    data = json.load(f)
                out["stats" if spec["kind"] == "app" else "result"] = data
            except ValueError as e:
                if rc == 0:
                    out["error"] = f"{name}: unreadable statistics: {e}"
        if spec["kind"] == "app" and spec["job"] == "bench" and rc == 0:
            try:
                with open(output, encoding="utf-8") as f:
                    out["report"] = json.load(f)
            except (OSError, ValueError) as e:
                out["error"] = f"{name}: unreadable report {output}: {e}"
        if tmp_output is not None and rc == 0 and not out["error"] and os.path.exists(tmp_output):
            os.replace(tmp_output, output)
        return out
    finally:
        if tmp_output is not None and os.path.exists(tmp_output):   # failed, timed out: no output
            try:
                os.unlink(tmp_output)
            except OSError:
                pass
        out["seconds"] = time.perf_counter() - t0
        shutil.rmtree(tmpdir, ignore_errors=True)


# ---------------------------------------------------------------------------------------------
# Rows


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


# ---------------------------------------------------------------------------------------------
# Cluster


def connect(scheduler=None, workers=None):
    """A dask.distributed Client: to `scheduler` (an address or a scheduler file), or to a new
    LocalCluster of `workers` processes with one thread each (default: one per core).

    Returns (client, close); call close() at the end (it also stops a cluster it started).
    """
    import logging
    from distributed import Client, LocalCluster
    if scheduler and workers:
        raise UsageError("--scheduler and --workers exclude each other")
    if scheduler:
        scheduler = os.fspath(scheduler)
        if os.path.isfile(scheduler):
            client = Client(scheduler_file=scheduler, timeout="30s")
        else:
            client = Client(scheduler, timeout="30s")
        return client, client.close
    n = int(workers) if workers else (os.cpu_count() or 1)
    if n < 1:
        raise UsageError(f"--workers {n}: at least 1")
    scratch = tempfile.mkdtemp(prefix="gsp-batch-workers-")
    try:
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=":0",
                               silence_logs=logging.ERROR, local_directory=scratch)
        client = Client(cluster)
    except BaseException:
        shutil.rmtree(scratch, ignore_errors=True)
        raise

    def close():
        try:
            client.close()
            cluster.close()
        finally:
            shutil.rmtree(scratch, ignore_errors=True)
    return client, close


def dashboard_link(client):
    """(address, note) of the scheduler's Dask dashboard, or None when it serves none.

    The note is "" or says why the page is empty (the scheduler lacks bokeh). The address is
    asked for once (2 s): a scheduler started with --no-dashboard answers 404.
    """
    import urllib.error
    import urllib.request
    try:
        if "dashboard" not in (client.scheduler_info().get("services") or {}):
            return None
        link = client.dashboard_link
        with urllib.request.urlopen(link, timeout=2) as page:
            body = page.read(4096).decode("utf-8", "replace")
    except urllib.error.HTTPError:
        return None
    except Exception:   # noqa: BLE001 - unreachable from here, or no address: nothing to print
        return None
    return link, ("it needs bokeh, which the scheduler lacks" if "needs bokeh" in body else "")


# ---------------------------------------------------------------------------------------------
# The run


def _parse_memory(value):
    if value is None or isinstance(value, int):
        return value
    s = str(value).strip().upper().rstrip("B")
    units = {"K": 1 << 10, "M": 1 << 20, "G": 1 << 30, "T": 1 << 40}
    try:
        if s and s[-1] in units:
            return int(float(s[:-1]) * units[s[-1]])
        return int(float(s))
    except ValueError:
        raise UsageError(f"--max-memory {value}: a size like 4G or 500M") from None


def run(job, inputs, outdir, *, scheduler=None, workers=None, client=None, options=(), bin_dir=None,
        ext=None, timeout=None, max_memory=None, retries=2, force=False, progress=None, on_client=None):
    """Run JOB on every mesh of INPUTS on Dask, outputs into OUTDIR; returns one dict per mesh.

    job: "geodesic", "sample", "remesh", "path", "bench" (the apps, `options` passed to them),
    "module:function", or a callable, called as fn(V, F, path) with `path` the file to write
    (renamed to OUTDIR/<name><ext> when it returns; fn may take `input=` too); it returns a
    dict of figures for the row, or None.
    inputs: files, folders and globs. client / scheduler / workers: where to run (default: a
    LocalCluster with a worker per core). timeout: seconds per mesh. max_memory: bytes (or
    "4G") of address space per mesh. retries: Dask's retries of a task whose worker failed.
    force: ignore the manifest (re-run everything). progress(row, done, total): called for
    every row as it is known (skipped rows first). on_client(client): called once connected
    (no cluster is started or contacted when every mesh is skipped).

    Every mesh is a row with status "ok", "error" (and its one-line `error`) or "skipped"
    (complete from an earlier run with the same settings). results.csv, results.json and
    manifest.jsonl are written to OUTDIR. Raises UsageError for a batch that cannot start,
    FileNotFoundError when the app is missing.
    """
    started = time.time()
    t0 = time.perf_counter()
    options = [str(o) for o in options]
    if callable(job) and not isinstance(job, str):
        fn, job_name = job, f"{getattr(job, '__module__', '?')}:{getattr(job, '__qualname__', 'callable')}"
    elif isinstance(job, str) and job in JOBS:
        fn, job_name = None, job
    elif isinstance(job, str) and ":" in job:
        fn, job_name = _load_callable(job), job
    else:
        raise UsageError(f"{job}: unknown job (one of {', '.join(JOBS)}, or module:function)")
    if fn is None:
        for o in options:
            if o.split("=", 1)[0] in _RESERVED_OPTIONS:
                raise UsageError(f"{o}: gsp-batch sets this option itself")
    elif options:
        raise UsageError(f"{job_name}: a callable job takes no job options ({' '.join(options)})")
    if timeout is not None and not (timeout > 0):
        raise UsageError(f"--timeout {timeout}: must be positive")
    max_memory = _parse_memory(max_memory)
    ext = ext or (DEFAULT_EXT.get(job_name, ".ply"))
    if not ext.startswith("."):
        ext = "." + ext
    paths = _expand_inputs(inputs)
    outdir = pathlib.Path(outdir).resolve()
    outdir.mkdir(parents=True, exist_ok=True)

    if fn is None:
        app = find_app(job_name, bin_dir)
        tool = _app_version(app)
        base = {"kind": "app", "job": job_name, "app": app,
                "output_flag": "--json" if job_name == "bench" else "-o",
                "extra": ["--no-table"] if job_name == "bench" else []}
    else:
        import cloudpickle
        tool = _callable_identity(fn)
        base = {"kind": "callable", "job": job_name, "function": cloudpickle.dumps(fn),
                "pythonpath": _callable_pythonpath(fn)}
    base.update(timeout=timeout, max_memory=max_memory, ext=ext)

    manifest = {} if force else _read_manifest(outdir)
    by_input = {}
    for e in manifest.values():
        if {"input", "input_size", "input_mtime_ns", "input_sha256"} <= e.keys():
            by_input[(e["input"], e["input_size"], e["input_mtime_ns"])] = e["input_sha256"]

    names = _output_names(paths, ext)
    rows = [None] * len(paths)
    tasks = []
    done = 0

    def report(i):
        nonlocal done
        done += 1
        if progress is not None:
            progress(rows[i], done, len(paths))

    for i, (p, name) in enumerate(zip(paths, names)):
        st = p.stat()
        sha = by_input.get((str(p), st.st_size, st.st_mtime_ns)) or _sha256_file(p)
        settings = {"job": job_name, "options": options, "tool": tool, "input_sha256": sha, "ext": ext}
        settings_hash = hashlib.sha256(json.dumps(settings, sort_keys=True).encode()).hexdigest()[:20]
        task = dict(base, input=str(p), output=str(outdir / name), output_name=name,
                    settings_hash=settings_hash, input_sha256=sha, input_size=st.st_size,
                    input_mtime_ns=st.st_mtime_ns, index=i)
        task["options"] = [o.replace("{name}", pathlib.Path(name).stem).replace("{outdir}", str(outdir))
                           for o in options]
        entry = manifest.get(name)
        if not force and _complete(entry, settings_hash, outdir):
            row = dict(entry.get("row") or {}, input=str(p), output=name, status="skipped", error="")
            rows[i] = row
            report(i)
        else:
            tasks.append(task)

    owned_close = None
    futures = {}
    try:
        if tasks:
            if client is None:
                client, owned_close = connect(scheduler, workers)
            if on_client is not None:
                on_client(client)
            from distributed import as_completed
            run_id = uuid.uuid4().hex[:8]
            # Largest meshes first: the long tasks start early and the last ones are short.
            order = sorted(tasks, key=lambda t: -t["input_size"])
            for rank, task in enumerate(order):
                key = f"gsp-batch-{run_id}-{task['index']}-{pathlib.Path(task['output_name']).stem[:40]}"
                spec = {k: v for k, v in task.items() if k not in ("settings_hash", "input_sha256",
                                                                   "input_mtime_ns", "index")}
                fut = client.submit(_run_task, spec, key=key, retries=retries, pure=False,
                                    priority=len(order) - rank)
                futures[fut] = task
            with open(outdir / MANIFEST, "a", encoding="utf-8") as mf:
                for fut in as_completed(list(futures)):
                    task = futures.pop(fut)
                    if fut.status == "finished":
                        res = fut.result()
                    else:
                        try:
                            exc = fut.exception()
                            msg = _one_line(exc)
                        except Exception as e:   # noqa: BLE001 - cancelled: whatever Dask says
                            msg = _one_line(e)
                        res = {"returncode": None, "error": f"task failed: {msg}"}
                    fut.release()
                    if (task["kind"] == "app" and res.get("returncode") == 2):
                        for f in futures:
                            f.cancel()
                        futures.clear()
                        raise UsageError(res.get("error") or f"{task['app']}: usage error")
                    row = _make_row(task, res)
                    rows[task["index"]] = row
                    if row["status"] == "ok":
                        files = {}
                        if row["output"] and os.path.exists(task["output"]):
                            files[row["output"]] = os.path.getsize(task["output"])
                        entry = {"output_name": task["output_name"], "input": task["input"],
                                 "input_size": task["input_size"], "input_mtime_ns": task["input_mtime_ns"],
                                 "input_sha256": task["input_sha256"], "settings_hash": task["settings_hash"],
                                 "job": job_name, "options": options, "tool": tool, "files": files,
                                 "finished": time.time(), "row": row}
                        mf.write(json.dumps(entry, default=_json_default) + "\n")
                        mf.flush()
                    report(task["index"])
    except UsageError:
        raise
    except BaseException as e:
        reason = "interrupted" if isinstance(e, KeyboardInterrupt) else _one_line(e)
        for i, r in enumerate(rows):
            if r is None:
                rows[i] = dict({c: None for c in COLUMNS}, input=str(paths[i]), status="error",
                               error=f"not finished: {reason}")
        raise
    finally:
        for f in futures:
            f.cancel()
        if owned_close is not None:
            try:
                owned_close()
            except Exception:   # noqa: BLE001 - closing a cluster that is going away anyway
                pass
        if all(r is not None for r in rows):
            counts = {s: sum(1 for r in rows if r["status"] == s) for s in ("ok", "skipped", "error")}
            meta = {"job": job_name, "options": options, "tool": tool, "outdir": str(outdir),
                    "started": started, "seconds": time.perf_counter() - t0, "meshes": len(rows),
                    "counts": counts}
            _write_tables(outdir, rows, meta)
            _compact_manifest(outdir)
    return rows


def _compact_manifest(outdir):
    """Rewrite manifest.jsonl with one line per output (the last), for outputs that still exist."""
    entries = _read_manifest(outdir)
    lines = []
    for name, e in entries.items():
        if all((outdir / f).exists() for f in (e.get("files") or {})):
            lines.append(json.dumps(e, default=_json_default))
    _write_atomic(outdir / MANIFEST, "".join(line + "\n" for line in lines))


# ---------------------------------------------------------------------------------------------
# Command line

# gsp-batch's own options and how many values each takes.
_OWN = {"-o": 1, "--output": 1, "--scheduler": 1, "--workers": 1, "--bin": 1, "--ext": 1, "--timeout": 1,
        "--max-memory": 1, "--retries": 1, "--force": 0, "-q": 0, "--quiet": 0, "-h": 0, "--help": 0}


def _is_option(token):
    return token.startswith("-") and len(token) > 1 and not _is_number(token)


def _is_number(token):
    try:
        float(token.split(",")[0])
        return True
    except ValueError:
        return False


def _split_argv(argv):
    """gsp-batch's own arguments, and the job's: everything after `--`, and any option gsp-batch
    does not know with the values that follow it (up to the next option)."""
    own, job_opts = [], []
    i = 0
    while i < len(argv):
        t = argv[i]
        if t == "--":
            job_opts += argv[i + 1:]
            break
        name = t.split("=", 1)[0]
        if _is_option(t) and name in _OWN:
            n = 0 if "=" in t else _OWN[name]
            own += argv[i:i + 1 + n]
            i += 1 + n
        elif _is_option(t):
            job_opts.append(t)
            i += 1
            while i < len(argv) and argv[i] != "--" and not _is_option(argv[i]):
                job_opts.append(argv[i])
                i += 1
        else:
            own.append(t)
            i += 1
    return own, job_opts


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        print(f"gsp-batch: error: {message}\nRun with --help for more information.", file=sys.stderr)
        sys.exit(2)


def _parser():
    p = _Parser(prog="gsp-batch", description=__doc__.split("\n\n")[0],
                usage="gsp-batch JOB INPUT... -o OUTDIR [--workers N | --scheduler ADDRESS] [options] "
                      "[--] [JOB OPTIONS]",
                epilog="Job options: everything after `--`, and any option gsp-batch does not know (with "
                       "the values that follow it), e.g. `gsp-batch geodesic meshes/ -o out --source-vertex 0`. "
                       "{name} and {outdir} in job options become the mesh's output name and OUTDIR. "
                       "Exit codes: 0 every mesh ok or skipped, 1 some failed (the table is still written), "
                       "2 usage error. See docs/batch.md.")
    p.add_argument("job", metavar="JOB", help=f"{', '.join(JOBS)}, or a Python callable module:function "
                                              "taking (V, F, path)")
    p.add_argument("inputs", metavar="INPUT", nargs="+", help="mesh files, folders (their mesh files) or globs")
    p.add_argument("-o", "--output", required=True, metavar="OUTDIR",
                   help="folder for the outputs, results.csv, results.json and manifest.jsonl")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler: tcp://host:port or a "
                                                         "scheduler file")
    g.add_argument("--workers", type=int, metavar="N", help="start a local cluster of N worker processes, one "
                                                           "thread each (default: one per core)")
    p.add_argument("--bin", metavar="DIR", help="folder of the gsp-* apps (default: $GSP_BIN_DIR, PATH, the "
                                                "checkout's build/bin)")
    p.add_argument("--ext", metavar="EXT", help="output extension (default: .ply; bench: .json)")
    p.add_argument("--timeout", type=float, metavar="S", help="seconds per mesh, then the mesh is an error")
    p.add_argument("--max-memory", metavar="SIZE", help="address space per mesh (e.g. 4G): beyond it the "
                                                       "mesh fails with 'out of memory'")
    p.add_argument("--retries", type=int, default=2, metavar="N",
                   help="re-runs of a task that raised on its worker (default 2; a dead worker's tasks "
                        "are re-run by Dask in any case)")
    p.add_argument("--force", action="store_true", help="re-run every mesh, ignoring the manifest")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar, no per-mesh error lines")
    return p


class _Progress:
    """A one-line progress bar on stderr when it is a terminal."""

    def __init__(self, stream, enabled, quiet):
        self.stream, self.enabled, self.quiet = stream, enabled, quiet
        self.t0 = time.perf_counter()
        self.counts = {"ok": 0, "skipped": 0, "error": 0}
        self.drawn = False

    def __call__(self, row, done, total):
        self.counts[row["status"]] = self.counts.get(row["status"], 0) + 1
        if row["status"] == "error" and not self.quiet:
            self.clear()
            print(f"gsp-batch: {row['input']}: {row['error']}", file=self.stream)
        if self.enabled:
            width = 30
            filled = int(width * done / max(total, 1))
            c = self.counts
            line = (f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total}  ok {c['ok']}  "
                    f"skipped {c['skipped']}  error {c['error']}  {time.perf_counter() - self.t0:.1f} s")
            self.stream.write(line)
            self.stream.flush()
            self.drawn = True

    def clear(self):
        if self.drawn:
            self.stream.write("\r\033[K")
            self.stream.flush()
            self.drawn = False


def main(argv=None):
    """The command line: exit 0 every mesh ok or skipped, 1 some failed, 2 usage error."""
    argv = list(sys.argv[1:] if argv is None else argv)
    own, job_opts = _split_argv(argv)
    args = _parser().parse_args(own)
    err = sys.stderr
    bar = _Progress(err, enabled=err.isatty() and not args.quiet, quiet=args.quiet)
    t0 = time.perf_counter()
    try:
        if args.scheduler and args.workers:
            raise UsageError("--scheduler and --workers exclude each other")
        if args.workers is not None and args.workers < 1:
            raise UsageError(f"--workers {args.workers}: at least 1")
        if args.retries < 0:
            raise UsageError(f"--retries {args.retries}: 0 or more")
        # Check the job, inputs and app before starting a cluster.
        if args.job not in JOBS and ":" not in args.job:
            raise UsageError(f"{args.job}: unknown job (one of {', '.join(JOBS)}, or module:function)")
        _expand_inputs(args.inputs)
        if args.job in JOBS:
            try:
                find_app(args.job, args.bin)
            except FileNotFoundError as e:
                raise UsageError(str(e)) from None
        else:
            _load_callable(args.job)

        def on_client(client):
            dashboard = dashboard_link(client)
            if dashboard:
                link, note = dashboard
                bar.clear()
                print(f"gsp-batch: dashboard {link}" + (f" ({note})" if note else ""), file=err)

        rows = run(args.job, args.inputs, args.output, scheduler=args.scheduler, workers=args.workers,
                   options=job_opts, bin_dir=args.bin, ext=args.ext, timeout=args.timeout,
                   max_memory=args.max_memory, retries=args.retries, force=args.force, progress=bar,
                   on_client=on_client)
    except UsageError as e:
        bar.clear()
        print(f"gsp-batch: error: {e}\nRun with --help for more information.", file=err)
        return 2
    except (OSError, ImportError) as e:
        bar.clear()
        print(f"gsp-batch: error: {e}", file=err)
        return 2 if isinstance(e, (FileNotFoundError, ImportError)) else 1
    except KeyboardInterrupt:
        bar.clear()
        print(f"gsp-batch: interrupted; {os.path.join(args.output, RESULTS_CSV)} lists what finished, "
              "a second run resumes", file=err)
        return 130
    bar.clear()
    seconds = time.perf_counter() - t0
    counts = {s: sum(1 for r in rows if r["status"] == s) for s in ("ok", "skipped", "error")}
    ran = counts["ok"] + counts["error"]
    rate = f", {ran / seconds:.2f} meshes/s" if ran and seconds > 0 else ""
    print(f"gsp-batch: {len(rows)} meshes in {seconds:.1f} s: {counts['ok']} ok, {counts['skipped']} skipped, "
          f"{counts['error']} failed{rate}; table {os.path.join(args.output, RESULTS_CSV)}", file=err)
    return 1 if counts["error"] else 0


if __name__ == "__main__":
    # `python3 -m gsp.batch`: run the imported module's main, so that the tasks are pickled by
    # reference to gsp.batch (workers import it), not by value from __main__.
    from gsp.batch import main as _main
    sys.exit(_main())
