"""Running the ``contact`` command line inside the test process, and the environment
of a child Python that imports the project."""
from __future__ import annotations

import contextlib
import io
import os
from pathlib import Path

from contact import cli

#: The project's root: a child Python imports sie and contact from there.
ROOT = Path(__file__).resolve().parents[2]


def run_cli(*args):
    """``contact ARGS`` in this process: (exit status, stdout, stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = cli.main([str(a) for a in args])
    return rc, out.getvalue(), err.getvalue()


def child_env() -> dict:
    """This process's environment, with the project importable from any directory."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), env.get("PYTHONPATH", "")])
    return env
