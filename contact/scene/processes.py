"""Process plumbing of the application: Python's cyclic collector paused over a run, and
what a process forked inside a pause (a pool's worker) gets.

A run keeps its results to its end; each pass of the collector that they set off walks the
young objects, and every so often all of the process's (numpy's, numba's, scipy's: ~1e5; a
Dask worker's ~1.6e5).  Reference counting frees what a run discards.
"""
from __future__ import annotations

import gc
import os
import threading
from contextlib import contextmanager

__all__ = ["cyclic_gc_paused"]

#: Open :func:`cyclic_gc_paused` blocks of this process (all threads together), and whether
#: the collector was on before the first of them: it comes back when the last one ends.
_gc_pauses = 0
_gc_on_before = False
_gc_lock = threading.Lock()


@contextmanager
def cyclic_gc_paused():
    """Python's cyclic garbage collector paused for a run of cases (and as it was before,
    after the last open pause of the process, whichever thread opened it).

    A process forked while a pause is open (a pool's worker started from inside one) gets
    the collector as it was before the pause: the child never reaches the pause's end (a
    pool's worker leaves by ``os._exit``), and would otherwise run without a collector for
    the rest of its life, whatever else it runs.  The objects it inherits are frozen there
    (:func:`gc.freeze`, as the Python documentation advises for a process forked without
    exec): its collections walk what it makes itself, not every object of numpy, numba and
    scipy, whose pages they would also copy by writing to them.
    """
    global _gc_pauses, _gc_on_before
    with _gc_lock:
        if _gc_pauses == 0:
            _gc_on_before = gc.isenabled()
        _gc_pauses += 1
        gc.disable()
    try:
        yield
    finally:
        with _gc_lock:
            # max: a forked child that leaves the pauses it inherited open counted them as
            # none (_gc_in_forked_child)
            _gc_pauses = max(0, _gc_pauses - 1)
            if _gc_pauses == 0 and _gc_on_before:
                gc.enable()


def _gc_in_forked_child():
    """After a fork, in the child: the collector as it was before the parent's open pauses
    (if on, with the inherited objects frozen), none of them open here, and a lock of its
    own (the parent's may have been held by a thread that the child does not have)."""
    global _gc_pauses, _gc_lock
    _gc_lock = threading.Lock()
    if _gc_pauses and _gc_on_before:
        gc.freeze()
        gc.enable()
    _gc_pauses = 0


if hasattr(os, "register_at_fork"):                 # POSIX; elsewhere processes are spawned
    os.register_at_fork(after_in_child=_gc_in_forked_child)
