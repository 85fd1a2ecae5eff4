"""Shared helpers: the section-calc command-line tool the bindings are checked against."""
import json
import os
import subprocess

import pytest

SECTION_CALC = os.environ.get("PLASCAP_SECTION_CALC", "section-calc")
SOURCE_DIR = os.environ.get("PLASCAP_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def section_calc(*args):
    """Runs section-calc; returns (exit code, stdout, the message after 'error: ' on stderr)."""
    run = subprocess.run([SECTION_CALC, *args], capture_output=True, text=True)
    error = run.stderr.strip().split("error: ", 1)[-1] if run.returncode else ""
    return run.returncode, run.stdout, error


def section_calc_json(*args):
    code, out, error = section_calc(*args, "--json")
    assert code == 0, error
    return json.loads(out)


@pytest.fixture
def source_dir():
    return SOURCE_DIR
