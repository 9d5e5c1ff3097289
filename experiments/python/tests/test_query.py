"""mink.collide, mink.score, mink.area, mink.methods, mink.run against hand-worked cases."""

import subprocess

import numpy as np
import pytest

import mink
from conftest import mink_exe


def test_collide_spheres_hand_worked():
    b1 = mink.Body("sphere a=1")
    c = mink.collide(b1, mink.Body("sphere a=2 at=5,0,0"))
    assert c.status == "separated" and c.certified == 1
    assert c.distance == pytest.approx(2.0, abs=1e-12 * c.scale)
    assert np.allclose(c.normal, (1, 0, 0), atol=1e-9)
    assert np.allclose(c.p1, (1, 0, 0), atol=1e-9) and np.allclose(c.p2, (3, 0, 0), atol=1e-9)
    o = mink.collide(b1, mink.Body("sphere a=2 at=0,2,0"))
    assert o.status == "overlapping" and o.distance == pytest.approx(-1.0, abs=1e-9)
    r = mink.collide(b1, mink.Body("sphere a=2 at=0,0,5"), method="ray")
    assert r.status == "separated" and r.directional == pytest.approx(2.0, abs=1e-9) and np.isnan(r.distance)
    w = mink.collide(b1, mink.Body("sphere a=2 at=5,0,0"), start=(1, 0.2, 0))
    assert w.distance == pytest.approx(2.0, abs=1e-12 * w.scale)


def test_collide_ellipsoids_axis_aligned():
    # along the x axis the gap of two axis-aligned ellipsoids is the centre distance minus the semi-axes
    c = mink.collide(mink.Body("ellipsoid a=20 b=40 c=50"), mink.Body("sphere a=10 at=40,0,0"))
    assert c.status == "separated" and c.distance == pytest.approx(10.0, rel=1e-10)


def test_collide_errors():
    s = mink.Body("sphere a=1")
    with pytest.raises(ValueError, match="3D"):
        mink.collide(mink.Body("circle a=1"), mink.Body("circle a=1"))
    with pytest.raises(ValueError, match="method"):
        mink.collide(s, s, method="gjk")
    with pytest.raises(ValueError, match="start"):
        mink.collide(s, s, start=(0, 0, 0))
    with pytest.raises(ValueError, match="start"):
        mink.collide(s, s, start=(1, 0))
    assert mink.collide(s, mink.Body("sphere a=1 at=3,0,0"), start=np.array([1.0, 0, 0])).distance == pytest.approx(1)
    with pytest.raises(ValueError, match="start"):
        mink.collide(s, s, method="ray", start=(1, 0, 0))


def ngon(r, n):
    t = 2 * np.pi * np.arange(n) / n
    return np.array([r * np.cos(t), r * np.sin(t)])


@pytest.mark.parametrize("n", [3, 8, 100])
@pytest.mark.parametrize("set_", ["plus", "contact"])
def test_score_regular_ngon_in_a_circle(n, set_):
    # circles r = 1 and 2: both sets are the circle R = 3; the inscribed n-gon is R (1 - cos(pi/n)) from it;
    # the size S = |I|_F |(1, 1)| + |I|_F |(2, 2)| = 2 + 4
    b1, b2 = mink.Body("circle a=1"), mink.Body("circle a=2")
    R = 3.0
    d = mink.score(b1, b2, ngon(R, n), set=set_)
    assert d.points == n and d.vertices == n and d.size == pytest.approx(6.0, rel=1e-15)
    assert d.hausdorff_abs == pytest.approx(R * (1 - np.cos(np.pi / n)), rel=1e-6)
    assert d.hausdorff_rel == pytest.approx(d.hausdorff_abs / d.size)
    assert d.off_boundary_max < 1e-13
    assert abs(d.area_rel - (n / (2 * np.pi) * np.sin(2 * np.pi / n) - 1)) <= d.area_bound + 1e-15
    assert "hausdorff" in d.message.lower()


def test_score_octahedron_in_a_sphere():
    # spheres r = 1 and 2 (plus): the sphere R = 3; the octahedron of its axis points has faces at R / sqrt(3)
    pts = np.hstack([3 * np.eye(3), -3 * np.eye(3)])
    d = mink.score(mink.Body("sphere a=1"), mink.Body("sphere a=2"), pts, set="plus")
    assert d.gap_in == pytest.approx(3 - np.sqrt(3), rel=1e-6)
    assert d.off_boundary_max < 1e-12
    assert d.area_rel == pytest.approx(1 / np.pi - 1, rel=1e-6)  # volume 4/3 R^3 against 4/3 pi R^3


def test_score_of_closed_form_points():
    b1, b2 = mink.Body("superellipse a=3 b=2 eps=0.5 rot=0.3"), mink.Body("ellipse a=1 b=0.5")
    x = mink.sum(b1, b2, n=2000)
    area, bound = mink.area(b1, b2)
    d = mink.score(b1, b2, x, truth=area, truth_bound=bound)
    assert d.off_boundary_rel < 1e-14 and d.hausdorff_rel < 1e-3 and d.area_rel < 0
    assert d.area_k == area
    # a point moved off the boundary is seen, at its index
    y = x.copy()
    y[:, 17] *= 1.01
    e = mink.score(b1, b2, y, truth=area, truth_bound=bound)
    assert e.worst == 17 and e.gap_out > 0.01


def test_area_circles():
    v, bound = mink.area(mink.Body("circle a=1"), mink.Body("circle a=2"), set="plus")
    assert abs(v - 9 * np.pi) <= bound + 1e-12
    v3, _ = mink.area(mink.Body("sphere a=1"), mink.Body("sphere a=2"))
    assert v3 == pytest.approx(36 * np.pi, rel=1e-6)


def test_score_errors():
    b = mink.Body("circle a=1")
    with pytest.raises(ValueError, match="points.*shape"):
        mink.score(b, b, np.zeros((5, 2)))
    with pytest.raises(TypeError, match="points.*int64"):
        mink.score(b, b, np.zeros((2, 5), dtype=np.int64))
    with pytest.raises(ValueError, match="points.*no points"):
        mink.score(b, b, np.zeros((2, 0)))
    with pytest.raises(ValueError, match="set"):
        mink.score(b, b, ngon(2, 5), set="minus")
    with pytest.raises(ValueError, match="tol"):
        mink.score(b, b, ngon(2, 5), tol=-1)
    with pytest.raises(ValueError, match="same dimension"):
        mink.score(b, mink.Body("sphere a=1"), ngon(2, 5))


def test_methods_are_the_registry():
    ms = mink.methods()
    names = [m.name for m in ms]
    assert len(set(names)) == len(names)
    out = subprocess.run([mink_exe(), "methods", "--csv"], check=True, capture_output=True, text=True).stdout
    cli = [line.split(",")[0] for line in out.splitlines()[1:] if line]
    assert names == cli
    g = ms[names.index("closed-gradient")]
    assert g.exact and not g.sampled and g.dims == (2, 3) and g.tolerance == 0
    f = ms[names.index("closed-gradient-f32")]
    assert f.approx and f.tolerance == pytest.approx(1e-6)
    assert all(set(m.dims) <= {2, 3} and m.summary for m in ms)


def test_run_a_method():
    b1, b2 = mink.Body("superellipse a=3 b=2 eps=0.5"), mink.Body("ellipse a=1 b=0.5")
    h = mink.run("hull-qhull", b1, b2, 200, set="plus")
    assert h.shape[0] == 2 and 3 <= h.shape[1] <= 400
    a, bound = mink.area(b1, b2, set="plus")
    d = mink.score(b1, b2, h, set="plus", truth=a, truth_bound=bound)
    assert d.hausdorff_rel < 1e-2 and d.gap_out <= 1e-12 * d.size  # a sampled hull lies inside the sum
    c = mink.run("closed-normal", b1, b2, 100)
    assert c.shape == (2, 100) and mink.score(b1, b2, c).off_boundary_rel < 1e-14
    with pytest.raises(ValueError, match="unknown"):
        mink.run("nope", b1, b2, 10)
    with pytest.raises(ValueError, match="edge-sort"):
        mink.run("edge-sort", mink.Body("sphere a=1"), mink.Body("sphere a=1"), 10)
    with pytest.raises(ValueError, match="hull-qhull"):
        mink.run("hull-qhull", b1, b2, 1)
