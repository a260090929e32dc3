"""`pip install --no-build-isolation .` from the checkout, as docs/python.md says, into a fresh
virtual environment (with Debian's numpy through --system-site-packages); then the installed
package is imported from outside the source tree. GSP_BUILD_DIR (set by ctest) makes pip reuse
the configured build instead of compiling everything again."""
import os
import shutil
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR


def test_pip_install_into_a_venv(tmp_path):
    if subprocess.run([sys.executable, "-c", "import venv, ensurepip"], capture_output=True).returncode:
        pytest.skip("python3-venv is not installed")
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    py = venv / "bin" / "python"
    env = dict(os.environ)
    env.pop("PYTHONPATH", None)   # the installed copy, not the build tree's
    work = tmp_path / "src"
    # A copy of the checkout (pip builds in the source tree; this one is left clean).
    shutil.copytree(SOURCE_DIR, work, ignore=shutil.ignore_patterns("build*", "out", ".git", "__pycache__"))
    r = subprocess.run([str(py), "-m", "pip", "install", "--no-build-isolation", "--no-deps", "--no-index", "-q", "."],
                       cwd=work, env=env, capture_output=True, text=True, timeout=1800)
    assert r.returncode == 0, r.stdout + r.stderr
    code = ("import gsp, numpy as np, pathlib; "
            "V, F = gsp.read_mesh('" + str(SOURCE_DIR / "data" / "samples" / "fertility.off") + "'); "
            "d = gsp.GeodesicSolver(V, F).distance(0); "
            "assert d.shape == (len(V),) and np.isfinite(d).all(); "
            "assert 'site-packages' in gsp.__file__; "
            "assert (pathlib.Path(gsp.__file__).parent / '__init__.pyi').exists(); print(gsp.__version__)")
    r = subprocess.run([str(py), "-c", code], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "0.1.0"
