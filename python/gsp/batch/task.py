"""The Dask task: one mesh on a worker, its app or callable child run as a subprocess (memory
limit, timeout, death with the worker) and what happened to it."""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import uuid

from .child import _CHILD
from .inputs import _sha256_file

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
    # An app writes its statistics to stdout (no scratch folder per mesh: creating and removing
    # one cost 7 ms a mesh here, as much as half a small mesh's own work); a callable's child
    # gets a scratch folder for its function and result.
    if spec.get("hash_input"):
        # for the manifest (the client left it to the worker: runner.run)
        try:
            out["input_sha256"] = _sha256_file(spec["input"])
        except OSError:
            pass    # the job reports the unreadable file
    tmpdir = None if spec["kind"] == "app" else tempfile.mkdtemp(prefix="gsp-batch-")
    output = spec["output"]
    tmp_output = None
    stats = None
    try:
        if spec["kind"] == "app":
            app = spec["app"]
            if not os.path.exists(app):      # another machine: the same app on its PATH
                app = shutil.which(os.path.basename(app)) or app
            argv = [app, spec["input"], *spec["options"], spec["output_flag"], output, "--stats", "-", "-q"]
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
                                    stdout=subprocess.PIPE if tmpdir is None else subprocess.DEVNULL,
                                    stderr=subprocess.PIPE, env=env,
                                    cwd=tmpdir or os.path.dirname(os.path.abspath(output)),
                                    preexec_fn=_limit_memory(spec.get("max_memory")))
        except OSError as e:
            out["error"] = f"{name}: cannot run: {e}"
            return out
        try:
            out_text, err = proc.communicate(timeout=spec.get("timeout"))
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
        text = None
        if tmpdir is None:
            text = out_text.decode("utf-8", "replace") if out_text and out_text.strip() else None
        elif os.path.exists(stats):
            with open(stats, encoding="utf-8") as f:
                text = f.read()
        if text is not None:
            try:
                out["stats" if spec["kind"] == "app" else "result"] = json.loads(text)
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
        if tmpdir is not None:
            shutil.rmtree(tmpdir, ignore_errors=True)
