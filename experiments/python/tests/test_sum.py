"""mink.sum: the same bits as the C batch (through the `mink sum` command's CSV, whose
%.17g round-trips every double), in place on numpy arrays, and its errors."""

import threading

import numpy as np
import pytest

import mink
from conftest import bits, cli_points

PAIRS2 = [("superellipse a=3 b=2 eps=0.5 rot=0.3 shear=1", "ellipse a=1 b=0.5 rot=-1"),
          ("superellipse a=1e-3 b=2 eps=1.9 at=5,1", "superellipse a=4 b=1 eps=0.05 M=1,2,0.5,3 at=-1,1")]
PAIRS3 = [("superquadric a=3 b=2 c=1.5 eps1=0.5 eps2=1.5 quat=0.9,0.1,0.3,0.2", "ellipsoid a=1 b=0.5 c=0.8"),
          ("sphere a=2 at=1,2,3", "superquadric a=1 b=0.5 c=0.8 eps1=1.2 eps2=0.3 M=1,0.2,0,0,1,0.3,0.1,0,2")]
OPTIONS = [dict(), dict(set="plus"), dict(form="normal"), dict(form="normal", param="normal"),
           dict(impl="scalar"), dict(form="paper", impl="scalar")]


def cli_args(opts):
    args = []
    for k in ("set", "form", "param", "impl"):
        if k in opts:
            args += ["--" + k, opts[k]]
    return args


@pytest.mark.parametrize("spec1, spec2", PAIRS2 + PAIRS3)
@pytest.mark.parametrize("opts", OPTIONS)
def test_same_bits_as_the_c_batch(spec1, spec2, opts):
    b1, b2 = mink.Body(spec1), mink.Body(spec2)
    dim = b1.dim
    n = 301 if dim == 2 else 23
    header, ref = cli_points("--dim", str(dim), "--body1", spec1, "--body2", spec2, "--n", str(n), "--contact",
                             *cli_args(opts))
    assert header == ["x", "y", "kx", "ky"] if dim == 2 else ["x", "y", "z", "kx", "ky", "kz"]
    x, k = mink.sum(b1, b2, n=n, kiss=True, **opts)
    assert x.shape == (dim, n if dim == 2 else n * n) and x.dtype == np.float64
    assert np.array_equal(bits(x), bits(ref[:dim])) and np.array_equal(bits(k), bits(ref[dim:]))
    # the same through explicit parameter vectors and a caller's output array
    u = mink.sample(dim, n)
    out = np.full_like(u, np.nan)
    assert mink.sum(b1, b2, u, out=out, **opts) is out
    assert np.array_equal(bits(out), bits(ref[:dim]))


def test_sample_matches_the_cli_grid():
    # B1 a unit circle at the origin, B2 a point-like tiny circle: x = f1(u) + tiny, so x ~ u
    u = mink.sample(2, 8)
    assert np.allclose(u, [np.cos(-np.pi + 2 * np.pi * np.arange(8) / 8), np.sin(-np.pi + 2 * np.pi * np.arange(8) / 8)],
                       rtol=0, atol=1e-15)
    assert u[1, 0] == 0.0 and u[0, 2] == 0.0  # multiples of pi/2 are exact
    g = mink.sample(3, 5)
    assert g.shape == (3, 25) and np.allclose(np.sum(g * g, axis=0), 1)
    assert np.array_equal(g[:, 0], [0, 0, -1]) and np.array_equal(g[:, 24], [0, 0, 1])
    s = mink.sample(2, 16, eps=0.3)
    assert s.shape == (2, 16) and not np.allclose(s, mink.sample(2, 16))
    with pytest.raises(ValueError, match="n"):
        mink.sample(3, 1)
    with pytest.raises(ValueError, match="dim"):
        mink.sample(4, 10)
    with pytest.raises(ValueError, match="eps"):
        mink.sample(2, 10, eps=5)


def test_circles_hand_worked():
    # the contact space of circles r1, r2 is the circle r1 + r2 about c1
    b1, b2 = mink.Body("circle a=1 at=2,3"), mink.Body("circle a=0.5 at=-7,7")
    x = mink.sum(b1, b2, n=1000)
    assert np.allclose(np.hypot(x[0] - 2, x[1] - 3), 1.5, rtol=0, atol=1e-14)
    p = mink.sum(b1, b2, n=1000, set="plus")
    assert np.allclose(np.hypot(p[0] + 5, p[1] - 10), 1.5, rtol=0, atol=1e-13)


def test_inputs_in_place_and_converted():
    b1, b2 = mink.Body(PAIRS2[0][0]), mink.Body(PAIRS2[0][1])
    u = mink.sample(2, 200)
    ref = mink.sum(b1, b2, u)
    # a strided view and a list are converted, with the same points
    wide = np.zeros((2, 400))
    wide[:, ::2] = u
    assert np.array_equal(mink.sum(b1, b2, wide[:, ::2]), ref)
    assert np.array_equal(mink.sum(b1, b2, u.tolist()), ref)
    # rows of a larger C-contiguous array are read in place
    big = np.vstack([u, u])
    assert np.array_equal(mink.sum(b1, b2, big[:2]), ref)
    # empty input
    assert mink.sum(b1, b2, np.zeros((2, 0))).shape == (2, 0)


def test_float32_runs_the_float_kernels():
    b1, b2 = mink.Body(PAIRS2[0][0]), mink.Body(PAIRS2[0][1])
    u32 = mink.sample(2, 500).astype(np.float32)
    x32 = mink.sum(b1, b2, u32)
    assert x32.dtype == np.float32
    # precision double on float arrays: the double call's points on the same directions, rounded
    assert np.array_equal(x32, mink.sum(b1, b2, u32.astype(np.float64)).astype(np.float32))
    f = mink.sum(b1, b2, u32, precision="f32")
    assert f.dtype == np.float32
    size = 20.0
    assert np.max(np.abs(f.astype(np.float64) - x32.astype(np.float64))) < 2e-6 * size
    with pytest.raises(TypeError, match="out"):
        mink.sum(b1, b2, u32, out=np.empty((2, 500)))


@pytest.mark.parametrize("kw, exc, words", [
    (dict(u=np.zeros((200, 2))), ValueError, ["u", "(200, 2)", "(2, N)"]),
    (dict(u=np.zeros((3, 10))), ValueError, ["u", "(2, N)"]),
    (dict(u=np.zeros(10)), ValueError, ["u", "shape"]),
    (dict(u=np.zeros((2, 10), dtype=np.int64)), TypeError, ["u", "int64", "float64"]),
    (dict(u=np.zeros((2, 10), dtype=np.float16)), TypeError, ["u", "float16"]),
    (dict(u=np.zeros((2, 10), dtype=complex)), TypeError, ["u", "complex"]),
    (dict(u="abc"), TypeError, ["u"]),
    (dict(u=np.zeros((2, 4)), n=4), TypeError, ["exactly one"]),
    (dict(), TypeError, ["exactly one"]),
    (dict(n=0), ValueError, ["n", "range"]),
    (dict(n="7"), TypeError, ["n"]),
    (dict(n=10, set="minus"), ValueError, ["set", "minus", "contact, plus"]),
    (dict(n=10, form=3), TypeError, ["form"]),
    (dict(n=10, impl="neon"), ValueError, ["impl", "neon"]),
    (dict(n=10, precision="half"), ValueError, ["precision"]),
    (dict(n=10, form="paper"), ValueError, ["form", "paper", "scalar"]),
    (dict(n=10, out=np.zeros((2, 11))), ValueError, ["out", "(2, 10)"]),
    (dict(n=10, out=np.zeros((2, 10), dtype=np.float32)), TypeError, ["out", "float64"]),
    (dict(n=10, out=np.zeros((10, 2)).T), ValueError, ["out", "contiguous"]),
    (dict(n=10, out=[[0.0] * 10] * 2), TypeError, ["out", "numpy"]),
    (dict(n=10, kiss=np.zeros((3, 10))), ValueError, ["kiss"]),
])
def test_bad_input_names_the_field(kw, exc, words):
    b1, b2 = mink.Body("ellipse a=2 b=1"), mink.Body("circle a=1")
    with pytest.raises(exc) as e:
        mink.sum(b1, b2, **kw)
    for w in words:
        assert w in str(e.value)


def test_bad_bodies_and_aliasing():
    b2d, b3d = mink.Body("circle a=1"), mink.Body("sphere a=1")
    with pytest.raises(ValueError, match="body2.*same dimension"):
        mink.sum(b2d, b3d, n=10)
    with pytest.raises(TypeError, match="body1.*mink.Body"):
        mink.sum("circle a=1", b2d, n=10)
    u = mink.sample(2, 10)
    with pytest.raises(ValueError, match="share memory"):
        mink.sum(b2d, b2d, u, out=u)
    out = np.empty((2, 10))
    with pytest.raises(ValueError, match="share memory"):
        mink.sum(b2d, b2d, u, out=out, kiss=out)
    ro = np.empty((2, 10))
    ro.setflags(write=False)
    with pytest.raises(ValueError, match="writeable"):
        mink.sum(b2d, b2d, u, out=ro)


def test_threads_get_their_own_answers():
    # the GIL is released around the kernels: concurrent calls give the serial answers
    pairs = [(mink.Body(a), mink.Body(b)) for a, b in PAIRS2 + PAIRS3]
    serial = [mink.sum(b1, b2, n=100000 if b1.dim == 2 else 300) for b1, b2 in pairs]
    got = [None] * len(pairs)

    def work(i):
        got[i] = mink.sum(*pairs[i], n=100000 if pairs[i][0].dim == 2 else 300)

    ts = [threading.Thread(target=work, args=(i,)) for i in range(len(pairs))]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    for a, b in zip(serial, got):
        assert np.array_equal(a, b)
