"""The replay of large scenes (docs/replay.md, "Large scenes"): the 1,175-joint five-storey frame
(examples/large) and a field of 1,000 posts run for 10,000 steps. Their pages stay within the frame
budget and the size bound, draw every frame in headless Chromium, and report their frame rate —
measured by the page itself in real time (over the DevTools pipe), not in virtual time. The figures
go to PLASCAP_PAGE_REPORT/large-replay.json for docs/replay.md."""
import json
import os

import pytest

from conftest import example, replay

MEGABYTE = 1e6
# The bound docs/replay.md states: the frames' 6 MB of data (8 MB as base64), the inlined libraries
# and page code (1.3 MB), and the scene's description, about 1 KB per body and joint.
def size_bound(bodies, joints):
    return 8.0 * MEGABYTE + 1.3 * MEGABYTE + 1000.0 * (bodies + joints)


def post_field(path):
    """1,000 posts on plastic root hinges, 20 to 200 N·m, two fifths of them at rest and the others
    kicked over at up to 1.2 rad/s: some stand, some yield and stop, the weakest fold under their own
    weight (P-delta), break at 0.6 rad and fall to the ground. 10 s at dt = 1 ms: 10,000 steps."""
    # The ground lies 0.3 m below the posts' feet, so that only fallen posts touch it.
    bodies = [{"name": "ground", "box": [80, 1, 60], "mass": 1, "position": [29, -0.8, 18], "static": True}]
    joints = []
    for i in range(40):
        for k in range(25):
            name, x, z = f"post-{i}-{k}", 1.5 * i, 1.5 * k
            spin = [0.0, 0.0, 0.4, 0.8, 1.2][(i + 2 * k) % 5]
            bodies.append({"name": name, "box": [0.1, 1.0, 0.1], "density": 2400, "position": [x, 0.5, z],
                           "velocity": [0.5 * spin, 0, 0], "angular_velocity": [0, 0, -spin]})
            capacity = 20 + 180 * ((i * 3 + k * 7) % 10) / 9
            joints.append({"name": f"root-{i}-{k}", "a": "world", "b": name, "anchor": [x, 0, z], "axis": [0, 1, 0],
                           "x_axis": [1, 0, 0],
                           "capacities": {"Mx": capacity, "Mz": capacity, "N": 1e5, "Qx": 1e5, "Qz": 1e5, "My": 1e3},
                           "dofs": {"N": "rigid", "Qx": "rigid", "Qz": "rigid", "My": "rigid", "Mx": "plastic", "Mz": "plastic"},
                           "max_plastic_rotation": 0.6})
    with open(path, "w") as f:
        json.dump({"name": "A field of 1,000 posts", "dt": 0.001, "duration": 10.0, "iterations": 10,
                   "gravity": [0, -9.81, 0], "bodies": bodies, "joints": joints}, f)
    return path


def check_large_page(page, summary, live_browser, budget_frames):
    size = os.path.getsize(page)
    bodies, joints = len(summary["bodies"]), len(summary["joints"])
    assert joints >= 1000
    assert size <= size_bound(bodies, joints), f"{page}: {size / MEGABYTE:.2f} MB"
    state = live_browser.state_when(page, "#autoplay")
    assert state["state"] == "done", state
    assert state["errors"] == "0", state.get("lastError")
    frames = int(state["frames"])
    assert 2 <= frames <= budget_frames
    assert int(state["framesDrawn"]) >= frames
    broken = sum(1 for j in summary["joints"].values() if j["broken"])
    assert int(state["brokenEnd"]) == broken
    return {"bodies": bodies, "joints": joints, "steps": summary["steps"], "frames": frames, "broken": broken,
            "megabytes": round(size / MEGABYTE, 2), "render_ms": float(state["renderMs"]), "fps": float(state["fps"]),
            "ready_ms": int(state["readyMs"]), "run_wall_seconds": round(summary["wall_seconds"], 1)}


def test_large_replays_stay_within_budget_and_play(tmp_path, live_browser):
    figures = {}
    # The frame's 1,020 bodies and 1,175 joints leave room for 6 MB / (1,020·14 + 1,175·8 B) = 253 frames.
    page, summary = replay(str(tmp_path), example("large/multistorey-frame.json"), "bullet")
    figures["multistorey-frame (bullet)"] = check_large_page(page, summary, live_browser, 253)
    # Issue 15's energy goal on the example, at its 150 iterations: the ledger's remainder within 2 % of
    # the energy handled (docs/structures.md, "Known limits": +1.1 % of 78.8 kJ; +2.6 % at 100).
    energy = summary["energy"]
    assert abs(energy["remainder"]) <= 0.02 * energy["handled"], energy
    page, summary = replay(str(tmp_path), post_field(str(tmp_path / "post-field.json")), "ode")
    assert summary["steps"] == 10000
    # 10,000 steps decimated to the byte budget: 6 MB / (1,001·14 + 1,000·8 B) = 272 frames.
    result = check_large_page(page, summary, live_browser, 272)
    assert result["frames"] == 272
    assert 0 < result["broken"] < 1000
    figures["post-field, 10,000 steps (ode)"] = result
    report = os.environ.get("PLASCAP_PAGE_REPORT")
    if report:
        os.makedirs(report, exist_ok=True)
        with open(os.path.join(report, "large-replay.json"), "w") as f:
            json.dump(figures, f, indent=2)
    print(json.dumps(figures, indent=2))
