"""Shared fixtures: the shared data set and the dualhex executable of the same build."""
import json
import os
import pathlib
import subprocess

import pytest


@pytest.fixture(scope="session")
def shared_data():
    path = pathlib.Path(os.environ.get("DUALHEX_SHARED_DATA", "/work/shared/data"))
    if not (path / "grids").is_dir():
        pytest.skip(f"shared data not found at {path} (set DUALHEX_SHARED_DATA)")
    return path


@pytest.fixture(scope="session")
def cli():
    """Runs the build's `dualhex` with --json and returns the parsed document."""
    exe = os.environ.get("DUALHEX_EXE")
    if not exe or not os.path.exists(exe):
        pytest.skip("DUALHEX_EXE (the dualhex executable) not set")

    def run(*args):
        out = subprocess.run([exe, *args, "--json"], check=True, capture_output=True, text=True)
        return json.loads(out.stdout)

    return run
