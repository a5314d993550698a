#!/usr/bin/env python3
"""Side-by-side comparison of skipnc's interpreter with LinuxCNC's rs274.

For each RS274NGC program, both interpreters are run without a machine:

    rs274 -t tool.tbl -g PROGRAM            (LinuxCNC's standalone interpreter)
    SKIPNC canon PROGRAM SKIPNC_ARGS        (default SKIPNC_ARGS: -d linuxcnc)

and the MOTION each one commands is extracted as a list of records:

    kind   what is compared                rs274 call         skipnc line
    rapid  end point                       STRAIGHT_TRAVERSE  RAPID
    feed   end point, feed                 STRAIGHT_FEED      FEED
    arc    end point, centre, plane,       ARC_FEED           ARC_CW / ARC_CCW
           direction and turns, feed
    probe  end point, feed                 STRAIGHT_PROBE     SKIP
    dwell  seconds                         DWELL              DWELL

The two lists are compared record by record.

Frame: machine millimetres of the controlled point
-------------------------------------------------
skipnc prints machine coordinates in mm with the tool length offset applied
(the point the machine moves). rs274 (LinuxCNC 2.9) prints the positions
the interpreter hands to the canonical layer: PROGRAM coordinates in the
length unit of the moment (inch under G20), without the work offsets and
without the tool offset. Those are given separately (SET_G5X_OFFSET,
SET_G92_OFFSET, SET_XY_ROTATION, USE_TOOL_LENGTH_OFFSET, in the unit in
force when printed) and LinuxCNC's motion side (emccanon.cc,
rotate_and_offset_pos) combines them as

    machine = rotate_xy(program + g92, rotation) + g5x + tool_offset

after turning each into mm. compare.py does the same to every rs274 record,
so both sides are compared in machine mm.

Rounding
--------
rs274 prints every number with 4 decimals (%.4f in saicanon.cc) and has no
option for more. Each printed number is thus exact to half a unit of its
last digit: 0.00005 mm, or 0.00005 inch = 0.00127 mm. A skipnc value agrees
when it lies within the sum of those half-digits over the printed numbers
that enter the machine value (the coordinate and each non-zero offset,
rotation included) plus --tolerance (mm, default 1e-6). For a plain
metric program without offsets that is 0.00005 mm + 1e-6 mm: skipnc's value
must round to the number rs274 printed. Feeds are compared in the same way
in mm/min (rs274 turns G93 inverse time into units per minute itself, one
SET_FEED_RATE before each move), dwells in seconds. Arc direction and turns
are compared exactly: rs274's `rotation` argument is +N for G3 and -N for
G2, N - 1 being the extra full turns (P word); skipnc's is +/-(1 + TURNS).

Null moves
----------
A rapid or feed that ends where the previous move ended moves nothing, and a
dwell of no time waits for nothing: both are dropped.
rs274 writes some (a G28 intermediate point equal to the present position,
for instance) where skipnc may not; such records are dropped on both sides
before comparing (--keep-null-moves keeps them).

Probes
------
In rs274 the probe "reaches" its end point (STRAIGHT_PROBE prints it) and
its dummy machine then stands 0.254 mm (0.01 in) back toward the start, so
a following incremental move or arc starts there, and #<_x> etc. read that
point. The programs in programs/ follow a probe with an absolute move.

Verdicts and exit status
------------------------
same        same motion; "both fail" when both sides reject the program
            (counted with the agreements, reported separately)
differs     the first differing record, both records shown
            (all of them with --list-differences)
error       one side fails (its message shown), the other does not
known       differs or fails on one side, but the program is listed in
            known_differences.txt

Exit 0 when every program gives the same motion (or both sides fail, or the
program is a listed known difference), 1 otherwise, 2 on a usage problem
(skipnc or the programs not found), and 77 (ctest's SKIP_RETURN_CODE) when
rs274 cannot be found.
"""

import argparse
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
AXES = ("X", "Y", "Z", "A", "B", "C")
LINEAR = ("X", "Y", "Z")
HALF_DIGIT = 0.5e-4  # half a unit of rs274's last printed digit (%.4f)
INCH_MM = 25.4

# plane -> (first axis, second axis, normal axis), LinuxCNC's ARC_FEED order
PLANES = {
    "XY": ("X", "Y", "Z"),
    "XZ": ("Z", "X", "Y"),  # G18: first = Z, second = X
    "YZ": ("Y", "Z", "X"),  # G19: first = Y, second = Z
}


class Record:
    """One motion record. `mm` holds the end point in machine mm per axis
    (degrees for A B C), `allow` the rounding allowance of the record's
    numbers in mm (0 for skipnc, whose numbers are exact)."""

    __slots__ = ("kind", "line", "text", "mm", "centre", "plane", "turns",
                 "feed", "seconds", "allow", "feed_allow")

    def __init__(self, kind, line, text):
        self.kind = kind
        self.line = line
        self.text = text
        self.mm = {a: 0.0 for a in AXES}
        self.centre = None  # {axis: mm} for the two in-plane axes
        self.plane = None  # "XY", "XZ", "YZ"
        self.turns = None
        self.feed = None  # mm/min
        self.seconds = None
        self.allow = 0.0
        self.feed_allow = 0.0

    def describe(self):
        if self.kind == "dwell":
            body = "dwell %s s" % fmt(self.seconds)
        else:
            body = self.kind + " " + " ".join(
                "%s%s" % (a, fmt(self.mm[a])) for a in AXES
                if a in LINEAR or abs(self.mm[a]) > 0)
            if self.kind == "arc":
                body += " centre " + " ".join(
                    "%s%s" % (a, fmt(v)) for a, v in self.centre.items())
                body += " plane %s turns %+d" % (self.plane, self.turns)
            if self.feed is not None:
                body += " F%s" % fmt(self.feed)
        return "%s: %s   <- %s" % (self.line, body, self.text)


def fmt(v):
    text = ("%.6f" % v).rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


# ----------------------------------------------------------------------------
# rs274 side

RS274_LINE = re.compile(r"^\s*(\d+)\s+N[.\d]*\s*([A-Z_0-9]+)\((.*)\)\s*$")
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def numbers(text):
    return [float(x) for x in NUMBER.findall(text)]


class Rs274State:
    """What rs274 has told the canonical layer so far: the unit, the plane,
    the feed, the offsets (kept in mm, with their rounding allowance)."""

    def __init__(self):
        self.unit = 1.0
        self.plane = "XY"
        self.feed = 0.0
        self.feed_unit = 1.0
        self.g5x = {a: 0.0 for a in AXES}
        self.g92 = {a: 0.0 for a in AXES}
        self.tlo = {a: 0.0 for a in AXES}
        self.rotation = 0.0
        # the rounding allowance each offset brings, per axis, mm
        self.offset_allow = {a: 0.0 for a in AXES}

    def set_offsets(self, which, values, first):
        table = getattr(self, which)
        for i, a in enumerate(AXES):
            v = values[first + i] if first + i < len(values) else 0.0
            table[a] = v * (self.unit if a in LINEAR else 1.0)
        self.update_allowance()

    def update_allowance(self):
        for a in AXES:
            u = self.unit if a in LINEAR else 1.0
            n = sum(1 for t in (self.g5x, self.g92, self.tlo) if t[a] != 0.0)
            self.offset_allow[a] = n * HALF_DIGIT * u

    def to_machine(self, prog):
        """Program coordinates as printed (dict axis -> value, program units)
        to machine mm, the way emccanon.cc does it."""
        mm = {}
        for a in AXES:
            u = self.unit if a in LINEAR else 1.0
            mm[a] = prog.get(a, 0.0) * u + self.g92[a]
        if self.rotation:
            t = math.radians(self.rotation)
            x, y = mm["X"], mm["Y"]
            mm["X"] = x * math.cos(t) - y * math.sin(t)
            mm["Y"] = x * math.sin(t) + y * math.cos(t)
        for a in AXES:
            mm[a] += self.g5x[a] + self.tlo[a]
        return mm

    def allowance(self, prog, axes):
        """Rounding allowance (mm) of a point made of printed numbers."""
        worst = 0.0
        radius = math.hypot(prog.get("X", 0.0) * self.unit + self.g92["X"],
                            prog.get("Y", 0.0) * self.unit + self.g92["Y"])
        for a in axes:
            u = self.unit if a in LINEAR else 1.0
            extra = 0.0
            if self.rotation and a in ("X", "Y"):
                extra = radius * math.radians(HALF_DIGIT) + 2 * HALF_DIGIT * u
            worst = max(worst, HALF_DIGIT * u + self.offset_allow[a] + extra)
        return worst


def parse_rs274(text):
    """Motion records from rs274's canonical call listing."""
    records = []
    st = Rs274State()
    for raw in text.splitlines():
        m = RS274_LINE.match(raw)
        if not m:
            continue
        line, call, args = m.group(1), m.group(2), m.group(3)
        if call == "USE_LENGTH_UNITS":
            st.unit = INCH_MM if "INCH" in args else 1.0
            continue
        if call == "SELECT_PLANE":
            st.plane = args.rsplit("_", 1)[-1]
            continue
        if call == "SET_FEED_RATE":
            st.feed = numbers(args)[0]
            st.feed_unit = st.unit
            continue
        if call == "SET_G5X_OFFSET":  # index, x y z a b c [u v w]
            st.set_offsets("g5x", numbers(args), 1)
            continue
        if call == "SET_G92_OFFSET":
            st.set_offsets("g92", numbers(args), 0)
            continue
        if call == "SET_XY_ROTATION":
            st.rotation = numbers(args)[0]
            continue
        if call == "USE_TOOL_LENGTH_OFFSET":  # x y z, a b c, u v w
            st.set_offsets("tlo", numbers(args), 0)
            continue
        if call in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "STRAIGHT_PROBE"):
            kind = {"STRAIGHT_TRAVERSE": "rapid", "STRAIGHT_FEED": "feed",
                    "STRAIGHT_PROBE": "probe"}[call]
            v = numbers(args)
            prog = {a: (v[i] if i < len(v) else 0.0) for i, a in enumerate(AXES)}
            r = Record(kind, "call " + line, raw.strip())
        elif call == "ARC_FEED":
            v = numbers(args)
            first, second, normal = PLANES[st.plane]
            r = Record("arc", "call " + line, raw.strip())
            prog = {first: v[0], second: v[1], normal: v[5]}
            for i, a in enumerate(("A", "B", "C")):
                prog[a] = v[6 + i] if 6 + i < len(v) else 0.0
            centre_prog = dict(prog)
            centre_prog[first], centre_prog[second] = v[2], v[3]
            centre_mm = st.to_machine(centre_prog)
            r.centre = {first: centre_mm[first], second: centre_mm[second]}
            r.plane = st.plane
            r.turns = int(v[4])
        elif call == "DWELL":
            r = Record("dwell", "call " + line, raw.strip())
            r.seconds = numbers(args)[0]
            r.allow = HALF_DIGIT
            records.append(r)
            continue
        else:
            continue
        r.mm = st.to_machine(prog)
        r.allow = st.allowance(prog, AXES)
        if r.kind != "rapid":
            r.feed = st.feed * st.feed_unit
            r.feed_allow = HALF_DIGIT * st.feed_unit
        records.append(r)
    return records


# ----------------------------------------------------------------------------
# skipnc side

SKIPNC_LINE = re.compile(r"^(\d+) (RAPID|FEED|ARC_CW|ARC_CCW|SKIP|DWELL)\b(.*)$")
AXIS_WORD = re.compile(r"([XYZABC])(-?[\d.]+(?:[eE][-+]?\d+)?)")
CENTRE_WORD = re.compile(r"\bC([XYZ])=(-?[\d.]+(?:[eE][-+]?\d+)?)")
FEED_WORD = re.compile(r"\bF(-?[\d.]+(?:[eE][-+]?\d+)?)")
TURNS_WORD = re.compile(r"\bTURNS(-?\d+)")
PLANE_OF = {("X", "Y"): "XY", ("Z", "X"): "XZ", ("Y", "Z"): "YZ"}


def parse_skipnc(text):
    """Motion records from `skipnc canon` output (machine mm, mm/min)."""
    records = []
    for raw in text.splitlines():
        m = SKIPNC_LINE.match(raw.strip())
        if not m:
            continue
        line, name, rest = m.group(1), m.group(2), m.group(3)
        if name == "DWELL":
            r = Record("dwell", "line " + line, raw.strip())
            r.seconds = float(rest.split()[0])
            records.append(r)
            continue
        kind = {"RAPID": "rapid", "FEED": "feed", "ARC_CW": "arc",
                "ARC_CCW": "arc", "SKIP": "probe"}[name]
        r = Record(kind, "line " + line, raw.strip())
        # the axis words come first; they end at the first other word
        for w in rest.split():
            am = AXIS_WORD.fullmatch(w)
            if not am:
                break
            r.mm[am.group(1)] = float(am.group(2))
        fm = FEED_WORD.search(rest)
        if kind != "rapid" and fm:
            r.feed = float(fm.group(1))
        if kind == "arc":
            centre = CENTRE_WORD.findall(rest)
            r.centre = {a: float(v) for a, v in centre}
            r.plane = PLANE_OF.get(tuple(a for a, _ in centre), "?")
            tm = TURNS_WORD.search(rest)
            extra = int(tm.group(1)) if tm else 0
            r.turns = (1 if name == "ARC_CCW" else -1) * (1 + extra)
        records.append(r)
    return records


# ----------------------------------------------------------------------------
# comparison

def drop_null_moves(records, tol_mm):
    """Drops rapids and feeds that end where the previous move ended (both
    interpreters start at machine zero), and dwells of no time."""
    out = []
    last, last_allow = {a: 0.0 for a in AXES}, 0.0
    for r in records:
        if r.kind == "dwell":
            if abs(r.seconds) > r.allow:  # a dwell of no time waits for nothing
                out.append(r)
            continue
        allowance = r.allow + last_allow + tol_mm
        if r.kind in ("rapid", "feed") and last is not None and all(
                abs(r.mm[a] - last[a]) <= allowance for a in AXES):
            continue
        last, last_allow = r.mm, r.allow
        out.append(r)
    return out


def compare_records(a, b, tol):
    """None when rs274 record a and skipnc record b agree, else a reason."""
    if a.kind != b.kind:
        return "kind %s vs %s" % (a.kind, b.kind)
    if a.kind == "dwell":
        if abs(a.seconds - b.seconds) > a.allow + tol:
            return "dwell time"
        return None
    for ax in AXES:
        if abs(a.mm[ax] - b.mm[ax]) > a.allow + tol:
            return "end point %s" % ax
    if a.kind == "arc":
        if a.plane != b.plane:
            return "arc plane"
        for ax, v in a.centre.items():
            if ax not in b.centre:
                return "arc centre axes"
            if abs(v - b.centre[ax]) > a.allow + tol:
                return "arc centre %s" % ax
        if a.turns != b.turns:
            return "arc direction/turns"
    if a.feed is not None:
        if b.feed is None:
            return "feed missing"
        if abs(b.feed - a.feed) > a.feed_allow + tol:
            return "feed"
    return None


# ----------------------------------------------------------------------------
# running the two interpreters

def run(cmd, cwd=None, timeout=60, env=None):
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True,
                           timeout=timeout, stdin=subprocess.DEVNULL, env=env)
    except subprocess.TimeoutExpired:
        return None, "", "timed out after %d s" % timeout
    except OSError as e:
        return None, "", str(e)
    return p.returncode, p.stdout, p.stderr


def clean_message(stderr):
    lines = [x.strip() for x in stderr.splitlines()
             if x.strip() and x.strip() != "executing"]
    return " | ".join(lines) if lines else "(no message)"


def run_rs274(rs274, program, tool_table):
    # rs274 may write a parameter file in its working folder: give it a
    # fresh one, so that no state carries over from program to program.
    # LinuxCNC 2.9 keeps the loaded tool table in a file it maps,
    # $HOME/.tool.mmap (libtooldata's tooldata_mmap.cc), shared by every
    # rs274 of that HOME: two comparisons run at once (ctest -j2) truncated
    # each other's table, which showed as "Requested tool 1 not found in the
    # tool table" or a SIGBUS. Each run gets the fresh folder as its HOME.
    # A run killed by a signal is still tried again, up to twice; an
    # ordinary error is not.
    for _ in range(3):
        with tempfile.TemporaryDirectory(prefix="rs274-") as tmp:
            cmd = [rs274]
            if tool_table:
                cmd += ["-t", tool_table]
            cmd += ["-g", os.path.abspath(program)]
            rc, out, err = run(cmd, cwd=tmp, env=dict(os.environ, HOME=tmp))
        if rc is None or rc >= 0:
            break
    if rc != 0:
        return None, clean_message(err) + ("" if rc is None else " (exit %d)" % rc)
    return parse_rs274(out), None


def run_skipnc(skipnc, program, args):
    rc, out, err = run([skipnc, "canon", os.path.abspath(program)] + args)
    if rc != 0:
        return None, clean_message(err) + ("" if rc is None else " (exit %d)" % rc)
    return parse_skipnc(out), None


def load_known(path):
    known = {}
    if not os.path.exists(path):
        return known
    with open(path, encoding="utf-8") as f:
        for raw in f:
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            name, _, reason = line.partition(" ")
            known[name] = reason.strip()
    return known


def collect_programs(dirs):
    """(name, path) pairs; the name is the path below the folder given (the
    file name for a file given), which is also the key in the known list."""
    progs = []
    for d in dirs:
        if os.path.isfile(d):
            progs.append((os.path.basename(d), d))
            continue
        for root, _, files in os.walk(d):
            for f in files:
                if f.lower().endswith(".ngc"):
                    path = os.path.join(root, f)
                    progs.append((os.path.relpath(path, d), path))
    return sorted(progs)


def main(argv=None):
    ap = argparse.ArgumentParser(
        description="Compare skipnc's motion with LinuxCNC rs274's, program by program.")
    ap.add_argument("--skipnc", required=True, help="path of the skipnc executable")
    ap.add_argument("--rs274", default="rs274", help="rs274 executable (default: rs274)")
    ap.add_argument("--programs", nargs="+", default=[os.path.join(HERE, "programs")],
                    help="folders (searched recursively for .ngc) or files")
    ap.add_argument("--skipnc-args", default="-d linuxcnc",
                    help="arguments after `canon FILE` (default: %(default)s)")
    ap.add_argument("--tool-table", default=os.path.join(HERE, "tool.tbl"),
                    help="tool table for rs274 -t ('' for none)")
    ap.add_argument("--known", default=os.path.join(HERE, "known_differences.txt"),
                    help="known differences file")
    ap.add_argument("--tolerance", type=float, default=1e-6, help="mm (default 1e-6)")
    ap.add_argument("--list-differences", action="store_true",
                    help="list every differing record, not only the first")
    ap.add_argument("--keep-null-moves", action="store_true",
                    help="do not drop zero-length rapids and feeds")
    ap.add_argument("--quiet", action="store_true", help="print only differing programs")
    opts = ap.parse_args(argv)

    rs274 = shutil.which(opts.rs274) or (opts.rs274 if os.access(opts.rs274, os.X_OK) else None)
    if not rs274:
        print("rs274 not installed: comparison skipped")
        return 77
    skipnc = shutil.which(opts.skipnc) or (opts.skipnc if os.access(opts.skipnc, os.X_OK) else None)
    if not skipnc:
        print("skipnc not found: %s" % opts.skipnc, file=sys.stderr)
        return 2
    tool_table = opts.tool_table if opts.tool_table and os.path.exists(opts.tool_table) else None
    if tool_table:
        tool_table = os.path.abspath(tool_table)
    skipnc_args = shlex.split(opts.skipnc_args)
    known = load_known(opts.known)
    programs = collect_programs(opts.programs)
    if not programs:
        print("no .ngc programs found in %s" % " ".join(opts.programs), file=sys.stderr)
        return 2

    counts = {"same": 0, "both-error": 0, "differs": 0, "error": 0, "known": 0}
    width = max(len(name) for name, _ in programs)
    for name, prog in programs:
        a, a_err = run_rs274(rs274, prog, tool_table)
        b, b_err = run_skipnc(skipnc, prog, skipnc_args)
        detail = []
        if a_err and b_err:
            verdict = "both-error"
            detail = ["rs274:  " + a_err, "skipnc: " + b_err]
        elif a_err or b_err:
            verdict = "error"
            detail = ["rs274:  " + a_err] if a_err else ["skipnc: " + b_err]
        else:
            if not opts.keep_null_moves:
                # the same rule on both sides, each in its own printed frame
                a = drop_null_moves(a, opts.tolerance)
                b = drop_null_moves(b, opts.tolerance)
            diffs = []
            for i in range(min(len(a), len(b))):
                why = compare_records(a[i], b[i], opts.tolerance)
                if why:
                    diffs.append((i, why))
                    if not opts.list_differences:
                        break
            if len(a) != len(b) and (opts.list_differences or not diffs):
                diffs.append((min(len(a), len(b)), "record count %d vs %d" % (len(a), len(b))))
            if not diffs:
                verdict = "same"
                detail = ["%d records" % len(a)] if not opts.quiet else []
            else:
                verdict = "differs"
                for i, why in diffs:
                    detail.append("record %d: %s" % (i + 1, why))
                    detail.append("  rs274:  " + (a[i].describe() if i < len(a) else "(none)"))
                    detail.append("  skipnc: " + (b[i].describe() if i < len(b) else "(none)"))
        if verdict in ("differs", "error") and name in known:
            detail.append("known difference: " + known[name])
            verdict = "known"
        elif name in known:
            detail.append("listed in %s but %s: the entry can go"
                          % (os.path.basename(opts.known), verdict))
        counts[verdict] += 1
        if opts.quiet and verdict in ("same", "known"):
            continue
        head = "%-*s  %s" % (width, name, verdict)
        if verdict == "same" and detail:
            head += " (%s)" % detail[0]
            detail = detail[1:]
        print(head)
        for d in detail:
            print("    " + d)
    total = len(programs)
    print("summary: %d programs: %d same, %d both fail, %d differ, %d error on one side, "
          "%d known differences" % (total, counts["same"], counts["both-error"],
                                    counts["differs"], counts["error"], counts["known"]))
    return 1 if counts["differs"] or counts["error"] else 0


if __name__ == "__main__":
    sys.exit(main())
