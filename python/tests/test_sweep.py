"""A sweep on a 2-worker local dask cluster gives the numbers a serial loop gives."""
import json
import os

import plascap
from conftest import SOURCE_DIR


def tension_block(dt):
    with open(os.path.join(SOURCE_DIR, "examples", "scenes", "paper-tension-block.json")) as f:
        scene = json.load(f)
    scene["dt"] = dt
    scene["duration"] = 1.0
    result = plascap.run_scene(scene, engine="ode")
    return {"dt": dt, "plastic": result["joints"]["top"]["plastic_displacement"], "steps": result["steps"]}


def test_a_time_step_sweep_on_two_workers_equals_the_serial_loop():
    steps = [1 / 60, 1 / 120, 1 / 240, 1 / 480]
    serial = [tension_block(dt) for dt in steps]
    assert plascap.sweep(tension_block, steps, workers=2) == serial
    frame = plascap.table(serial)
    assert list(frame.columns) == ["dt", "plastic", "steps"] and len(frame) == 4


def test_a_sweep_goes_to_a_running_scheduler_by_its_address():
    from dask.distributed import LocalCluster
    steps = [1 / 60, 1 / 240]
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        assert plascap.sweep(tension_block, steps, scheduler=cluster.scheduler_address) == [tension_block(dt) for dt in steps]
