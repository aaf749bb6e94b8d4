"""Running a scene's cases in chunks: in this process, in a process pool or on a Dask cluster.

One task per case costs more than the case when the case is cheap: a cylindrical punch solves
in a fraction of a millisecond, a Dask task costs milliseconds of CPU between the scheduler,
the client and the worker (the documentation, Accuracy and speed: Sweeps, has the
measurements behind this module's constants).  Cases therefore travel in chunks, and a chunk travels as a range of case
indices with the scene they come from: the worker builds its cases itself
(:meth:`contact.scene.spec.Scene.iter_cases`), so that the process that hands out the work
neither builds nor pickles them one by one.  Chunks are

* consecutive in scene order: each worker computes the surface constants of a speed once and
  keeps them (:func:`contact.scene.run._shared_constants`, cached per process), and builds a
  material and a punch once per distinct spec (:func:`build_once`), so a chunk need not be
  cut where the speed changes;
* sized to the work: a chunk holds about ``TARGET_CHUNK_S`` of solving, estimated from the
  first chunk (solved in this process first, unless the workers are processes of their own,
  which are sized from their first chunks) and again from each chunk a worker finishes, and
  there are at least ``CHUNKS_PER_WORKER`` chunks per worker so that a slow chunk does not
  leave the others idle;
* solved together where their cases share the material, the punch and the numerics
  (:func:`contact.scene.run.run_cases`, :func:`contact.solve_batch`).

Results come back in scene order, a chunk at a time (:func:`iter_chunks`), so that a sweep
runs in memory that does not grow with its length: at most ``CHUNKS_AHEAD`` full chunks per worker are handed out
past the first case not yet delivered (those running, and those done early that wait for it).

A case that fails in the library comes back as its exception; the results stop after the first
one in scene order, and the chunks after it are cancelled, so that the caller can raise it (a
:class:`~contact.scene.spec.CaseError` naming the case) as a serial run would.
"""
from __future__ import annotations

import functools
import itertools
import math
import time
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait

from .processes import cyclic_gc_paused

#: Seconds of solving a chunk aims at: well above a Dask task's overhead (shorter chunks put a
#: LocalCluster further behind a process pool).
TARGET_CHUNK_S = 0.2
#: At least this many chunks per worker, for balance.
CHUNKS_PER_WORKER = 4
#: Toward the end a chunk holds at most 1/(TAIL_SPLIT workers) of the cases left.
TAIL_SPLIT = 2
#: Full chunks per worker handed out past the first case not yet delivered.
CHUNKS_AHEAD = 8
#: Cases solved here first, to size the chunks of an executor: the first of them alone, which
#: warms this process up (numba loading its kernels), then the rest as one chunk,
#: timed.
_PROBE = 16
#: Bytes a process pool's result pipe is asked to hold (:func:`widen_result_pipe`): a
#: chunk's results (~0.75 kB a case of ``contact run``'s encoded text, ``TARGET_CHUNK_S`` of
#: cases: 1-3 MB) then go in a few writes instead of one per 64 kB.
RESULT_PIPE_BYTES = 1 << 20
#: Most cases per chunk without an executor (solved together, delivered in order): a sweep
#: of any length runs in memory for this many results.
SERIAL_CHUNK = 256
#: Seconds between two counts of a Dask cluster's workers during a sweep (a cluster grows and
#: shrinks; asking costs a round trip to its scheduler).
RECOUNT_S = 1.0
#: Longest wait for a chunk before the executor is looked at: a Dask client whose scheduler
#: is gone closes, and its chunks never come back.
WAIT_S = 5.0


@functools.lru_cache(maxsize=64)
def _built(spec):
    """spec.build(), once per process for each distinct (hashable) spec."""
    return spec.build()


def build_once(spec):
    """The built material or punch of ``spec``; specs that cannot be hashed are built each time."""
    try:
        return _built(spec)
    except TypeError:                       # unhashable spec (e.g. holding an array)
        return spec.build()


def run_chunk(fn, cases):
    """[(index, result)] for the cases, in order: ``fn(cases)`` (a list of them) gives one
    result per case, a case's library input error (contact.ContactInputError,
    sie.SIEInputError) in place of its result, so that the caller can report the first
    failing case in scene order.  Python's cyclic collector is paused throughout
    (:func:`contact.scene.processes.cyclic_gc_paused`), the building of the cases from
    their scene included: the collector's passes over a worker's imported objects would
    otherwise cost each case."""
    with cyclic_gc_paused():
        cases = list(cases)
        return list(zip([case.index for case in cases], fn(cases)))


def chunk_size(n_cases, workers, seconds_per_case):
    """Cases per chunk: about TARGET_CHUNK_S of work, and at least CHUNKS_PER_WORKER chunks
    per worker."""
    by_time = max(1, int(TARGET_CHUNK_S / max(seconds_per_case, 1e-6)))
    by_balance = max(1, math.ceil(n_cases / (CHUNKS_PER_WORKER * max(workers, 1))))
    return max(1, min(by_time, by_balance))


def worker_count(executor) -> int:
    """How many cases an executor runs at once: a process pool's workers, a Dask client's
    threads (1 for anything else)."""
    n = getattr(executor, "_max_workers", None)
    if n:
        return int(n)
    client = _dask_client(executor)
    if client is not None:
        try:
            return max(1, sum(client.nthreads().values()))
        except Exception:                     # a scheduler without workers yet
            return 1
    return 1


def _dask_client(executor):
    """The Dask client behind ``Client.get_executor()`` (distributed's ClientExecutor keeps
    it as ``_client``), or None for any other executor."""
    return getattr(executor, "_client", None)


class ChunkResults:
    """The [(index, result)] of one chunk as a single object on its way back: Dask serializes
    a plain list (or tuple) element by element, in more of the client's time than one piece
    (a process pool pickles either in one piece), with the seconds the worker spent on it
    (what sizes the next chunks)."""
    __slots__ = ("items", "seconds", "_failed")

    def __init__(self, items, seconds=math.nan, failed=...):
        self.items = items
        self.seconds = seconds
        self._failed = failed                   # ...: not known yet

    @property
    def failed(self) -> int | None:
        """The index of the chunk's first case whose result is an exception (a library input
        error, see :func:`run_chunk`), or None: known without a look at each case for a chunk
        that crossed as columns (every result a named tuple of one type, none an exception),
        found once otherwise."""
        if self._failed is ...:
            self._failed = next((i for i, res in self.items if isinstance(res, Exception)),
                                None)
        return self._failed

    def up_to_failure(self) -> tuple:
        """(the items up to the first failure included, whether there was one)."""
        if self.failed is None:
            return self.items, False
        return _up_to_failure(self.items)

    def __reduce__(self):
        """Pickled a column at a time where every result is a named tuple of one type (a
        lean writer's :class:`~contact.scene.table.CaseText`): lists of strings and numbers,
        which pickle and unpickle in C, in place of a Python call per case each way."""
        kind = type(self.items[0][1]) if self.items else None
        if getattr(kind, "_fields", None) and issubclass(kind, tuple) \
                and not hasattr(self.items[0][1], "__dict__") \
                and all(type(res) is kind for _, res in self.items):
            indices, results = zip(*self.items)
            return _from_columns, (kind, indices, list(zip(*results)), self.seconds)
        return ChunkResults, (self.items, self.seconds)


def _from_columns(kind, indices, columns, seconds) -> ChunkResults:
    """The ChunkResults that :meth:`ChunkResults.__reduce__` took apart: its named tuples
    made again from their columns; none of them an exception."""
    make = functools.partial(tuple.__new__, kind)
    return ChunkResults(list(zip(indices, map(make, zip(*columns)))), seconds, failed=None)


def run_range(fn, source, start: int, stop: int) -> ChunkResults:
    """:func:`run_chunk` on the cases ``start`` <= index < ``stop`` of ``source`` (a
    :class:`~contact.scene.spec.Scene`), built here: what a worker runs."""
    t0 = time.perf_counter()
    items = run_chunk(fn, source.iter_cases(start, stop))
    return ChunkResults(items, time.perf_counter() - t0)


def iter_chunked(fn, source, executor, on_done):
    """(index, result or its exception) for each case of ``source``, in its order: the
    chunks of :func:`iter_chunks` case by case."""
    return itertools.chain.from_iterable(iter_chunks(fn, source, executor, on_done))


def iter_chunks(fn, source, executor, on_done):
    """The cases of ``source`` solved in chunks, delivered a chunk at a time in scene order:
    each a list of (index, result or its exception), ending with the chunk of the first
    exception (a library input error, see :func:`run_chunk`), cut after it; ``fn`` solves
    a list of cases (:func:`contact.scene.run.run_cases`).  Delivering chunks, not cases,
    keeps the consumer's work per case to what it does with the case (a generator step per
    case would be a cost of its own in the process that feeds the workers).

    ``source`` is a :class:`~contact.scene.spec.Scene` (anything with ``case_count`` and
    ``iter_cases(start, stop)``, picklable when ``executor`` runs elsewhere).  The first
    case solved here is a chunk of its own: it warms this process up (numba loading its
    kernels), and that time is its own alone, where a chunk's cases share their chunk's
    (:func:`contact.scene.run.run_cases`).  ``executor`` None (or fewer than two cases):
    every case here, in chunks of about ``TARGET_CHUNK_S`` of work (sized from the chunk
    before, ``SERIAL_CHUNK`` at most: the progress moves a few times a second).
    Otherwise, where the executor's workers are this process's threads or forks
    (:func:`_warms_workers`), the first ``_PROBE`` cases run here as two chunks (the first
    case, which warms this process up and the workers forked after it, then the rest,
    whose time sizes the chunks: :func:`chunk_size`); the rest
    go to ``executor`` as ranges of indices (:func:`run_range`), at most ``CHUNKS_AHEAD``
    full chunks per worker past the first case not yet delivered (a process pool's result
    pipe first widened to hold a chunk: :func:`widen_result_pipe`).  Once a case fails, the
    chunks after it are cancelled and those before it awaited.  ``on_done(k)`` is called as
    k cases finish.  A Dask client that has closed meanwhile (its scheduler lost) is a
    ConnectionError (:func:`_check_client`), looked for when no chunk has come back for
    ``WAIT_S``.
    """
    total = source.case_count
    if executor is None or total < 2:
        start, size = 0, 1
        while start < total:
            stop = min(total, start + size)
            t0 = time.perf_counter()
            items = _run_here(fn, source, start, stop, on_done)
            per_case = (time.perf_counter() - t0) / (stop - start)
            items, failed = _up_to_failure(items)
            yield items
            if failed:
                return
            size = max(1, min(SERIAL_CHUNK, int(TARGET_CHUNK_S / max(per_case, 1e-6))))
            start = stop
        return
    workers = worker_count(executor)
    widen_result_pipe(executor)
    if not _warms_workers(executor):        # each worker warms up on its first chunk
        yield from _windowed(fn, source, executor, 0, total, None, workers, on_done)
        return
    # the probe in two chunks: the first case warms this process up (numba's cache), the rest
    # is timed
    probe, per_case = min(_PROBE, total), math.inf
    for start, stop in ((0, 1), (1, probe)):
        t0 = time.perf_counter()
        items, failed = _up_to_failure(_run_here(fn, source, start, stop, on_done))
        yield items
        if failed:
            return
        per_case = (time.perf_counter() - t0) / (stop - start)
    yield from _windowed(fn, source, executor, probe, total, per_case, workers, on_done)


def _ahead(per_case: float) -> int:
    """Chunks per worker handed out past the first case not yet delivered: CHUNKS_AHEAD
    once a case's time is known, one (each worker's first chunk) before."""
    return CHUNKS_AHEAD if math.isfinite(per_case) else 1


def widen_result_pipe(executor) -> int | None:
    """Ask the pipe that a :class:`~concurrent.futures.ProcessPoolExecutor`'s workers send
    their results through to hold ``RESULT_PIPE_BYTES`` (Linux's ``F_SETPIPE_SZ``, up to
    ``/proc/sys/fs/pipe-max-size``; a larger pipe is left as it is); its size in bytes, or
    None where there is no such pipe or its size cannot be set (another platform, another
    executor).

    A worker writes a chunk's results into the pipe, holding the pool's one write lock, and
    is blocked until all of it is in: with the default 64 kB, until this process's thread
    that reads the pipe has taken all but the last 64 kB out, a read at a time, each waiting
    for the GIL while this process's main thread writes the files (up to the interpreter's
    switch interval, 5 ms).  The more workers, the busier that main thread and the longer
    each one waits, idle, with the others queued on the lock.  A pipe that holds a whole
    chunk frees the worker as soon as it has written it.
    """
    try:
        import fcntl
    except ImportError:                  # not POSIX
        return None
    queue = getattr(executor, "_result_queue", None) if isinstance(
        executor, ProcessPoolExecutor) else None
    reader = getattr(queue, "_reader", None)
    set_size = getattr(fcntl, "F_SETPIPE_SZ", None)
    if reader is None or set_size is None:
        return None
    size = RESULT_PIPE_BYTES
    try:
        with open("/proc/sys/fs/pipe-max-size") as fh:
            size = min(size, int(fh.read()))
    except (OSError, ValueError):
        pass
    try:
        current = fcntl.fcntl(reader.fileno(), fcntl.F_GETPIPE_SZ)
        return current if current >= size else fcntl.fcntl(reader.fileno(), set_size, size)
    except (OSError, ValueError):        # above this user's limit, or the pipe is closed
        return None


def _check_client(executor) -> None:
    """Raise ConnectionError if ``executor`` is a Dask client's that has closed (it lost its
    scheduler and did not reconnect): the chunks handed to it will not come back."""
    client = _dask_client(executor)
    if client is not None and getattr(client, "status", None) in ("closing", "closed"):
        address = getattr(getattr(client, "scheduler", None), "address", "?")
        raise ConnectionError(f"lost the Dask scheduler at {address}: its client has closed "
                              "(the scheduler stopped, or the network failed); the cases not "
                              "yet back are not solved")


def _warms_workers(executor) -> bool:
    """Whether warming this process up warms the executor's workers too: they are its
    threads or its forks (a pool of the "fork" start method, made after the warm-up), or
    unknown.  Not a Dask cluster's workers nor a pool of "spawn" or "forkserver"
    processes: each of those warms up on its own first chunk, and solving here first would
    only keep them waiting (numba loading its kernels, in series)."""
    if _dask_client(executor) is not None:
        return False
    context = getattr(executor, "_mp_context", None)         # a ProcessPoolExecutor's
    return context is None or context.get_start_method() == "fork"


def _run_here(fn, source, start, stop, on_done):
    """:func:`run_chunk` on cases ``start`` <= index < ``stop``, in this process."""
    items = run_chunk(fn, source.iter_cases(start, stop))
    on_done(len(items))
    return items


def _up_to_failure(items):
    """(the items up to the first failure included, whether there was one)."""
    for k, (_, res) in enumerate(items):
        if isinstance(res, Exception):
            return items[:k + 1], True
    return items, False


def tail_size(size: int, left: int, workers: int) -> int:
    """Cases in the next chunk when ``left`` cases are not yet handed out: ``size``, or less
    toward the end of the sweep, a 1/(TAIL_SPLIT workers) share of what is left (guided
    self-scheduling: the last chunks are short, so that the workers finish together instead
    of one of them solving a full chunk alone), down to ``size`` / TAIL_SPLIT**3."""
    share = math.ceil(left / (TAIL_SPLIT * max(workers, 1)))
    return max(1, min(size, left, max(share, size // TAIL_SPLIT ** 3)))


def _windowed(fn, source, executor, start, total, per_case, workers, on_done):
    """The cases ``start`` <= index < ``total`` (:func:`iter_chunked`): ranges of about
    :func:`chunk_size` cases (:func:`tail_size` toward the end) submitted to ``executor``
    while fewer than ``CHUNKS_AHEAD`` chunks per worker handed out wait for delivery,
    delivered in order.  ``per_case``: the seconds a case takes, from the first cases
    (solved here, in a process that may still be warming up: an upper bound), lowered to
    what each finished chunk took in its worker, and the chunks sized again; None when
    nothing was solved here: a first chunk of ``_PROBE // 2`` cases for each worker (which
    warms it up), and no more until one of them comes back.  ``workers``: how many run at
    once; a Dask cluster's are counted again every ``RECOUNT_S`` as chunks come back
    (workers that join an adaptive cluster, or start after the sweep, get work too)."""
    recount = _dask_client(executor) is not None
    counted = time.monotonic()
    left = max(total - start, 1)
    if per_case is None:                # infinite until a chunk comes back
        per_case, size = math.inf, max(1, _PROBE // 2)
    else:
        size = chunk_size(left, workers, per_case)
    done = {}                           # first index of a finished chunk -> its ChunkResults
    running = {}                        # future -> first index of its chunk
    next_start = start                  # first index not yet handed out
    delivered = start                   # first index not yet delivered
    failed = math.inf                   # index of the first failing case known
    try:
        while delivered < total:
            while next_start < min(total, failed) and \
                    next_start - delivered < _ahead(per_case) * workers * size:
                stop = next_start + tail_size(size, total - next_start, workers)
                running[executor.submit(run_range, fn, source, next_start, stop)] = next_start
                next_start = stop
            while delivered in done:
                items, failed_here = done.pop(delivered).up_to_failure()
                yield items
                if failed_here:
                    return
                delivered = items[-1][0] + 1
            if delivered >= next_start:
                continue                    # all handed out so far delivered: hand out more
            finished, _ = wait(running, timeout=WAIT_S, return_when=FIRST_COMPLETED)
            if not finished:
                _check_client(executor)
            for fut in finished:
                first = running.pop(fut)
                if fut.cancelled():
                    continue
                chunk = fut.result()
                items = chunk.items
                on_done(len(items))
                done[first] = chunk
                if items and chunk.seconds < per_case * len(items):
                    per_case = chunk.seconds / len(items)
                    size = chunk_size(left, workers, per_case)
                if chunk.failed is not None:
                    failed = min(failed, chunk.failed)
            if recount and time.monotonic() - counted >= RECOUNT_S:
                counted = time.monotonic()
                now = worker_count(executor)
                if now != workers:
                    workers = now
                    if math.isfinite(per_case):
                        size = chunk_size(left, workers, per_case)
            for fut, first in list(running.items()):
                if first > failed and fut.cancel():
                    del running[fut]
    finally:
        for fut in running:
            fut.cancel()
