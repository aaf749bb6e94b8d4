"""mpmath reference values kept in a JSON file of this directory, so that a test pays for its
slow quadratures once.

``SIE_TEST_RECOMPUTE_REFS=1`` ignores the file, computes every value again and rewrites it; a
key missing from the file is computed and added when the test session ends (:func:`write_all`,
from tests/conftest.py).  The values are the tests' own independent references (mpmath),
never the library's output.
"""
from __future__ import annotations

import json
import os
from pathlib import Path

__all__ = ["StoredReferences", "write_all"]

#: Every StoredReferences made in this process, for :func:`write_all`.
_MADE = []


class StoredReferences:
    """The values of one file: :meth:`real` and :meth:`complex` return the stored value of a
    key, or compute it (and keep it for :meth:`write`)."""

    def __init__(self, name: str):
        self.path = Path(__file__).resolve().parent / name
        recompute = os.environ.get("SIE_TEST_RECOMPUTE_REFS") == "1"
        self.values = {} if recompute or not self.path.exists() else \
            json.loads(self.path.read_text())
        self.new = {}
        _MADE.append(self)

    def real(self, key, compute) -> float:
        """The stored float of ``key``, or float(compute())."""
        if key in self.values:
            return self.values[key]
        value = float(compute())
        self.values[key] = self.new[key] = value
        return value

    def complex(self, key, compute) -> complex:
        """The stored complex value of ``key`` (as [re, im]), or complex(compute())."""
        if key in self.values:
            return complex(*self.values[key])
        value = complex(compute())
        self.values[key] = self.new[key] = [value.real, value.imag]
        return value

    def write(self) -> None:
        """Rewrite the file where this run computed values (sorted keys)."""
        if self.new:
            self.path.write_text(json.dumps(dict(sorted(self.values.items())), indent=0) + "\n")


def write_all() -> None:
    """:meth:`StoredReferences.write` of every file opened in this process."""
    for refs in _MADE:
        refs.write()
