"""ctest entry for the Python module's tests: pytest on this folder. Exits 77
(skipped) when pytest or NumPy is missing, except in CI (CI=true)."""
import os
import sys


def main():
    try:
        import numpy  # noqa: F401
        import pytest
    except ImportError as e:
        print(f"python tests skipped: {e} "
              "(scripts/setup.sh installs python3-pytest, python3-numpy)")
        return 1 if os.environ.get("CI") == "true" else 77
    return pytest.main(["-q", "-p", "no:cacheprovider", sys.argv[1]])


# Dask's worker processes start by importing this module again: only the
# first process runs the tests.
if __name__ == "__main__":
    sys.exit(main())
