"""Jobs that are Python callables (`module:function`): loading them, what their outputs depend on,
what the child process needs to unpickle them."""
import hashlib
import inspect
import os
import pathlib
import sys

from .apps import JOBS
from .errors import UsageError


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
