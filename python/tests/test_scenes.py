"""Scenes run from Python give plastic-sim's summary and trace, number for number."""
import csv
import json
import os
import re
import select
import subprocess
import sys
import warnings

import numpy
import pytest

import plascap
from conftest import SOURCE_DIR

PLASTIC_SIM = os.environ.get("PLASCAP_PLASTIC_SIM", "plastic-sim")
SCENES = os.path.join(SOURCE_DIR, "examples", "scenes")


def plastic_sim(*args):
    run = subprocess.run([PLASTIC_SIM, "--quiet", *args], capture_output=True, text=True)
    return run.returncode, run.stdout, run.stderr.strip().split("error: ", 1)[-1]


def without_wall_time(summary):
    summary = dict(summary)
    summary.pop("wall_seconds")
    return summary


@pytest.mark.parametrize("engine", ["bullet", "ode"])
@pytest.mark.parametrize("scene", ["paper-tension-block.json", "cantilever-bending.json", "collapsing-stack.json"])
def test_summary_matches_plastic_sim(scene, engine):
    path = os.path.join(SCENES, scene)
    code, out, _ = plastic_sim(path, "--engine", engine, "--json")
    assert code == 0
    assert without_wall_time(plascap.run_scene(path, engine=engine)) == without_wall_time(json.loads(out))


def test_trace_matches_plastic_sim_csv(tmp_path):
    path = os.path.join(SCENES, "cantilever-bending.json")
    trace_file = tmp_path / "trace.csv"
    assert plastic_sim(path, "--csv", str(trace_file))[0] == 0
    with open(trace_file) as f:
        rows = list(csv.reader(f))
    trace = plascap.run_scene(path, trace=True)["trace"]
    assert list(trace) == rows[0]
    for i, name in enumerate(rows[0]):
        assert isinstance(trace[name], numpy.ndarray)
        assert numpy.allclose(trace[name], [float(r[i]) for r in rows[1:]], rtol=1e-9, atol=0), name


def test_the_paper_tension_block_flows_as_table_3_5():
    # 6000 kg on an 80 kN joint, g = 10, dt = 1/60 s, one free step: 3 steps at 80 kN against
    # 60 kN stop it 0.0027778 m below where the joint took hold (the paper's Table 3.5).
    for engine in plascap.engines():
        result = plascap.run_scene(os.path.join(SCENES, "paper-tension-block.json"), engine=engine)
        assert result["joints"]["top"]["plastic_displacement"] == pytest.approx(0.0027778, abs=2e-7), engine


def test_a_scene_as_a_dict_runs_like_its_file():
    path = os.path.join(SCENES, "paper-tension-block.json")
    with open(path) as f:
        scene = json.load(f)
    assert without_wall_time(plascap.run_scene(scene)) == without_wall_time(plascap.run_scene(path))


def test_a_bad_scene_raises_what_plastic_sim_prints(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"dt": 0.01, "duration": 1, "bodies": [{"name": "a", "box": [1, 1, 1], "mass": 1}],
                               "joints": [{"name": "j", "a": "world", "b": "nobody", "anchor": [0, 0, 0]}]}))
    code, _, message = plastic_sim(str(bad))
    assert code == 2
    with pytest.raises(ValueError) as raised:
        plascap.run_scene(str(bad))
    assert str(raised.value) == message
    with pytest.raises(ValueError, match="engine"):
        plascap.run_scene(os.path.join(SCENES, "paper-tension-block.json"), engine="havok")


def test_the_trace_records_orientations_a_spinning_cube_turns_at_its_rate():
    # A free cube spinning at w = 2 rad/s about z (symmetric inertia: no precession) has the
    # orientation q(t) = (cos(w t/2), 0, 0, sin(w t/2)).
    scene = {"dt": 1 / 240, "duration": 1.0, "gravity": [0, 0, 0],
             "bodies": [{"name": "cube", "box": [1, 1, 1], "mass": 1, "position": [0, 5, 0], "angular_velocity": [0, 0, 2]}],
             "joints": []}
    for engine in plascap.engines():
        trace = plascap.run_scene(scene, engine=engine, trace=True)["trace"]
        t = trace["time"]
        assert numpy.allclose(trace["cube.qw"], numpy.cos(t), atol=1e-4), engine
        assert numpy.allclose(trace["cube.qz"], numpy.sin(t), atol=1e-4), engine
        assert numpy.allclose(trace["cube.qx"], 0, atol=1e-12) and numpy.allclose(trace["cube.qy"], 0, atol=1e-12), engine


LARGE = os.path.join(SOURCE_DIR, "examples", "large", "multistorey-frame.json")
ISLAND = r"largest island's 7050 rows \(1020 bodies joined by joints\).*--engine ode \(dWorldQuickStep\)"


def test_ode_step_warns_before_a_run_of_hours():
    # The large example is one island of 7,050 rows (1,175 joints of six): dWorldStep's dense solve
    # takes about a minute a step. The warning comes before the first step, so warnings as errors
    # stop the run at once. In a child process with a timeout: without the warning the run would
    # take a day, and the test must fail, not hang.
    code = f"import plascap; plascap.run_scene({LARGE!r}, engine='ode-step')"
    run = subprocess.run([sys.executable, "-W", "error::RuntimeWarning", "-c", code], capture_output=True, text=True, timeout=120)
    assert run.returncode != 0
    assert re.search("RuntimeWarning: ode-step \\(dWorldStep\\) solves the " + ISLAND, run.stderr), run.stderr


def test_plastic_sim_says_so_as_the_run_starts():
    with subprocess.Popen([PLASTIC_SIM, LARGE, "--engine", "ode-step"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          text=True) as sim:
        try:  # written before the first step, which takes a minute
            ready, _, _ = select.select([sim.stderr], [], [], 60)
            first = sim.stderr.readline() if ready else "nothing within 60 s"
        finally:
            sim.kill()
    assert re.match("plastic-sim: warning: ode-step \\(dWorldStep\\) solves the " + ISLAND, first), first


def test_small_scenes_run_without_a_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        result = plascap.run_scene(os.path.join(SCENES, "simply-supported-beam.json"), engine="ode-step")
    assert result["warnings"] == []
