"""mink.Body: from SPEC strings and from parameters, and its errors."""

import numpy as np
import pytest

import mink


def test_spec_2d_and_3d():
    b = mink.Body("superellipse a=3 b=2 eps=0.5 rot=0.3 at=1,2")
    assert b.dim == 2 and b.shape == (3.0, 2.0, 0.5) and b.at == (1.0, 2.0)
    c, s = np.cos(0.3), np.sin(0.3)
    assert np.allclose(b.M, [[c, -s], [s, c]], rtol=0, atol=1e-15)
    assert b.spec == "superellipse a=3 b=2 eps=0.5 rot=0.3 at=1,2"
    e = mink.Body("ellipsoid a=1 b=2 c=3")
    assert e.dim == 3 and e.shape == (1.0, 2.0, 3.0, 1.0, 1.0) and e.at == (0.0, 0.0, 0.0)
    assert np.array_equal(e.M, np.eye(3))
    assert "ellipsoid a=1 b=2 c=3" in repr(e)


def test_params_equal_spec():
    s = mink.Body("superellipse a=3 b=2 eps=0.5 M=1,0.5,-0.2,2 at=1,-1")
    p = mink.Body(shape=(3, 2, 0.5), M=[[1, 0.5], [-0.2, 2]], at=(1, -1))
    assert p.spec is None and p.shape == s.shape and p.at == s.at and np.array_equal(p.M, s.M)
    q = mink.Body("circle a=1")
    assert np.array_equal(mink.sum(s, q, n=64), mink.sum(p, q, n=64))
    assert "shape=(3.0, 2.0, 0.5)" in repr(p)


def test_measure_closed_forms():
    # pi a b for an ellipse, 4/3 pi a b c for an ellipsoid, 4 a b for eps -> 0 is not reachable; a circle scaled by M
    assert mink.Body("ellipse a=3 b=2").measure() == pytest.approx(6 * np.pi, rel=1e-14)
    assert mink.Body("ellipsoid a=1 b=2 c=3").measure() == pytest.approx(8 * np.pi, rel=1e-14)
    assert mink.Body(shape=(1, 1, 1), M=[2, 0, 0, 3]).measure() == pytest.approx(6 * np.pi, rel=1e-14)


@pytest.mark.parametrize("spec, words", [
    ("superellipse a=3 b=2", ["spec", "eps"]),
    ("superellipse a=3 b=2 eps=3", ["spec", "eps", "3"]),
    ("ellipse a=-1 b=1", ["spec", "a"]),
    ("blob a=1", ["spec", "unknown kind", "blob"]),
    ("ellipse a=1 b=1 colour=red", ["spec", "colour"]),
    ("ellipse a=1 b=1 M=1,2,2,4", ["spec", "M"]),
    ("", ["spec"]),
])
def test_bad_spec_names_the_field(spec, words):
    with pytest.raises(ValueError) as e:
        mink.Body(spec)
    for w in words:
        assert w in str(e.value)


@pytest.mark.parametrize("kw, exc, words", [
    (dict(shape=(1, 2)), ValueError, ["shape", "3", "5"]),
    (dict(shape=(1, 2, 3)), ValueError, ["eps"]),
    (dict(shape=(1, 2, 1), M=[1, 2, 3]), ValueError, ["M", "4"]),
    (dict(shape=(1, 2, 1), M=[[1, 2], [2, 4]]), ValueError, ["M"]),
    (dict(shape=(1, 2, 1), at=(0, 0, 0)), ValueError, ["at", "2"]),
    (dict(shape=(1, 2, 1), at=(0, np.inf)), ValueError, ["at"]),
    (dict(shape=(1, 2, np.nan)), ValueError, ["eps"]),
    (dict(shape="abc"), TypeError, ["shape"]),
    (dict(shape=(1, 2, 1), M="x"), TypeError, ["M"]),
    (dict(), TypeError, ["SPEC"]),
])
def test_bad_params_name_the_field(kw, exc, words):
    with pytest.raises(exc) as e:
        mink.Body(**kw)
    for w in words:
        assert w in str(e.value)


def test_spec_type_and_both_forms():
    with pytest.raises(TypeError, match="spec"):
        mink.Body(3)
    with pytest.raises(TypeError, match="not both"):
        mink.Body("circle a=1", shape=(1, 1, 1))
    b = mink.Body("circle a=1")
    with pytest.raises(TypeError, match="immutable"):
        b.__init__("circle a=2")
    with pytest.raises(AttributeError):
        b.dim = 3
