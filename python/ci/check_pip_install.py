"""`pip install --no-build-isolation --no-index .` into a fresh `venv --system-site-packages`,
then `import raycast` from outside the source and build trees (docs/python.md "Installing").

Usage: check_pip_install.py SOURCE_DIR [CMAKE_BUILD_DIR]. With CMAKE_BUILD_DIR the install
builds the target raycast_python in that configured tree (what setup.py does after configuring
its own), so the check takes seconds; without it, setup.py configures and compiles from
scratch. Exits non-zero with pip's or Python's output on any failure."""
import os
import subprocess
import sys
import tempfile
import time


def run(args, **kwargs):
    result = subprocess.run(args, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        sys.exit(f"failed: {' '.join(args)}\n{result.stdout}\n{result.stderr}")
    return result.stdout


def main():
    source = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="raycast-pip-") as scratch:
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        env["RAYCAST_PIP_BUILD_DIR"] = os.path.join(scratch, "build")
        if len(sys.argv) > 2:
            env["RAYCAST_CMAKE_BUILD_DIR"] = os.path.abspath(sys.argv[2])
        venv = os.path.join(scratch, "venv")
        start = time.monotonic()
        # The system pip (python3-pip) serves the venv through its system site-packages.
        run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip", venv])
        python = os.path.join(venv, "bin", "python")
        run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index", "-q",
             source], env=env, cwd=scratch)
        elapsed = time.monotonic() - start
        check = ("import os, numpy as np, raycast, raycast.image, raycast.open3d_scene\n"
                 "assert raycast.__file__.startswith(os.environ['VENV']), raycast.__file__\n"
                 "d = os.path.dirname(raycast.__file__)\n"
                 "assert os.path.exists(os.path.join(d, '_raycast.pyi'))\n"
                 "s = raycast.RaycastingScene()\n"
                 "s.add_triangles(np.eye(3, dtype=np.float32), np.array([[0, 1, 2]]))\n"
                 "r = s.cast_rays(np.array([[0, 0, 0, 1, 1, 1]], np.float32))\n"
                 "assert abs(r['t_hit'][0] - 1 / 3) < 1e-6, r\n"
                 "print(raycast.__version__, raycast.__file__)\n")
        out = run([python, "-c", check], env=dict(env, VENV=venv), cwd=scratch)
        print(f"installed in {elapsed:.1f} s: {out.strip()}")


if __name__ == "__main__":
    main()
