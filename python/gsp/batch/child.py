"""The child process that runs a callable job on one mesh (a fresh interpreter on the worker)."""
import inspect
import json
import pathlib
import pickle
import sys
import time

from .errors import _one_line
from .jsonable import _json_default

# The child process of a callable job (so that a crash or an out-of-memory stays with it).
_CHILD = "import sys\nfrom gsp.batch.child import _child_main\nsys.exit(_child_main(sys.argv[1:]))\n"


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
