"""mink: exact, closed-form Minkowski sums of smooth convex bodies, from Python.

The C library (libmink, libmink_cspace and the baselines' registry and error
measure) behind numpy arrays; docs/python.md documents every function.

    import mink
    b1 = mink.Body("superellipse a=3 b=2 eps=0.5 rot=0.3")
    b2 = mink.Body("ellipse a=1 b=0.5")
    x = mink.sum(b1, b2, n=200)              # (2, 200): the contact space's boundary
    d = mink.score(b1, b2, x)                # its independent error measure
    print(d.hausdorff_rel)

Point arrays have shape (dim, N), one row per coordinate (the C library's
structure of arrays), so that C-contiguous float64 arrays are read and written
in place. Bad input raises ValueError or TypeError naming the argument; other
failures of the C library raise mink.Error.
"""

import os as _os
import re as _re

from ._mink import (Body, Boundary, Collision, Deviation, Error, Method, area, collide, impls, methods, run,
                    sample, scene, score, sum, version)
from ._mink import Batch, collide_batch

__all__ = ["Body", "Boundary", "Collision", "Deviation", "Error", "Method", "area", "collide", "impls",
           "methods", "run", "sample", "scene", "scene_file", "score", "sum", "version"]
__all__ += ["Batch", "collide_batch"]
__version__ = version()


def scene_file(path, **options):
    """scene_file(path, **options) -> list of Boundary

    mink.scene on a scene file: reads the file and, for a 3D scene that names
    `rotations FILE`, that file too (relative to the scene file's folder, as
    `mink scene` does). Options as for mink.scene.
    """
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if "rotations" not in options:
        for line in text.splitlines():
            m = _re.match(r"\s*rotations\s+(\S+)", line.split("#", 1)[0])
            if m:
                rpath = m.group(1)
                if not _os.path.isabs(rpath):
                    rpath = _os.path.join(_os.path.dirname(path), rpath)
                with open(rpath, encoding="utf-8") as f:
                    options["rotations"] = f.read()
                break
    return scene(text, **options)
