"""run(): a job over every mesh of the inputs on Dask, skipping what the manifest says is done."""
import hashlib
import json
import os
import pathlib
import time
import uuid

from .apps import DEFAULT_EXT, JOBS, _RESERVED_OPTIONS, _app_version, find_app
from .callables import _callable_identity, _callable_pythonpath, _load_callable
from .cluster import connect
from .errors import UsageError, _one_line
from .inputs import _expand_inputs, _output_names, _sha256_file
from .jsonable import _json_default
from .manifest import _compact_manifest, _complete, _read_manifest
from .outdir import MANIFEST
from .rows import COLUMNS, _make_row, _write_tables
from .task import _run_task


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



def _app_extra(job_name, options):
    """What gsp-batch adds to an app's command line after the job options."""
    extra = ["--no-table"] if job_name == "bench" else []
    # One core per worker: gsp-geodesic would use every core of the machine on big meshes.
    if job_name == "geodesic" and not any(o == "--threads" or str(o).startswith("--threads=") for o in options):
        extra += ["--threads", "1"]
    return extra

def _completed_with_results(client, futures):
    """(future, result) as tasks finish, in batches; result is {"returncode": None, "error": ...}
    for a task that failed (its worker died more often than the retries allow) or was
    cancelled."""
    from distributed import as_completed
    pending = as_completed(futures)
    for batch in pending.batches():
        # A task whose result lived on a worker that died after it finished is computed again
        # by Dask (its status goes back to pending): wait for it again instead of calling it
        # failed (its exception is None then; a CI run under load reported "task failed:
        # NoneType: None" for one mesh of the killed-worker test).
        again = [f for f in batch if f.status in ("pending", "lost")]
        for fut in again:
            pending.add(fut)
        batch = [f for f in batch if f not in again]
        finished = [f for f in batch if f.status == "finished"]
        try:
            results = dict(zip(finished, client.gather(finished))) if finished else {}
        except Exception:   # noqa: BLE001 - lost between completion and gather: one at a time
            results = {}
        for fut in batch:
            if fut in results:
                yield fut, results[fut]
                continue
            try:
                if fut.status == "finished":
                    yield fut, fut.result()
                    continue
                msg = _one_line(fut.exception())
            except Exception as e:   # noqa: BLE001 - cancelled or lost: whatever Dask says
                msg = _one_line(e)
            yield fut, {"returncode": None, "error": f"task failed: {msg}"}


def run(job, inputs, outdir, *, scheduler=None, workers=None, client=None, options=(), bin_dir=None,
        ext=None, timeout=None, max_memory=None, retries=2, force=False, progress=None, on_client=None,
        worker_processes=False):
    """Run JOB on every mesh of INPUTS on Dask, outputs into OUTDIR; returns one dict per mesh.

    job: "geodesic", "sample", "remesh", "path", "bench" (the apps, `options` passed to them),
    "module:function", or a callable, called as fn(V, F, path) with `path` the file to write
    (renamed to OUTDIR/<name><ext> when it returns; fn may take `input=` too); it returns a
    dict of figures for the row, or None.
    inputs: files, folders and globs. client / scheduler / workers: where to run (default: a
    LocalCluster with a worker per core, threads of this process unless worker_processes;
    every mesh runs in a process of its own either way). timeout: seconds per mesh. max_memory: bytes (or
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
                "output_flag": "--json" if job_name == "bench" else "-o", "extra": _app_extra(job_name, options)}
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

    def settings_hash_of(sha):
        settings = {"job": job_name, "options": options, "tool": tool, "input_sha256": sha, "ext": ext}
        return hashlib.sha256(json.dumps(settings, sort_keys=True).encode()).hexdigest()[:20]

    for i, (p, name) in enumerate(zip(paths, names)):
        st = p.stat()
        entry = manifest.get(name)
        # The input's hash is needed here only to compare with a manifest entry; otherwise the
        # worker hashes it beside the job (on a first run of many small meshes hashing them
        # all here was a serial part of the batch, 0.6 ms a mesh on the client).
        sha = by_input.get((str(p), st.st_size, st.st_mtime_ns))
        if sha is None and entry and not force:
            sha = _sha256_file(p)
        task = dict(base, input=str(p), output=str(outdir / name), output_name=name,
                    settings_hash=settings_hash_of(sha) if sha else None, input_sha256=sha,
                    input_size=st.st_size, input_mtime_ns=st.st_mtime_ns, index=i,
                    hash_input=sha is None)
        task["options"] = [o.replace("{name}", pathlib.Path(name).stem).replace("{outdir}", str(outdir))
                           for o in options]
        if not force and sha and _complete(entry, task["settings_hash"], outdir):
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
                client, owned_close = connect(scheduler, workers, processes=worker_processes)
            if on_client is not None:
                on_client(client)
            run_id = uuid.uuid4().hex[:8]
            # Largest meshes first: the long tasks start early and the last ones are short.
            # One graph for the whole batch (client.map): Client.submit sends a graph per task
            # and reads the calling module's source for each (Dask's computation record), which
            # cost the client 12 ms a mesh here, as much as a small mesh's own work, and on
            # two cores the client shares them with the workers. The workers take the tasks of one
            # graph in the order given (checked: a shuffled list ran in its own order).
            order = sorted(tasks, key=lambda t: -t["input_size"])
            keys, specs = [], []
            for rank, task in enumerate(order):
                keys.append(f"gsp-batch-{run_id}-{rank:07d}-{pathlib.Path(task['output_name']).stem[:40]}")
                specs.append({k: v for k, v in task.items() if k not in ("settings_hash", "input_sha256",
                                                                         "input_mtime_ns", "index")})
            futures = dict(zip(client.map(_run_task, specs, key=keys, retries=retries, pure=False), order))
            with open(outdir / MANIFEST, "a", encoding="utf-8") as mf:
                # The finished tasks' results fetched together, one gather per batch of
                # completions (not one Future.result() round trip each; as_completed's own
                # with_results gathers each future concurrently and trips a race in this
                # Dask's TCP writes).
                for fut, res in _completed_with_results(client, list(futures)):
                    task = futures.pop(fut)
                    fut.release()
                    if (task["kind"] == "app" and res.get("returncode") == 2):
                        for f in futures:
                            f.cancel()
                        futures.clear()
                        raise UsageError(res.get("error") or f"{task['app']}: usage error")
                    if task["hash_input"] and res.get("input_sha256"):
                        task["input_sha256"] = res["input_sha256"]
                        task["settings_hash"] = settings_hash_of(task["input_sha256"])
                    row = _make_row(task, res)
                    rows[task["index"]] = row
                    if row["status"] == "ok" and task["settings_hash"]:
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
