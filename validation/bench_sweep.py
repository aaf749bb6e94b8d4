"""``make bench`` (sweep part): how a scene's sweep scales, measured in one run.

Writes validation/out/bench_sweep.md.  The sweep: the paper's material, a cylindrical punch
(R = 100, P = 0.01), speeds x frictions asking ends, exponents and SIFs: 100 x 100 (the
issue's 1e4-case sweep) in process, with where its time goes; 316 x 316 (1e5 cases) through
the Python API (:func:`contact.scene.run_scene`, every result kept in the calling process)
on process pools and Dask clusters, against its own serial run (the 1e4 sweep takes well
under a second in process, where the fixed costs of a pool would weigh as much as the
parallel work).  Wall times (the pools and the cluster are wall-time objects), the shortest
of ``REPEATS`` runs of each configuration after a warm-up run; each row gives its ratio to
the serial run of the same build, which varies less between machines than the time itself.

Then ``contact run --quiet`` end to end (start-up, solving, writing result.json and
sweep.csv) on 1e5 cases, 5e4 a core on a machine of more cores (:func:`cli_side`):
``--jobs N`` for N up to the machine's cores against ``--jobs 1`` (the issue's measure), and
``--scheduler`` to a Dask LocalCluster of N worker processes against ``--jobs N``, with the
CPU time each run spent and where its wall time went (imports, to the first chunk of
results, the stream of chunks, writing, exit: :data:`_TIMED_CONTACT_RUN`), and the machine's
own ceiling for N workers: N processes solving the same cases at once with nothing passed
between them (:func:`processes_alone`), measured just before each ``--jobs N`` run: the
most any pool could reach there, at that time; and ``--jobs 1`` and ``--jobs N`` as the
command runs by default, the table printed and the progress bar drawn.  ``python -m
validation.bench_sweep --cli`` runs these rows alone (bench_sweep_cli.md): the table of a
machine with many cores.

Targets (issue "sweeps that scale"):

* ``contact run --jobs N`` at >= 0.8 N of ``--jobs 1``, >= 1.7x on 2 cores (the API's
  pools, whose calling process builds every result object, are held to the same figures);
* Dask (LocalCluster of N worker processes) within 15 % of the process pool at equal N;
* a 1e5-case sweep in bounded memory, writing its table: the peak resident size of
  ``contact run`` on 1e5 cases within 10 % of that on 1e4 (both stated);
* in process: the 1e4-case sweep in < 1 s (cases solved in batches: contact.solve_batch).
"""
from __future__ import annotations

import contextlib
import importlib.util
import itertools
import math
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

OUT = Path(__file__).resolve().parent / "out"


def _usable_cpus() -> int:
    """The CPUs this process may run on, as ``contact run --jobs 0`` counts them."""
    from contact.cli import usable_cpus
    return usable_cpus()


def sweep_toml(n_speed, n_friction, fields=("ends", "exponents", "sif")):
    speeds = ", ".join(repr(float(v)) for v in np.round(np.linspace(0.0, 0.9, n_speed), 6))
    frictions = ", ".join(repr(float(v)) for v in np.round(np.linspace(0.0, 0.5, n_friction), 6))
    return (f'title = "sweep {n_speed} x {n_friction}"\n[material]\npreset = "zhou2014"\n'
            f'[punch]\nkind = "cylindrical"\nradius = 100.0\n[motion]\nload = 0.01\n'
            f"speed = [{speeds}]\nfriction = [{frictions}]\n[outputs]\n"
            f"fields = {list(fields)!r}\n".replace("'", '"'))


#: Dask settings for sweeps of sub-millisecond cases (docs/scenes.rst, sweeps on a
#: cluster): no statistical profiler sampling the task thread every 10 ms; glibc's malloc
#: left to tune its own thresholds (Dask's nannies set MALLOC_TRIM_THRESHOLD_, which also
#: fixes the mmap threshold: every array over 128 kB is mapped and unmapped; None unsets it
#: alone, Dask's one-thread limits for BLAS stay); each process's event loop checked every
#: second, not every 20 ms, the workers' memory every second, not every 100 ms, the system
#: every 5 s, not every 0.5 s (each wake-up takes the GIL from the task thread or a core from
#: the workers).  Measured on 2 cores over a 1e5-case `contact run`: the workers' task
#: threads spend 5-7 % more CPU than a process pool's workers with these settings, 14 % with
#: Dask's defaults; the nannies and the scheduler 0.6 s together, 0.9 s with the first two
#: settings alone.
DASK_SWEEP_CONFIG = {"distributed.worker.profile.enabled": False,
                     "distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None,
                     "distributed.admin.tick.interval": "1s",
                     "distributed.worker.memory.monitor-interval": "1s",
                     "distributed.admin.system-monitor.interval": "5s"}


def local_cluster(n):
    """A LocalCluster of n single-threaded worker processes with DASK_SWEEP_CONFIG.

    A nanny copies its pre-spawn variables into the environment of the process it runs in
    for good (distributed's ``os.environ.update``), and a variable already in the
    environment wins over the config: after any cluster with Dask's defaults in this
    process, ``MALLOC_TRIM_THRESHOLD_`` would reach these workers too.  It is out of the
    environment while they start (and put back after)."""
    import dask
    from distributed import LocalCluster
    inherited = os.environ.pop("MALLOC_TRIM_THRESHOLD_", None)
    try:
        with dask.config.set(DASK_SWEEP_CONFIG):
            return LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                dashboard_address=None, worker_dashboard_address=None)
    finally:
        if inherited is not None:
            os.environ["MALLOC_TRIM_THRESHOLD_"] = inherited


#: Timed runs per configuration; the fastest counts (the others met a busier machine).
REPEATS = 3


def _fastest_in_turns(fns, repeats=REPEATS) -> list:
    """The shortest wall time of each of ``fns``, run in turns ``repeats`` times, so that a
    slower spell of the machine does not fall on one of them only."""
    best = [math.inf] * len(fns)
    for _ in range(repeats):
        for k, fn in enumerate(fns):
            best[k] = min(best[k], _timed(fn, 1)[0])
    return best


def _timed(fn, repeats=REPEATS):
    """(the shortest wall time of ``repeats`` calls of fn, the last call's result)."""
    best = math.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def in_process_rows(scene):
    """The sweep in this process, and where its time goes (:func:`breakdown_rows`)."""
    from contact.scene import run_scene
    run_scene(scene)                                            # warm this process
    t1, _ = _timed(lambda: run_scene(scene))
    per_case = t1 / scene.case_count
    return [(f"{scene.case_count} cases, serial, in process", t1,
             f"{per_case * 1e6:.0f} us a case",
             "1e4 cases < 1 s" + (" PASS" if t1 * 1e4 / scene.case_count < 1.0 else " FAIL"))
            ] + breakdown_rows(scene) + encoding_rows(scene)


def scaling_rows(scene):
    """The sweep in this process, on process pools and on Dask LocalClusters of 1, 2 and
    all cores' workers, each against the serial run of the same build."""
    from contact.scene import run_scene
    rows = []
    run_scene(scene)                                            # warm this process
    t1, serial = _timed(lambda: run_scene(scene))
    rows.append((f"{scene.case_count} cases, serial, in process", t1, "1.00", ""))
    cores = _usable_cpus()
    pooled = {}
    for n in sorted({1, 2, cores}):
        with ProcessPoolExecutor(n) as ex:
            run_scene(scene, executor=ex)                       # start and warm the workers
            t, res = _timed(lambda: run_scene(scene, executor=ex))
        pooled[n] = t
        same = all(repr(a.entry) == repr(b.entry) for a, b in zip(serial.cases, res.cases))
        need = 1.7 if n == 2 else 0.8 * n          # the figure for 2 cores, else 0.8 N
        rows.append((f"process pool, {n} worker(s){'' if same else ' (RESULTS DIFFER)'}", t,
                     f"{t1 / t:.2f}x serial", f">= {need:.1f}x"
                     + (" PASS" if t1 / t >= need else " FAIL")))
    try:
        from distributed import Client
    except ImportError:
        rows.append(("Dask LocalCluster", float("nan"), "distributed not installed", ""))
        return rows
    for n in sorted({1, 2, cores}):
        with local_cluster(n) as cl, Client(cl) as client:
            ex = client.get_executor(pure=False)
            run_scene(scene, executor=ex)
            t, res = _timed(lambda: run_scene(scene, executor=ex))
        same = all(repr(a.entry) == repr(b.entry) for a, b in zip(serial.cases, res.cases))
        ref = pooled.get(n)
        ratio = f"{t / ref:.2f}x the pool" if ref else ""
        differ = "" if same else " (RESULTS DIFFER)"
        verdict = (" PASS" if t / ref <= 1.15 else " FAIL") if ref else ""
        rows.append((f"Dask LocalCluster, {n} worker processes{differ}", t, ratio,
                     "<= 1.15x the pool" + verdict))
    return rows


def breakdown_rows(scene):
    """Where the in-process time goes: :func:`contact.solve_batch` on every case of the
    scene (material and punch built once, the cases in one batch), then with the residual
    of the diagnostics, and the whole scene; the three timed in turn ``REPEATS`` times (the
    fastest of each counts), so that a slower spell of the machine does not fall on one of
    them only.  The scene's share is the difference: building the cases, their chunks and
    entries, the warnings."""
    import contact
    cases = scene.cases()
    material, punch = cases[0].material.build(), cases[0].punch.build()
    columns = {k: [c.inputs[k] for c in cases] for k in ("load", "speed", "friction",
                                                         "direction")}

    def solve_all(residual):
        contact.solve_batch(material, punch, residual=residual, **columns)
    from contact.scene import run_scene
    t_solve, t_both, t_scene = _fastest_in_turns(
        (lambda: solve_all(False), lambda: solve_all(True), lambda: run_scene(scene)))
    n = len(cases)
    parts = [("contact.solve_batch", t_solve), ("the residual (diagnostics)", t_both - t_solve),
             ("the scene (cases, chunks, entries)", t_scene - t_both)]
    return [(f"  of which {name}", t, f"{t / n * 1e6:.0f} us a case, {t / t_scene:.0%}", "")
            for name, t in parts]


def encoding_rows(scene):
    """What ``contact run`` adds to each case where it is solved
    (:class:`contact.scene.output.CaseEncoder`): its result.json entry and sweep.csv rows
    as text, and without ``--quiet`` its row of the printed table, each timed on the scene's
    results, in turns ``REPEATS`` times (the fastest counts)."""
    from contact.scene import run_scene
    from contact.scene.output import CaseEncoder
    results = run_scene(scene).cases
    texts = CaseEncoder(scene, lean=True)
    rows = CaseEncoder(scene, lean=True, table=True)
    t_texts, t_rows = _fastest_in_turns((lambda: [texts(r) for r in results],
                                         lambda: [rows(r) for r in results]))
    n = len(results)
    parts = [("its result.json entry and sweep.csv rows", t_texts),
             ("its row of the printed table (without --quiet)", t_rows - t_texts)]
    return [(f"  contact run adds where a case is solved: {name}", t,
             f"{t / n * 1e6:.1f} us a case", "") for name, t in parts]


def _contact_run(path, out, *args, entry=("-m", "contact"), quiet=True) -> list:
    """The command line of ``contact run --quiet ARGS`` on a scene file, in this Python
    (``entry``: how the interpreter is told to run it, ``python -m contact`` by default;
    ``quiet`` False: without ``--quiet``, the table printed and the progress bar drawn)."""
    return [sys.executable, *entry, "run", str(path), "--out", str(out),
            *(("--quiet",) if quiet else ()), *args]


#: ``contact run`` as its console script runs it (:func:`contact.cli.console`), with the
#: moments its phases end written to stderr as one line as it exits: ``PHASES`` and
#: ``name=seconds`` fields, from the start of its Python code (the imports done; the first
#: and the last worker forked, for a pool that forks; the first and the last chunk of
#: results delivered; the files written), and the CPU time of the command's own process (all
#: its threads, not its workers) at the first and the last chunk (``cpu_first``,
#: ``cpu_last``): how busy it kept itself while the workers solved; for a process pool that
#: forks, the chunks its workers handed back (``sent``) and the wall seconds they spent
#: doing it, all workers together (``sending``: pickling a chunk's results and writing them
#: into the pool's result pipe, waiting while it is full).
_TIMED_CONTACT_RUN = """
import os, sys, time
t0 = time.perf_counter()
import contact.cli
import contact.scene.run as run
def since_start():
    return time.perf_counter() - t0
marks = {"imported": since_start()}
def iter_chunks(*args, _inner=run.iter_chunks, **kwargs):
    for chunk in _inner(*args, **kwargs):
        if "first" not in marks:
            marks["first"], marks["cpu_first"] = since_start(), time.process_time()
        yield chunk
    marks["last"], marks["cpu_last"] = since_start(), time.process_time()
run.iter_chunks = iter_chunks
forks = None
if hasattr(os, "register_at_fork"):     # POSIX: each forked worker writes when it starts
    forks, fork_log = os.pipe()
    os.register_at_fork(after_in_child=lambda: os.write(fork_log, b"%.4f " % since_start()))
    # each forked worker of a process pool appends the seconds each chunk's results took to
    # hand back (one file, opened for appending before the forks)
    import concurrent.futures.process as pool
    import tempfile
    fd, sends_path = tempfile.mkstemp()
    os.close(fd)
    sends = os.open(sends_path, os.O_RDWR | os.O_APPEND)
    os.unlink(sends_path)
    def sendback_result(*args, _inner=pool._sendback_result, **kwargs):
        t = time.perf_counter()
        _inner(*args, **kwargs)
        os.write(sends, b"%.6f " % (time.perf_counter() - t))
    pool._sendback_result = sendback_result
try:
    contact.cli.console()               # main(), then out by SystemExit
finally:
    marks["written"] = since_start()
    if forks is not None:
        os.close(fork_log)
        os.set_blocking(forks, False)
        try:
            forked = [float(t) for t in os.read(forks, 1 << 16).split()]
        except BlockingIOError:         # a worker still holds the pipe open, wrote nothing
            forked = []
        if forked:
            marks["forks"] = len(forked)
            marks["forked_first"], marks["forked_last"] = min(forked), max(forked)
        sent = [float(t) for t in os.pread(sends, os.fstat(sends).st_size, 0).split()]
        os.close(sends)
        if sent:
            marks["sent"], marks["sending"] = len(sent), sum(sent)
    print("PHASES", *(f"{k}={v:.4f}" for k, v in marks.items()), file=sys.stderr)
"""


def _timed_contact_run(path, out, *args, quiet=True) -> list:
    """The command line of ``contact run --quiet ARGS`` through ``_TIMED_CONTACT_RUN``."""
    return _contact_run(path, out, *args, entry=("-c", _TIMED_CONTACT_RUN), quiet=quiet)


def _phases(stderr: str) -> dict:
    """The ``PHASES`` line of a ``_TIMED_CONTACT_RUN``: {name: seconds} ({} without one)."""
    for line in stderr.splitlines():
        if line.startswith("PHASES "):
            return {k: float(v) for k, v in (f.split("=") for f in line.split()[1:])}
    return {}


def phase_text(phases: dict, wall: float) -> str:
    """Where a run's wall time went: start-up (imports, then to the first chunk of results),
    the stream of chunks, the files written, the exit with the interpreter's start (before
    the first mark) ("?" for a phase not reached); and, for a pool that forks, the time its
    workers spent handing back their chunks, each and as a share of theirs in the stream."""
    at = {"start": 0.0, **phases, "end": wall}

    def gap(a, b):
        return f"{at[b] - at[a]:.2f}" if a in at and b in at else "?"
    busy = forks = ""
    if {"cpu_first", "cpu_last", "first", "last"} <= at.keys() and at["last"] > at["first"]:
        share = (at["cpu_last"] - at["cpu_first"]) / (at["last"] - at["first"])
        busy = f"the command's process busy {share:.0%} of the stream"
    if {"sent", "sending", "forks", "first", "last"} <= at.keys() and at["last"] > at["first"]:
        spent = at["sending"] / (at["forks"] * (at["last"] - at["first"]))
        busy += (f"{'; ' if busy else ''}its workers handed back {at['sent']:.0f} chunks in "
                 f"{at['sending']:.2f} s, {1e3 * at['sending'] / at['sent']:.1f} ms each, "
                 f"{spent:.1%} of their time")
    busy = f" ({busy})" if busy else ""
    if {"forked_first", "forked_last"} <= at.keys():
        forks = f" (workers forked at {at['forked_first']:.2f}-{at['forked_last']:.2f})"
    return (f"imports {gap('start', 'imported')} + to the first chunk {gap('imported', 'first')}"
            f"{forks}"
            f" + stream {gap('first', 'last')}{busy} + writing {gap('last', 'written')}"
            f" + exit and interpreter start {gap('written', 'end')} s")


#: Seconds the processes of :func:`processes_alone` solve for, all of them at once.
CEILING_S = 2.0
#: Cases of the sweep that the processes of :func:`processes_alone` take their chunks from.
CEILING_CASES = 20_000


def _solve_alone(fn, scene, chunks, seconds, ready, conn):
    """Solve the ``chunks`` ((start, stop) of case indices of ``scene``), over again in
    turn, as a worker of ``contact run`` would (:func:`contact.scene.batch.run_range`),
    keeping nothing, from the moment every process of the group has passed ``ready`` (a
    barrier) until ``seconds`` have passed; send back the cases solved in those seconds
    (the chunk running at the end counted for the share of its time that falls in them).
    The first chunk is solved once before the barrier, uncounted: a fresh fork's first
    chunk pays for the pages it copies on writing (15 % of a chunk on the 2-core VM), which
    a pool's workers pay once in a run of minutes."""
    from contact.scene.batch import run_range
    run_range(fn, scene, *chunks[0])
    ready.wait()
    t0 = time.perf_counter()
    solved, now = 0.0, t0
    for start, stop in itertools.cycle(chunks):
        begun = now
        run_range(fn, scene, start, stop)
        now = time.perf_counter()
        if now - t0 >= seconds:
            solved += (stop - start) * (t0 + seconds - begun) / (now - begun)
            break
        solved += stop - start
    conn.send(solved)
    conn.close()


@contextlib.contextmanager
def processes_alone(text, cases=CEILING_CASES, seconds=CEILING_S):
    """The machine's own ceiling for N workers, measured when asked: a function ``alone(n)``
    -> (cases a second, slowest / fastest process) of n processes solving at once (None where
    processes cannot be forked).

    The n processes, forked from this one (warm), solve chunks of the same ``cases`` cases
    of the sweep of TOML ``text`` (ten stretches spread over it, so that they mix its inputs
    as the whole sweep does), sized as a pool's (:func:`contact.scene.batch.chunk_size`),
    with the chunk function of ``contact run`` (each case encoded as its writers want it),
    nothing passing between them or to a parent: what a pool's workers do, less the pool.
    They start together (a barrier) and each counts what it solved in the same ``seconds``,
    so that every one of them is busy for the whole of the time measured (where each solved
    a fixed number of cases instead, those that finished first would leave the slower ones
    the machine to themselves for a while, and the summed rate would overstate what n busy
    processes get).  Their rate is the sum of each one's cases / ``seconds``.  On a machine
    that runs n busy processes slower than one (shared physical cores, memory bandwidth, a
    hypervisor's other guests), n times the rate of one is out of any pool's reach; and on
    one whose speed drifts from minute to minute, a pool is best judged against this rate
    measured just before it."""
    import functools
    import multiprocessing as mp
    from contact.scene import SceneWriter, parse_scene_text
    from contact.scene.batch import chunk_size, run_range
    from contact.scene.run import _solved_and_encoded
    if "fork" not in mp.get_all_start_methods():
        yield None
        return
    ctx = mp.get_context("fork")
    scene = parse_scene_text(text, source="<bench ceiling>")
    with tempfile.TemporaryDirectory() as tmp:
        writer = SceneWriter(scene, Path(tmp) / "out", scene.case_count, figures=False,
                             table=False)
        fn = functools.partial(_solved_and_encoded, writer.encoder())
        run_range(fn, scene, 0, 64)                             # warm this process
        per_case = run_range(fn, scene, 64, 320).seconds / 256
        total = scene.case_count
        chunk = chunk_size(total, 1, per_case)          # as a pool sizes its chunks
        # ten stretches spread over the sweep: its mix of speeds and frictions
        length = max(1, min(cases, total) // 10)
        chunks = [(s, min(first + length, s + chunk))
                  for first in (k * (total - length) // 9 for k in range(10))
                  for s in range(first, first + length, chunk)]

        def alone(n):
            ready = ctx.Barrier(n, timeout=120)     # a process that never comes ends them
            pipes = [ctx.Pipe(duplex=False) for _ in range(n)]
            procs = [ctx.Process(target=_solve_alone,
                                 args=(fn, scene, chunks, seconds, ready, send))
                     for _, send in pipes]
            for proc in procs:
                proc.start()
            for _, send in pipes:           # a child that dies is then an EOFError here
                send.close()
            solved = [recv.recv() for recv, _ in pipes]
            for proc in procs:
                proc.join()
            return sum(solved) / seconds, max(solved) / min(solved)
        try:
            yield alone
        finally:
            writer.abort()


#: Cases of ``contact run``'s timed sweep per core of the machine, 1e5 at least: its start-up
#: (imports, numba loading its cached kernels: ~0.6 s on the 2-core VM, 1.1-1.5 s on a
#: 16-core gVisor sandbox) runs on one core, and N workers can
#: reach 0.8 N only where the parallel work is at least 4 N - 5 times the start-up (Amdahl).
CLI_CASES_PER_CORE = 50_000


def cli_side(cores: int, per_core: int = CLI_CASES_PER_CORE) -> int:
    """The side of the square speed x friction sweep that ``contact run`` is timed on: 316
    (1e5 cases) up to 2 cores, ``per_core`` cases per core beyond."""
    return math.isqrt(max(100_000, per_core * cores))


def compile_bytecode() -> None:
    """Write the bytecode of sie and contact (``compileall``: only what is missing or
    stale), as a package installed by pip has it, so that each ``contact run`` timed loads
    its modules instead of compiling them.  An editable install under
    PYTHONDONTWRITEBYTECODE (set in this project's CI and sandboxes) compiles them at every
    start otherwise: 60 ms of its 0.38 s of imports on the 2-core VM."""
    import compileall

    import contact
    import sie
    for package in (sie, contact):
        compileall.compile_dir(Path(package.__file__).parent, quiet=1)


def cli_rows(n_speed, n_friction, repeats=3, counts=None, printed=False):
    """``contact run --quiet --jobs N`` end to end (a fresh process: start-up, solving and
    writing result.json and sweep.csv), the best of ``repeats`` runs, for N up to the
    machine's cores, against ``--jobs 1``: what a user of the command sees, and the issue's
    measure (>= 0.8 N, >= 1.7x on 2 cores).  Then ``--scheduler`` to a Dask LocalCluster of
    2 and of all cores' worker processes (started here, warmed on a small sweep), against
    ``--jobs N``, each cluster run against the pool run right after it (the median of
    their ratios).  The runs compared go in turns (--jobs 1, 2, ..., then again; the cluster
    and the pool of its size in turns), so that a slower spell of a shared machine weighs
    on each alike; before each ``--jobs N`` run, N processes solve alone
    (:func:`processes_alone`), and the run's rate is given as a share of theirs: what the
    pool and the command's start-up and writing cost, on a machine whose speed drifts
    between runs (the 16-core machine's did by up to 1.5x over minutes).  Each row gives the
    CPU time of the run's processes together and how much of N cores it kept busy.

    ``counts``: the pool sizes N to time (1, the reference, always; the clusters are of the
    largest and of 2 where timed); None: 1, 2, 4, 8, 16 and the machine's cores, up to
    them.  ``printed``: also ``contact run`` as it runs by default, the table printed and
    the progress bar drawn (without ``--quiet``), ``--jobs 1`` and of the largest count, in
    turns with the others."""
    cores = _usable_cpus()
    rows, runs = [], {}
    compile_bytecode()
    with tempfile.TemporaryDirectory() as tmp:
        path, small = Path(tmp) / "sweep.toml", Path(tmp) / "small.toml"
        path.write_text(sweep_toml(n_speed, n_friction))
        small.write_text(sweep_toml(20, 20))
        out = Path(tmp) / "out"

        def run(args, scene=path, cluster=None, quiet=True):
            shutil.rmtree(out, ignore_errors=True)
            before = _children_cpu_s() + _cluster_cpu_s(cluster)
            t0 = time.perf_counter()
            proc = subprocess.run(_timed_contact_run(scene, out, *args, quiet=quiet),
                                  capture_output=True, text=True)
            wall = time.perf_counter() - t0
            cpu = _children_cpu_s() + _cluster_cpu_s(cluster) - before
            marks = _phases(proc.stderr)
            phases = phase_text(marks, wall)
            stream = marks.get("last", math.nan) - marks.get("first", math.nan)
            # each run as it ends, on stderr: a bench stopped at a time limit still tells
            # what it measured
            print(f"  {' '.join(args)}{' (small)' if scene is small else ''}"
                  f"{'' if quiet else ' (printed)'}: {wall:.2f} s, "
                  f"CPU {cpu:.1f} s, exit {proc.returncode}; {phases}", file=sys.stderr,
                  flush=True)
            return wall, proc.returncode, cpu, phases, stream

        def best(key, n):
            wall, rc, cpu, phases, _ = min(runs[key], key=lambda r: r[0])
            return wall, rc, (f"CPU {cpu:.1f} s ({cpu / (n * wall):.0%} of {n} core(s)); "
                              f"{phases}")

        def fastest(key):
            return min(r[0] for r in runs[key])

        def failed(rc):
            return "" if rc == 0 else f" (FAILED: exit status {rc})"
        if counts is None:
            counts = {1, 2, 4, 8, 16, cores} & set(range(1, cores + 1))
        counts = sorted(set(counts) | {1})
        printed_counts = sorted({1, max(counts)}) if printed else []
        solo = {}                       # N -> [(rate, spread) of N processes alone]
        with processes_alone(sweep_toml(n_speed, n_friction)) as alone:
            for _ in range(repeats):
                for jobs in counts:
                    if alone is not None:
                        solo.setdefault(jobs, []).append(alone(jobs))
                        rate, spread = solo[jobs][-1]
                        print(f"  {jobs} process(es) solving alone: {rate:.0f} cases/s "
                              f"(slowest {spread:.2f}x the fastest)", file=sys.stderr,
                              flush=True)
                    runs.setdefault(jobs, []).append(run(("--jobs", str(jobs))))
                for jobs in printed_counts:
                    runs.setdefault(("printed", jobs), []).append(
                        run(("--jobs", str(jobs)), quiet=False))
        cases = n_speed * n_friction
        for jobs in counts:
            t, rc, busy = best(jobs, jobs)
            need = 1.7 if jobs == 2 else 0.8 * jobs
            ratio = fastest(1) / t
            # the run's rate, and its stream's, against that of N processes solving alone
            # just before it
            of = ""
            if jobs in solo:
                share = statistics.median(cases / r[0] / rate
                                          for r, (rate, _) in zip(runs[jobs], solo[jobs]))
                stream = statistics.median(cases / r[4] / rate if r[4] > 0 else math.nan
                                           for r, (rate, _) in zip(runs[jobs], solo[jobs]))
                of = (f" ({share:.0%} of the rate of {jobs} process(es) solving alone just "
                      f"before; its stream {stream:.0%})")
            rows.append((f"`contact run --quiet --jobs {jobs}`{failed(rc)}", t,
                         f"{ratio:.2f}x --jobs 1{of}; {busy}",
                         "" if jobs == 1 else f">= {need:.1f}x"
                         + (" PASS" if ratio >= need else " FAIL")))
        for jobs in printed_counts:
            t, rc, busy = best(("printed", jobs), jobs)
            rows.append((f"`contact run --jobs {jobs}` (the table printed, the progress bar)"
                         f"{failed(rc)}", t, f"{fastest(('printed', 1)) / t:.2f}x its --jobs 1, "
                         f"{t / fastest(jobs):.2f}x the time with --quiet; {busy}", ""))
        if solo:
            one = max(solo[1])[0]
            rows.append((f"the machine's ceiling: N processes solving at once for "
                         f"{CEILING_S:g} s (chunks of the same "
                         f"{min(CEILING_CASES, cases) // 10 * 10} cases), nothing passed "
                         "between them", float("nan"),
                         "; ".join(f"N = {n}: {max(r)[0] / one:.2f}x one (slowest process "
                                   f"{max(r)[1]:.2f}x the fastest)"
                                   f"{_beyond(n, max(r)[0] / one)}" for n, r in solo.items()),
                         "above any pool"))
        if importlib.util.find_spec("distributed") is None:
            rows.append(("`contact run --scheduler`", float("nan"), "distributed not installed",
                         ""))
            return rows
        # a cluster of one worker has no pool to be held to (--jobs 1 solves in the process
        # itself); the API rows (scaling_rows) measure it against a pool of one.  The
        # cluster of all cores first: the row a machine of many cores is run for
        for n in sorted({2, max(counts)} & set(counts) - {1}, reverse=True):
            with local_cluster(n) as cl:
                address = ("--scheduler", cl.scheduler_address)
                run(address, small)                     # the workers import and load kernels
                for _ in range(repeats):
                    runs.setdefault(("dask", n), []).append(run(address, cluster=cl))
                    runs[n].append(run(("--jobs", str(n))))
            t, rc, busy = best(("dask", n), n)
            # each cluster run against the pool run right after it
            paired = statistics.median(d[0] / p[0] for d, p in zip(runs[("dask", n)],
                                                         runs[n][-repeats:]))
            rows.append((f"`contact run --quiet --scheduler` (LocalCluster, {n} worker "
                         f"processes){failed(rc)}", t,
                         f"{paired:.2f}x --jobs {n} run in turns with it (median of "
                         f"{repeats}); {busy}",
                         "<= 1.15x" + (" PASS" if paired <= 1.15 else " FAIL")))
    return rows


def _beyond(n: int, times_one: float) -> str:
    """What a ceiling of n processes that reads more than n times one process says: that
    one process was measured in a slower spell of the machine than the n (nothing else
    makes n processes more than n times as fast), so that the shares of the rate of
    processes alone in the rows above are no better than the machine's drift."""
    if times_one <= n:
        return ""
    return f" (over {n}x: the one process met a slower spell of the machine)"


def _children_cpu_s() -> float:
    """CPU seconds of this process's finished children (``contact run`` and its pool's
    workers, which it waited for)."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _cluster_cpu_s(cluster) -> float:
    """CPU seconds so far of a LocalCluster's worker processes and of this process, which
    runs its scheduler and nannies (0 without a cluster)."""
    if cluster is None:
        return 0.0
    import psutil                       # a dependency of distributed
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime + sum(
        sum(psutil.Process(w.process.pid).cpu_times()[:2]) for w in cluster.workers.values())


#: Runs a command and prints the peak resident size, in kB, of the largest process it
#: started (itself, or one of its workers): a fresh process per measurement, so that no other
#: child of the benchmark counts.
_PEAK_RSS = ("import resource, subprocess, sys; "
             "rc = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL).returncode; "
             "print(rc, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")


def memory_run(n_speed, n_friction, jobs=0):
    """(wall s, peak RSS MB of the largest process, files written, exit status) of
    ``contact run --quiet --jobs JOBS`` on an n_speed x n_friction sweep asking ends and
    exponents."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "big.toml"
        path.write_text(sweep_toml(n_speed, n_friction, ("ends", "exponents")))
        out = Path(tmp) / "out"
        t0 = time.perf_counter()
        proc = subprocess.run([sys.executable, "-c", _PEAK_RSS,
                               *_contact_run(path, out, "--jobs", str(jobs))],
                              capture_output=True, text=True)
        t = time.perf_counter() - t0
        rc, peak_kb = (int(v) for v in proc.stdout.split())
        files = sorted(p.name for p in out.glob("*"))
    return t, peak_kb / 1024.0, files, rc


def memory_rows(jobs=0):
    """Peak resident size of ``contact run`` on 1e4 and 1e5 cases: bounded when the tenfold
    sweep peaks about as high (the results are written as they come, nothing per case is
    kept)."""
    rows, peaks = [], []
    for n_speed in (100, 1000):
        t, peak, files, rc = memory_run(n_speed, 100, jobs)
        peaks.append(peak)
        rows.append((f"{n_speed * 100} cases, `contact run --jobs {jobs}`"
                     f"{'' if rc == 0 else f' (FAILED: exit status {rc})'}", t,
                     f"peak RSS {peak:.0f} MB (largest process); wrote {', '.join(files)}",
                     "bounded"))
    growth = peaks[1] - peaks[0]
    rows[1] = rows[1][:3] + (f"bounded: {growth:+.1f} MB from 1e4 cases"
                             + (" PASS" if growth < 0.1 * peaks[0] else " FAIL"),)
    return rows


def _pool_sizes(text: str) -> list:
    """``--counts``: comma-separated pool sizes, each at least 1."""
    import argparse
    try:
        sizes = [int(v) for v in text.split(",")]
    except ValueError:
        sizes = []
    if not sizes or min(sizes) < 1:
        raise argparse.ArgumentTypeError(
            f"expected pool sizes of at least 1, comma-separated (e.g. 1,8,16), got {text!r}")
    return sizes


def main(argv=None):
    """``--quick``: every configuration on small sweeps (the timings mean little);
    ``--cli``: the ``contact run`` rows alone (:func:`cli_rows`, on :func:`cli_side` of the
    machine's cores), written to bench_sweep_cli.md: the table of a machine with many cores;
    ``--repeats N``: the best of N runs of each ``contact run`` (default 3); ``--counts
    1,8,16``: the pool sizes timed (a machine's table in fewer minutes); ``--per-core N``:
    the cases of ``contact run``'s sweep per core of the machine (default
    ``CLI_CASES_PER_CORE``; 1e5 at least): where the one-core start-up stops mattering."""
    import argparse
    from contact.scene import parse_scene_text
    parser = argparse.ArgumentParser(prog="python -m validation.bench_sweep",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small sweeps")
    parser.add_argument("--cli", action="store_true", help="the contact run rows alone")
    parser.add_argument("--repeats", type=int, default=3,
                        help="runs of each contact run configuration, the best counts")
    parser.add_argument("--counts", type=_pool_sizes, default=None,
                        help="the --jobs N to time, comma-separated (1 is always timed); "
                             "default: 1, 2, 4, 8, 16 and the machine's cores, up to them")
    parser.add_argument("--per-core", type=int, default=CLI_CASES_PER_CORE,
                        help="cases of the contact run sweep per core of the machine "
                             f"(default {CLI_CASES_PER_CORE}; 1e5 cases at least)")
    args = parser.parse_args(sys.argv[1:] if argv is None else argv)
    if args.repeats < 1:
        parser.error(f"--repeats must be at least 1, got {args.repeats}")
    if args.per_core < 1:
        parser.error(f"--per-core must be at least 1, got {args.per_core}")
    quick, cli_only, repeats = args.quick, args.cli, args.repeats
    OUT.mkdir(parents=True, exist_ok=True)
    cores = _usable_cpus()
    rows = []
    if not cli_only:
        scene = parse_scene_text(sweep_toml(20 if quick else 100, 20 if quick else 100),
                                 source="<bench sweep>")
        rows += in_process_rows(scene)
        # the pools and clusters on a sweep 10 times longer: the 1e4-case sweep takes ~0.4 s
        # in process, where their fixed costs (starting the chunks, the first chunk solved
        # here) would weigh as much as the parallel work
        rows += scaling_rows(parse_scene_text(sweep_toml(20 if quick else 316,
                                                         20 if quick else 316),
                                              source="<bench sweep 1e5>"))
    side = 20 if quick else cli_side(cores, args.per_core)
    rows += cli_rows(side, side, repeats, args.counts, printed=not cli_only)
    if not (quick or cli_only):
        rows += memory_rows()
    lines = ["# sweep benchmarks", "",
             "Sweeps of a cylindrical punch (speed x friction; ends, exponents, SIFs) on "
             f"{cores} cores; wall times; `contact run` on {side * side} cases.", "",
             "| run | wall [s] | ratio | target |", "|---|---|---|---|"]
    lines += [f"| {r} | {'' if math.isnan(t) else f'{t:.2f}'} | {ratio} | {target} |"
              for r, t, ratio, target in rows]
    text = "\n".join(lines) + "\n"
    (OUT / ("bench_sweep_cli.md" if cli_only else "bench_sweep.md")).write_text(text)
    print(text)


if __name__ == "__main__":
    main(sys.argv[1:])
