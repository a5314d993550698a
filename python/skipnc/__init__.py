"""skipnc from Python: run a part program on the simulated machine and get the
report as a dict and the trace as NumPy arrays; run sweeps by scenario range
(locally on threads, or on a Dask cluster: skipnc.dask_sweep).

    import skipnc
    r = skipnc.run("probe.nc", scene="part.toml", vars=["5063"],
                   params={"6200#7": 1}, variables={101: 200.0})
    r.report["variables"]["5063"], r.trace["Z_act"]

    s, table = skipnc.sweep("touch.sweep.toml")
    table["#140"], table["pass"]        # NumPy arrays keyed by column name

run() takes what `skipnc run` takes (strict, expect, repeat and seed, plot),
with the same checks, alarms and exit codes. docs/python.md tells it all.
"""
import json
import numbers
import os
import re
import typing

import numpy as np

from ._skipnc import StartError, Sweep, __version__  # noqa: F401
from . import _skipnc

__all__ = ["run", "Run", "Sweep", "StartError", "sweep", "concat", "to_toml", "__version__"]


class Run(typing.NamedTuple):
    """What run() gives.

    report: the JSON report of `skipnc run --report` as a dict (docs/cli.md);
        with repeat=N, the report of `skipnc run --repeat N --report`
        (format "skipnc-repeat/1": one entry per latched value, variable and
        offset, with nominal, mean, std, min, max, worst).
    trace: the columns of `skipnc run --trace`, same names in the same order,
        as NumPy arrays (float64 at full precision; `file` as strings); None
        with trace=False or repeat.
    exit_code: as `skipnc run`: 0 completed, 1 alarm or interrupted, 3 an
        expectation failed (an expected outcome that held is 0).
    failed: one line per expectation that failed ("expectation failed: ...").
    """
    report: dict
    trace: typing.Optional[dict]
    exit_code: int
    failed: list


def _toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        return repr(float(v))
    if isinstance(v, (str, os.PathLike)):
        return json.dumps(os.fspath(v))  # a TOML basic string has JSON's escapes
    if isinstance(v, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise TypeError(f"cannot write {type(v).__name__} as TOML")


def _key(k):
    k = str(k)
    return k if re.fullmatch(r"[A-Za-z0-9_-]+", k) else json.dumps(k)


def _is_tables(v):
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(isinstance(x, dict) for x in v)


def _toml_lines(doc, what):
    """The TOML text of a dict, and for each of its lines the key it writes
    ("trigger[0].axis"; "" for blank lines)."""
    lines, keys = [], []

    def emit(text, key):
        lines.append(text)
        keys.append(key)

    def table(prefix, where, d):
        plain = {k: v for k, v in d.items() if not isinstance(v, dict) and not _is_tables(v)}
        for k, v in plain.items():
            key = f"{where}.{k}" if where else str(k)
            try:
                emit(f"{_key(k)} = {_toml_value(v)}", key)
            except TypeError as e:
                raise TypeError(f"{what}, key {key}: {e}") from None
        for k, v in d.items():
            if k in plain:
                continue
            name = f"{prefix}.{_key(k)}" if prefix else _key(k)
            key = f"{where}.{k}" if where else str(k)
            if isinstance(v, dict):
                emit("", "")
                emit(f"[{name}]", key)
                table(name, key, v)
            else:
                for i, item in enumerate(v):
                    emit("", "")
                    emit(f"[[{name}]]", f"{key}[{i}]")
                    table(name, f"{key}[{i}]", item)

    table("", "", doc)
    return "\n".join(lines) + "\n", keys


def to_toml(doc: dict) -> str:
    """A machine or scene given as a dict, as TOML text: scalars and arrays,
    tables (dict) and arrays of tables (list of dicts)."""
    return _toml_lines(doc, "dict")[0]


class _Source:
    """A machine or scene argument: a name or file, or a dict read as TOML
    text under the name "<base_dir>/scene (dict)" (relative paths in it
    resolve against base_dir); errors are told in the dict's keys."""

    def __init__(self, value, what, base_dir):
        self.what = f"{what} (dict)"
        self.text, self.keys, self.origin = "", [], ""
        if value is None:
            self.name = ""
        elif isinstance(value, dict):
            self.text, self.keys = _toml_lines(value, self.what)
            self.origin = self.name = os.path.join(base_dir, self.what)
        else:
            self.name = os.fspath(value)

    def explain(self, message):
        """The error message with the dict's keys in place of its lines."""
        if not self.origin:
            return message

        def key(m):
            line = int(m.group(1))
            if 1 <= line <= len(self.keys) and self.keys[line - 1]:
                return f"{self.what}, key {self.keys[line - 1]}"
            return f"{self.what}, line {line}"
        message = re.sub(re.escape(self.origin) + r":(\d+)(?::\d+)?", key, message)
        return message.replace(self.origin, self.what)


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
                name, _, value = text.partition("=")
                try:
                    out.append((int(name.strip().lstrip("#")), float(value)))
                except ValueError:
                    raise StartError(f"{os.fspath(variables)}:{lineno}:1: error: line is not "
                                     f"'#<n> = <number>'") from None
        return out
    return [(int(str(k).lstrip("#")), float(v)) for k, v in variables.items()]


def _strings(value):
    if value is None:
        return []
    if isinstance(value, (str, os.PathLike)):
        return [os.fspath(value)]
    return [os.fspath(v) for v in value]


def _trace(columns):
    if columns is None:
        return None
    names, arrays, files = columns
    out = {}
    for name in names:
        if name == "file":
            out[name] = np.asarray(files if files else [""], dtype=str)[arrays[name]]
        else:
            out[name] = arrays[name]
    return out


def run(program=None, *, program_text=None, machine="mill3", scene=None, dialect="",
        params=None, variables=None, include=None, vars=None, trace=True, strict=False,
        expect=None, repeat=0, seed=None, plot=None, base_dir=None) -> Run:
    """Runs a part program (a file, or program_text) on a simulated machine,
    as `skipnc run` does, and returns a Run (report, trace, exit_code, failed).

    machine: a built-in name ("mill3"), a machine file, or a dict (the TOML
        file's tables as dicts, arrays of tables as lists of dicts).
    scene: a scene file or a dict.
    base_dir: the folder that relative paths inside a machine or scene dict
        (`extends`, a mesh's `file`) are taken from; default the current
        working directory. Paths given as arguments are taken as Python takes
        them (from the current working directory).
    dialect: "fanuc", "linuxcnc", ...; "" the machine's.
    params: {"6200#7": 1} or ["6200#7=1"] (--param).
    variables: {101: 200.0} or a file of "#101 = 200" lines, set before the
        first block (#1-#33, #100-#199, #500-#999).
    include: subprogram folders (-I).  vars: variables to report ("5063",
        "#<name>"; --var).
    trace: the trace's columns in Run.trace (--trace).
    strict: a warning is an alarm (--strict).
    expect: "#140=-3+-0.01", "status=completed", "alarm=3001" (or the alarm's
        code or key), or a list (--expect): failures in Run.failed, exit_code 3,
        every verdict in Run.report["expectations"].
    repeat, seed: N runs with the probe's scatter and one without, from seed
        `seed` (--repeat N --seed S); Run.report is then their statistics.
    plot: a file or a list of files, .svg or .html: pictures of the run (--plot).

    Raises StartError (a ValueError) when the run cannot start, as `skipnc
    run` exits with status 2, naming the file, line and column (for a dict:
    its key, "scene (dict), key trigger[0].axis"). An alarm during the run is
    not an exception: report["status"] is "alarm".
    """
    if (program is None) == (program_text is None):
        raise ValueError("give program (a file) or program_text")
    if repeat and (expect or plot):
        raise ValueError("repeat cannot be combined with expect or plot")
    if seed is not None and not repeat:
        raise ValueError("seed is the first seed of repeat's runs: give repeat too")
    base = os.path.abspath(os.fspath(base_dir) if base_dir is not None else os.getcwd())
    m, s = _Source(machine, "machine", base), _Source(scene, "scene", base)
    spec = _skipnc.RunSpec()
    spec.program = os.fspath(program) if program is not None else ""
    spec.program_text = program_text or ""
    spec.machine, spec.machine_text = m.name, m.text
    spec.scene, spec.scene_text = s.name, s.text
    spec.dialect = dialect
    spec.params = _params(params)
    spec.include = _strings(include)
    spec.vars = [str(v) for v in (vars or [])]
    try:
        if repeat:
            out = _skipnc.repeat(spec, _variables(variables), strict, int(repeat), seed)
        else:
            out = _skipnc.run(spec, _variables(variables), trace, strict, _strings(expect),
                              _strings(plot))
    except StartError as e:
        raise StartError(s.explain(m.explain(str(e)))) from None
    return Run(json.loads(out["report"]), _trace(out.get("trace")), out["exit_code"],
               list(out.get("failed", [])))


def concat(tables):
    """One table from several (the tables of Sweep.run over ranges, in order)."""
    tables = list(tables)
    if not tables:
        raise ValueError("no tables")
    return {k: np.concatenate([t[k] for t in tables]) for k in tables[0]}


def sweep(spec, *, scenarios=None, seed=None, workers=0, csv=None, json_path=None):
    """Runs a sweep spec (docs/cli.md, `skipnc sweep`) on `workers` threads
    (0: every core). Returns (Sweep, table): the table is a dict of NumPy
    arrays keyed by column name (Sweep.columns: scenario, status, each varied
    quantity, each variable as "#140", each check, pass, ...). Writes the CSV
    and JSON tables of `skipnc sweep` when paths are given."""
    s = Sweep(os.fspath(spec), scenarios, seed)
    table = s.run(0, s.count, workers)
    if csv:
        with open(csv, "w", encoding="utf-8") as f:
            f.write(s.csv(table))
    if json_path:
        with open(json_path, "w", encoding="utf-8") as f:
            f.write(s.json(table))
    return s, table
