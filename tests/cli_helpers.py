"""Running the ``contact`` command line inside the test process."""
from __future__ import annotations

import contextlib
import io

from contact import cli


def run_cli(*args):
    """``contact ARGS`` in this process: (exit status, stdout, stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = cli.main([str(a) for a in args])
    return rc, out.getvalue(), err.getvalue()
