"""Chunked execution of a scene's cases (contact.scene.batch): chunk sizes, ranges of
indices built where they run, scene order and per-case errors through a process pool and a
Dask cluster, results identical to a serial run.  (Streaming -- results in order as they complete,
a bounded window, bounded memory -- is tested in test_scene_stream.py.)"""
from __future__ import annotations

import itertools
import math
import os
import sys
import time
from collections import namedtuple
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import contact
from contact.scene import load_scene, run_scene
from contact.scene import batch

FakeCase = namedtuple("FakeCase", "index material speed inputs")


class FakeSource:
    """What iter_chunked needs of a Scene: case_count and iter_cases(start, stop) (a
    module-level class: the worker processes of a pool unpickle it)."""

    def __init__(self, cases):
        self.cases = list(cases)
        self.case_count = len(self.cases)

    def iter_cases(self, start=0, stop=None):
        return iter(self.cases[start:stop])


def fake_cases(n, speeds=(0.0, 0.3)):
    per = n // len(speeds)
    return FakeSource(FakeCase(i, "m", speeds[min(i // per, len(speeds) - 1)], {"speed": 0.0})
                      for i in range(n))


def indices(cases):
    """A chunk function (what run_cases is to a scene): each case's index."""
    return [case.index for case in cases]


def double_or_fail(cases):
    """A chunk function: twice each index, and the library's error in place of cases 5 and
    9 (as run_cases returns a failing case)."""
    return [contact.LoadError(f"case {c.index} fails") if c.index in (5, 9) else 2 * c.index
            for c in cases]


def test_chunk_size_targets_the_time_and_the_balance():
    # 1 ms per case: TARGET_CHUNK_S / 1 ms per chunk by time, for a long sweep
    assert batch.chunk_size(10**6, 2, 1e-3) == int(batch.TARGET_CHUNK_S / 1e-3)
    # 1000 cases on 2 workers allow 125 by balance (CHUNKS_PER_WORKER = 4)
    assert batch.chunk_size(1000, 2, 1e-3) == min(125, int(batch.TARGET_CHUNK_S / 1e-3))
    # a slow case: one per chunk
    assert batch.chunk_size(1000, 2, 1.0) == 1
    # few cases: at least CHUNKS_PER_WORKER chunks per worker
    assert batch.chunk_size(16, 2, 1e-5) == 2
    assert batch.chunk_size(1, 8, 1e-5) == 1


def test_chunks_are_consecutive_ranges_built_by_the_worker(monkeypatch):
    """After the probe (three cases here), the rest goes out as consecutive ranges of
    chunk_size cases, shorter toward the end (tail_size); each worker builds its cases from
    the source."""
    monkeypatch.setattr(batch, "chunk_size", lambda n, workers, per_case: 4)
    monkeypatch.setattr(batch, "_PROBE", 3)
    ex = _InlineExecutor()
    got = list(batch.iter_chunked(indices, fake_cases(30), ex, lambda k: None))
    # 27 left on 2 workers: 4 while ceil(left / 4) >= 4 (27, 23, 19, 15 left), then
    # ceil(left / 4): 11 -> 3, 8 -> 2, 6 -> 2, then one at a time
    assert ex.ranges == [(3, 7), (7, 11), (11, 15), (15, 19), (19, 22), (22, 24), (24, 26),
                         (26, 27), (27, 28), (28, 29), (29, 30)]
    assert got == [(i, i) for i in range(30)]


@pytest.mark.parametrize("size, left, workers", [(540, 9997, 2), (1, 50, 2), (100, 7, 16),
                                                 (64, 10**5, 16), (8, 9, 1)])
def test_tail_chunks_shrink_and_cover_every_case(size, left, workers):
    """Guided self-scheduling: the chunk sizes never grow, never exceed ``size`` nor fall below
    size / TAIL_SPLIT**3 (except the very last cases), and add up to the cases left; the last
    chunk holds no more than its share of the last round."""
    sizes = []
    while left > 0:
        k = batch.tail_size(size, left, workers)
        sizes.append(k)
        left -= k
    assert sizes == sorted(sizes, reverse=True) and sizes[0] <= size
    floor = max(1, size // batch.TAIL_SPLIT ** 3)
    assert all(k >= floor for k in sizes[:-1])
    assert sizes[-1] <= max(floor, math.ceil(size / batch.TAIL_SPLIT))


def test_scene_cases_by_index_equal_the_sweep():
    """Scene.case(i) (a mixed-radix digit per swept key) and iter_cases(start, stop) build the
    same cases as the whole sweep, in its order; an index outside the sweep is refused."""
    s = _sweep_three_keys()
    every = s.cases()
    assert [c.index for c in every] == list(range(s.case_count)) and s.case_count == 12
    assert all(s.case(i) == c for i, c in enumerate(every))
    assert list(s.iter_cases(5, 9)) == every[5:9]
    assert list(s.iter_cases(10, 99)) == every[10:]
    for bad in (-1, 12, 1.0, True):
        with pytest.raises(IndexError, match=r"case index must be in \[0, 12\)"):
            s.case(bad)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.integers(1, 4), min_size=0, max_size=4), st.permutations(range(4)))
def test_case_by_index_is_the_cartesian_product(lengths, order):
    """Any number of swept keys in any order, any lengths: case i carries the i-th point of
    itertools.product of the swept lists (the first swept key varying slowest), and the
    ranges of iter_cases cut that sequence without a gap or an overlap."""
    from contact.scene import parse_scene_text
    keys = [("speed", 0.1), ("friction", 0.05), ("load", 0.01), ("radius", 50.0)]
    keys = [keys[k] for k in order][:len(lengths)]
    swept = {key: [step * (j + 1) for j in range(m)] for (key, step), m in zip(keys, lengths)}
    motion = "".join(f"{k} = {swept[k]}\n" for k, _ in keys if k != "radius")
    radius = swept.get("radius", 100.0)
    s = parse_scene_text(f'title = "t"\n[material]\npreset = "zhou2014"\n[punch]\n'
                         f'kind = "cylindrical"\nradius = {radius}\n[motion]\n'
                         f'{motion if "load" in swept else motion + "load = 0.01" + chr(10)}'
                         '[outputs]\nfields = ["ends"]\n')
    names = [key for _, key in s.sweep]
    expected = list(itertools.product(*(swept[k] for k in names)))
    assert s.case_count == len(expected)
    for i, point in enumerate(expected):
        case = s.case(i)
        assert case.index == i and tuple(case.inputs[k] for k in names) == point
    cut = sorted({0, s.case_count} | {len(expected) // 3, len(expected) // 2})
    pieces = [c.index for a, b in zip(cut[:-1], cut[1:]) for c in s.iter_cases(a, b)]
    assert pieces == list(range(s.case_count))


def test_punch_specs_are_the_distinct_punches_of_the_sweep():
    """What the scene checks at parse time: each punch once, those of the cases in order."""
    s = _sweep_three_keys()
    specs = list(s.punch_specs())
    assert len(specs) == 2 and specs == list(dict.fromkeys(c.punch for c in s.cases()))


def _sweep_three_keys():
    from contact.scene import parse_scene_text
    return parse_scene_text(
        'title = "t"\n[material]\npreset = "zhou2014"\n[punch]\nkind = "cylindrical"\n'
        'radius = [100.0, 50.0]\n[motion]\nload = 0.01\nspeed = [0.0, 0.3]\n'
        'friction = [0.0, 0.1, 0.2]\n[outputs]\nfields = ["ends"]\n')


@pytest.mark.parametrize("pool", ["serial", "threads", "processes"])
def test_first_failure_in_scene_order_ends_the_results(pool):
    cases = fake_cases(40)
    if pool == "serial":
        got = list(batch.iter_chunked(double_or_fail, cases, None, lambda k: None))
    else:
        make = ThreadPoolExecutor if pool == "threads" else ProcessPoolExecutor
        with make(2) as ex:
            got = list(batch.iter_chunked(double_or_fail, cases, ex, lambda k: None))
    assert [i for i, _ in got] == list(range(6))            # in order, up to the failure
    assert all(res == 2 * i for i, res in got[:5])
    assert isinstance(got[5][1], contact.LoadError)


@pytest.mark.parametrize("pool", ["serial", "processes"])
def test_chunks_come_whole_and_the_failing_one_is_cut_after_its_failure(pool, monkeypatch):
    """iter_chunks delivers lists of (index, result), in scene order and without gaps; the
    chunk that holds the first failure ends with it; none comes after it."""
    monkeypatch.setattr(batch, "_PROBE", 4)
    monkeypatch.setattr(batch, "SERIAL_CHUNK", 3)
    cases = fake_cases(40)
    if pool == "serial":
        chunks = list(batch.iter_chunks(double_or_fail, cases, None, lambda k: None))
    else:
        with ProcessPoolExecutor(2) as ex:
            chunks = list(batch.iter_chunks(double_or_fail, cases, ex, lambda k: None))
    assert all(isinstance(c, list) and c for c in chunks)
    flat = [i for chunk in chunks for i, _ in chunk]
    assert flat == list(range(6))
    assert isinstance(chunks[-1][-1][1], contact.LoadError)
    assert not any(isinstance(res, Exception) for chunk in chunks[:-1] for _, res in chunk)
    if pool == "serial":                         # the first case, then SERIAL_CHUNK a time
        assert [len(c) for c in chunks] == [1, 3, 2]
    else:                                        # the probe: the first case, then the rest
        assert [len(c) for c in chunks[:2]] == [1, 3]


def test_progress_counts_cases():
    counted = []
    cases = fake_cases(12)
    with ThreadPoolExecutor(2) as ex:
        list(batch.iter_chunked(indices, cases, ex, counted.append))
    assert sum(counted) == 12


def test_serial_runs_chunks_of_cases(monkeypatch):
    """Without an executor the cases still go to the chunk function in chunks (solved
    together): the first case alone (it warms the process up), then as many as
    TARGET_CHUNK_S of work holds, SERIAL_CHUNK at most; delivered in order."""
    monkeypatch.setattr(batch, "SERIAL_CHUNK", 7)
    seen = []

    def record(cases):
        seen.append([c.index for c in cases])
        return indices(cases)
    got = list(batch.iter_chunked(record, fake_cases(20), None, lambda k: None))
    assert got == [(i, i) for i in range(20)]
    assert seen == [[0], list(range(1, 8)), list(range(8, 15)), list(range(15, 20))]
    # slow cases: chunks of one, the progress moves with each case
    seen.clear()

    def slow(cases):                        # a case takes as long as a chunk should
        time.sleep(batch.TARGET_CHUNK_S * len(cases))
        return record(cases)
    monkeypatch.setattr(batch, "TARGET_CHUNK_S", 0.01)
    list(batch.iter_chunked(slow, fake_cases(6), None, lambda k: None))
    assert [len(c) for c in seen] == [1] * 6


def test_worker_count():
    with ProcessPoolExecutor(3) as ex:
        assert batch.worker_count(ex) == 3
    assert batch.worker_count(object()) == 1


Text = namedtuple("Text", "index json row")


@pytest.mark.parametrize("items", [
    [(7, Text(7, '{"a": 1}', "7,1\r\n")), (8, Text(8, "{}", "8,\r\n"))],
    [(3, Text(3, "x", "y")), (4, contact.LoadError("case 4 fails"))],      # not all texts
    [(3, Text(3, "x", "y")), (4, contact.LoadError("case 4")), (5, Text(5, "z", "w"))],
    [(0, 0), (1, 2)],                                                     # not named tuples
    []])
def test_chunk_results_cross_a_column_at_a_time_and_come_back_equal(items):
    """A chunk of one named tuple type is pickled as its columns (one reduce for the chunk,
    none per case) and made again as the same tuples of the same type, known to hold no
    failure without a look at its cases; any other chunk is pickled as it is.  Either way
    the chunk names its first failing case and is cut after it."""
    import pickle
    chunk = batch.ChunkResults(items, 0.25)
    reduced = chunk.__reduce__()
    by_columns = bool(items) and all(type(r) is Text for _, r in items)
    assert (reduced[0] is batch._from_columns) == by_columns
    back = pickle.loads(pickle.dumps(chunk))
    assert back.seconds == 0.25 and [i for i, _ in back.items] == [i for i, _ in items]
    for (_, a), (_, b) in zip(items, back.items):
        assert type(a) is type(b) and (a == b if not isinstance(a, Exception) else
                                       str(a) == str(b))
    first_failure = next((i for i, r in items if isinstance(r, Exception)), None)
    assert back.failed == chunk.failed == first_failure
    if by_columns:
        assert back._failed is None                       # known on arrival: nothing scanned
    kept, failed = back.up_to_failure()
    assert failed == (first_failure is not None)
    assert [i for i, _ in kept] == [i for i, _ in items
                                    if first_failure is None or i <= first_failure]


def test_which_executors_are_warmed_up_by_this_process():
    """The probe (cases solved here first) warms workers that are this process's threads or
    forks; a pool of spawned processes or a Dask cluster's workers warm up on their own."""
    import multiprocessing
    assert batch._warms_workers(ThreadPoolExecutor(1))
    assert batch._warms_workers(_InlineExecutor())                   # unknown: as before
    fork = ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("fork"))
    spawn = ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn"))
    assert batch._warms_workers(fork) and not batch._warms_workers(spawn)
    fork.shutdown(), spawn.shutdown()


class _OwnProcesses(ThreadPoolExecutor):
    """Threads that pass for a pool of spawned processes (batch._warms_workers is False);
    records each submission's range and how many chunks had come back before it."""
    import multiprocessing
    _mp_context = multiprocessing.get_context("spawn")

    def __init__(self, workers):
        super().__init__(workers)
        self.submitted, self.finished = [], 0

    def submit(self, fn, *args):
        self.submitted.append((args[2], args[3], self.finished))
        fut = super().submit(fn, *args)
        fut.add_done_callback(lambda f: setattr(self, "finished", self.finished + 1))
        return fut


def test_workers_of_their_own_get_a_first_chunk_each_then_sized_ones(monkeypatch):
    """Nothing is solved here when the workers do not inherit this process: each worker
    gets a first chunk of _PROBE // 2 cases, no more goes out until one of them is back,
    and the chunks after it are sized from its time; every case delivered in order."""
    import threading
    monkeypatch.setattr(batch, "_PROBE", 6)
    here = threading.get_ident()
    solved_here = []

    def solve(cases):
        solved_here.extend(c.index for c in cases if threading.get_ident() == here)
        time.sleep(1e-3 * len(cases))
        return [c.index for c in cases]
    with _OwnProcesses(2) as ex:
        got = list(batch.iter_chunked(solve, fake_cases(400, speeds=(0.0,)), ex,
                                      lambda k: None))
    assert got == [(i, i) for i in range(400)] and not solved_here
    assert [s[:2] for s in ex.submitted[:2]] == [(0, 3), (3, 6)]
    assert ex.submitted[2][2] >= 1                  # the third after a first chunk came back
    sizes = [stop - start for start, stop, _ in ex.submitted]
    assert max(sizes) > 3


class _GrowingCluster:
    """A Dask client's executor in miniature: its workers are 16 threads, counted by its
    client's ``nthreads()``, which reports one worker at the first count and all 16 after
    (a cluster that grows while the sweep runs); records how many chunks ran at once."""

    def __init__(self):
        import threading
        self._pool = ThreadPoolExecutor(16)
        self._client = self
        self._lock = threading.Lock()
        self.counts = self.running = self.most_running = 0

    def nthreads(self):
        self.counts += 1
        return {f"worker-{k}": 1 for k in range(1 if self.counts == 1 else 16)}

    def submit(self, fn, *args):
        def tracked():
            with self._lock:
                self.running += 1
                self.most_running = max(self.most_running, self.running)
            try:
                return fn(*args)
            finally:
                with self._lock:
                    self.running -= 1
        return self._pool.submit(tracked)


def test_a_cluster_that_grows_during_the_sweep_gets_work_for_all_its_workers(monkeypatch):
    """The sweep starts on a cluster of one worker, which then has 16: they are counted again
    as chunks come back, and more than the 8 chunks that one worker is handed ahead run at
    once; every case delivered in order."""
    monkeypatch.setattr(batch, "RECOUNT_S", 0.0)

    def solve(cases):
        time.sleep(2e-3 * len(cases))
        return [c.index for c in cases]
    ex = _GrowingCluster()
    with ex._pool:
        got = list(batch.iter_chunked(solve, fake_cases(2000, speeds=(0.0,)), ex,
                                      lambda k: None))
    assert got == [(i, i) for i in range(2000)]
    assert ex.counts >= 2 and ex.most_running > batch.CHUNKS_AHEAD


class _ClosedClient:
    """A Dask client's executor whose client has closed (its scheduler gone): what it was
    handed never comes back."""
    status = "closed"
    scheduler = namedtuple("Rpc", "address")("tcp://10.0.0.1:8786")

    def __init__(self):
        self._client = self

    def nthreads(self):
        return {"worker-0": 1}

    def submit(self, fn, *args):
        from concurrent.futures import Future
        return Future()                                 # never done


def test_a_cluster_whose_client_has_closed_ends_the_sweep_with_its_address(monkeypatch):
    """Chunks handed to a Dask client that has lost its scheduler never come back: the sweep
    looks at the client when none has come back for WAIT_S and ends with a ConnectionError
    naming the scheduler, instead of waiting forever."""
    monkeypatch.setattr(batch, "WAIT_S", 0.01)
    with pytest.raises(ConnectionError, match="lost the Dask scheduler at tcp://10.0.0.1:8786"):
        list(batch.iter_chunked(indices, fake_cases(40), _ClosedClient(), lambda k: None))


def _sweep():
    return load_scene(contact.scene.__file__.replace("__init__.py", "") +
                      "../../validation/scenes/fig4a_cylindrical_speed.toml")


def test_process_pool_equals_serial_in_scene_order():
    s = _sweep()
    serial = run_scene(s)
    with ProcessPoolExecutor(2) as ex:
        pooled = run_scene(s, executor=ex)
    assert [c.index for c in pooled.cases] == [c.index for c in serial.cases]
    for a, b in zip(serial.cases, pooled.cases):
        assert repr(a.entry) == repr(b.entry)


@pytest.mark.slow
def test_dask_local_cluster_equals_serial():
    distributed = pytest.importorskip("distributed")
    s = _sweep()
    serial = run_scene(s)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        ex = client.get_executor(pure=False)
        assert batch.worker_count(ex) == 2 and not batch._warms_workers(ex)
        got = run_scene(s, executor=ex)
    for a, b in zip(serial.cases, got.cases):
        assert repr(a.entry) == repr(b.entry)


class GcOnSource(FakeSource):
    """A FakeSource that records, as each case is built, whether the collector is on."""

    def iter_cases(self, start=0, stop=None):
        import gc
        for case in super().iter_cases(start, stop):
            yield case._replace(inputs={"gc": gc.isenabled()})


def gc_states(cases):
    """A chunk function: whether the collector was on as each case was built, and now."""
    import gc
    return [(case.inputs["gc"], gc.isenabled()) for case in cases]


def collector_on(_):
    """Whether this process's collector is on (a task for each of a pool's workers)."""
    import gc
    time.sleep(0.02)
    return gc.isenabled()


def test_a_chunk_runs_with_the_collector_paused_its_cases_built_included():
    """run_chunk (a worker's run_range, the serial path) pauses the cyclic collector while
    the chunk's cases are built and solved, and leaves it on after."""
    import gc
    assert gc.isenabled()
    items = batch.run_range(gc_states, GcOnSource(fake_cases(6).cases), 1, 5).items
    assert items == [(i, (False, False)) for i in range(1, 5)]
    assert gc.isenabled()


@pytest.mark.filterwarnings("ignore:This process .* is multi-threaded:DeprecationWarning")
def test_a_fork_pool_that_ran_a_scene_keeps_its_collector():
    """run_scene pauses the collector while it collects the results, and a pool's workers
    are forked from inside that pause: a user's pool is left with its workers' collector on
    for whatever it runs next."""
    import gc
    import multiprocessing
    from contact.scene import parse_scene_text
    scene = parse_scene_text(                   # more cases than the probe solved here
        'title = "t"\n[material]\npreset = "zhou2014"\n[punch]\nkind = "cylindrical"\n'
        'radius = 100.0\n[motion]\nload = 0.01\nspeed = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5]\n'
        'friction = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5]\n[outputs]\nfields = ["ends"]\n')
    assert scene.case_count > 2 * batch._PROBE
    with ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("fork")) as ex:
        run_scene(scene, executor=ex)
        assert all(ex.map(collector_on, range(8)))
    assert gc.isenabled()


def test_built_specs_are_shared():
    s = _sweep()
    c0, c1 = s.cases()[:2]
    assert batch.build_once(c0.material) is batch.build_once(c1.material)
    assert batch.build_once(c0.punch) is batch.build_once(c1.punch)


@pytest.mark.slow
def test_separate_scheduler_and_worker_processes(tmp_path):
    """`dask scheduler` and a `dask worker` process started as separate commands on
    127.0.0.1, `contact run --scheduler` sent to them: the result equals the serial run.
    The command is started before the worker: it says that it waits for one.  (Work
    shared between several workers is tested on a LocalCluster of 2 in test_cli and
    test_bench_sweep; a second worker process here would only add its start-up.)"""
    distributed = pytest.importorskip("distributed")
    import json
    import socket
    import subprocess
    import sys
    from pathlib import Path
    dask_cli = Path(sys.executable).with_name("dask")
    if not dask_cli.exists():
        pytest.skip("the dask command is not installed beside this Python")
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port = sock.getsockname()[1]
    address = f"tcp://127.0.0.1:{port}"
    quiet = dict(stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=tmp_path)
    procs = [subprocess.Popen([str(dask_cli), "scheduler", "--host", "127.0.0.1", "--port",
                               str(port), "--dashboard-address", ":0"], **quiet)]
    try:
        with distributed.Client(address, timeout="60s"):
            pass                                            # the scheduler is up
        scene = Path(contact.scene.__file__).parents[2] / "validation/scenes/fig4a_cylindrical_speed.toml"
        err = tmp_path / "stderr.txt"
        with open(err, "w") as fh:
            run = subprocess.Popen([sys.executable, "-m", "contact", "run", str(scene), "--out",
                                    str(tmp_path / "cluster"), "--quiet", "--scheduler",
                                    address], stdout=subprocess.DEVNULL, stderr=fh)
        procs.append(run)
        deadline = time.monotonic() + 120
        while "no workers yet" not in err.read_text() and run.poll() is None \
                and time.monotonic() < deadline:
            time.sleep(0.05)
        assert err.read_text().startswith(f"contact: --scheduler {address} has no workers yet")
        procs.append(subprocess.Popen([str(dask_cli), "worker", address, "--nworkers", "1",
                                       "--nthreads", "1", "--no-dashboard"], **quiet))
        assert run.wait(timeout=300) == 0, err.read_text()
    finally:
        for p in reversed(procs):
            p.terminate()
        for p in procs:
            try:
                p.wait(timeout=30)
            except subprocess.TimeoutExpired:
                p.kill()
    got = json.loads((tmp_path / "cluster" / "result.json").read_text())["cases"]
    serial = run_scene(_sweep()).to_json()["cases"]
    assert json.dumps(got, sort_keys=True) == json.dumps(json.loads(json.dumps(serial, default=_plain)), sort_keys=True)


def _plain(o):
    import numpy as np
    return o.tolist() if isinstance(o, np.ndarray) else float(o)


class _InlineExecutor:
    """An executor that runs each task at submit (every chunk is done before it is awaited)
    and records the ranges of cases handed out."""
    _max_workers = 2

    def __init__(self):
        self.ranges = []

    def submit(self, fn, *args):
        from concurrent.futures import Future
        self.ranges.append(args[2:])
        fut = Future()
        fut.set_result(fn(*args))
        return fut


def test_every_case_delivered_when_the_window_empties_at_once(monkeypatch):
    """All cases read so far delivered in one go (every chunk already done): reading goes on
    to the end of the sweep instead of stopping at the first window."""
    monkeypatch.setattr(batch, "chunk_size", lambda n, workers, per_case: 4)
    monkeypatch.setattr(batch, "CHUNKS_AHEAD", 1)
    got = list(batch.iter_chunked(indices, fake_cases(100, speeds=(0.0,)),
                                  _InlineExecutor(), lambda k: None))
    assert got == [(i, i) for i in range(100)]


def _pipe_max_size() -> int:
    with open("/proc/sys/fs/pipe-max-size") as fh:
        return int(fh.read())


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="F_SETPIPE_SZ is Linux's")
def test_iter_chunks_widens_a_pools_result_pipe():
    """Once iter_chunks has run on a process pool, the pipe its workers send their results
    through holds RESULT_PIPE_BYTES (or this system's most, if less), not the default 64 kB."""
    import fcntl
    with ProcessPoolExecutor(2) as ex:
        got = list(batch.iter_chunked(indices, fake_cases(8), ex, lambda k: None))
        assert [i for i, _ in got] == list(range(8))
        size = fcntl.fcntl(ex._result_queue._reader.fileno(), fcntl.F_GETPIPE_SZ)
    assert size == min(batch.RESULT_PIPE_BYTES, _pipe_max_size()) > 64 * 1024


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="F_SETPIPE_SZ is Linux's")
def test_a_widened_result_pipe_takes_a_whole_chunk_without_a_reader():
    """A worker writes a chunk of results of ~0.9 MB into a widened result pipe in one go,
    nothing reading it (a 64 kB pipe would take 64 kB and block it), and the pipe gives back
    exactly what went in.  (A pool not started yet: no thread of its own reads the pipe.)"""
    if _pipe_max_size() < batch.RESULT_PIPE_BYTES:
        pytest.skip("this system's pipe-max-size is below RESULT_PIPE_BYTES")
    ex = ProcessPoolExecutor(1)
    try:
        assert batch.widen_result_pipe(ex) == batch.RESULT_PIPE_BYTES
        reader, writer = ex._result_queue._reader.fileno(), ex._result_queue._writer.fileno()
        message = bytes(range(256)) * (900_000 // 256)
        os.set_blocking(writer, False)
        try:
            assert os.write(writer, message) == len(message)    # no BlockingIOError
        finally:
            os.set_blocking(writer, True)
        back = b""
        while len(back) < len(message):
            back += os.read(reader, len(message) - len(back))
        assert back == message
    finally:
        ex.shutdown()


def test_only_a_process_pool_has_a_result_pipe_to_widen():
    assert batch.widen_result_pipe(None) is None
    with ThreadPoolExecutor(1) as ex:
        assert batch.widen_result_pipe(ex) is None


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="F_SETPIPE_SZ is Linux's")
def test_a_result_pipe_already_larger_is_not_shrunk(monkeypatch):
    """A pipe that already holds more than RESULT_PIPE_BYTES (here the default 64 kB
    against 16 kB asked) is left as it is."""
    import fcntl
    monkeypatch.setattr(batch, "RESULT_PIPE_BYTES", 16 * 1024)
    with ProcessPoolExecutor(1) as ex:
        fd = ex._result_queue._reader.fileno()
        before = fcntl.fcntl(fd, fcntl.F_GETPIPE_SZ)
        assert before > batch.RESULT_PIPE_BYTES
        assert batch.widen_result_pipe(ex) == before == fcntl.fcntl(fd, fcntl.F_GETPIPE_SZ)
