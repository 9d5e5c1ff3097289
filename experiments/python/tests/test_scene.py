"""mink.scene: certified C-obstacles, checked point by point with the independent error
measure (mink.score shares no code with libmink_cspace)."""

import gc

import numpy as np
import pytest

import mink

SCENE2 = """dim 2
robot ellipse a=1 b=0.5 rot=0.2
obstacle circle a=2 at=5,0
obstacle superellipse a=2 b=1 eps=0.4 rot=0.5 at=-4,1   # a boxy one
obstacle box size=2,1 at=0,6
headings 2
"""

SCENE3 = """dim 3
robot ellipsoid a=1 b=0.5 c=0.3
obstacle superquadric a=2 b=1 c=1.5 eps1=0.6 eps2=1.2 at=5,0,0
quaternions 1,0,0,0;0.9238795325112867,0,0.3826834323650898,0
"""


def robot_at(spec, dim, R):
    """The robot's body under rotation R: map R M (the scene's convention)."""
    b = mink.Body(spec)
    return mink.Body(shape=b.shape, M=R @ b.M, at=(0,) * dim)


def rot2(t):
    return np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]])


def test_scene2_inner_and_outer_certified():
    bs = mink.scene(SCENE2, tol=1e-3, outer=True)
    assert len(bs) == 2 * 3 * 2
    truth = {}
    obstacles = {0: "circle a=2 at=5,0", 1: "superellipse a=2 b=1 eps=0.4 rot=0.5 at=-4,1"}
    for b in bs:
        assert b.points.shape[0] == 2 and b.points.shape[1] >= 3 and b.faces is None
        assert b.within_tol and 0 < b.error <= 1e-3
        if b.obstacle not in obstacles:
            assert b.model_error > 0 and b.model.startswith("inner superellipse")
            continue
        robot = robot_at("ellipse a=1 b=0.5 rot=0.2", 2, rot2(2 * np.pi * b.orientation / 2))
        obstacle = mink.Body(obstacles[b.obstacle])
        key = (b.orientation, b.obstacle)
        if key not in truth:
            truth[key] = mink.area(obstacle, robot)  # once per pair: about a second each
        d = mink.score(obstacle, robot, np.ascontiguousarray(b.points), truth=truth[key][0], truth_bound=truth[key][1])
        assert d.hausdorff_abs <= b.error + 1e-12
        if b.bound == "inner":
            assert d.off_boundary_max < 1e-9 and d.gap_out < 1e-9
        else:
            assert d.gap_in < 1e-9  # the outer boundary encloses the C-obstacle


def test_scene3_faces_and_certificate():
    bs = mink.scene(SCENE3, tol=1e-2)
    assert len(bs) == 2
    for b in bs:
        n = b.points.shape[1]
        assert b.points.shape[0] == 3 and b.faces.shape[1] == 3 and b.faces.dtype == np.int32
        assert b.faces.min() >= 0 and b.faces.max() < n and b.within_tol
        q = [(1, 0, 0, 0), (0.9238795325112867, 0, 0.3826834323650898, 0)][b.orientation]
        w, x, y, z = q
        R = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                      [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                      [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
        robot = robot_at("ellipsoid a=1 b=0.5 c=0.3", 3, R)
        obstacle = mink.Body("superquadric a=2 b=1 c=1.5 eps1=0.6 eps2=1.2 at=5,0,0")
        d = mink.score(obstacle, robot, np.ascontiguousarray(b.points))
        assert d.off_boundary_max < 1e-9 and d.hausdorff_abs <= b.error + 1e-9


def test_arrays_outlive_the_list():
    pts = mink.scene(SCENE2, tol=1e-2)[0].points
    ref = pts.copy()
    gc.collect()
    assert np.array_equal(pts, ref) and not pts.flags.writeable


def test_uniform_mode_and_range():
    bs = mink.scene(SCENE2, mode="uniform", uniform=64, orientations=[1, 2])
    assert {b.orientation for b in bs} == {1} and all(b.points.shape[1] == 64 for b in bs)


@pytest.mark.parametrize("text, kw, words", [
    ("dim 2\nrobot ellipse a=1\n", {}, ["line 2", "b"]),
    ("dim 4\n", {}, ["line 1"]),
    (SCENE2, dict(tol=-1), ["tol"]),
    (SCENE2, dict(mode="paper"), ["mode"]),
    (SCENE2, dict(threads=0), ["threads"]),
    (SCENE2, dict(orientations=(0, 9)), ["orientations"]),
    (SCENE2, dict(orientations=(0.5, 1)), ["orientations", "integers"]),
    (SCENE2, dict(orientations=[0]), ["orientations", "2"]),
    ("dim 3\nrobot sphere a=1\nobstacle sphere a=1 at=3,0,0\nrotations r.txt\n", {}, ["rotations", "r.txt"]),
])
def test_scene_errors(text, kw, words):
    with pytest.raises(ValueError) as e:
        mink.scene(text, **kw)
    for w in words:
        assert w in str(e.value)


def test_scene_file_reads_rotations(tmp_path):
    (tmp_path / "rot.txt").write_text("w,x,y,z\n1,0,0,0\n0,1,0,0\n")
    f = tmp_path / "s.txt"
    f.write_text("dim 3\nrobot sphere a=1\nobstacle sphere a=1 at=3,0,0\nrotations rot.txt\n")
    bs = mink.scene_file(str(f), tol=1e-2)
    assert [b.orientation for b in bs] == [0, 1]
    (tmp_path / "bad.txt").write_text("1,0,0\n")
    f.write_text("dim 3\nrobot sphere a=1\nobstacle sphere a=1 at=3,0,0\nrotations bad.txt\n")
    with pytest.raises(ValueError, match="rotations"):
        mink.scene_file(str(f))
