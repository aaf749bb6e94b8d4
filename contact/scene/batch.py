"""Running a scene's cases in chunks: in this process, in a process pool or on a Dask cluster.

One task per case costs more than the case when the case is cheap (a cylindrical punch solves
in ~0.5 ms; a Dask task costs 5-25 ms of CPU between the scheduler, the client and the worker
on a loaded 2-core machine, a process-pool task ~0.1 ms plus pickling).  Cases therefore
travel in chunks:

* of one material, in scene order: each worker computes the surface constants of a speed
  once and keeps them (:func:`contact.scene.run._shared_constants`, cached per process), so a
  chunk need not be cut where the speed changes (cut there, a sweep whose inner key is the
  friction would make chunks no longer than one speed's cases, whatever their cost);
* sized to the work: a chunk holds about ``TARGET_CHUNK_S`` of solving, estimated from the
  first cases (solved in this process first), and there are at least ``CHUNKS_PER_WORKER``
  chunks per worker so that a slow chunk does not leave the others idle;
* each worker builds a material and a punch once per distinct spec (:func:`build_once`).

Cases are read from an iterator as they are needed and their results come back in its order
(:func:`iter_chunked`), so that a sweep runs in memory that does not grow with its length: at
most ``CHUNKS_AHEAD`` full chunks per worker are read past the first case not yet delivered
(those running, and those done early that wait for it), and a group of cases of one material
is cut into a chunk when it is full or when its first case is half that window behind the
newest case read (:class:`Chunker`).

A case that fails in the library comes back as its exception; the results stop after the first
one in scene order, and the chunks after it are cancelled, so that the caller can raise it (a
:class:`~contact.scene.spec.CaseError` naming the case) as a serial run would.
"""
from __future__ import annotations

import collections
import functools
import itertools
import math
import time
from concurrent.futures import FIRST_COMPLETED, wait

#: Seconds of solving a chunk aims at: well above a Dask task's overhead (measured: 0.05 s
#: chunks put a LocalCluster 1.2-1.4x behind a process pool on 2 cores, 0.2 s 1.1-1.25x).
TARGET_CHUNK_S = 0.2
#: At least this many chunks per worker, for balance.
CHUNKS_PER_WORKER = 4
#: Full chunks per worker read past the first case not yet delivered.
CHUNKS_AHEAD = 8
#: Cases solved here first, to size the chunks (the fastest of them counts).
_PROBE = 3


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
    """[(index, fn(case) or its exception)] for each case, in order.

    A library input error (contact.ContactInputError, sie.SIEInputError) is returned in place
    of the result, so that the caller can report the first failing case in scene order;
    anything else propagates.
    """
    import contact
    import sie
    out = []
    for case in cases:
        try:
            res = fn(case)
        except (contact.ContactInputError, sie.SIEInputError) as exc:
            res = exc
        out.append((case.index, res))
    return out


def chunk_size(n_cases, workers, seconds_per_case):
    """Cases per chunk: about TARGET_CHUNK_S of work, and at least CHUNKS_PER_WORKER chunks
    per worker."""
    by_time = max(1, int(TARGET_CHUNK_S / max(seconds_per_case, 1e-6)))
    by_balance = max(1, math.ceil(n_cases / (CHUNKS_PER_WORKER * max(workers, 1))))
    return max(1, min(by_time, by_balance))


class Chunker:
    """Cases grouped by material as they are read, handed out as chunks in scene order within
    each: a group when it holds ``size`` cases, or when its first case is ``lag`` cases
    behind the newest one read (so that a case whose key is rare does not wait for others of
    its key while the cases after it are solved)."""

    def __init__(self, size: int, lag: int):
        self.size, self.lag = size, lag
        self._groups = {}              # key -> (position of its first case, cases); oldest first
        self._read = 0

    def add(self, case) -> list:
        """The chunks ready once ``case`` is read."""
        key = case.material
        if key not in self._groups:
            self._groups[key] = (self._read, [])
        group = self._groups[key][1]
        group.append(case)
        self._read += 1
        ready = [self._groups.pop(key)[1]] if len(group) == self.size else []
        while self._groups:
            oldest, (first, group) = next(iter(self._groups.items()))
            if self._read - 1 - first < self.lag:
                break
            ready.append(self._groups.pop(oldest)[1])
        return ready

    def flush(self, below=math.inf) -> list:
        """Every group left as a chunk, keeping its cases whose index is below ``below``."""
        chunks = [[c for c in group if c.index < below] for _, group in self._groups.values()]
        self._groups.clear()
        return [chunk for chunk in chunks if chunk]


def worker_count(executor) -> int:
    """How many cases an executor runs at once: a process pool's workers, a Dask client's
    threads (1 for anything else)."""
    n = getattr(executor, "_max_workers", None)
    if n:
        return int(n)
    client = getattr(executor, "_client", None)
    if client is not None:
        try:
            return max(1, sum(client.nthreads().values()))
        except Exception:                     # a scheduler without workers yet
            return 1
    return 1


def iter_chunked(fn, cases, executor, on_done, total: int):
    """(case, fn(case) or its exception) for each case of the iterable ``cases``, in its order,
    ending after the first exception (a library input error, see :func:`run_chunk`).

    ``executor`` None (or fewer than two cases): every case here, one after the other.
    Otherwise the first three cases run here (the fastest sizes the chunks: :func:`chunk_size`
    for the ``total`` cases), the rest go to ``executor`` in chunks of one material
    (:class:`Chunker`), at most ``CHUNKS_AHEAD`` full chunks per worker read past the first
    case not yet delivered.  Once a case fails, the chunks after it are cancelled and those
    before it awaited.  ``on_done(k)`` is called as k cases finish.
    """
    cases = iter(cases)
    if executor is None or total < 2:
        for case in cases:
            res = _run_here(fn, case, on_done)
            yield case, res
            if isinstance(res, Exception):
                return
        return
    per_case = math.inf
    for case in itertools.islice(cases, _PROBE):    # the first is slower (caches fill)
        t0 = time.perf_counter()
        res = _run_here(fn, case, on_done)
        per_case = min(per_case, time.perf_counter() - t0)
        yield case, res
        if isinstance(res, Exception):
            return
    workers = worker_count(executor)
    size = chunk_size(max(total - _PROBE, 1), workers, per_case)
    yield from _windowed(fn, cases, executor, size, CHUNKS_AHEAD * workers * size, on_done)


def _run_here(fn, case, on_done):
    """fn(case) or its library input error, in this process."""
    ((_, res),) = run_chunk(fn, [case])
    on_done(1)
    return res


def _windowed(fn, cases, executor, size, ahead, on_done):
    """The cases after the probe (:func:`iter_chunked`): read while fewer than ``ahead`` wait
    for delivery, grouped into chunks (:class:`Chunker`, a group cut when its first case is
    ``ahead // 2`` behind the newest read, so that the first case waiting is always submitted
    before reading stops), submitted to ``executor``, delivered in order."""
    waiting = collections.deque()       # cases read and not yet delivered, in order
    ready = {}                          # index -> result, for cases of ``waiting``
    chunker = Chunker(size, max(1, ahead // 2))
    running = {}                        # future -> index of its chunk's first case
    failed = math.inf                   # index of the first failing case known
    unread = True

    def submit(chunks):
        for chunk in chunks:
            running[executor.submit(run_chunk, fn, chunk)] = chunk[0].index

    try:
        while True:
            while unread and failed == math.inf and len(waiting) < ahead:
                case = next(cases, None)
                if case is None:
                    unread = False
                    break
                waiting.append(case)
                submit(chunker.add(case))
            if not unread or failed < math.inf:
                submit(chunker.flush(below=failed))
            while waiting and waiting[0].index in ready:
                case = waiting.popleft()
                res = ready.pop(case.index)
                yield case, res
                if isinstance(res, Exception):
                    return
            if not waiting:
                if unread and failed == math.inf:
                    continue                # all read so far delivered: read on
                return
            done, _ = wait(running, return_when=FIRST_COMPLETED)
            for fut in done:
                del running[fut]
                if fut.cancelled():
                    continue
                items = fut.result()
                on_done(len(items))
                ready.update(items)
                failed = min([failed] + [i for i, r in items if isinstance(r, Exception)])
            for fut, first in list(running.items()):
                if first > failed and fut.cancel():
                    del running[fut]
    finally:
        for fut in running:
            fut.cancel()
