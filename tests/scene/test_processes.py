"""The application's pause of Python's cyclic collector over a run
(contact.scene.processes.cyclic_gc_paused): counted over the process's threads, restored as
it was, and what a process forked inside a pause (a pool's worker) gets."""
import gc
import os
import threading

import pytest

import contact
from contact.scene.processes import cyclic_gc_paused


def test_a_pause_leaves_the_collector_as_it_was():
    assert gc.isenabled()
    with pytest.raises(contact.ContactLossError):
        with cyclic_gc_paused():
            assert not gc.isenabled()
            raise contact.ContactLossError("inside")
    assert gc.isenabled()
    gc.disable()
    try:
        with cyclic_gc_paused():
            assert not gc.isenabled()
        assert not gc.isenabled()
    finally:
        gc.enable()


def test_pauses_in_two_threads_leave_the_collector_off_until_the_last_ends():
    """A thread's pause that ends while another thread's is open leaves the collector off;
    it comes back with the last."""
    entered, release = threading.Event(), threading.Event()

    def other():
        with cyclic_gc_paused():
            entered.set()
            release.wait(10)

    assert gc.isenabled()
    t = threading.Thread(target=other)
    with cyclic_gc_paused():
        t.start()
        assert entered.wait(10)
    assert not gc.isenabled()           # this thread's pause ended, the other's is open
    release.set()
    t.join(10)
    assert gc.isenabled()


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs os.fork")
@pytest.mark.filterwarnings("ignore:This process .* is multi-threaded:DeprecationWarning")
@pytest.mark.parametrize("on_before", [True, False])
def test_a_process_forked_inside_a_pause_gets_the_collector_as_before(on_before):
    """A child forked while a pause is open never reaches its end (a pool's worker leaves by
    os._exit): it starts with the collector as it was before the pause (if on, with what it
    inherited frozen), and with no pause open (its own then end with the collector as
    before)."""
    was = gc.isenabled()
    (gc.enable if on_before else gc.disable)()
    try:
        with cyclic_gc_paused():
            read, write = os.pipe()
            frozen = gc.get_freeze_count()
            pid = os.fork()
            if pid == 0:                                        # the child
                try:
                    states = [gc.get_freeze_count() > frozen, gc.isenabled()]
                    with cyclic_gc_paused():
                        states.append(gc.isenabled())
                    states.append(gc.isenabled())
                    os.write(write, bytes(states))
                finally:
                    os._exit(0)
            os.close(write)
            with os.fdopen(read, "rb") as fh:
                states = [bool(b) for b in fh.read()]
            os.waitpid(pid, 0)
            assert not gc.isenabled()                           # the parent's pause is open
        assert states == [on_before, on_before, False, on_before]
        assert gc.isenabled() is on_before
    finally:
        (gc.enable if was else gc.disable)()
