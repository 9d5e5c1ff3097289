"""mink.collide_batch against the one-pair mink.collide and against spheres worked by hand."""

import numpy as np
import pytest

import mink

MODES = ["status", "clearance", "distance", "full"]
STATUS = {"separated": 0, "touching": 1, "overlapping": 2}


def random_pairs(count, seed):
    """Superquadrics, ellipsoids and spheres at random poses and exponents (box-like ones included),
    some far apart, some near, some overlapping."""
    rng = np.random.default_rng(seed)
    bodies1, bodies2 = [], []
    for k in range(count):
        pair = []
        for side in range(2):
            a, b, c = rng.uniform(0.5, 3.0, 3)
            kind = k % 3
            rot = ",".join(f"{v:.6f}" for v in rng.normal(size=4))
            at = ",".join(f"{v:.6f}" for v in (rng.uniform(-4, 4, 3) if side else (0, 0, 0)))
            if kind == 0:
                e1, e2 = rng.uniform(0.1, 1.6, 2)
                spec = f"superquadric a={a:.6f} b={b:.6f} c={c:.6f} eps1={e1:.6f} eps2={e2:.6f} quat={rot} at={at}"
            elif kind == 1:
                spec = f"ellipsoid a={a:.6f} b={b:.6f} c={c:.6f} quat={rot} at={at}"
            else:
                spec = f"sphere a={a:.6f} at={at}"
            pair.append(mink.Body(spec))
        bodies1.append(pair[0])
        bodies2.append(pair[1])
    return bodies1, bodies2


@pytest.fixture(scope="module")
def pairs():
    b1, b2 = random_pairs(300, 2028)
    one = [mink.collide(x, y) for x, y in zip(b1, b2)]
    return b1, b2, one


@pytest.mark.parametrize("mode", MODES)
def test_batch_agrees_with_one_pair_query(pairs, mode):
    b1, b2, one = pairs
    delta = 0.5
    r = mink.collide_batch(b1, b2, mode, delta=delta)
    n = len(b1)
    assert r.status.shape == (n,) and r.normal.shape == (3, n) and r.p1.shape == (3, n) and r.path.shape == (n,)
    assert r.lanes in ("avx512", "avx2", "scalar")
    kinds = set()
    for k, c in enumerate(one):
        assert r.status[k] == STATUS[c.status], (k, c.status, r.status[k])
        assert r.scale[k] == pytest.approx(c.scale, rel=1e-14)
        assert r.lower[k] <= c.distance + 1e-12 * c.scale and c.distance <= r.upper[k] + 1e-12 * c.scale, k
        kinds.add(int(r.path[k]))
        if mode == "full" or (mode == "distance" and c.status != "overlapping"):
            assert abs(r.distance[k] - c.distance) <= 1e-12 * c.scale, (k, r.distance[k], c.distance)
        if mode == "clearance" and abs(c.distance - delta) > 1e-11 * c.scale:
            assert bool(r.clear[k]) == (c.distance >= delta), (k, c.distance)
        if r.path[k] == 0:  # a separating direction n: f(n) > 0, and the witnesses are support points
            nrm = r.normal[:, k]
            assert abs(np.linalg.norm(nrm) - 1) < 1e-12
        if r.path[k] == 1:  # an overlap point: one point of both bodies
            assert np.array_equal(r.p1[:, k], r.p2[:, k])
    assert 3 not in kinds
    if mode == "status":  # the batch's own certificates answered some pairs, not only the one-pair query
        assert {0, 1} <= kinds, kinds
    if mode != "clearance":
        assert r.clear is None
    counts = {s: int(np.sum(r.status == v)) for s, v in STATUS.items()}
    assert counts["separated"] > 50 and counts["overlapping"] > 50, counts


def test_batch_spheres_hand_worked():
    # unit sphere at the origin against spheres of radius 2: centre distance 5 (sd = 2), 4 (sd = 1) on
    # the x, y, z axes and 2 (sd = -1, depth 1); the separated pairs' witnesses are on the centre line
    s = mink.Body("sphere a=1")
    others = [mink.Body("sphere a=2 at=5,0,0"), mink.Body("sphere a=2 at=0,4,0"), mink.Body("sphere a=2 at=0,0,2")]
    sd = np.array([2.0, 1.0, -1.0])
    full = mink.collide_batch(s, others, "full")
    assert list(full.status) == [0, 0, 2]
    assert np.allclose(full.distance, sd, atol=1e-12 * full.scale)
    assert np.allclose(full.normal[:, 0], (1, 0, 0), atol=1e-9) and np.allclose(full.normal[:, 1], (0, 1, 0), atol=1e-9)
    assert np.allclose(full.p1[:, 0], (1, 0, 0), atol=1e-9) and np.allclose(full.p2[:, 0], (3, 0, 0), atol=1e-9)
    dist = mink.collide_batch(s, others, "distance")
    assert np.allclose(dist.distance[:2], sd[:2], atol=1e-12 * dist.scale[:2]) and np.isnan(dist.distance[2])
    st = mink.collide_batch(s, others)  # mode status by default
    assert list(st.status) == [0, 0, 2] and np.all(st.lower[:2] > 0) and st.upper[2] < 0
    assert np.all(st.lower <= sd + 1e-12) and np.all(sd <= st.upper + 1e-12)
    cl = mink.collide_batch(s, others, "clearance", delta=1.5)
    assert list(cl.clear) == [True, False, False]
    # the scale is |d| + |M1|_F + |M2|_F, |r I|_F = sqrt(3) r
    assert np.allclose(full.scale, np.array([5.0, 4.0, 2.0]) + np.sqrt(3) * 3)


def test_batch_indices_and_broadcast():
    obstacles = [mink.Body("sphere a=1 at=4,0,0"), mink.Body("sphere a=1 at=0,1.5,0"), mink.Body("sphere a=2 at=0,0,-9")]
    robot = [mink.Body("sphere a=1"), mink.Body("sphere a=0.5 at=0,0,-6")]
    i1 = np.array([0, 0, 0, 1, 1, 1])
    i2 = [0, 1, 2, 0, 1, 2]
    r = mink.collide_batch(robot, obstacles, "full", index1=i1, index2=i2)
    for k in range(6):
        c = mink.collide(robot[i1[k]], obstacles[i2[k]])
        assert r.status[k] == STATUS[c.status] and abs(r.distance[k] - c.distance) <= 1e-12 * c.scale
    # one Body for every pair: index left out on its side
    b = mink.collide_batch(robot[0], obstacles, "full")
    assert np.array_equal(b.distance, r.distance[:3])
    assert mink.collide_batch([], [], "full").status.shape == (0,)


def test_batch_bad_input_names_the_field():
    s = mink.Body("sphere a=1")
    with pytest.raises(ValueError, match="mode"):
        mink.collide_batch(s, s, "gjk")
    with pytest.raises(ValueError, match="delta"):
        mink.collide_batch(s, s, "clearance", delta=-1)
    with pytest.raises(ValueError, match="delta"):
        mink.collide_batch(s, s, "clearance", delta=float("nan"))
    with pytest.raises(TypeError, match="bodies1"):
        mink.collide_batch(3, s)
    with pytest.raises(TypeError, match="bodies2: item 1"):
        mink.collide_batch([s, s], [s, "sphere a=1"])
    with pytest.raises(ValueError, match="bodies1: item 0: a 2D body"):
        mink.collide_batch([mink.Body("circle a=1")], [s])
    with pytest.raises(ValueError, match="bodies2: 3 bodies for 2 pairs"):
        mink.collide_batch([s, s], [s, s, s])
    with pytest.raises(ValueError, match="index2: 5 at position 1 is out of range"):
        mink.collide_batch([s], [s, s], index1=[0, 0], index2=[1, 5])
    with pytest.raises(ValueError, match="index1: -1"):
        mink.collide_batch([s], [s], index1=[-1])
    with pytest.raises(TypeError, match="index1"):
        mink.collide_batch([s], [s], index1=[0.5])
    with pytest.raises(ValueError, match="index2: 1 indices for 2 pairs"):
        mink.collide_batch([s], [s], index1=[0, 0], index2=[0])
