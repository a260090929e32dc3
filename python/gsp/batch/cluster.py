"""Where the tasks run: a Dask client (an existing scheduler or a LocalCluster) and its dashboard."""
import os
import shutil
import tempfile

from .errors import UsageError


def connect(scheduler=None, workers=None, processes=False):
    """A dask.distributed Client: to `scheduler` (an address or a scheduler file), or to a new
    LocalCluster of `workers` workers with one thread each (default: one per core).

    The local workers are threads of this process unless `processes` (then each is a process
    with a nanny that restarts it). Every mesh runs in a process of its own either way (an app,
    or a callable's child), so a worker only waits on it: threads start in a fraction of the
    time (no interpreter per worker importing Dask) and stop at once.

    Returns (client, close); call close() at the end (it also stops a cluster it started).
    """
    import logging
    import dask
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
        # Without the workers' statistical profiler (a thread sampling every stack each 10 ms):
        # the dashboard's profile page has nothing to show for tasks that wait on an app, and
        # on a machine with as many cores as workers that thread takes a worker's time.
        with dask.config.set({"distributed.worker.profile.enabled": False}):
            # TCP on the loopback for threads too (Dask's default for them, inproc, names the
            # machine's address in the dashboard link): as fast here, and the same addresses.
            cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=bool(processes),
                                   protocol="tcp://", host="127.0.0.1", dashboard_address=":0",
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
