"""manifest.jsonl, what a second run skips: one JSON line per complete output, the last line for
an output wins."""
import json

from .jsonable import _json_default
from .outdir import MANIFEST, _write_atomic


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


def _compact_manifest(outdir):
    """Rewrite manifest.jsonl with one line per output (the last), for outputs that still exist."""
    entries = _read_manifest(outdir)
    lines = []
    for name, e in entries.items():
        if all((outdir / f).exists() for f in (e.get("files") or {})):
            lines.append(json.dumps(e, default=_json_default))
    _write_atomic(outdir / MANIFEST, "".join(line + "\n" for line in lines))
