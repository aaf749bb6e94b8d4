"""Chunked execution of a scene's cases (contact.scene.batch): chunk sizes, grouping by
(material, speed), scene order and per-case errors through a process pool and a Dask
cluster, results identical to a serial run."""
from __future__ import annotations

from collections import namedtuple
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import pytest

import contact
from contact.scene import CaseError, load_scene, run_scene
from contact.scene import batch
from contact.scene.run import _map_in_order

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
    # 1 ms per case: 50 per chunk by time; 1000 cases on 2 workers allow 125 by balance
    assert batch.chunk_size(1000, 2, 1e-3) == 50
    # a slow case: one per chunk
    assert batch.chunk_size(1000, 2, 1.0) == 1
    # few cases: at least CHUNKS_PER_WORKER chunks per worker
    assert batch.chunk_size(16, 2, 1e-5) == 2
    assert batch.chunk_size(1, 8, 1e-5) == 1


def test_chunks_share_material_and_speed():
    cases = fake_cases(10, speeds=(0.0, 0.3))
    chunks = batch.chunks_of(cases, 3)
    assert [c.index for ch in chunks for c in ch] == list(range(10))
    assert all(len({(c.material, c.speed) for c in ch}) == 1 for ch in chunks)
    assert [len(ch) for ch in chunks] == [3, 2, 3, 2]       # a chunk ends where the speed changes
    # speed varying fastest (friction swept first): still full chunks of one speed
    mixed = [FakeCase(i, "m", (0.0, 0.3)[i % 2], {}) for i in range(10)]
    chunks = batch.chunks_of(mixed, 3)
    assert [[c.index for c in ch] for ch in chunks] == [[0, 2, 4], [6, 8], [1, 3, 5], [7, 9]]


@pytest.mark.parametrize("pool", ["serial", "threads", "processes"])
def test_first_failure_in_scene_order_is_reported(pool):
    cases = fake_cases(40)
    if pool == "serial":
        done = batch.map_chunked(double_or_fail, cases, None, lambda k: None)
        assert sorted(done) == list(range(6))          # stops at the first failure
    else:
        make = ThreadPoolExecutor if pool == "threads" else ProcessPoolExecutor
        with make(2) as ex:
            done = batch.map_chunked(double_or_fail, cases, ex, lambda k: None)
        assert all(done[i] == 2 * i for i in range(5))  # every case before it ran
        assert isinstance(done[5], contact.LoadError)

    class Scene:
        source = "s.toml"
    with pytest.raises(CaseError, match=r"s.toml: case 5 .*LoadError: case 5 fails"):
        _map_in_order(double_or_fail, cases, None, False, Scene())


def test_progress_counts_cases():
    counted = []
    cases = fake_cases(12)
    with ThreadPoolExecutor(2) as ex:
        batch.map_chunked(lambda c: c.index, cases, ex, counted.append)
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
