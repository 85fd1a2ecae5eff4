"""The task docs/python.md sweeps on dask (scripts/python-doc.py): workers import it from here."""
import json

import plascap


def tension_block(dt):
    """The paper's tension block (examples/scenes) at time step dt [s] on ODE: its plastic elongation."""
    with open("examples/scenes/paper-tension-block.json") as f:
        scene = json.load(f)
    scene["dt"], scene["duration"] = dt, 1.0
    result = plascap.run_scene(scene, engine="ode")
    return {"dt [s]": round(dt, 6), "steps": result["steps"],
            "plastic [m]": round(result["joints"]["top"]["plastic_displacement"], 7)}
