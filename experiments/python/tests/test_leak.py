"""Reference counts and memory stay flat over 10^5 calls, errors included."""

import sys

import numpy as np
import pytest

import mink


def rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


B1 = mink.Body("superellipse a=3 b=2 eps=0.5 rot=0.3")
B2 = mink.Body("ellipse a=1 b=0.5")
S1, S2 = mink.Body("superquadric a=2 b=1 c=1.5 eps1=0.6 eps2=1.2"), mink.Body("sphere a=1 at=5,0,0")
U = mink.sample(2, 16)
OUT = np.empty((2, 16))
PTS = mink.sum(B1, B2, n=16)
AREA = mink.area(B1, B2)


def call_sum():
    mink.sum(B1, B2, U)


def call_sum_out_kiss():
    mink.sum(B1, B2, U, out=OUT, kiss=True)


def call_sum_n():
    mink.sum(B1, B2, n=16, set="plus")


def call_body():
    mink.Body("superellipse a=3 b=2 eps=0.5 rot=0.3").M


def call_body_params():
    mink.Body(shape=(1, 2, 0.5), M=[[1, 0], [0, 1]], at=(1, 1))


def call_bad_spec():
    with pytest.raises(ValueError):
        mink.Body("superellipse a=3 b=2 eps=7")


def call_bad_dtype():
    with pytest.raises(TypeError):
        mink.sum(B1, B2, U.astype(np.int32))


def call_bad_shape():
    with pytest.raises(ValueError):
        mink.sum(B1, B2, U.T)


def call_collide():
    mink.collide(S1, S2)


def call_collide_batch():
    mink.collide_batch([S1, S2], [S2, S1, S2], "clearance", index1=[0, 1, 1], index2=[2, 0, 1], delta=0.5)


def call_collide_batch_bad_index():
    with pytest.raises(ValueError):
        mink.collide_batch([S1], [S2], index1=[0, 3])


def call_score():
    mink.score(B1, B2, PTS, truth=AREA[0], truth_bound=AREA[1])


def call_methods():
    mink.methods()


@pytest.mark.parametrize("fn, calls", [
    (call_sum, 100000), (call_sum_out_kiss, 100000), (call_sum_n, 100000), (call_body, 100000),
    (call_body_params, 100000), (call_bad_spec, 100000), (call_bad_dtype, 100000), (call_bad_shape, 100000),
    (call_collide, 100000), (call_score, 5000), (call_methods, 100000),
    (call_collide_batch, 50000), (call_collide_batch_bad_index, 100000)])
def test_memory_flat(fn, calls):
    refs = [sys.getrefcount(o) for o in (B1, B2, U, OUT, PTS)]
    for _ in range(2000):
        fn()
    before = rss_bytes()
    for _ in range(calls):
        fn()
    grown = rss_bytes() - before
    assert grown < 1 << 20, f"{fn.__name__}: memory grew {grown} bytes over {calls} calls"
    assert [sys.getrefcount(o) for o in (B1, B2, U, OUT, PTS)] == refs


def test_scene_memory_flat():
    text = "dim 2\nrobot ellipse a=1 b=0.5\nobstacle circle a=2 at=5,0\nheadings 2\n"
    for _ in range(200):
        mink.scene(text, tol=1e-2)
    before = rss_bytes()
    for _ in range(5000):
        bs = mink.scene(text, tol=1e-2)
    del bs
    assert rss_bytes() - before < 2 << 20
