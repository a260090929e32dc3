"""Inputs (files, folders, globs) to mesh paths, their output names in OUTDIR, their content hash."""
import glob
import hashlib
import os
import pathlib

from .errors import UsageError
from .outdir import _RESERVED

#: The files a folder input contributes.
MESH_EXTENSIONS = (".ply", ".obj", ".off", ".stl", ".gltf", ".glb")


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
