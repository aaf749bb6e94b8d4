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
Each subprocess compiles the few kernels that n = 20 needs (~3-5 s).
"""
from __future__ import annotations

import json
import os
import shutil
import stat
import subprocess
import sys
from pathlib import Path

import pytest

#: every test here compiles the kernels in fresh interpreters (10-25 s each)
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


def run_child(cache_dir=None, sie_cache=None, pythonpath=REPO, extra_env=None, timeout=120):
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


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """A first run into an empty writable cache directory: compiles and writes the cache."""
    cache = tmp_path_factory.mktemp("numba_cache_ref")
    out = run_child(cache_dir=cache)
    assert out["cache_enabled"] is True
    assert out["cache_kinds"] == ["FunctionCache"], out["cache_kinds"]
    files = cache_files(cache)
    assert any(f.suffix == ".nbi" for f in files) and any(f.suffix == ".nbc" for f in files), \
        "the reference run wrote no cache files: the cache is not in use"
    assert len(out["x"]) == 20 and len(out["w"]) == 20
    return out


def same_numbers(out, ref):
    assert out["x"] == ref["x"], "nodes differ from the reference run"
    assert out["w"] == ref["w"], "weights differ from the reference run"


def test_cache_off_by_environment(reference, tmp_path):
    cache = tmp_path / "cache"
    cache.mkdir()
    out = run_child(cache_dir=cache, sie_cache="0")
    same_numbers(out, reference)
    assert out["cache_enabled"] is False
    assert out["cache_kinds"] == ["NullCache"], out["cache_kinds"]
    assert cache_files(cache) == [], "SIE_NUMBA_CACHE=0 must not write cache files"


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


def test_unwritable_cache_dir(reference, tmp_path):
    cache, kind = _unwritable_cache_dir(tmp_path)
    try:
        out = run_child(cache_dir=cache)
        same_numbers(out, reference)
    finally:
        if cache.name == "readonly":
            cache.chmod(0o755)
    assert "Traceback" not in out["stderr"], f"{kind}: {out['stderr'][-2000:]}"


def test_no_writable_cache_location_at_all(reference, tmp_path):
    """No locator can work: NUMBA_CACHE_DIR and the user-wide cache (XDG_CACHE_HOME)
    below a regular file, and a copy of the package whose __pycache__ is a regular
    file.  numba then refuses cache=True at decoration time; sie must compile
    without the cache instead of failing at import."""
    blocker = tmp_path / "file.txt"
    blocker.write_text("a regular file: nothing can be created below it\n")
    pkg_root = tmp_path / "pkg"
    shutil.copytree(REPO / "sie", pkg_root / "sie",
                    ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc"))
    (pkg_root / "sie" / "__pycache__").write_text("not a directory\n")
    out = run_child(cache_dir=blocker / "numba", pythonpath=pkg_root,
                    extra_env={"XDG_CACHE_HOME": str(blocker / "xdg"), "PYTHONDONTWRITEBYTECODE": "1"})
    assert out["sie_file"].startswith(str(pkg_root)), out["sie_file"]
    same_numbers(out, reference)
    assert out["cache_kinds"] == ["NullCache"], out["cache_kinds"]     # the fallback really ran
    assert not list(tmp_path.rglob("*.nbi")) and not list(tmp_path.rglob("*.nbc"))
    assert "Traceback" not in out["stderr"], out["stderr"][-2000:]


def test_corrupt_cache_files(reference, tmp_path):
    """Every .nbi and .nbc overwritten with garbage after a first run."""
    cache = tmp_path / "cache"
    run_child(cache_dir=cache)                        # populate
    files = cache_files(cache)
    assert files
    for f in files:
        f.write_bytes(b"\x80\x04garbage, not a pickle \xff\x00" * 3)
    out = run_child(cache_dir=cache)
    same_numbers(out, reference)
    # and once more, now that the cache has been rebuilt (or left alone)
    same_numbers(run_child(cache_dir=cache), reference)


def test_corrupt_data_files_only(reference, tmp_path):
    """Index files intact, data files (.nbc) garbage, e.g. a process killed mid-write."""
    cache = tmp_path / "cache"
    run_child(cache_dir=cache)
    data = [f for f in cache_files(cache) if f.suffix == ".nbc"]
    assert data
    for f in data:
        f.write_bytes(f.read_bytes()[: len(f.read_bytes()) // 3])   # truncated
    out = run_child(cache_dir=cache)
    same_numbers(out, reference)


def test_entries_are_dropped_when_any_module_of_the_package_changed(reference, tmp_path):
    """numba checks a kernel's entry against its own file alone, not against the modules of
    the kernels it compiles into itself: after a change to any module of the package every
    entry is dropped and compiled again (the gaussjacobi kernels here, their file untouched,
    after a change to sie/_dd.py whose kernels they call); with nothing changed, every entry
    is loaded as it is."""
    pkg_root = tmp_path / "pkg"
    shutil.copytree(REPO / "sie", pkg_root / "sie",
                    ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc", "*.stamp"))
    cache = tmp_path / "cache"

    def entries():
        return {f.name: f.stat().st_mtime_ns for f in cache_files(cache)
                if f.name.startswith("gaussjacobi.")}
    same_numbers(run_child(cache_dir=cache, pythonpath=pkg_root), reference)
    first = entries()
    assert first and list(cache.rglob("sie-sources.stamp"))
    same_numbers(run_child(cache_dir=cache, pythonpath=pkg_root), reference)
    assert entries() == first                                   # nothing changed: loaded
    dd = pkg_root / "sie" / "_dd.py"
    dd.write_text(dd.read_text() + "\n# a change to a module of callees\n")
    same_numbers(run_child(cache_dir=cache, pythonpath=pkg_root), reference)
    again = entries()
    assert again.keys() == first.keys()
    assert all(again[name] != first[name] for name in first)    # dropped and compiled again
