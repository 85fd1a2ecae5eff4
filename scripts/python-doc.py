#!/usr/bin/python3
"""Writes docs/python.md from a real session: runs each code block below with the plascap module
of the build tree and puts its output under it, and draws docs/python-ipe300-interaction.png with
matplotlib (Debian: python3-matplotlib, installed on demand).

    scripts/python-doc.py        (after scripts/build.sh; about ten seconds)
"""
import contextlib
import io
import os
import subprocess
import sys
import textwrap

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "build", "python"))
os.chdir(ROOT)

try:
    import matplotlib
except ImportError:
    print("python-doc: installing python3-matplotlib", file=sys.stderr)
    subprocess.run(["apt-get", "install", "-y", "-qq", "python3-matplotlib"], check=True, stdout=subprocess.DEVNULL)
    import matplotlib
matplotlib.use("Agg")

INTRO = """# plascap in Python

`import plascap` gives sections, materials and their plastic capacities by both routes, the exact
coupled yield surface, and scenes on Bullet or ODE, with sweeps on dask. SI units throughout (m, N,
N·m, Pa). This page is written by `scripts/python-doc.py` from a real session: every output below
is what the code printed.

**Set-up.** README's commands build the module (`PLASCAP_BUILD_PYTHON`, on when pybind11 is found)
for Debian's interpreter, `/usr/bin/python3`, which sees Debian's `pybind11-dev`, `python3-numpy`,
`python3-distributed` and `python3-pandas`; a `python3` earlier on PATH (pyenv, conda) may not, and
CMake uses `/usr/bin/python3` unless `-DPython3_EXECUTABLE=...` says otherwise. From the build
tree: `PYTHONPATH=build/python /usr/bin/python3`; installed: `cmake --install build` puts the
package in the interpreter's `lib/python3.X/dist-packages` under the prefix (`/usr/local` by
default, on Debian's path). Every function has a docstring (`help(plascap.Section.capacities)`).
Bad input raises `plascap.InputError`, a `ValueError` carrying the message the command-line tools
print.
"""

SESSION = [
    ("## Sections and capacities",
     """\
import plascap
ipe = plascap.Section.shape("IPE 300", material="S355")
print(ipe)
c = ipe.capacities()                      # exact closed forms (paper eqs. 2.10-2.14)
print(f"Mx = {c.Mx:.0f} N*m, Mz = {c.Mz:.0f} N*m, N = {c.N:.0f} N, Qz = {c.Qz:.0f} N")
print(f"Mx / fy = {c.Mx / 355e6 * 1e6:.1f} cm^3 (EN 10365 table: Wpl,y = 628.4 cm^3)")
k = ipe.capacities(method="cubature")     # CGAL mesh + GSL cubature, with error estimates
print(f"cubature Mx = {k.Mx:.6f} +- {k.errors['Mx']:.1e} N*m on {k.triangles} triangles")
e = ipe.elastic_properties()
print(f"Ixx = {e.Ixx * 1e8:.0f} cm^4, EIxx = {e.EIxx:.4g} N*m^2")
print(f"J = {ipe.torsion_constant().J * 1e8:.2f} cm^4, T_p = {ipe.plastic_torque().T:.0f} N*m")"""),
    ("A polygon with a hole, a section file, and what bad input says:",
     """\
box = plascap.Section.polygon([(-0.1, -0.15), (0.1, -0.15), (0.1, 0.15), (-0.1, 0.15)],
                              holes=[[(-0.09, -0.14), (0.09, -0.14), (0.09, 0.14), (-0.09, 0.14)]],
                              material="S355")
print(box.capacities(only="N,Mx,My"))
print(plascap.Section.from_file("sections/examples/t-section.json").capacities().Mx)
try:
    plascap.Section.shape("IPE 310", material="S355")
except ValueError as error:
    print("ValueError:", error)"""),
    ("## A catalogue study",
     """\
rows = []
for name in plascap.shapes("IPE")[::3]:
    s = plascap.Section.shape(name, material="S355")
    c, e = s.capacities(), s.elastic_properties()
    rows.append({"shape": name, "Mx [kN m]": round(c.Mx / 1e3, 1), "Mx/Mel": round(c.Mx / (355e6 * e.Wx), 3)})
print(plascap.table(rows).to_string(index=False))"""),
    ("## The exact yield surface",
     """\
y = ipe.yield_condition()                 # N-Mx-Mz surface reduced by shear and torsion
print(f"U = {y.utilisation(N=500e3, Mx=150e3, Qz=100e3):.4f}")
print({k: round(v, 4) for k, v in y.evaluate(N=500e3, Mx=150e3).items() if k != "gradient"})
curve = ipe.interaction_curve("N-Mx", samples=180)   # a NumPy array of (N, Mx) rows
print(curve.shape, f"largest Mx {curve[:, 1].max():.0f} N*m")

import matplotlib.pyplot as plt
fig, ax = plt.subplots(figsize=(5, 4))
ax.plot(curve[:, 1] / 1e3, curve[:, 0] / 1e3, label="exact N-Mx")
p = ipe.capacities()                      # the linear interaction of the independent limits
ax.plot([p.Mx / 1e3, 0, -p.Mx / 1e3, 0, p.Mx / 1e3], [0, p.N / 1e3, 0, -p.N / 1e3, 0], "--", label="linear")
ax.set_xlabel("Mx [kN m]"), ax.set_ylabel("N [kN]"), ax.set_title("IPE 300, S355"), ax.legend()
fig.tight_layout(), fig.savefig("docs/python-ipe300-interaction.png", dpi=100)"""),
    ("![The IPE 300's exact N–Mx interaction diagram](python-ipe300-interaction.png)\n\n## Scenes",
     """\
print(plascap.engines())
r = plascap.run_scene("examples/scenes/paper-tension-block.json", engine="ode", trace=True)
print(f"plastic elongation {r['joints']['top']['plastic_displacement']:.7f} m (paper Table 3.5: 0.0027778)")
print(f"{len(r['trace'])} trace columns, {len(r['trace']['time'])} steps; block.y at the end {r['trace']['block.y'][-1]:.5f} m")"""),
    ("## A time-step sweep on dask\n\n`plascap.sweep(function, items)` computes `function(item)` for every item on a dask "
     "cluster: a local one of `workers` processes by default, or the scheduler at `scheduler=` "
     "(e.g. `\"tcp://10.0.0.5:8786\"`). The function must be importable by the workers (a module's, "
     "not one typed at the prompt); this page's comes from `scripts/python_doc_tasks.py`.",
     """\
import sys; sys.path.insert(0, "scripts")
from python_doc_tasks import tension_block
results = plascap.sweep(tension_block, [1 / 30, 1 / 60, 1 / 120, 1 / 240], workers=2)
print(plascap.table(results).to_string(index=False))"""),
]


def main():
    out = [INTRO]
    namespace = {}
    for text, code in SESSION:
        out.append(text + "\n")
        captured = io.StringIO()
        with contextlib.redirect_stdout(captured):
            exec(compile(code, "<python-doc>", "exec"), namespace)
        out.append("```python\n" + code + "\n```\n")
        if captured.getvalue().strip():
            out.append("```\n" + captured.getvalue().rstrip() + "\n```\n")
    with open(os.path.join(ROOT, "docs", "python.md"), "w") as f:
        f.write("\n".join(out))
    print("python-doc: wrote docs/python.md and docs/python-ipe300-interaction.png")


if __name__ == "__main__":
    main()
