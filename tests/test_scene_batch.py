"""Chunked execution of a scene's cases (contact.scene.batch): chunk sizes, grouping by
material, scene order and per-case errors through a process pool and a Dask
cluster, results identical to a serial run.  (Streaming -- results in order as they complete,
a bounded window, bounded memory -- is tested in test_scene_stream.py.)"""
from __future__ import annotations

from collections import namedtuple
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import pytest

import contact
from contact.scene import load_scene, run_scene
from contact.scene import batch

FakeCase = namedtuple("FakeCase", "index material speed inputs")


def fake_cases(n, speeds=(0.0, 0.3)):
    per = n // len(speeds)
    return [FakeCase(i, "m", speeds[min(i // per, len(speeds) - 1)], {"speed": 0.0})
            for i in range(n)]


def double_or_fail(case):
    """Fails like the library for cases 5 and 9."""
    if case.index in (5, 9):
        raise contact.LoadError(f"case {case.index} fails")
    return 2 * case.index


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


def chunked(cases, size, lag=1000):
    """Every chunk batch.Chunker hands out for ``cases``, in the order it does."""
    chunker = batch.Chunker(size, lag)
    return [chunk for case in cases for chunk in chunker.add(case)] + chunker.flush()


def indices(chunks):
    return [[c.index for c in chunk] for chunk in chunks]


def test_chunks_share_the_material_in_scene_order():
    cases = fake_cases(10, speeds=(0.0, 0.3))
    chunks = sorted(chunked(cases, 3), key=lambda ch: ch[0].index)
    assert indices(chunks) == [[0, 1, 2], [3, 4, 5], [6, 7, 8], [9]]   # across the speeds
    # two materials interleaved: each chunk holds one, in scene order within it
    mixed = [FakeCase(i, ("m1", "m2")[i % 2], 0.0, {}) for i in range(10)]
    assert indices(chunked(mixed, 3)) == [[0, 2, 4], [1, 3, 5], [6, 8], [7, 9]]


def test_a_rare_key_is_cut_once_it_lags():
    """Case 0 alone with its material: its chunk is handed out once the newest case read is
    ``lag`` cases after it, not at the end."""
    cases = [FakeCase(0, "x", 0.3, {})] + [FakeCase(i, "m", 0.3, {}) for i in range(1, 9)]
    chunker = batch.Chunker(3, 4)
    out = [indices(chunker.add(case)) for case in cases]
    assert out == [[], [], [], [[1, 2, 3]], [[0]], [], [[4, 5, 6]], [], []]
    assert indices(chunker.flush(below=8)) == [[7]]         # after a failure at case 8


@pytest.mark.parametrize("pool", ["serial", "threads", "processes"])
def test_first_failure_in_scene_order_ends_the_results(pool):
    cases = fake_cases(40)
    if pool == "serial":
        got = list(batch.iter_chunked(double_or_fail, cases, None, lambda k: None, 40))
    else:
        make = ThreadPoolExecutor if pool == "threads" else ProcessPoolExecutor
        with make(2) as ex:
            got = list(batch.iter_chunked(double_or_fail, iter(cases), ex, lambda k: None, 40))
    assert [c.index for c, _ in got] == list(range(6))      # in order, up to the failure
    assert all(res == 2 * c.index for c, res in got[:5])
    assert isinstance(got[5][1], contact.LoadError)


def test_progress_counts_cases():
    counted = []
    cases = fake_cases(12)
    with ThreadPoolExecutor(2) as ex:
        list(batch.iter_chunked(lambda c: c.index, cases, ex, counted.append, 12))
    assert sum(counted) == 12


def test_worker_count():
    with ProcessPoolExecutor(3) as ex:
        assert batch.worker_count(ex) == 3
    assert batch.worker_count(object()) == 1


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


def test_dask_local_cluster_equals_serial():
    distributed = pytest.importorskip("distributed")
    s = _sweep()
    serial = run_scene(s)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        ex = client.get_executor(pure=False)
        assert batch.worker_count(ex) == 2
        got = run_scene(s, executor=ex)
    for a, b in zip(serial.cases, got.cases):
        assert repr(a.entry) == repr(b.entry)


def test_built_specs_are_shared():
    s = _sweep()
    c0, c1 = s.cases()[:2]
    assert batch.build_once(c0.material) is batch.build_once(c1.material)
    assert batch.build_once(c0.punch) is batch.build_once(c1.punch)


def test_separate_scheduler_and_worker_processes(tmp_path):
    """`dask scheduler` and two `dask worker` processes started as separate commands on
    127.0.0.1, `contact run --scheduler` sent to them: the result equals the serial run."""
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
        procs += [subprocess.Popen([str(dask_cli), "worker", address, "--nworkers", "1",
                                    "--nthreads", "1", "--no-dashboard"], **quiet)
                  for _ in range(2)]
        with distributed.Client(address, timeout="60s") as client:
            client.wait_for_workers(2, timeout=60)
        scene = Path(contact.scene.__file__).parents[2] / "validation/scenes/fig4a_cylindrical_speed.toml"
        out = subprocess.run([sys.executable, "-m", "contact", "run", str(scene), "--out",
                              str(tmp_path / "cluster"), "--quiet", "--scheduler", address],
                             capture_output=True, text=True, timeout=300)
        assert out.returncode == 0, out.stderr
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
    """An executor that runs each task at submit: every chunk is done before it is awaited."""
    _max_workers = 2

    def submit(self, fn, *args):
        from concurrent.futures import Future
        fut = Future()
        fut.set_result(fn(*args))
        return fut


def test_every_case_delivered_when_the_window_empties_at_once(monkeypatch):
    """All cases read so far delivered in one go (every chunk already done): reading goes on
    to the end of the sweep instead of stopping at the first window."""
    monkeypatch.setattr(batch, "chunk_size", lambda n, workers, per_case: 4)
    monkeypatch.setattr(batch, "CHUNKS_AHEAD", 1)
    cases = fake_cases(100, speeds=(0.0,))
    got = list(batch.iter_chunked(lambda c: c.index, iter(cases), _InlineExecutor(),
                                  lambda k: None, 100))
    assert [c.index for c, _ in got] == list(range(100))
    assert all(res == c.index for c, res in got)
