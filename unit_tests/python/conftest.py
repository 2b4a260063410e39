"""Shared fixtures of the Python package's tests: the `lrsvo` program to compare against, and a scratch folder.

ctest runs these with PYTHONPATH at the build tree's package and LRSVO_PROGRAM at the lrsvo program.
"""

import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def lrsvo_program():
    program = os.environ.get("LRSVO_PROGRAM")
    if not program:
        pytest.fail("LRSVO_PROGRAM is not set (ctest sets it to the lrsvo program)")
    return program


@pytest.fixture
def run_cli(lrsvo_program):
    """Runs `lrsvo ARGS...`, fails the test on a nonzero exit status, returns stdout."""

    def run(*args):
        done = subprocess.run([lrsvo_program, *map(str, args)], capture_output=True, text=True)
        assert done.returncode == 0, f"lrsvo {' '.join(map(str, args))} exited {done.returncode}: {done.stderr}"
        return done.stdout

    return run
