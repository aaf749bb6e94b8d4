"""``contact run`` streams: cases built lazily (Scene.iter_cases, Scene.case_count), results
delivered in scene order as they complete through a bounded window (iter_scene,
contact.scene.batch.iter_chunked), and written as they come (SceneWriter) in memory that does
not grow with the sweep.

Oracles: the in-memory run (run_scene) and its content (SceneResult.to_json, .table(), the
curves and maps of its cases), which the streamed files must equal; a read counter for the
window; tracemalloc for the memory.
"""
from __future__ import annotations

import contextlib
import csv
import itertools
import json
import subprocess
import sys
import textwrap
import threading
import time
import tracemalloc
from collections import namedtuple
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import contact
from contact.scene import (CaseError, CaseResult, CaseText, SceneWriter, format_table,
                           iter_scene, parse_scene_text, run_scene)
from contact.scene import batch, output
from contact.scene import run as run_module
from contact.scene.output import dumps_json
from contact.scene.summary import TABLE_ROWS, table_cell

from cli_helpers import child_env, run_cli

ROOT = Path(__file__).resolve().parents[2]
FakeCase = namedtuple("FakeCase", "index material speed inputs")

#: Flat punch, two widths x two speeds x two frictions (8 cases): every kind of field, the
#: curves on an automatic x (one X column per case), a small subsurface grid through the corners.
EVERY_FIELD = """
title = "every field"
[material]
preset = "zhou2014"
[punch]
kind = "flat"
half_width = [1.0, 1.5]
[motion]
load = 0.01
speed = [0.0, 0.6]
friction = [0.0, 0.3]
[outputs]
fields = ["ends", "exponents", "sif", "pressure", "shear", "sigma_xx", "roots", "constants",
          "subsurface"]
grid = { x = { start = -2, stop = 2, num = 9 }, y = { start = -1, stop = 0, num = 5 } }
"""

#: Cylinder, speed x friction on a shared x grid (one X column).
SHARED_X = """
title = "cylinder"
[material]
preset = "zhou2014"
[punch]
kind = "cylindrical"
radius = 100.0
[motion]
load = 0.01
speed = [0.3, 0.6]
friction = [0.0, 0.1, 0.2, 0.3]
[outputs]
fields = ["ends", "exponents", "pressure"]
x = { start = -0.5, stop = 0.5, num = 41 }
"""


def load_sweep(n):
    """n cases of a cylinder that differ only by the load (the exponents, hence the solver's
    caches, are the same): ~1 ms each."""
    loads = ", ".join(repr(0.01 + 1e-6 * k) for k in range(n))
    return parse_scene_text(textwrap.dedent(f"""
        [material]
        preset = "zhou2014"
        [punch]
        kind = "cylindrical"
        radius = 100.0
        [motion]
        load = [{loads}]
        speed = 0.3
        friction = 0.2
        [outputs]
        fields = ["ends"]
    """))


def read_csv(path):
    with open(path, newline="") as fh:
        return list(csv.reader(fh))


def cell(text):
    if text == "":
        return None
    try:
        return int(text)
    except ValueError:
        return float(text)


def without_timing(doc):
    return {k: v for k, v in doc.items() if k != "timing_s"}


# --------------------------------------------------------------------------
# lazy cases
# --------------------------------------------------------------------------
def test_cases_are_built_lazily_and_counted_without_building_them():
    s = parse_scene_text(EVERY_FIELD)
    assert s.case_count == 8 == len(s.cases())
    lazy = s.iter_cases()
    assert iter(lazy) is lazy                                     # an iterator, not a list
    assert list(itertools.islice(lazy, 3)) == s.cases()[:3]
    assert [c.index for c in s.iter_cases()] == list(range(8))
    big = parse_scene_text(SHARED_X.replace("[0.3, 0.6]", "[" + ", ".join(
        f"{0.9 * k / 999:.6f}" for k in range(1000)) + "]"))
    assert big.case_count == 4000
    assert next(big.iter_cases()).label == "speed = 0, friction = 0"


# --------------------------------------------------------------------------
# the streamed files equal the in-memory result
# --------------------------------------------------------------------------
def expected_curve_csv(result, name):
    """The curve CSV from the cases in memory: X and a column per case when they share x,
    else a pair of columns per case; repr of each number, empty where not finite."""
    def cells(v):
        return ["" if not np.isfinite(y) else repr(y) for y in np.asarray(v).tolist()]
    curves = [res.curve(name) for res in result.cases]
    labels = [res.label for res in result.cases]
    if all(np.array_equal(x, curves[0][0]) for x, _ in curves):
        header = ["X"] + labels
        columns = [cells(curves[0][0])] + [cells(v) for _, v in curves]
    else:
        header = [h for label in labels for h in (f"X ({label})", label)]
        columns = [c for x, v in curves for c in (cells(x), cells(v))]
    return [header] + [list(row) for row in zip(*columns)]


@pytest.mark.parametrize("jobs", [1, 2])
@pytest.mark.parametrize("text", [EVERY_FIELD, SHARED_X], ids=["every_field", "shared_x"])
def test_streamed_files_equal_the_in_memory_result(tmp_path, text, jobs):
    """``contact run`` (serially, and through a 2-worker process pool) writes what run_scene
    holds: result.json (the same text but for timing_s), sweep.csv (its table), the curve
    CSVs, the maps; the printed table is format_table's."""
    path = tmp_path / "scene.toml"
    path.write_text(text)
    rc, stdout, err = run_cli("run", path, "--out", tmp_path / "out", "--jobs", jobs,
                              "--no-figures")
    assert rc == 0, err
    out = tmp_path / "out"
    s = parse_scene_text(text, source=str(path))
    result = run_scene(s)
    doc = result.to_json()

    streamed = (out / "result.json").read_text()
    assert without_timing(json.loads(streamed)) == without_timing(
        json.loads(dumps_json(doc)))
    assert json.loads(streamed)["timing_s"] > 0

    def untimed(text):
        return [line for line in text.splitlines() if not line.startswith('  "timing_s": ')]
    assert untimed(streamed) == untimed(dumps_json(doc)) and streamed.endswith("}\n")

    columns, rows = result.table()
    table = read_csv(out / "sweep.csv")
    assert table[0] == columns
    assert [[cell(c) for c in row] for row in table[1:]] == rows

    for name in result.curve_fields:
        assert read_csv(out / f"{name}.csv") == expected_curve_csv(result, name), name

    if "subsurface" in s.fields:
        with np.load(out / "subsurface.npz") as z:
            assert z["cases"].tolist() == list(range(8))
            assert z["labels"].tolist() == [res.label for res in result.cases]
            for res in result.cases:
                for q in ("x", "y", "sigma_xx", "sigma_yy", "sigma_xy", "max_shear",
                          "max_tension"):
                    want = getattr(res.subsurface, q) if q in "xy" else \
                        res.subsurface.quantity(q)
                    np.testing.assert_array_equal(z[f"case{res.index}/{q}"], want)
        rows = read_csv(out / "subsurface.csv")
        assert len(rows) == 1 + 8 * 9 * 5 and rows[0][0] == "case"

    def shape(text):                 # the table without its times
        return [line.rsplit(None, 1)[0] if line[:6].strip().isdigit() else line
                for line in text.splitlines() if "total time" not in line]
    printed = stdout[:stdout.index("  wrote ")]
    assert shape(printed) == shape(format_table(result))


def test_quiet_run_keeps_no_table_and_writes_the_same_files(tmp_path):
    """``--quiet`` prints nothing and keeps no table (SceneWriter(table=False)); the files
    are those of a run that prints."""
    path = tmp_path / "scene.toml"
    path.write_text(SHARED_X)
    for name, extra in (("loud", ()), ("quiet", ("--quiet",))):
        rc, stdout, err = run_cli("run", path, "--out", tmp_path / name, "--no-figures", *extra)
        assert rc == 0, err
        assert (stdout == "") == (name == "quiet")

    def untimed(p):
        return [line for line in p.read_text().splitlines() if '"timing_s"' not in line]
    for f in ("result.json", "sweep.csv"):
        assert untimed(tmp_path / "quiet" / f) == untimed(tmp_path / "loud" / f), f
    s = parse_scene_text(SHARED_X)
    with SceneWriter(s, tmp_path / "w", s.case_count, figures=False, table=False) as w:
        assert w.summary is None
        with pytest.raises(ValueError, match="table=False"):
            w.table(0.0)


@pytest.mark.slow
def test_curve_csv_spooled_in_blocks(tmp_path, monkeypatch):
    """Cases buffered and read back a few at a time (a block smaller than the sweep) give
    the same CSV."""
    monkeypatch.setattr(output.CurveColumns, "BLOCK", 3)
    s = parse_scene_text(SHARED_X)
    result = run_scene(s)
    output.write_outputs(result, tmp_path, figures=False)
    assert read_csv(tmp_path / "pressure.csv") == expected_curve_csv(result, "pressure")
    auto = parse_scene_text(EVERY_FIELD.replace(', "subsurface"', "").split("grid =")[0])
    result = run_scene(auto)
    output.write_outputs(result, tmp_path / "auto", figures=False)
    for name in ("pressure", "shear", "sigma_xx"):
        assert read_csv(tmp_path / "auto" / f"{name}.csv") == expected_curve_csv(result, name)


def test_long_sweep_prints_its_first_and_last_cases_and_extremes():
    n = TABLE_ROWS + 20
    result = run_scene(load_sweep(n))
    lines = format_table(result).splitlines()
    header = next(k for k, line in enumerate(lines) if line.split()[:1] == ["case"])
    body = [line.split() for line in lines[header + 1:header + 1 + TABLE_ROWS + 3]]
    half = TABLE_ROWS // 2
    assert [r[0] for r in body] == ([str(k) for k in range(half)] + ["..."]
                                    + [str(k) for k in range(n - half, n)] + ["min", "max"])
    x_left = [res.entry["ends"][0] for res in result.cases]
    col = lines[header].split().index("x_left")
    assert body[-2][col] == f"{min(x_left):.10g}" and body[-1][col] == f"{max(x_left):.10g}"
    assert f"(20 of {n} cases not shown" in lines[header + TABLE_ROWS + 4]
    assert lines[-1].startswith(f"  total time {result.timing_s:.3f} s for {n} case(s)")


def test_long_sweep_min_and_max_are_each_columns_extreme_printed_values():
    """The min and max rows of a long sweep: for each column, the smallest and largest value
    printed in it over every case, taken here from the case entries and formatted as the
    table prints them (exponents to 8 significant digits, SIFs and stresses 6; the flat
    punch's ends do not move, the cylinder's are checked above)."""
    n = TABLE_ROWS + 8
    speeds = ", ".join(repr(0.9 * k / n) for k in range(n))
    result = run_scene(parse_scene_text(textwrap.dedent(f"""
        [material]
        preset = "zhou2014"
        [punch]
        kind = "flat"
        half_width = 1.0
        [motion]
        load = 0.01
        speed = [{speeds}]
        friction = 0.3
        [outputs]
        fields = ["ends", "exponents", "pressure", "sigma_xx", "sif"]
        x = {{ start = -2.0, stop = 2.0, num = 81 }}
        """)))
    entries = [res.entry for res in result.cases]
    printed = {
        "alpha": [f"{e['exponents']['right']:.8g}" for e in entries],
        "beta": [f"{e['exponents']['left']:.8g}" for e in entries],
        "K_left": [f"{e['sif']['left']:.6g}" for e in entries],
        "K_right": [f"{e['sif']['right']:.6g}" for e in entries],
        "max p (sampled)": [f"{np.nanmax(e['pressure']['values']):.6g}" for e in entries],
        "min sigma_xx": [f"{np.nanmin(e['sigma_xx']['values']):.6g}" for e in entries],
        "max sigma_xx": [f"{np.nanmax(e['sigma_xx']['values']):.6g}" for e in entries]}
    lines = format_table(result).splitlines()
    header = next(k for k, line in enumerate(lines) if line.split()[:1] == ["case"])
    # the column names hold spaces: cells are found by where their column ends
    ends = {name: lines[header].index(name) + len(name) for name in printed}

    def cell(line, name):
        return line[:ends[name]].split()[-1]
    lowest, highest = lines[header + TABLE_ROWS + 2], lines[header + TABLE_ROWS + 3]
    assert lowest.split()[0] == "min" and highest.split()[0] == "max"
    for name, cells in printed.items():
        values = [float(c) for c in cells]
        assert len(set(values)) > 1, name                     # a column that varies
        assert cell(lowest, name) == cells[int(np.argmin(values))], name
        assert cell(highest, name) == cells[int(np.argmax(values))], name


@settings(max_examples=300, deadline=None)
@given(a=st.floats(allow_nan=False, allow_infinity=False),
       b=st.floats(allow_nan=False, allow_infinity=False),
       column=st.sampled_from(["x_left", "alpha", "K_right", "max p (sampled)", "check",
                               "time ms", "speed"]))
def test_printed_cells_round_monotonically(a, b, column):
    """A column's min and max are taken over its raw numbers and then printed: right only
    because every cell's format rounds monotonically (a <= b: cell(a) reads <= cell(b))."""
    lo, hi = sorted((a, b))
    assert float(table_cell(column, lo)) <= float(table_cell(column, hi))


def test_long_sweep_table_from_the_workers_texts_is_the_same(tmp_path):
    """The printed table of a long sweep made from the rows the workers send (lean texts,
    a chunk at a time) equals format_table of the kept results: first and last cases, and
    each column's extremes over every case."""
    s = load_sweep(TABLE_ROWS + 60)
    expected = untimed_table(format_table(run_scene(s)))
    with SceneWriter(s, tmp_path / "out", s.case_count, figures=False) as writer, \
            ProcessPoolExecutor(2) as ex:
        assert writer.encoder().lean
        run = iter_scene(s, executor=ex, encode=writer.encoder())
        for results in run.chunks():
            assert all(isinstance(res, CaseText) for res in results)
            writer.add_all(results)
        assert untimed_table(writer.table(1.0)) == expected
    assert any(line.split()[:1] == ["min"] for line in expected)


# --------------------------------------------------------------------------
# order, window, failures
# --------------------------------------------------------------------------
def test_scene_order_kept_when_chunks_finish_out_of_order(monkeypatch):
    """Case 3 (the first sent to the pool) is slow, so later chunks finish first: the results
    still come in scene order, and no more than the window (CHUNKS_AHEAD full chunks per
    worker) is handed out past the first case not yet delivered."""
    monkeypatch.setattr(batch, "chunk_size", lambda n, workers, per_case: 4)
    monkeypatch.setattr(batch, "CHUNKS_AHEAD", 2)
    monkeypatch.setattr(batch, "_PROBE", 3)
    window = 2 * 2 * 4
    finished, lock = [], threading.Lock()

    def solve(cases):
        out = []
        for case in cases:
            if case.index == 3:
                time.sleep(0.2)
            with lock:
                finished.append(case.index)
            out.append(-case.index)
        return out

    class Source:
        """300 cases; records the highest index handed out to a worker."""
        case_count = 300
        handed = 0

        def iter_cases(self, start=0, stop=None):
            stop = self.case_count if stop is None else stop
            with lock:
                self.handed = max(self.handed, stop)
            return (FakeCase(i, "m", float(i % 5), {}) for i in range(start, stop))

    source = Source()
    delivered, ahead = [], 0
    with ThreadPoolExecutor(2) as ex:
        for index, res in batch.iter_chunked(solve, source, ex, lambda k: None):
            ahead = max(ahead, source.handed - len(delivered))
            delivered.append(index)
            assert res == -index
    assert delivered == list(range(300))
    assert finished != sorted(finished)                      # out of order, delivered in order
    assert finished.index(3) > 3 + window // 2
    assert ahead <= window


def run_cases_failing_at_5_and_9(cases):
    """run_cases, but cases 5 and 9 fail as the library does (a module-level function: the
    worker processes of a pool forked from the test find it)."""
    return [contact.LoadError(f"case {c.index} fails") if c.index in (5, 9) else r
            for c, r in zip(cases, _run_cases(cases))]


_run_cases = run_module.run_cases


@pytest.mark.parametrize("jobs", [1, 2])
def test_first_failing_case_is_reported_and_nothing_written(tmp_path, monkeypatch, jobs):
    monkeypatch.setattr(run_module, "run_cases", run_cases_failing_at_5_and_9)
    path = tmp_path / "scene.toml"
    path.write_text(SHARED_X.replace("[0.0, 0.1, 0.2, 0.3]", "[0.0, 0.1, 0.2, 0.3, 0.4, 0.5]"))
    s = parse_scene_text(path.read_text(), source=str(path))
    pool = ProcessPoolExecutor(2) if jobs == 2 else contextlib.nullcontext()
    with pool as ex:
        run = iter_scene(s, executor=ex)
        got = []
        with pytest.raises(CaseError, match=r"scene.toml: case 5 \(speed = 0.3, friction = 0.5, "
                                            r".*LoadError: case 5 fails"):
            for res in run:
                got.append(res.index)
    assert got == [0, 1, 2, 3, 4]
    rc, stdout, err = run_cli("run", path, "--out", tmp_path / "out", "--jobs", jobs)
    assert rc == 1 and "case 5 (speed = 0.3, friction = 0.5" in err and "Traceback" not in err
    assert not (tmp_path / "out").exists()                   # nothing half-written is left
    (tmp_path / "kept").mkdir()
    rc, _, _ = run_cli("run", path, "--out", tmp_path / "kept", "--quiet", "--jobs", jobs)
    assert rc == 1 and list((tmp_path / "kept").iterdir()) == []


def test_run_scene_is_the_stream_collected():
    s = parse_scene_text(SHARED_X)
    run = iter_scene(s)
    streamed = list(run)
    collected = run_scene(s)
    assert [r.index for r in streamed] == list(range(s.case_count))
    assert [repr(r.entry) for r in streamed] == [repr(r.entry) for r in collected.cases]
    assert run.warnings == collected.warnings and run.timing_s > 0


# --------------------------------------------------------------------------
# memory
# --------------------------------------------------------------------------
def traced_peak(fn):
    tracemalloc.start()
    try:
        fn()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def memory_peaks(tmp_path) -> tuple:
    """(streamed N, streamed 4N, kept N, kept 4N): the peaks traced while N = 100 and 400
    cases are streamed into a SceneWriter (the lower of two runs each: numpy's and Python's
    allocators move the peak of identical runs by ~10 kB) and kept by run_scene, after a
    warm-up run (imports, the solver's caches)."""
    def streamed(s):
        run = iter_scene(s)
        with SceneWriter(s, tmp_path / f"out{s.case_count}", s.case_count,
                         figures=False) as writer:
            for res in run:
                writer.add(res)
            writer.finish(run.timing_s, run.warnings)
    n = 100
    few, many = load_sweep(n), load_sweep(4 * n)
    streamed(many)
    small = min(traced_peak(lambda: streamed(few)) for _ in range(2))
    large = min(traced_peak(lambda: streamed(many)) for _ in range(2))
    rows = read_csv(tmp_path / f"out{4 * n}" / "sweep.csv")
    assert len(rows) == 4 * n + 1 and rows[-1][0] == str(4 * n - 1)
    return small, large, traced_peak(lambda: run_scene(few)), traced_peak(lambda: run_scene(many))


#: memory_peaks in a fresh interpreter, SERIAL_CHUNK = 25 (results held at once: at most this)
_PEAKS_CHILD = """
import json, sys
from pathlib import Path
sys.path[:0] = [sys.argv[1]]
from contact.scene import batch
batch.SERIAL_CHUNK = 25
from test_scene_stream import memory_peaks
print(json.dumps(memory_peaks(Path(sys.argv[2]))))
"""


@pytest.mark.slow
def test_memory_does_not_grow_with_the_sweep(tmp_path):
    """Keeping the results, as run_scene does, costs ~1.7 kB per case: ~500 kB more at 4N
    cases than at N.  Streaming them into the writers (the scenes, and their lists of swept
    values, made beforehand; the results of one chunk, at most SERIAL_CHUNK, held at a time)
    peaks less than a tenth of that higher at 4N: ~25 kB measured, what the allocators and
    the file buffers move; a result kept per case would show as 1.7 kB a case.  Measured in
    a fresh interpreter: in the one running the whole suite, what other tests left behind
    (threads of a Dask cluster, caches, the collector's state) moved both streamed peaks by
    70-130 kB once."""
    proc = subprocess.run([sys.executable, "-c", _PEAKS_CHILD, str(ROOT / "tests" / "scene"),
                           str(tmp_path)], env=child_env(), capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode == 0, proc.stderr[-3000:]
    small, large, kept_small, kept_large = json.loads(proc.stdout.splitlines()[-1])
    assert kept_large - kept_small > 300 * 100              # the measure sees growth
    assert large - small < 0.1 * (kept_large - kept_small), (small, large, kept_small,
                                                             kept_large)


# --------------------------------------------------------------------------
# outputs encoded where the cases are solved
# --------------------------------------------------------------------------
@pytest.mark.parametrize("quiet", [False, True])
@pytest.mark.parametrize("fields", [["ends", "exponents", "sif", "pressure"],
                                    ["zones", "sif"], ["ends", "constants"]])
def test_cases_encoded_by_the_workers_write_the_same_files(tmp_path, fields, quiet):
    """A writer's text of each case made where the case is solved (iter_scene's encode=,
    here by the workers of a pool) gives result.json and sweep.csv byte for byte as the
    writer's own formatting does (per-speed fields, "constants", join the entries in the
    parent: those cases are formatted there).  A writer that keeps nothing but the text
    and the printed table's rows (no curves) gets lean results (CaseText, with their rows),
    fed a chunk at a time: the printed table is the same too."""
    s = parse_scene_text(SHARED_X.replace('["ends", "exponents", "pressure"]',
                                          json.dumps(fields)))

    def write(out, encode, executor=None):
        with SceneWriter(s, out, s.case_count, figures=False, table=not quiet) as writer:
            encoder = writer.encoder() if encode else None
            assert encoder is None or encoder.lean == ("pressure" not in fields)
            run = iter_scene(s, executor=executor, encode=encoder)
            for results in run.chunks():
                for res in results:
                    encoded = encode and "constants" not in fields
                    if encoded and encoder.lean:              # the text alone
                        assert isinstance(res, CaseText) and res.label == s.case(res.index).label
                    else:
                        assert isinstance(res, CaseResult)
                        assert (res.encoded is not None) == encoded
                writer.add_all(results)
            table = None if quiet else untimed_table(writer.table(1.0))
            writer.finish(1.0, run.warnings)
        return table, {name: (out / name).read_bytes() for name in ("result.json", "sweep.csv")}
    plain = write(tmp_path / "plain", False)
    with ProcessPoolExecutor(2) as ex:
        assert write(tmp_path / "pool", True, ex) == plain
    assert write(tmp_path / "here", True) == plain


def untimed_table(text):
    """The printed table without what depends on the clock (its last column, the case's
    time, and the total)."""
    return [line.rsplit(None, 1)[0] for line in text.splitlines()
            if line.strip() and not line.startswith("  total time")]


@pytest.mark.slow
def test_chunks_are_sized_again_from_what_the_workers_took(monkeypatch):
    """The first cases, solved here while the process warms up, can take far longer than
    the rest: each finished chunk's time in its worker lowers the estimate, and the chunks
    after it grow (here: the probe takes 50 ms a case, the workers 1 ms)."""
    monkeypatch.setattr(batch, "_PROBE", 2)
    monkeypatch.setattr(batch, "CHUNKS_PER_WORKER", 1)
    slow_first = {"left": 2}

    def solve(cases):
        if slow_first["left"] > 0:
            slow_first["left"] -= len(cases)
            time.sleep(0.05 * len(cases))
        else:
            time.sleep(0.001 * len(cases))
        return [c.index for c in cases]

    class Source:
        case_count = 2000

        def iter_cases(self, start=0, stop=None):
            return (FakeCase(i, "m", 0.0, {}) for i in range(start, stop or self.case_count))

    sizes = []

    class Recording(ThreadPoolExecutor):
        def submit(self, fn, *args):
            sizes.append(args[3] - args[2])
            return super().submit(fn, *args)
    with Recording(1) as ex:
        got = [i for i, _ in batch.iter_chunked(solve, Source(), ex, lambda k: None)]
    assert got == list(range(2000))
    # TARGET_CHUNK_S / 50 ms = 4 cases a chunk at first; ~200 once a worker took 1 ms a case
    assert sizes[0] <= 4 and max(sizes) >= 100
