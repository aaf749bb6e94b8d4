"""Shared pytest configuration.

No known-open cases: the manufactured-solution suites pass in full, including exponents
within 3e-9 of +-1 (a/b = +-1e8) and gaps of 1e-6 between intervals (where the phi error is
measured against the rounding floor of the discrete system, see
``tests/sie/test_sie_intervals.py::rounding_scale``).  If a case has to be marked xfail, mark it
on the test with its exact id and ``strict=True``.
"""

import shutil
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

_BACKGROUND = pytest.StashKey()


class Background:
    """Work that slow tests wait for, started as soon as collection ends.

    A test module that defines ``start_in_background(background)`` and ``BACKGROUND_FOR`` (the
    names of the fixtures that use that work) has it called once, when the tests selected
    include one that uses such a fixture (and not under ``--collect-only``); the fixture then
    takes the results of what it started (and starts the work itself where the module was not
    started so).  The jobs run two at a time in threads of this process and each waits on
    child processes (a Sphinx build, the validation report, interpreters that compile the
    numba kernels): the suite itself runs in one process on one core, and these use the
    other while the suite runs the tests before them.  What is left of them when the session
    ends is dropped (the jobs not started; a job running finishes on its own)."""

    def __init__(self):
        self._pool = ThreadPoolExecutor(2, thread_name_prefix="tests-background")
        self._root = Path(tempfile.mkdtemp(prefix="pytest-background-"))

    def submit(self, fn, *args):
        """Run fn(*args) in the background: a concurrent.futures.Future."""
        return self._pool.submit(fn, *args)

    def mkdtemp(self, name):
        """A new empty directory, removed at the end of the session."""
        return Path(tempfile.mkdtemp(prefix=f"{name}-", dir=self._root))

    def close(self):
        self._pool.shutdown(wait=False, cancel_futures=True)
        shutil.rmtree(self._root, ignore_errors=True)


def pytest_collection_finish(session):
    if session.config.option.collectonly:
        return
    starts = {}                           # in the order the tests will run
    for item in session.items:
        module = getattr(item, "module", None)
        start = getattr(module, "start_in_background", None)
        if start is not None and module not in starts and \
                set(getattr(module, "BACKGROUND_FOR", ())) & set(getattr(item, "fixturenames", ())):
            starts[module] = start
    if starts:
        background = session.config.stash[_BACKGROUND] = Background()
        for start in starts.values():
            start(background)


def pytest_sessionfinish(session):
    background = session.config.stash.get(_BACKGROUND, None)
    if background is not None:
        background.close()
    # the mpmath references computed in this run (tests/reference/_stored.py), if any module
    # used them
    stored = sys.modules.get("_stored")
    if stored is not None:
        stored.write_all()


@pytest.fixture(autouse=True)
def _mpmath_precision():
    """mpmath's working precision restored after every test: a test that sets its own leaves
    the next one what it found (a module's fixture may set it for the module's tests)."""
    import mpmath
    dps = mpmath.mp.dps
    yield
    mpmath.mp.dps = dps
