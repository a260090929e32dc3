"""The examples/ scripts run as a user runs them (fresh interpreter, default arguments)."""
import os
import pathlib
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

EXAMPLES = sorted((SOURCE_DIR / "examples").glob("*.py"))


@pytest.mark.parametrize("script", EXAMPLES, ids=[p.name for p in EXAMPLES])
def test_example_runs(script, tmp_path):
    args = [sys.executable, str(script)]
    if "--out" in script.read_text():
        args += ["--out", str(tmp_path)]
    r = subprocess.run(args, capture_output=True, text=True, env=os.environ.copy(), timeout=600)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip()
    if "--out" in script.read_text():
        assert any(tmp_path.iterdir())


def test_there_are_examples():
    assert len(EXAMPLES) >= 4
