"""Throughput of mink.sum against the C batch call it wraps, interleaved.

    PYTHONPATH=build/experiments/python python3 experiments/python/bench/bench_sum.py \
        --lib build/experiments/python/libmink_pybench.so [--n 1000000] [--rounds 21]

Each round runs, on the same parameter arrays, the C call timed in C
(libmink_pybench: mkSum2_Batch / mkSum3_Batch into a preallocated array),
mink.sum writing into a preallocated array (out=) and mink.sum allocating its
output, each Python call timed around the call with time.perf_counter; the
order rotates from round to round, so that each goes first in a third of them. Prints the
median seconds of each and the ratios of the Python calls' times to the C call's
(1.00 = no overhead), for 2D (n points) and 3D (a grid of about n points).
"""

import argparse
import ctypes
import statistics
import sys
import time

import numpy as np

import mink

PAIRS = {
    2: ("superellipse a=3 b=2 eps=0.5 rot=0.3 shear=1", "superellipse a=1 b=0.5 eps=1.5"),
    3: ("superquadric a=3 b=2 c=1.5 eps1=0.5 eps2=1.5 quat=0.9,0.1,0.3,0.2",
        "superquadric a=1 b=0.5 c=0.8 eps1=1.2 eps2=0.3"),
}


def bench(lib, dim, n, rounds):
    spec1, spec2 = PAIRS[dim]
    b1, b2 = mink.Body(spec1), mink.Body(spec2)
    side = n if dim == 2 else int(round(n ** 0.5))
    u = mink.sample(dim, side)
    count = u.shape[1]
    out_c = np.empty_like(u)
    out_py = np.empty_like(u)
    ptr = ctypes.POINTER(ctypes.c_double)
    c_times, py_out_times, py_new_times = [], [], []
    def run_c():
        s = lib.mkPyBench_Sum(dim, spec1.encode(), spec2.encode(), u.ctypes.data_as(ptr), out_c.ctypes.data_as(ptr),
                              count)
        if s < 0:
            sys.exit("bench_sum: the C call failed")
        c_times.append(s)

    def run_py_out():
        t0 = time.perf_counter()
        mink.sum(b1, b2, u, out=out_py)
        py_out_times.append(time.perf_counter() - t0)

    def run_py_new():
        t0 = time.perf_counter()
        fresh = mink.sum(b1, b2, u)
        py_new_times.append(time.perf_counter() - t0)
        del fresh

    order = [run_c, run_py_out, run_py_new]
    for r in range(rounds):
        for f in order[r % 3:] + order[:r % 3]:  # each goes first in a third of the rounds
            f()
    if not np.array_equal(out_c, out_py):
        sys.exit("bench_sum: mink.sum's points differ from the C call's")
    c, po, pn = (statistics.median(t) for t in (c_times, py_out_times, py_new_times))
    print(f"{dim}D,{count},{c:.6f},{po:.6f},{pn:.6f},{po / c:.3f},{pn / c:.3f}")
    return po / c, pn / c


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--lib", required=True, help="the path of libmink_pybench.so (the build's experiments/python)")
    ap.add_argument("--n", type=int, default=1000000, help="points per call (default 1000000)")
    ap.add_argument("--rounds", type=int, default=21, help="interleaved rounds (default 21)")
    a = ap.parse_args()
    if a.n < 4 or a.rounds < 1:
        ap.error("--n must be >= 4 and --rounds >= 1")
    lib = ctypes.CDLL(a.lib)
    lib.mkPyBench_Sum.restype = ctypes.c_double
    lib.mkPyBench_Sum.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p, ctypes.POINTER(ctypes.c_double),
                                  ctypes.POINTER(ctypes.c_double), ctypes.c_int]
    print(f"# mink.sum against the C batch call, median of {a.rounds} interleaved rounds, kernel "
          f"{mink.impls()[-1]}; ratio = Python seconds / C seconds")
    print("dim,points,c_s,py_out_s,py_alloc_s,ratio_out,ratio_alloc")
    for dim in (2, 3):
        bench(lib, dim, a.n, a.rounds)


if __name__ == "__main__":
    main()
