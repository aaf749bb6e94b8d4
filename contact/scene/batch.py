"""Running a scene's cases in chunks: in this process, in a process pool or on a Dask cluster.

One task per case costs more than the case when the case is cheap (a cylindrical punch solves
in ~0.5 ms; a Dask task costs about that much to schedule, a process-pool task ~0.1 ms plus
pickling).  Cases therefore travel in chunks:

* grouped by (material, speed), so that a chunk shares the surface constants
  (:func:`contact.scene.run._shared_constants`, cached per process);
* sized to the work: a chunk holds about ``TARGET_CHUNK_S`` of solving, estimated from the
  first cases (solved in this process first), and there are at least ``CHUNKS_PER_WORKER``
  chunks per worker so that a slow chunk does not leave the others idle;
* each worker builds a material and a punch once per distinct spec (:func:`build_once`).

A case that fails in the library comes back as its exception, and the caller raises the first
one in scene order (a :class:`~contact.scene.spec.CaseError` naming the case), as a serial run
would.
"""
from __future__ import annotations

import functools
import math
import time
from concurrent.futures import as_completed

#: Seconds of solving a chunk aims at (tens of milliseconds: well above a task's overhead).
TARGET_CHUNK_S = 0.05
#: At least this many chunks per worker, for balance.
CHUNKS_PER_WORKER = 4
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


def chunks_of(cases, size):
    """Chunks of at most ``size`` cases that share material and speed: the cases grouped by
    (material, speed) in the order the groups first appear, each group cut in scene order
    (results are put back in scene order by the caller, whatever key the scene sweeps
    first)."""
    groups = {}
    for case in cases:
        groups.setdefault((case.material, case.speed), []).append(case)
    return [g[i:i + size] for g in groups.values() for i in range(0, len(g), size)]


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


def map_chunked(fn, cases, executor, on_done):
    """{index: result or exception} for the cases run.

    ``executor`` None: every case here, one after the other.  Otherwise the first three cases
    run here (the fastest sizes the chunks), the rest go to ``executor`` in chunks
    (:func:`chunk_size`, :func:`chunks_of`).  Once a case fails, chunks that start after it
    are cancelled and those before it are awaited, so the first failure in scene order is
    among the results.  ``on_done(k)`` is called as k cases finish.
    """
    done = {}

    def collect(items):
        for index, res in items:
            done[index] = res
        on_done(len(items))
        return min((i for i, r in items if isinstance(r, Exception)), default=None)

    if executor is None or len(cases) < 2:
        for case in cases:
            if collect(run_chunk(fn, [case])) is not None:
                break
        return done
    per_case = math.inf
    for case in cases[:_PROBE]:           # the first is slower (caches fill): take the fastest
        t0 = time.perf_counter()
        if collect(run_chunk(fn, [case])) is not None:
            return done
        per_case = min(per_case, time.perf_counter() - t0)
    rest = cases[_PROBE:]
    if not rest:
        return done
    size = chunk_size(len(rest), worker_count(executor), per_case)
    futures = {executor.submit(run_chunk, fn, chunk): chunk[0].index
               for chunk in chunks_of(rest, size)}
    try:
        failed = math.inf
        for fut in as_completed(futures):
            if fut.cancelled():
                continue
            bad = collect(fut.result())
            if bad is not None and bad < failed:
                failed = bad
                for other, first in futures.items():
                    if first > failed:
                        other.cancel()
    finally:
        for fut in futures:
            fut.cancel()
    return done
