"""The numba on-disk cache never breaks ``sie`` (sie/_jit.py).

Each case runs ``import sie; sie.gauss_jacobi(20, 0.3, -0.2)`` in a fresh
interpreter (``sys.executable -c``) and compares the nodes and weights bit for
bit with a reference run that compiled into an empty, writable cache:

(i)   ``SIE_NUMBA_CACHE=0``: no cache at all (nothing is written);
(ii)  ``NUMBA_CACHE_DIR`` read-only (chmod 0o555), or, when running as root
      (root writes anyway), a path below a regular file, which can never be
      created (numba then falls back to the package's own __pycache__); and
      no writable location at all (NUMBA_CACHE_DIR and XDG_CACHE_HOME below a
      regular file, a copy of the package whose __pycache__ is a file), where
      sie/_jit.py must compile without a cache;
(iii) every cached file overwritten with garbage after a first run; and the
      nastier variant where the index (.nbi) files are intact and only the
      data (.nbc) files are garbage (a process killed while writing).
Each subprocess that finds no usable cache compiles the kernels of the package
(~5-10 s).  The runs of all cases are independent interpreters, so they run two at
a time, all started by the module fixture ``runs`` -- or, in a session that selects
these tests, by tests/conftest.py as soon as collection ends, while the tests before
these run (the suite itself runs on one core) -- and each test then judges its own
case's runs.  The "first run" of the corrupt-cache cases is a copy of the reference
run's cache (the files a first run writes), not a compilation of its own.
"""
from __future__ import annotations

import json
import os
import shutil
import stat
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

#: every test here waits for interpreters that compile the kernels (~40 s for the module)
pytestmark = pytest.mark.slow

REPO = Path(__file__).resolve().parents[2]

CHILD = """
import json, sys, sie, sie._jit
from numba.core.dispatcher import Dispatcher
x, w = sie.gauss_jacobi(20, 0.3, -0.2)
# which cache class each compiled kernel of the package got (FunctionCache / NullCache)
kinds = sorted({type(getattr(d, "_cache", None)).__name__
                for name, mod in list(sys.modules.items()) if name.startswith("sie.")
                for d in vars(mod).values() if isinstance(d, Dispatcher)})
print(json.dumps({"x": [v.hex() for v in x.tolist()], "w": [v.hex() for v in w.tolist()],
                  "cache_enabled": sie._jit.CACHE_ENABLED, "sie_file": sie.__file__,
                  "cache_kinds": kinds}))
"""


def run_child(cache_dir=None, sie_cache=None, pythonpath=REPO, extra_env=None, timeout=300):
    env = {k: v for k, v in os.environ.items()
           if k not in ("NUMBA_CACHE_DIR", "SIE_NUMBA_CACHE", "NUMBA_DISABLE_JIT", "PYTHONPATH")}
    env["PYTHONPATH"] = str(pythonpath)
    env.update(extra_env or {})
    if cache_dir is not None:
        env["NUMBA_CACHE_DIR"] = str(cache_dir)
    if sie_cache is not None:
        env["SIE_NUMBA_CACHE"] = sie_cache
    p = subprocess.run([sys.executable, "-c", CHILD], env=env, cwd=pythonpath, capture_output=True,
                       text=True, timeout=timeout)
    assert p.returncode == 0, f"child failed (rc={p.returncode}):\n{p.stderr[-3000:]}"
    out = json.loads(p.stdout.strip().splitlines()[-1])
    out["stderr"] = p.stderr
    return out


def cache_files(root):
    return sorted(p for p in Path(root).rglob("*") if p.is_file() and p.suffix in (".nbi", ".nbc"))


def copy_package(dest):
    """A copy of the sie package below ``dest`` (sources only: no bytecode, no cache)."""
    shutil.copytree(REPO / "sie", dest / "sie",
                    ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc", "*.stamp"))
    return dest


# --------------------------------------------------------------------------------------
# the cases: each a function of its own empty directory, run in a thread of the fixture
# ``runs``; it returns what its test judges (an exception is raised again by that test)
# --------------------------------------------------------------------------------------
def case_reference(tmp):
    """A first run into an empty writable cache directory: compiles and writes the cache."""
    cache = tmp / "cache"
    cache.mkdir()
    return {"out": run_child(cache_dir=cache), "cache": cache, "files": cache_files(cache)}


def case_cache_off(tmp):
    cache = tmp / "cache"
    cache.mkdir()
    return {"out": run_child(cache_dir=cache, sie_cache="0"), "files": cache_files(cache)}


def _unwritable_cache_dir(tmp_path):
    """A read-only directory, or (as root, who can write anyway) a path below a regular file."""
    ro = tmp_path / "readonly"
    ro.mkdir()
    ro.chmod(stat.S_IRUSR | stat.S_IXUSR | stat.S_IRGRP | stat.S_IXGRP | stat.S_IROTH | stat.S_IXOTH)
    if not os.access(ro, os.W_OK):
        return ro, "read-only directory"
    ro.chmod(0o755)                     # root: chmod does not stop writes
    blocker = tmp_path / "file.txt"
    blocker.write_text("a regular file: nothing can be created below it\n")
    return blocker / "sub", "path below a regular file"


def case_unwritable(tmp):
    cache, kind = _unwritable_cache_dir(tmp)
    try:
        return {"out": run_child(cache_dir=cache), "kind": kind}
    finally:
        if cache.name == "readonly":
            cache.chmod(0o755)


def case_no_writable_location(tmp):
    blocker = tmp / "file.txt"
    blocker.write_text("a regular file: nothing can be created below it\n")
    pkg_root = copy_package(tmp / "pkg")
    (pkg_root / "sie" / "__pycache__").write_text("not a directory\n")
    out = run_child(cache_dir=blocker / "numba", pythonpath=pkg_root,
                    extra_env={"XDG_CACHE_HOME": str(blocker / "xdg"), "PYTHONDONTWRITEBYTECODE": "1"})
    return {"out": out, "pkg_root": pkg_root,
            "written": list(tmp.rglob("*.nbi")) + list(tmp.rglob("*.nbc"))}


def _first_run(reference, tmp):
    """The cache as a first run into an empty directory leaves it: the reference's files."""
    cache = tmp / "cache"
    shutil.copytree(reference.result()["cache"], cache)
    return cache


def case_corrupt_files(tmp, reference):
    """Every .nbi and .nbc overwritten with garbage after a first run."""
    cache = _first_run(reference, tmp)
    files = cache_files(cache)
    for f in files:
        f.write_bytes(b"\x80\x04garbage, not a pickle \xff\x00" * 3)
    out = run_child(cache_dir=cache)
    # and once more, now that the cache has been rebuilt (or left alone)
    return {"files": files, "outs": [out, run_child(cache_dir=cache)]}


def case_corrupt_data_only(tmp, reference):
    """Index files intact, data files (.nbc) garbage, e.g. a process killed mid-write."""
    cache = _first_run(reference, tmp)
    data = [f for f in cache_files(cache) if f.suffix == ".nbc"]
    for f in data:
        f.write_bytes(f.read_bytes()[: len(f.read_bytes()) // 3])   # truncated
    return {"data": data, "out": run_child(cache_dir=cache)}


def case_module_changed(tmp):
    """A copy of the package run three times on one cache: a first run, again with nothing
    changed, and after a change to sie/_dd.py (the gaussjacobi kernels' entries before and
    after each)."""
    pkg_root = copy_package(tmp / "pkg")
    cache = tmp / "cache"

    def entries():
        return {f.name: f.stat().st_mtime_ns for f in cache_files(cache)
                if f.name.startswith("gaussjacobi.")}
    outs, states = [], []
    outs.append(run_child(cache_dir=cache, pythonpath=pkg_root))
    states.append(entries())
    stamped = bool(list(cache.rglob("sie-sources.stamp")))
    outs.append(run_child(cache_dir=cache, pythonpath=pkg_root))
    states.append(entries())
    dd = pkg_root / "sie" / "_dd.py"
    dd.write_text(dd.read_text() + "\n# a change to a module of callees\n")
    outs.append(run_child(cache_dir=cache, pythonpath=pkg_root))
    states.append(entries())
    return {"outs": outs, "entries": states, "stamped": stamped}


class _Runs:
    """The cases' results by name: a case's exception is raised again where it is asked."""

    def __init__(self, futures):
        self._futures = futures

    def __getitem__(self, name):
        return self._futures[name].result()


def _start(submit, mkdtemp):
    """Every case submitted (``submit(fn, *args)`` -> a future), each in a directory of its
    own (``mkdtemp(name)``): the reference first, the cases that copy its cache last."""
    futures = {}

    def start(name, fn, *args):
        futures[name] = submit(fn, mkdtemp(f"numba_{name}"), *args)
    start("reference", case_reference)
    start("module_changed", case_module_changed)
    start("cache_off", case_cache_off)
    start("no_writable_location", case_no_writable_location)
    start("unwritable", case_unwritable)
    start("corrupt_files", case_corrupt_files, futures["reference"])
    start("corrupt_data_only", case_corrupt_data_only, futures["reference"])
    return futures


#: the fixture ``runs`` is what tests/conftest.py starts early (the interpreters, ~80 s of
#: one core, run while the tests before these run)
BACKGROUND_FOR = ("runs",)
_STARTED = {}


def start_in_background(background):
    _STARTED.update(_start(background.submit, background.mkdtemp))


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """Every case's runs: those started in the background by tests/conftest.py, or started
    here, two interpreters at a time (one where one core is usable)."""
    if _STARTED:
        futures = dict(_STARTED)
        _STARTED.clear()
        yield _Runs(futures)
        return
    workers = max(1, min(2, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity")
                         else os.cpu_count() or 1))
    with ThreadPoolExecutor(workers) as pool:
        futures = _start(pool.submit, tmp_path_factory.mktemp)
        yield _Runs(futures)
        for future in futures.values():     # a test that failed early: its cases still end
            future.cancel()


@pytest.fixture(scope="module")
def reference(runs):
    """The reference run: it wrote both kinds of cache files, with the cache on."""
    ref = runs["reference"]
    out = ref["out"]
    assert out["cache_enabled"] is True
    assert out["cache_kinds"] == ["FunctionCache"], out["cache_kinds"]
    files = ref["files"]
    assert any(f.suffix == ".nbi" for f in files) and any(f.suffix == ".nbc" for f in files), \
        "the reference run wrote no cache files: the cache is not in use"
    assert len(out["x"]) == 20 and len(out["w"]) == 20
    return out


def same_numbers(out, ref):
    assert out["x"] == ref["x"], "nodes differ from the reference run"
    assert out["w"] == ref["w"], "weights differ from the reference run"


def test_cache_off_by_environment(reference, runs):
    run = runs["cache_off"]
    out = run["out"]
    same_numbers(out, reference)
    assert out["cache_enabled"] is False
    assert out["cache_kinds"] == ["NullCache"], out["cache_kinds"]
    assert run["files"] == [], "SIE_NUMBA_CACHE=0 must not write cache files"


def test_unwritable_cache_dir(reference, runs):
    run = runs["unwritable"]
    out = run["out"]
    same_numbers(out, reference)
    assert "Traceback" not in out["stderr"], f"{run['kind']}: {out['stderr'][-2000:]}"


def test_no_writable_cache_location_at_all(reference, runs):
    """No locator can work: NUMBA_CACHE_DIR and the user-wide cache (XDG_CACHE_HOME)
    below a regular file, and a copy of the package whose __pycache__ is a regular
    file.  numba then refuses cache=True at decoration time; sie must compile
    without the cache instead of failing at import."""
    run = runs["no_writable_location"]
    out = run["out"]
    assert out["sie_file"].startswith(str(run["pkg_root"])), out["sie_file"]
    same_numbers(out, reference)
    assert out["cache_kinds"] == ["NullCache"], out["cache_kinds"]     # the fallback really ran
    assert run["written"] == []
    assert "Traceback" not in out["stderr"], out["stderr"][-2000:]


def test_corrupt_cache_files(reference, runs):
    """Every .nbi and .nbc overwritten with garbage after a first run."""
    run = runs["corrupt_files"]
    assert run["files"]
    for out in run["outs"]:     # the run on garbage, then once more on what it left
        same_numbers(out, reference)


def test_corrupt_data_files_only(reference, runs):
    """Index files intact, data files (.nbc) garbage, e.g. a process killed mid-write."""
    run = runs["corrupt_data_only"]
    assert run["data"]
    same_numbers(run["out"], reference)


def test_entries_are_dropped_when_any_module_of_the_package_changed(reference, runs):
    """numba checks a kernel's entry against its own file alone, not against the modules of
    the kernels it compiles into itself: after a change to any module of the package every
    entry is dropped and compiled again (the gaussjacobi kernels here, their file untouched,
    after a change to sie/_dd.py whose kernels they call); with nothing changed, every entry
    is loaded as it is."""
    run = runs["module_changed"]
    for out in run["outs"]:
        same_numbers(out, reference)
    first, unchanged, again = run["entries"]
    assert first and run["stamped"]
    assert unchanged == first                                   # nothing changed: loaded
    assert again.keys() == first.keys()
    assert all(again[name] != first[name] for name in first)    # dropped and compiled again
