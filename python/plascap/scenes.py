"""Scenes run on Bullet or ODE, as plastic-sim runs them (docs/plastic-sim.md).

run_scene() returns plastic-sim's JSON summary as a dict ("bodies", "joints", "nodes", "energy",
...) and, with trace=True, its per-step trace under "trace": {column: array} with the columns of
plastic-sim --csv (time; each body's position, velocity and orientation; each joint's forces and
offsets, plastic deformation, dissipated energy and state; the energy ledger; node displacements).
"""
import csv
import io
import json
import os

from . import _plascap
from .arrays import column


def _scene_argument(scene):
    """(text or path, is_path) for a dict, JSON text or a path."""
    if isinstance(scene, dict):
        return json.dumps(scene), False
    if isinstance(scene, (str, os.PathLike)) and not str(scene).lstrip().startswith("{"):
        return os.fspath(scene), True
    if isinstance(scene, str):
        return scene, False
    raise TypeError("scene: a dict in plastic-sim's format, its JSON text, or the path of a scene file")


def _trace(text):
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        return {}
    header, values = rows[0], rows[1:]
    return {name: column(float(r[i]) for r in values) for i, name in enumerate(header)}  # all numeric


def run_scene(scene, engine="bullet", trace=False):
    """Runs a scene (dict, JSON text or path) on `engine` (see engines()); returns its summary.

    Bad scenes raise InputError with plastic-sim's message. What the engine foresees before the
    run (ode-step on an island of thousands of rows: hours of dense solves) is a RuntimeWarning
    first, and is in the summary's "warnings" too. The run releases the GIL."""
    text, is_path = _scene_argument(scene)
    summary, trace_csv = _plascap._run_scene(text, is_path, engine, trace)
    result = json.loads(summary)
    if trace:
        result["trace"] = _trace(trace_csv)
    return result
