#!/usr/bin/env python3
"""Diagnostic (docs/structures.md, "Known limits"; the property test is tests/test_structure_energy.cpp): random small frames —
3 to 5 nodes in a box of 4 x 3 x 1 m, a tree of members of random standard shapes (S355) and 1 to 4
segments, fixed at the first node, gravity and one ramped random force — run on Bullet and ODE; prints
the energy ledger's remainder as a share of the energy handled, the part of it Bullet's position
corrections did, the joints' rows' work their laws did not book (joints_unbooked), and the dissipated
energy. A joint law that never creates energy keeps joints_unbooked at or below 0 (the solver's slack
only takes energy) and the dissipated energy at or above 0.
Usage: scripts/random-frame-energy.py [SEED] [FRAMES] [coupled|box]   (after scripts/build.sh)."""
import json
import random
import subprocess
import sys

SIM = "build/tools/plastic-sim/plastic-sim"
SHAPES = ["IPE 200", "HEB 200", "SHS 200x200x10", "CHS 168.3x8"]


def frame(rng, yield_surface):
    n = rng.randint(3, 5)
    nodes = {"N%d" % i: [round(rng.uniform(0, 4), 2), round(rng.uniform(0, 3), 2), round(rng.uniform(-0.5, 0.5), 2)]
             for i in range(n)}
    members = [{"name": "m%d" % i, "from": "N%d" % rng.randrange(i), "to": "N%d" % i, "shape": rng.choice(SHAPES),
                "material": "S355", "segments": rng.randint(1, 4), "yield_surface": yield_surface} for i in range(1, n)]
    force = [rng.uniform(-5e4, 5e4) for _ in range(3)]
    return {"dt": 0.002, "duration": 0.6, "iterations": 100, "gravity": [0, -9.81, 0], "nodes": nodes, "members": members,
            "supports": {"N0": "fixed"},
            "loads": [{"node": "N%d" % rng.randrange(1, n), "force": force, "history": [[0, 0], [0.3, 1]]}]}


def main():
    seed = int(sys.argv[1]) if len(sys.argv) > 1 else 1
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 6
    yield_surface = sys.argv[3] if len(sys.argv) > 3 else "coupled"
    rng = random.Random(seed)
    print("frame engine remainder/handled corrections/handled joints_unbooked/handled handled[J] dissipated[J]")
    for k in range(count):
        scene = frame(rng, yield_surface)
        for engine in ["bullet", "ode"]:
            run = subprocess.run([SIM, "-", "--engine", engine, "--json"], input=json.dumps(scene), capture_output=True, text=True)
            if run.returncode != 0:
                print(k, engine, "error:", run.stderr.strip()[:200])
                continue
            e = json.loads(run.stdout)["energy"]
            scale = max(e["handled"], 1e-9)
            print(k, engine, "%+.3f" % (e["remainder"] / scale), "%+.3f" % (e.get("corrections", 0.0) / scale),
                  "%+.3f" % (e.get("joints_unbooked", 0.0) / scale), "%.0f" % e["handled"], "%.0f" % e["dissipated"])


if __name__ == "__main__":
    main()
