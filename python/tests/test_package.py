"""The package as Python users expect it: its version is the CMake project's,
every public function and class has a docstring, help() reads well."""
import inspect
import os
import pydoc
import re

import skipnc
import skipnc.dask_sweep

SRC = os.environ["SKIPNC_SOURCE_DIR"]


def test_version_is_the_cmake_project_version():
    with open(os.path.join(SRC, "CMakeLists.txt"), encoding="utf-8") as f:
        version = re.search(r"project\(skipnc VERSION ([0-9.]+)", f.read()).group(1)
    assert skipnc.__version__ == version


def _public(obj):
    for name in getattr(obj, "__all__", None) or dir(obj):
        if not name.startswith("_"):
            yield name, getattr(obj, name)


def test_every_public_function_and_class_has_a_docstring():
    missing = []
    for mod in (skipnc, skipnc.dask_sweep):
        for name, value in _public(mod):
            if not (inspect.isclass(value) or callable(value)):
                continue
            if len((value.__doc__ or "").strip()) < 20:
                missing.append(f"{mod.__name__}.{name}")
            if inspect.isclass(value):
                for member, attr in vars(value).items():
                    if member.startswith("_") or not (callable(attr) or isinstance(attr, property)):
                        continue
                    if len((attr.__doc__ or "").strip()) < 10:
                        missing.append(f"{mod.__name__}.{name}.{member}")
    assert missing == []


def test_help_reads_well():
    text = pydoc.render_doc(skipnc, renderer=pydoc.plaintext)
    assert "run(program=None, *, program_text=None" in text
    assert "strict" in text and "expect" in text and "repeat" in text and "plot" in text
    sweep = pydoc.render_doc(skipnc.Sweep, renderer=pydoc.plaintext)
    assert "run(begin, end, workers=1)" in sweep
    assert "csv(table)" in sweep


def test_the_dask_module_says_the_main_guard_first():
    first = skipnc.dask_sweep.__doc__.split("\n\n")[:2]
    assert 'if __name__ == "__main__":' in "\n\n".join(first)
