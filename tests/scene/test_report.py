"""Smoke build of the validation report (``python -m validation.report --quick``) on a reduced
grid: every section builds, the files and figures exist and are real pictures, and a few
headline numbers are where the full report puts them.  The full report (``make report``)
stays outside the test suite."""
from __future__ import annotations

import pickle
import re
import subprocess
import sys
import types
from pathlib import Path

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
import matplotlib.image  # noqa: E402

from validation import report  # noqa: E402

FIGURES = ("fig1_flat.png", "fig2_triangular.png", "fig3_parabolic.png", "fig4_cylindrical.png",
           "convergence.png", "work_precision.png", "subsurface_friction.png",
           "partial_slip.png")

REPO = Path(__file__).resolve().parents[2]

# the build in a child interpreter, which hands back what the tests read of its Ctx (the
# entries of ctx.store that pickle: the numbers; not the solutions some sections keep)
CHILD = """
import pickle, sys, time
from validation import report
t0 = time.perf_counter()
ctx = report.build(sys.argv[1], quick=True, log=lambda *a: None)
elapsed = time.perf_counter() - t0
store = {}
for key, value in ctx.store.items():
    try:
        store[key] = pickle.loads(pickle.dumps(value))
    except Exception:
        pass
with open(sys.argv[2], "wb") as fh:
    pickle.dump(dict(failures=ctx.failures, timings=ctx.timings, headline=ctx.headline,
                     store=store, elapsed=elapsed), fh)
"""


def _build(root):
    """``report.build(quick=True)`` into ``root/report`` in a child interpreter: (the folder,
    a namespace of the Ctx's failures, timings, headline and store, the build's seconds)."""
    out, got = root / "report", root / "ctx.pickle"
    proc = subprocess.run([sys.executable, "-c", CHILD, str(out), str(got)], cwd=REPO,
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr[-6000:]
    with open(got, "rb") as fh:
        ctx = types.SimpleNamespace(**pickle.load(fh))
    return out, ctx, ctx.elapsed


#: the fixture ``built`` is what tests/conftest.py starts early (the quick build, ~25 s, runs
#: while the tests before these run)
BACKGROUND_FOR = ("built",)
_STARTED = {}


def start_in_background(background):
    _STARTED["report"] = background.submit(_build, background.mkdtemp("report"))


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    started = _STARTED.pop("report", None)
    return started.result() if started else _build(tmp_path_factory.mktemp("report"))


@pytest.mark.slow
def test_every_section_builds(built):
    out, ctx, elapsed = built
    print(f"[report] quick build {elapsed:.1f} s, sections: "
          + ", ".join(f"{k}: {v:.1f} s" for k, v in ctx.timings.items()))
    assert ctx.failures == []
    assert set(ctx.timings) == {str(k) for k in range(1, 12)}
    assert set(ctx.headline) == {str(k) for k in range(1, 12)}


@pytest.mark.slow
def test_files_exist_and_figures_are_pictures(built):
    out, ctx, _ = built
    md = (out / "report.md").read_text(encoding="utf-8")
    html = (out / "index.html").read_text(encoding="utf-8")
    for k in range(1, 12):
        assert re.search(rf"^## {k}\. ", md, re.M), f"section {k} heading missing"
    referenced = set(re.findall(r"!\[[^\]]*\]\(([^)]+)\)", md))
    assert set(FIGURES) <= referenced
    if ctx.store["peer"]["peer"] is not None:
        assert "peer_hertz.png" in referenced
    for name in referenced:
        path = out / name
        assert path.exists() and path.stat().st_size > 10_000, name
        assert f'src="{name}"' in html
        img = matplotlib.image.imread(path)
        assert img.ndim == 3 and img.shape[0] >= 300 and img.shape[1] >= 600, (name, img.shape)
        assert float(np.std(img[..., :3])) > 0.02, f"{name} looks blank"
    # the two renderings carry the same tables
    assert md.count("\n|---") == html.count("<table>")


@pytest.mark.slow
def test_headline_numbers_in_bounds(built):
    _, ctx, _ = built
    st = ctx.store
    assert st["table1_worst"] <= 5.1e-5                        # 4 printed decimals
    assert abs(st["c_R"] - 0.9936147) < 1e-6
    assert max(st["constants"]["eig"], st["constants"]["fourier"]) <= 1e-10
    assert st["constants"]["isotropic"] <= 1e-13
    assert st["fig_cf_err"] <= 1e-10                           # numeric = closed form on the figures
    assert 0.1 <= st["cyl_printed_worst"] <= 1.0               # errata item 4: tens of percent
    assert st["cyl_printed_check"] <= 1e-10                    # ... and cos(pi alpha) fixes it
    assert st["exponent_worst"] > 0.9                          # errata item 2: printed branch is off by ~1
    assert st["closed_form_worst"] <= 1e-10
    hard = st["hard"]
    assert hard["sie"] <= 1e-9 and hard["contact"] <= 1e-10 and hard["constants"] <= 1e-13
    # convergence: rounded flat with breaks at rounding, without breaks not
    conv = st["convergence"]
    assert min(e for e in conv["rounded flat, breaks"][1] if e is not None) <= 1e-13
    assert min(e for e in conv["rounded flat, no breaks"][1] if e is not None) >= 1e-6
    # subsurface: Hertz (Johnson eq. 4.49: 0.30028 p0 at 0.78615 a) and mu* of the sliding cylinder
    sub = st["subsurface"]
    assert abs(sub["tau"] - 0.3002831060) <= 1e-9 and abs(sub["depth"] - 0.7861514) <= 1e-5
    assert sub["axis_err"] <= 1e-10 and 0.37 < sub["mu_star"] < 0.39
    # work-precision: the SIE core reaches 1e-12 and beats the scipy baseline at that n
    n, t_o, e_o, t_n, e_n = next(r for r in st["sie_wp"] if r[2] <= 1e-12)
    assert t_o < t_n
    # Sec. 6 claims: the cylindrical peak-location claim in c is refuted, the mu one reproduced
    claims = {(r[0], r[1]): r[2] for r in st["claims"]}
    assert claims[("6.5, Fig. 4a", "cylindrical: the peak compressive location moves toward -a as c increases")] \
        == "**refuted**"
    assert claims[("6.5, Fig. 4b", "cylindrical: the peak compressive location moves toward -a as mu increases")] \
        == "**reproduced**"
    # peer section: ours solves Hertz to rounding; the peer (if installed) is within 1e-1
    ours = st["peer"]["ours"]
    assert max(r[2] for r in ours) <= 1e-12 and max(r[3] for r in ours) <= 1e-12
    if st["peer"]["peer"] is not None:
        assert min(r[4] for r in st["peer"]["peer"]) <= 1e-2
    # partial slip and rolling: Cattaneo and Carter to rounding, Coulomb on a rounded flat
    slip = st["partial_slip"]
    assert max(slip.values()) <= 1e-12, slip


def test_cli_rejects_unknown_option(capsys):
    with pytest.raises(SystemExit) as exc:
        report.main(["--no-such-option"])
    assert exc.value.code == 2
