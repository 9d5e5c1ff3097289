"""Shared helpers of the mink module's tests."""

import os
import subprocess

import numpy as np


def mink_exe():
    """The `mink` command of the same build (MINK_EXE, set by ctest)."""
    exe = os.environ.get("MINK_EXE")
    assert exe and os.path.exists(exe), "MINK_EXE must name the build's mink command (run the tests with ctest)"
    return exe


def cli_points(*args):
    """The CSV of `mink sum ARGS` as an array (columns, rows): one row per column of the file."""
    out = subprocess.run([mink_exe(), "sum", *args], check=True, capture_output=True, text=True).stdout
    lines = out.splitlines()
    header = lines[0].split(",")
    data = np.array([[float(v) for v in line.split(",")] for line in lines[1:]])
    return header, np.ascontiguousarray(data.T)


def bits(a):
    """The array's bits, for exact comparisons (-0.0 differs from 0.0)."""
    a = np.ascontiguousarray(a)
    return a.view(np.uint64 if a.dtype == np.float64 else np.uint32)
