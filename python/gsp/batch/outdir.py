"""OUTDIR's own files (the tables and the manifest, beside the meshes' outputs), written atomically."""
import os
import pathlib
import tempfile

MANIFEST = "manifest.jsonl"
RESULTS_CSV = "results.csv"
RESULTS_JSON = "results.json"
_RESERVED = {MANIFEST, RESULTS_CSV, RESULTS_JSON}


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
