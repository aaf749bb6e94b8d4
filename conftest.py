"""Root pytest configuration: what the doctest collection of ``sie/`` and ``contact/`` skips.

``pyproject.toml`` runs pytest with ``--doctest-modules`` over ``tests``, ``sie`` and
``contact``, which imports every module there.  These are left out: entry points that run a
command, and the numba warm-up (it compiles every kernel when run as a script).
"""
collect_ignore = [
    "contact/__main__.py",     # ``python -m contact``: the command line
    "sie/warmup.py",           # ``python -m sie.warmup``: compiles and caches every kernel
]
