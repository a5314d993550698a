"""ctest python_pip_install: `pip install .` as a user does it, offline, in a
new virtual environment that sees the system's packages (Debian's NumPy,
setuptools):

    python3 -m venv --system-site-packages VENV
    VENV/bin/python -m pip install --no-build-isolation --no-index REPO
    VENV/bin/python -c "import skipnc; print(skipnc.__version__)"

Usage: pip_install.py REPO VERSION [BUILD_TREE]. With BUILD_TREE (a
configured CMake tree) the install builds only _skipnc there and reuses its
libraries (SKIPNC_CMAKE_BUILD_DIR, setup.py); without it, setup.py builds
everything in Release. Exits 77 (skipped) where venv or pip is missing,
except in CI (CI=true)."""
import os
import subprocess
import sys
import tempfile
import time


def missing(what):
    print(f"pip install test skipped: {what} (Debian: python3-venv, python3-pip)")
    return 1 if os.environ.get("CI") == "true" else 77


def main():
    repo, version = sys.argv[1], sys.argv[2]
    env = dict(os.environ)
    env.pop("PYTHONPATH", None)  # the installed package, not a build tree's
    if len(sys.argv) > 3:
        env["SKIPNC_CMAKE_BUILD_DIR"] = sys.argv[3]
    with tempfile.TemporaryDirectory(prefix="skipnc-venv-") as tmp:
        venv = os.path.join(tmp, "venv")
        if subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", venv]).returncode:
            return missing("python3 -m venv failed")
        python = os.path.join(venv, "bin", "python")
        if subprocess.run([python, "-m", "pip", "--version"], capture_output=True).returncode:
            return missing("no pip in the virtual environment")
        start = time.monotonic()
        p = subprocess.run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index",
                            "--quiet", repo], env=env, cwd=tmp)
        print(f"pip install: {time.monotonic() - start:.1f} s")
        if p.returncode:
            return 1
        p = subprocess.run([python, "-c", "import skipnc; print(skipnc.__version__)"],
                           env=env, cwd=tmp, capture_output=True, text=True)
        print(p.stdout + p.stderr, end="")
        if p.returncode or p.stdout.strip() != version:
            print(f"expected version {version}")
            return 1
        p = subprocess.run([python, "-m", "pip", "show", "skipnc"], env=env, cwd=tmp,
                           capture_output=True, text=True)
        if "License: MIT" not in p.stdout:
            print(f"no MIT licence in the metadata:\n{p.stdout}")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
