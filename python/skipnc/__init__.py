"""skipnc from Python: run a part program on the simulated machine and get the
report as a dict and the trace as NumPy arrays; run sweeps by scenario range
(locally on threads, or on a Dask cluster: skipnc.dask_sweep).

    import skipnc
    r = skipnc.run("probe.nc", scene="part.toml", vars=["5063"],
                   params={"6200#7": 1}, variables={101: 200.0})
    r.report["variables"]["5063"], r.trace["Z_act"]
"""
import json
import os
import re
import tempfile
from typing import NamedTuple

from ._skipnc import StartError, Sweep  # noqa: F401
from . import _skipnc

__all__ = ["run", "Run", "Sweep", "StartError", "sweep", "to_toml"]


class Run(NamedTuple):
    report: dict  # the JSON report of `skipnc run --report` (docs/cli.md)
    trace: dict   # column name (as the CSV trace's header) -> numpy array; None with trace=False
    exit_code: int  # as `skipnc run`: 0 completed, 1 alarm


def _toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)  # a TOML basic string has JSON's escapes
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise TypeError(f"cannot write {type(v).__name__} as TOML")


def _key(k):
    k = str(k)
    return k if re.fullmatch(r"[A-Za-z0-9_-]+", k) else json.dumps(k)


def to_toml(doc: dict) -> str:
    """A machine or scene given as a dict, as TOML text: scalars and arrays,
    tables (dict) and arrays of tables (list of dicts)."""
    def table(prefix, d, out):
        plain = {k: v for k, v in d.items() if not isinstance(v, dict)
                 and not (isinstance(v, list) and v and all(isinstance(x, dict) for x in v))}
        for k, v in plain.items():
            out.append(f"{_key(k)} = {_toml_value(v)}")
        for k, v in d.items():
            if k in plain:
                continue
            name = f"{prefix}.{_key(k)}" if prefix else _key(k)
            if isinstance(v, dict):
                out.append(f"\n[{name}]")
                table(name, v, out)
            else:
                for item in v:
                    out.append(f"\n[[{name}]]")
                    table(name, item, out)
    out = []
    table("", doc, out)
    return "\n".join(out) + "\n"


def _params(params):
    if params is None:
        return []
    if isinstance(params, dict):
        return [f"{k}={v}" for k, v in params.items()]
    return [str(p) for p in params]


def _variables(variables):
    """dict {number: value}, or the path of a variable file ("#N = V" lines)."""
    if variables is None:
        return []
    if isinstance(variables, (str, os.PathLike)):
        out = []
        with open(variables, encoding="utf-8") as f:
            for lineno, line in enumerate(f, 1):
                text = line.strip()
                if not text or text.startswith(";"):
                    continue
                name, sep, value = text.partition("=")
                try:
                    out.append((int(name.strip().lstrip("#")), float(value)))
                except ValueError:
                    raise StartError(f"{variables}:{lineno}:1: error: line is not "
                                     f"'#<n> = <number>'") from None
        return out
    return [(int(str(k).lstrip("#")), float(v)) for k, v in variables.items()]


def run(program=None, *, program_text=None, machine="mill3", scene=None, dialect="",
        params=None, variables=None, include=None, vars=None, trace=True) -> Run:
    """Runs a part program (a file, or program_text) on a simulated machine.

    machine: a built-in name ("mill3"), a machine file, or a dict (as the TOML
    file's tables); scene: a scene file or a dict; params: {"6200#7": 1} or
    ["6200#7=1"]; variables: {101: 200.0} or a file of "#101 = 200" lines,
    set before the first block (#1-#33, #100-#199, #500-#999); vars: the
    variables to report ("5063", "#<name>").
    Raises StartError (a ValueError) when the run cannot start, with the
    file, line and column, as `skipnc run` exits with status 2.
    """
    if (program is None) == (program_text is None):
        raise ValueError("give program (a file) or program_text")
    with tempfile.TemporaryDirectory(prefix="skipnc-") as tmp:
        def as_file(value, name):
            if value is None:
                return ""
            if isinstance(value, dict):
                path = os.path.join(tmp, name)
                with open(path, "w", encoding="utf-8") as f:
                    f.write(to_toml(value))
                return path
            return os.fspath(value)
        report, columns, code = _skipnc.run(
            os.fspath(program) if program is not None else "", program_text or "",
            as_file(machine, "machine.toml"), as_file(scene, "scene.toml"), dialect,
            _params(params), _variables(variables),
            [os.fspath(p) for p in (include or [])], [str(v) for v in (vars or [])], trace)
    return Run(json.loads(report), columns, code)


def sweep(spec, *, scenarios=None, seed=None, workers=0, csv=None, json_path=None):
    """Runs a sweep spec (docs/cli.md, `skipnc sweep`) on `workers` threads
    (0: every core). Returns (Sweep, rows); writes the CSV and JSON tables when
    paths are given."""
    s = Sweep(os.fspath(spec), scenarios, seed)
    rows = s.run(0, s.count, workers)
    if csv:
        with open(csv, "w", encoding="utf-8") as f:
            f.write(s.csv(rows))
    if json_path:
        with open(json_path, "w", encoding="utf-8") as f:
            f.write(s.json(rows))
    return s, rows
