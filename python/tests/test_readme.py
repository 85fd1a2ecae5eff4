"""The README's Python example runs and prints the IPE 300's Mx (Wpl,y * fy = 628.4 cm^3 * 355 MPa)."""
import os
import re
import subprocess
import sys

from conftest import SOURCE_DIR


def test_the_readme_python_example_runs():
    with open(os.path.join(SOURCE_DIR, "README.md")) as f:
        readme = f.read()
    code = re.search(r"PYTHONPATH=build/python /usr/bin/python3 -c '([^']+)'", readme).group(1)
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert abs(float(run.stdout) - 628.4e-6 * 355e6) < 0.005 * 628.4e-6 * 355e6
