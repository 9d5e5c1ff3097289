#!/usr/bin/env python3
"""support.py - an external method (mink/external.h, docs/compare.md) that is
exact: the support points of the sum at n unit normals (2D: n angles evenly
spaced; 3D: n*n directions of a Fibonacci sphere), each the sum of both
bodies' support points from the dual-norm formula of a superellipse /
superquadric. Reads jobs on stdin, answers on stdout, until stdin closes."""
import math
import sys
import time


def dual(v, q):
    """||v||_q and its gradient, for the support point (v nonzero)."""
    big = max(abs(x) for x in v)
    if big == 0:
        return 0.0, [0.0] * len(v)
    w = [abs(x) / big for x in v]
    norm = big * sum(x ** q for x in w) ** (1.0 / q)
    g = [math.copysign((abs(x) / norm) ** (q - 1.0), x) if x else 0.0 for x in v]
    return norm, g


def support2(p, n):
    a, b, eps = p[0:3]
    M = [[p[3], p[4]], [p[5], p[6]]]
    m = [M[0][0] * n[0] + M[1][0] * n[1], M[0][1] * n[0] + M[1][1] * n[1]]  # M^T n
    _, g = dual([a * m[0], b * m[1]], 2.0 / (2.0 - eps))
    x = [a * g[0], b * g[1]]
    return [M[0][0] * x[0] + M[0][1] * x[1], M[1][0] * x[0] + M[1][1] * x[1]]


def support3(p, n):
    a, b, c, e1, e2 = p[0:5]
    M = [p[5:8], p[8:11], p[11:14]]
    m = [sum(M[r][k] * n[r] for r in range(3)) for k in range(3)]  # M^T n
    v = [a * m[0], b * m[1], c * m[2]]
    q2, q1 = 2.0 / (2.0 - e2), 2.0 / (2.0 - e1)
    inner, gi = dual(v[0:2], q2)
    _, go = dual([inner, v[2]], q1)
    x = [a * go[0] * gi[0], b * go[0] * gi[1], c * go[1]]
    return [sum(M[r][k] * x[k] for k in range(3)) for r in range(3)]


def directions(dim, n):
    if dim == 2:
        return [[math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)] for k in range(n)]
    count, golden = n * n, math.pi * (3.0 - math.sqrt(5.0))
    out = []
    for k in range(count):
        z = 1.0 - 2.0 * (k + 0.5) / count
        r = math.sqrt(max(0.0, 1.0 - z * z))
        out.append([r * math.cos(golden * k), r * math.sin(golden * k), z])
    return out


def solve(job):
    dim, n, plus = int(job["dim"]), int(job["n"]), job["set"] == "plus"
    p1 = [float(x) for x in job["params1"].split()]
    p2 = [float(x) for x in job["params2"].split()]
    t1, t2 = p1[-dim:], p2[-dim:]
    support = support2 if dim == 2 else support3
    pts = []
    for d in directions(dim, n):
        s1, s2 = support(p1, d), support(p2, d)  # about the centres
        pts.append([t1[i] + s1[i] + s2[i] + (t2[i] if plus else 0.0) for i in range(dim)])
    return pts


def main():
    job = {}
    for line in sys.stdin:
        line = line.rstrip("\n")
        if line == "end":
            start = time.perf_counter()
            pts = solve(job)
            seconds = time.perf_counter() - start
            out = ["points %d" % len(pts)] + [" ".join(repr(x) for x in p) for p in pts]
            out.append("seconds %.9g" % seconds)
            sys.stdout.write("\n".join(out) + "\n")
            sys.stdout.flush()
            job = {}
        elif line:
            key, _, value = line.partition(" ")
            job[key] = value


if __name__ == "__main__":
    main()
