"""The figures of a scene: one PNG per curve field (a family coloured by the swept value) and,
with the ``"subsurface"`` field, two contour maps of the stress under the surface (small
multiples).  Each draws a fixed subset of the cases (:func:`evenly_spaced`),
so a sweep of any length draws in bounded time and memory."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from .run import SceneResult
from .spec import Scene, _fmt

#: The subsurface figures show at most this many cases (small multiples); a longer sweep shows
#: this many, evenly spaced through it (first and last included), and says so in the title.
SUBSURFACE_PANELS = 6
NO_MATPLOTLIB = ("matplotlib is not installed: no PNG figures written "
                 "(pip install 'sie-contact[plot]')")


def evenly_spaced(count: int, most: int) -> list:
    """Positions of at most ``most`` of ``count`` cases, evenly spaced through them (first and
    last included; all of them when there are no more than ``most``)."""
    if count <= most:
        return list(range(count))
    return np.unique(np.round(np.linspace(0, count - 1, most)).astype(int)).tolist()


# --------------------------------------------------------------------------
# the field under the surface: contour maps
# --------------------------------------------------------------------------
_MAP_LABELS = {"max_shear": "max shear (S)", "sigma_xx": r"$\sigma_{XX}$ (S)"}
_MAP_MARKS = {"max_shear": ("max_shear", "max shear"), "sigma_xx": ("max_tension",
                                                                    r"max tension $\sigma_1$")}


def _subsurface_shown(cases) -> list:
    """The cases the subsurface figures show: all, or SUBSURFACE_PANELS evenly spaced."""
    return _shown_cases(cases, SUBSURFACE_PANELS)


def _write_subsurface_figures(scene: Scene, shown: list, total: int, out: Path,
                              messages: list) -> list[Path]:
    """subsurface_max_shear.png and subsurface_sigma_xx.png: filled contours of each shown case
    (``shown``, at most SUBSURFACE_PANELS of the ``total`` cases: small multiples, one shared
    colour bar), the surface at the top, each contact zone a thick segment on it and the
    extremum marked (the largest max shear; on the sigma_XX map the largest tension
    sigma_1).  Without matplotlib: none, and a warning in ``messages``."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.ticker import MaxNLocator
    except ImportError:
        _no_matplotlib(messages)
        return []
    n = len(shown)
    title = scene.title
    if n < total:
        title += f"\n{n} of {total} cases shown (evenly spaced; subsurface.npz has all)"
    ncols = min(n, 3)
    nrows = -(-n // ncols)
    written = []
    for name in ("max_shear", "sigma_xx"):
        maps = [res.subsurface.quantity(name) for res in shown]
        lo, hi = _robust_limits(maps, pad=False)
        if name == "sigma_xx":
            top = max(abs(lo), abs(hi)) or 1.0
            lo, hi, cmap = -top, top, "RdBu_r"
        else:
            lo, hi, cmap = 0.0, (hi if hi > 0 else 1.0), "viridis"
        full = np.concatenate([m[np.isfinite(m)] for m in maps] or [np.zeros(1)])
        levels = MaxNLocator(nbins=20).tick_values(lo, hi)
        lo, hi = levels[0], levels[-1]
        extend = {(False, False): "neither", (True, False): "min", (False, True): "max",
                  (True, True): "both"}[(bool(full.size and full.min() < lo),
                                         bool(full.size and full.max() > hi))]
        # a fixed layout (no layout engine: constrained layout would double the time)
        pw, ph = (5.0, 3.8) if n == 1 else (3.3, 2.9)          # one panel's box, inches
        width, height = 1.5 + pw * ncols, (1.0 if n < total else 0.8) + ph * nrows
        left, right = 0.75 / width, 1.0 - 1.3 / width
        bottom, top = 0.55 / height, 1.0 - (0.75 if n < total else 0.55) / height
        fig, axes = plt.subplots(nrows, ncols, figsize=(width, height), squeeze=False,
                                 gridspec_kw=dict(left=left, right=right, bottom=bottom, top=top,
                                                  wspace=0.25, hspace=0.45))
        quantity, mark_label = _MAP_MARKS[name]
        for k, ax in enumerate(axes.flat):
            if k >= n:
                ax.set_axis_off()
                continue
            res = shown[k]
            m = res.subsurface
            cs = ax.contourf(m.x, m.y, maps[k], levels=levels, cmap=cmap, extend=extend)
            for z in res.zones:
                ax.plot(z["ends"], [0.0, 0.0], color="k", lw=4, solid_capstyle="butt",
                        clip_on=False, zorder=5, label="contact" if k == 0 and z is res.zones[0]
                        else None)
            e = res.entry["subsurface"][quantity]
            ax.plot([e["X"]], [e["Y"]], ls="none", marker="X", ms=8, mfc="w", mec="k",
                    zorder=6, clip_on=False, label=mark_label if k == 0 else None)
            ax.set_xlim(m.x[0], m.x[-1])
            ax.set_ylim(m.y[0], m.y[-1])
            ratio = (m.y[-1] - m.y[0]) / (m.x[-1] - m.x[0])
            if 0.2 <= ratio <= 5.0:
                ax.set_aspect("equal")
            if total > 1:
                ax.set_title(f"case {res.index}: {res.label}", fontsize=8)
            if k % ncols == 0:
                ax.set_ylabel("Y (L)")
            if k // ncols == nrows - 1 or k + ncols >= n:
                ax.set_xlabel("X (L)")
            ax.xaxis.set_major_locator(MaxNLocator(5))         # few ticks: each costs time
            ax.yaxis.set_major_locator(MaxNLocator(4))
            ax.tick_params(labelsize=8)
            if k == 0:
                ax.legend(fontsize=7, loc="lower right", framealpha=0.8)
        cax = fig.add_axes((right + 0.25 / width, bottom, 0.15 / width, top - bottom))
        ticks = MaxNLocator(6).tick_values(lo, hi)
        ticks = ticks[(ticks >= lo - 1e-9 * (hi - lo)) & (ticks <= hi + 1e-9 * (hi - lo))]
        cbar = fig.colorbar(cs, cax=cax, ticks=ticks)
        cbar.set_label(_MAP_LABELS[name])
        fig.suptitle(title, fontsize=10)
        path = out / f"subsurface_{name}.png"
        fig.savefig(path, dpi=100)
        plt.close(fig)
        written.append(path)
    return written


_AXIS_LABELS = {"pressure": "pressure p(X)", "shear": "shear traction q(X)",
                "sigma_xx": r"$\sigma_{XX}(X, 0)$"}
#: Units of the quantities in the figures (UNITS: stresses S, lengths L).
_CURVE_UNIT = "S"
_INPUT_UNITS = {"load": "S L", "radius": "L", "half_width": "L"}
#: A sweep's curve figures draw at most this many cases (evenly spaced through the sweep,
#: first and last included; the title says so).
MAX_CURVES = 200
#: A swept input with at most this many distinct values gets a discrete colour bar.
DISCRETE_COLOURS = 12
_LINESTYLES = ("-", "--", ":", "-.")


def _shown_cases(cases, most: int) -> list:
    """At most ``most`` of ``cases``, evenly spaced (:func:`evenly_spaced`)."""
    return [cases[k] for k in evenly_spaced(len(cases), most)]


def _input_label(key: str) -> str:
    unit = _INPUT_UNITS.get(key)
    return f"{key} ({unit})" if unit else key


def _no_matplotlib(messages: list) -> None:
    """The warning that no PNG is written, once in ``messages``."""
    if NO_MATPLOTLIB not in messages:
        messages.append(NO_MATPLOTLIB)


def _write_curve_figures(scene: Scene, shown: list, total: int, out: Path, name: str,
                         messages: list) -> list[Path]:
    """{name}.png, the figure of one curve field (:func:`curve_figure`) from the cases it
    draws (``shown``: at most MAX_CURVES of the ``total`` cases, evenly spaced).  Without
    matplotlib: none, and a warning in ``messages``."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        _no_matplotlib(messages)
        return []
    fig = _curve_figure(scene, shown, total, name)
    path = out / f"{name}.png"
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return [path]


def curve_figure(result: SceneResult, name: str):
    """The matplotlib figure of one curve field; the caller closes it.

    One case: its curve, the contact ends dotted (the zones shaded when there are several).
    A sweep: a family of curves (one LineCollection) coloured by the first swept input, with
    a colour bar (viridis; discrete ticks at its values when it takes few); a second swept
    input with at most 4 values is told apart by line style (legend), a further one is named
    in the title; the ends of every zone of a case with several are ticks on the axis in its
    colour.  At most :data:`MAX_CURVES` cases are drawn (evenly spaced; the title says so).
    """
    return _curve_figure(result.scene, _shown_cases(result.cases, MAX_CURVES),
                         len(result.cases), name)


def _curve_figure(scene: Scene, shown: list, total: int, name: str):
    """:func:`curve_figure` of the cases drawn, ``shown``, out of ``total``."""
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7.5, 4.5), layout="constrained")
    if total > 1 and scene.sweep:
        title = _draw_family(fig, ax, scene, shown, total, name)
    else:
        res = shown[0]
        x, v = res.curve(name)
        ax.plot(x, v, lw=1.3, color="C0")
        _draw_zones(ax, res.zones)
        ax.set_ylim(*_robust_limits([v]))
        title = scene.title
    ax.axhline(0.0, color="0.7", lw=0.6, zorder=0)
    ax.set_xlabel("X (L)")
    ax.set_ylabel(f"{_AXIS_LABELS[name]} ({_CURVE_UNIT})")
    ax.set_title(title, fontsize=10)
    return fig


def _draw_family(fig, ax, scene: Scene, shown: list, total: int, name: str) -> str:
    """A sweep's curves of one field on ``ax`` (see :func:`curve_figure`): ``shown``, out of
    ``total`` cases; returns the title."""
    import matplotlib as mpl
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D

    swept = [key for _, key in scene.sweep]
    key = swept[0]
    values = np.array([res.entry["inputs"][key] for res in shown], dtype=float)
    distinct = np.unique(values)
    cmap = mpl.colormaps["viridis"]
    if len(distinct) <= DISCRETE_COLOURS:
        mids = 0.5 * (distinct[1:] + distinct[:-1])
        first = distinct[0] - (mids[0] - distinct[0] if len(distinct) > 1 else 0.5)
        last = distinct[-1] + (distinct[-1] - mids[-1] if len(distinct) > 1 else 0.5)
        bounds = np.concatenate([[first], mids, [last]])
        norm = mpl.colors.BoundaryNorm(bounds, cmap.N)
        ticks = distinct
    else:
        norm = mpl.colors.Normalize(distinct[0], distinct[-1])
        ticks = None
    curves = [res.curve(name) for res in shown]
    segments = [np.column_stack([x, v]) for x, v in curves]
    styles = "solid"
    legend = []
    second = swept[1] if len(swept) > 1 else None
    notes = []
    if second is not None:
        other = [res.entry["inputs"][second] for res in shown]
        levels = list(dict.fromkeys(other))
        if len(levels) <= len(_LINESTYLES):
            styles = [_LINESTYLES[levels.index(v)] for v in other]
            legend = [Line2D([], [], color="0.3", lw=1.2, ls=_LINESTYLES[k],
                             label=f"{second} = {_fmt(v)}") for k, v in enumerate(levels)]
        else:
            notes.append(f"{second} also varies")
        notes += [f"{k} also varies" for k in swept[2:]]
    lc = LineCollection(segments, cmap=cmap, norm=norm, linewidths=1.2, linestyles=styles)
    lc.set_array(values)
    ax.add_collection(lc)
    xs = np.concatenate([x for x, _ in curves])
    ax.set_xlim(float(np.min(xs)), float(np.max(xs)))
    ax.set_ylim(*_robust_limits([v for _, v in curves]))
    marks = [(x, val) for res, val in zip(shown, values) if len(res.zones) > 1
             for z in res.zones for x in z["ends"]]
    if marks:
        mx, mv = np.array(marks).T
        ax.scatter(mx, np.zeros_like(mx), c=mv, cmap=cmap, norm=norm, marker="|", s=100,
                   linewidths=1.2, zorder=3)
    cbar = fig.colorbar(lc, ax=ax, ticks=ticks, pad=0.02)
    cbar.set_label(_input_label(key))
    if ticks is not None:
        whole = isinstance(shown[0].entry["inputs"][key], int)     # direction: -1, +1
        cbar.ax.set_yticklabels([_fmt(int(v) if whole else float(v)) for v in ticks])
    if legend:
        ax.legend(handles=legend, fontsize=8)
    title = scene.title
    if notes:
        title += f" ({'; '.join(notes)})"
    if len(shown) < total:
        title += (f"\n{len(shown)} of {total} cases drawn (evenly spaced; {name}.csv has "
                  "all)")
    return title


def _draw_zones(ax, zones):
    """One case: a dotted line at every contact end, each zone shaded when there are several."""
    for z in zones:
        for x_end in z["ends"]:
            ax.axvline(x_end, color="0.6", ls=":", lw=0.8)
        if len(zones) > 1:
            ax.axvspan(*z["ends"], color="0.85", alpha=0.5, lw=0)


def _robust_limits(curves, pad=True) -> tuple:
    """y-limits that show the curves without letting a sampled singular spike flatten them:
    the full range, unless it exceeds 4x the 1..99 percentile range (padded by 6 %, or not)."""
    v = np.concatenate([c[np.isfinite(c)].ravel() for c in curves] or [np.zeros(1)])
    if v.size == 0:
        return -1.0, 1.0
    lo, hi = float(v.min()), float(v.max())
    plo, phi = (float(q) for q in np.percentile(v, [1, 99]))
    if hi - lo > 4.0 * (phi - plo) > 0:
        lo, hi = plo, phi
    if not pad:
        return lo, hi
    pad = 0.06 * (hi - lo) if hi > lo else max(1.0, abs(hi))
    return lo - pad, hi + pad


