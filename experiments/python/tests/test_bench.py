"""The benchmark runs and prints its ratios (a smoke run on few points: no timing is asserted)."""

import os
import subprocess
import sys


def test_bench_runs():
    script = os.path.join(os.environ["MINK_PY_SOURCE"], "bench", "bench_sum.py")
    out = subprocess.run([sys.executable, script, "--lib", os.environ["MINK_PYBENCH"], "--n", "1000", "--rounds", "3"],
                         check=True, capture_output=True, text=True).stdout.splitlines()
    rows = [line.split(",") for line in out if line[:2] in ("2D", "3D")]
    assert [r[0] for r in rows] == ["2D", "3D"]
    assert all(float(r[5]) > 0 and float(r[6]) > 0 for r in rows)
