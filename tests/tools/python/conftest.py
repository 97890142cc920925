"""Shared fixtures of the Python module's tests (tests/tools/python, run by ctest).

ctest sets PYTHONPATH to <build>/python (the module), SCALLOP_BINARY to the built
`scallop` executable and SCALLOP_SOURCE_DIR to the repository, so each test can run
the CLI on the same input and compare."""
import json
import os
import subprocess

import pytest


def _env(name):
    value = os.environ.get(name)
    if not value:
        pytest.exit(f"{name} is not set: run these tests through ctest", returncode=2)
    return value


@pytest.fixture(scope="session")
def scallop_binary():
    return _env("SCALLOP_BINARY")


@pytest.fixture(scope="session")
def source_dir():
    return _env("SCALLOP_SOURCE_DIR")


@pytest.fixture(scope="session")
def cli(scallop_binary):
    """cli(*args) runs `scallop args...`; returns the CompletedProcess (text)."""

    def run(*args, check=True):
        done = subprocess.run([scallop_binary, *map(str, args)], capture_output=True, text=True)
        if check and done.returncode != 0:
            raise AssertionError(f"scallop {' '.join(map(str, args))} exited "
                                 f"{done.returncode}: {done.stderr}")
        return done

    return run


@pytest.fixture(scope="session")
def cli_json(cli):
    """cli_json(*args) runs `scallop args... --json` and parses its stdout."""
    return lambda *args: json.loads(cli(*args, "--json").stdout)


def ball_job(spacing=0.05, size=6.0, step_over=1.5):
    """A small ball-cutter raster job (a dict with the job file's keys)."""
    return {
        "tool": {"type": "ball", "radius": 2.0},
        "stock": {"min": [0, 0, -3], "max": [size, size * 0.75, 0]},
        "grid": {"spacing": spacing},
        "path": {"raster": {"direction": "x", "step_over": step_over, "depth": 0.4,
                            "lead_deg": 0, "tilt_deg": 0, "zigzag": False}},
    }


def bull_job(spacing=0.04):
    """A bull cutter with lead and tilt: the exact sweep of a tilted torus."""
    return {
        "tool": {"type": "bull", "radius": 3.0, "corner_radius": 1.0},
        "stock": {"min": [0, 0, -5], "max": [8, 7, 0]},
        "grid": {"spacing": spacing},
        "path": {"raster": {"direction": "y", "step_over": 2.5, "depth": 0.5,
                            "lead_deg": 5, "tilt_deg": 3, "zigzag": True}},
    }


def write_job(tmp_path, job, name="job.json"):
    path = tmp_path / name
    path.write_text(json.dumps(job))
    return path
