"""`cmake --install` puts a package that imports and works outside the build tree."""

import os
import subprocess
import sys

import numpy as np


def test_install_into_a_temporary_prefix(tmp_path):
    prefix = tmp_path / "prefix"
    subprocess.run([os.environ["MINK_CMAKE"], "--install", os.environ["MINK_BUILD_DIR"], "--prefix", str(prefix),
                    "--component", "python"], check=True, capture_output=True)
    site = prefix / os.environ["MINK_PY_INSTALL_DIR"]
    assert (site / "mink" / "__init__.py").exists()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    code = ("import mink, numpy; b = mink.Body('ellipse a=2 b=1'); x = mink.sum(b, b, n=8, set='plus'); "
            "print(mink.__file__); print(repr(x.tolist()))")
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True, env=env,
                         cwd=str(tmp_path)).stdout.splitlines()
    assert out[0].startswith(str(site))
    # the installed module computes what the build tree's does
    import mink
    b = mink.Body("ellipse a=2 b=1")
    assert np.array_equal(np.array(eval(out[1])), mink.sum(b, b, n=8, set="plus"))
