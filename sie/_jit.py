"""One project-wide numba ``jit`` wrapper.

Every compiled kernel in the library goes through :func:`jit` so that the
defaults live in one place: ``nopython`` (no object mode), ``nogil``,
``cache=True`` and one eagerly-declared signature at most.

Environment
-----------
``SIE_NUMBA_CACHE=0``
    Turn the on-disk cache off (compile in every process).

Robustness
----------
* A read-only package directory: numba itself falls back to the user-wide
  cache directory (or ``NUMBA_CACHE_DIR``); if no location is writable at
  all, numba refuses ``cache=True`` at decoration time, and we then compile
  without a cache instead of failing at import.
* A corrupt cache index (a truncated ``.nbi`` file, e.g. from a killed
  process) makes numba raise an unpickling error on first call; we detect
  unreadable index files of this package at import and remove them, or turn
  caching off if they cannot be removed.
* A corrupt data file (``.nbc``) behind a valid index is only found when the
  kernel is first called: every dispatcher's cache lookup is wrapped so that a
  failing load counts as a cache miss (numba then compiles and overwrites the
  entry).
* numba checks a kernel's entry against its own file only, not against the
  files of the kernels it calls and compiles into itself: the package's entries
  are dropped wherever any of its modules changed since they were written
  (:func:`_drop_stale_entries`).
"""
from __future__ import annotations

import os
import pickle
import warnings
from pathlib import Path

import numba

__all__ = ["jit", "CACHE_ENABLED"]

_OFF = {"0", "false", "no", "off"}
CACHE_ENABLED = os.environ.get("SIE_NUMBA_CACHE", "1").strip().lower() not in _OFF


def _index_files():
    """Numba cache index files that may belong to this package."""
    here = Path(__file__).resolve().parent
    roots = [here / "__pycache__"]
    user_dir = os.environ.get("NUMBA_CACHE_DIR")
    if user_dir:
        roots.append(Path(user_dir))
    for root in roots:
        if root.is_dir():
            yield from root.rglob("*.nbi")


def _sanitize_cache() -> bool:
    """Remove unreadable cache index files; return False if caching must be off."""
    ok = True
    for index in _index_files():
        try:
            with open(index, "rb") as fh:
                pickle.load(fh)  # the version header
                stamp_and_overloads = fh.read()
            pickle.loads(stamp_and_overloads)
        except Exception:  # any unpickling error means the file is unusable
            try:
                index.unlink()
            except OSError:
                ok = False
    return ok


if CACHE_ENABLED and not _sanitize_cache():
    warnings.warn(
        "sie: a corrupt numba cache index could not be removed; compiling without the cache",
        RuntimeWarning,
        stacklevel=2,
    )
    CACHE_ENABLED = False


_WARNED: list = []
_STAMPED: list = []
#: Beside the package's cache entries: the stat of every module of the package when they
#: were written (:func:`_drop_stale_entries`).
STAMP_NAME = "sie-sources.stamp"


def _sources_stamp(modules) -> str:
    """(name, size, mtime) of every module of the package, as one line."""
    return repr(sorted((p.name, st.st_size, st.st_mtime_ns)
                       for p in modules for st in (p.stat(),)))


def _drop_stale_entries(dispatcher):
    """Once per process, at the first kernel decorated (before any is called): drop the
    package's cache entries where its modules changed since they were written.

    numba keys a kernel's entry by the stat of the kernel's own file, not of the files of
    the kernels it calls and compiles into itself: a kernel whose callee in another module
    changed would load its old machine code, silently (as ``sie.batch._cauchy_limits`` kept
    an old ``sie.cauchy_kernels._f0``).  A stamp of every module's stat kept beside the
    entries catches that; a changed stamp drops them all (recompiled on first call).
    Installed packages never change: one stat per module at import."""
    if _STAMPED:
        return
    _STAMPED.append(True)
    where = getattr(getattr(dispatcher, "_cache", None), "_cache_path", None)
    if not where:
        return
    where = Path(where)
    modules = list(Path(__file__).resolve().parent.glob("*.py"))
    stamp = _sources_stamp(modules)
    try:
        if (where / STAMP_NAME).read_text() == stamp:
            return
    except OSError:
        pass                                # none yet (a first run), or unreadable
    ours = {p.stem for p in modules}
    try:
        for entry in where.iterdir():
            if entry.suffix in (".nbi", ".nbc") and entry.name.split(".", 1)[0] in ours:
                entry.unlink(missing_ok=True)
        (where / STAMP_NAME).write_text(stamp)
    except OSError:     # a cache numba cannot write either: it compiles in memory then
        pass


def _tolerate_corrupt_entries(dispatcher):
    """Make an unreadable cache entry a cache miss instead of an error on first call."""
    cache = getattr(dispatcher, "_cache", None)
    load = getattr(cache, "load_overload", None)
    if load is None:
        return dispatcher

    def load_overload(*args, **kwargs):
        try:
            return load(*args, **kwargs)
        except Exception:  # truncated / garbage .nbc: recompile and overwrite
            return None

    cache.load_overload = load_overload
    return dispatcher


def jit(signature=None, **options):
    """Compile a small, pure numeric kernel with the library's defaults.

    Parameters
    ----------
    signature : str or numba signature, optional
        One eager signature (compiling several signatures eagerly is what
        makes imports slow; we never do).
    **options
        Extra numba options (rarely needed); ``cache``, ``nopython`` and
        ``nogil`` are fixed here.
    """
    opts = dict(nopython=True, nogil=True, cache=CACHE_ENABLED, error_model="numpy")
    opts.update(options)

    def decorate(fn):
        args = (signature,) if signature is not None else ()
        try:
            dispatcher = numba.jit(*args, **opts)(fn)
            if opts.get("cache"):
                _drop_stale_entries(dispatcher)
            return _tolerate_corrupt_entries(dispatcher)
        except RuntimeError as exc:  # "cannot cache function ...: no locator available"
            if not opts.get("cache"):
                raise
            if not _WARNED:                       # once per process, not once per kernel
                _WARNED.append(True)
                warnings.warn(f"sie: numba cache unavailable ({exc}); compiling without it",
                              RuntimeWarning, stacklevel=2)
            return numba.jit(*args, **{**opts, "cache": False})(fn)

    return decorate
