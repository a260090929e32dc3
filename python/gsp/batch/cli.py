"""The command line (gsp-batch, python3 -m gsp.batch): job options split from gsp-batch's own,
checks before a cluster starts, the summary line and the exit code."""
import argparse
import os
import sys
import time

from .apps import JOBS, find_app
from .callables import _load_callable
from .cluster import dashboard_link
from .errors import UsageError
from .inputs import _expand_inputs
from .outdir import RESULTS_CSV
from .progress import _Progress
from .runner import run

# gsp-batch's own options and how many values each takes.
_OWN = {"-o": 1, "--output": 1, "--scheduler": 1, "--workers": 1, "--worker-processes": 0, "--bin": 1, "--ext": 1,
        "--timeout": 1, "--max-memory": 1, "--retries": 1, "--force": 0, "-q": 0, "--quiet": 0, "-h": 0,
        "--help": 0}


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
    # The description is the first line of the package's docstring (gsp/batch/__init__.py).
    p = _Parser(prog="gsp-batch", description=sys.modules[__package__].__doc__.split("\n\n")[0],
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
    g.add_argument("--workers", type=int, metavar="N", help="start a local cluster of N workers, one thread "
                                                           "each (default: one per core)")
    p.add_argument("--worker-processes", action="store_true",
                   help="the local cluster's workers as processes (each restarted by a nanny if it dies) "
                        "instead of threads of gsp-batch; every mesh runs in its own process either way")
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
        if args.scheduler and args.worker_processes:
            raise UsageError("--worker-processes applies to a local cluster, not to --scheduler")
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
                   on_client=on_client, worker_processes=args.worker_processes)
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
