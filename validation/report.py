"""``make report``: the validation report, every number computed when it is built.

    python -m validation.report [--quick] [--out DIR] [--only 1,3,8]

Writes ``DIR/report.md`` and ``DIR/index.html`` (the same content) with the PNG figures beside
them; DIR defaults to ``validation/report/``.  ``--quick`` runs every section on a reduced grid
(small n, fewer speeds and frictions; the test suite's smoke build); the full build takes a few
minutes on 2 cores.

Sections (Zhou, Lee & Jang, Arch. Mech. 66 (2014); errata: see the documentation, Theory: errata
of Zhou et al. 2014):
 1. Table 1 beside the printed values          (validation/report_paper.py)
 2. kernel constants three ways, c_R           (validation/report_paper.py, reference_constants.py)
 3. Figures 1-4 reproduced, printed vs corrected (validation/report_paper.py)
 4. closed forms vs the numeric path           (validation/report_numerics.py)
 5. convergence in n                           (validation/report_numerics.py)
 6. work-precision, Gauss-Jacobi timing        (validation/report_numerics.py)
 7. hard cases                                 (validation/report_numerics.py)
 8. the paper's Sec. 6 claims                  (validation/report_paper.py)
 9. peer: ContactMechanics on Hertz            (validation/report_peer.py)
10. the stress field under the surface         (validation/report_subsurface.py)
11. partial slip and rolling (Cattaneo, Carter) (validation/report_slip.py)
"""
from __future__ import annotations

import argparse
import os
import platform
import sys
import time
import traceback
import warnings
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path

import numpy as np

from .report_doc import Doc

OUT = Path(__file__).resolve().parent / "report"
FIGURES = ("fig1_flat.png", "fig2_triangular.png", "fig3_parabolic.png", "fig4_cylindrical.png",
           "convergence.png", "work_precision.png", "peer_hertz.png",
           "subsurface_friction.png", "partial_slip.png")


@dataclass
class Ctx:
    doc: Doc
    out: Path
    quick: bool
    headline: dict = field(default_factory=dict)
    store: dict = field(default_factory=dict)
    timings: dict = field(default_factory=dict)
    failures: list = field(default_factory=list)


def _sections():
    from . import report_numerics as RN
    from . import report_paper as RP
    from . import report_peer as RPe
    from . import report_slip as RSl
    from . import report_subsurface as RS
    return [
        ("1", RP.section_table1),
        ("2", RP.section_constants),
        ("3", RP.section_figures),
        ("4", RN.section_closed_forms),
        ("5", RN.section_convergence),
        ("6", RN.section_work_precision),
        ("7", RN.section_hard_cases),
        ("8", RP.section_claims),
        ("9", RPe.section_peer),
        ("10", RS.section_subsurface),
        ("11", RSl.section_partial_slip),
    ]


def _versions():
    import numba
    import scipy
    parts = [f"Python {sys.version.split()[0]}", f"numpy {np.__version__}", f"scipy {scipy.__version__}",
             f"numba {numba.__version__}"]
    try:
        import matplotlib
        parts.append(f"matplotlib {matplotlib.__version__}")
    except ImportError:
        pass
    return ", ".join(parts)


def build(out=OUT, quick=False, only=None, log=print):
    """Build the report into ``out``; returns the Ctx (headline numbers, timings, failures)."""
    import matplotlib
    matplotlib.use("Agg")
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    for name in FIGURES:                  # no stale figure from an earlier build (e.g. a skipped peer)
        if (out / name).exists():
            (out / name).unlink()
    doc = Doc("Validation report: Cauchy SIEs and the moving frictional punch (Zhou, Lee & Jang 2014)")
    ctx = Ctx(doc=doc, out=out, quick=quick)
    t_all = time.perf_counter()
    for key, fn in _sections():
        if only and key not in only:
            continue
        log(f"report: section {key} ...")
        t0 = time.perf_counter()
        n_blocks = len(doc.blocks)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")          # warnings are reported as numbers instead
                fn(ctx)
        except Exception as exc:                          # a broken section must not hide the rest
            del doc.blocks[n_blocks + 1:]
            if len(doc.blocks) == n_blocks:
                doc.h(f"{key}. (section failed)")
            doc.p(f"**This section failed while the report was built:** `{type(exc).__name__}: {exc}`")
            doc.pre(traceback.format_exc())
            ctx.failures.append((key, f"{type(exc).__name__}: {exc}"))
            log(traceback.format_exc())
        ctx.timings[key] = time.perf_counter() - t0
        log(f"report: section {key} done in {ctx.timings[key]:.1f} s")
    total = time.perf_counter() - t_all

    head = Doc("")
    head.p(f"Built {datetime.now(timezone.utc).strftime('%Y-%m-%d %H:%M UTC')} on {os.cpu_count()} cores "
           f"({platform.machine()}), {_versions()}; mode: **{'quick (reduced grid)' if quick else 'full'}**; "
           f"build time {total:.0f} s (" + ", ".join(f"section {k}: {v:.1f} s" for k, v in ctx.timings.items())
           + "). Every number below was computed in this build; times are wall times (best of a few "
             "warm calls unless said) on this shared machine and vary by tens of percent between builds. "
             "Conventions: p > 0 compressive, "
             "direction -1 = punch sliding toward -X (trailing edge on the right), mu_f = -direction mu, "
             "Hc[f](X) = (1/pi) PV int f(t)/(t - X) dt; relative speed c = V/sqrt(C33/rho).")
    head.h("Headline numbers")
    head.ul([f"**{k}.** {v}" for k, v in sorted(ctx.headline.items(), key=lambda kv: int(kv[0]))]
            + ([f"**Failed sections:** {', '.join(k for k, _ in ctx.failures)}"] if ctx.failures else []))
    doc.blocks[0:0] = head.blocks
    doc.write(out)
    ctx.store["build_time"] = total
    log(f"report: wrote {out / 'report.md'} and {out / 'index.html'} in {total:.0f} s")
    return ctx


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m validation.report", description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="reduced grids (smoke build, < 1 min)")
    ap.add_argument("--out", type=Path, default=OUT, help=f"output directory (default {OUT})")
    ap.add_argument("--only", default=None, help="comma-separated section numbers to build (default: all)")
    args = ap.parse_args(argv)
    only = set(args.only.split(",")) if args.only else None
    ctx = build(args.out, quick=args.quick, only=only)
    return 1 if ctx.failures else 0


if __name__ == "__main__":
    sys.exit(main())
