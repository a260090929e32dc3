"""The jobs that are apps (gsp-geodesic, gsp-sample, gsp-cvt, gsp-path, gsp-bench) and where to find them."""
import os
import pathlib
import shutil
import subprocess

#: Job name -> the app that runs it.
JOBS = {"geodesic": "gsp-geodesic", "sample": "gsp-sample", "remesh": "gsp-cvt", "path": "gsp-path",
        "bench": "gsp-bench"}
#: Default output extension per job (callables: .ply).
DEFAULT_EXT = {"geodesic": ".ply", "sample": ".ply", "remesh": ".ply", "path": ".ply", "bench": ".json"}

# Options gsp-batch sets itself for every app.
_RESERVED_OPTIONS = {"-o", "--output", "--stats", "--json", "-h", "--help", "--version"}


def find_app(job, bin_dir=None):
    """The absolute path of JOB's app: in `bin_dir` when given (only there), else in $GSP_BIN_DIR,
    on PATH, or in the checkout's build/bin beside the package.

    Raises FileNotFoundError naming the places searched.
    """
    name = JOBS[job]
    if bin_dir:
        folders = [pathlib.Path(bin_dir)]
    else:
        here = pathlib.Path(__file__).resolve().parent.parent   # build/python/gsp or python/gsp
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
