"""Shared by the Python tests: the grainmesh program beside the module (ctest sets
GRAINMESH_BINARY and PYTHONPATH), and a report without what differs from run to run."""

import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def binary():
    path = os.environ.get("GRAINMESH_BINARY", "build/grainmesh")
    assert os.path.exists(path), f"the grainmesh program is not at {path} (set GRAINMESH_BINARY)"
    return path


@pytest.fixture(scope="session")
def run_binary(binary):
    def run(*args):
        return subprocess.run([binary, *map(str, args)], capture_output=True, text=True, timeout=600)
    return run


def without_timings(report):
    """The report without its seconds and memory figures (all else is the run's to the bit)."""
    if isinstance(report, dict):
        return {k: without_timings(v) for k, v in report.items()
                if k not in ("seconds", "memory_mib", "peak_memory_mib")}
    if isinstance(report, list):
        return [without_timings(v) for v in report]
    return report
