# The pytest suite of the Python bindings (docs/python.md). ctest runs it from the source tree with
# PYTHONPATH=build/<preset>/python and ROLLWEAR_EXE, the command line the results are compared with.
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def source():
    return SOURCE


@pytest.fixture(scope="session")
def rollwear_exe():
    exe = os.environ.get("ROLLWEAR_EXE", str(SOURCE / "build" / "release" / "app" / "rollwear"))
    if not os.path.exists(exe):
        pytest.skip(f"no rollwear program at {exe} (set ROLLWEAR_EXE)")
    return exe


@pytest.fixture
def cli(rollwear_exe):
    """runs `rollwear ARGS...`; returns the CompletedProcess"""

    def run(*args, cwd=SOURCE):
        return subprocess.run([rollwear_exe, *map(str, args)], cwd=cwd, capture_output=True, text=True)

    return run
