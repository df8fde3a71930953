"""Figures of a wing-body juncture, after TM-4406 figs 3-10 (matplotlib, Agg back end)."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

__all__ = ["plot_gap_and_intersection", "plot_lower_intersection", "plot_fillet_sections",
           "plot_station_areas"]


def _body_outline(ax, body, colour="0.4", label="body", ls="-"):
    x = np.linspace(body.x_global[0], body.x_global[-1], 400)
    r = body.radius_at(x)
    ax.plot(x, r + body.origin[1], color=colour, lw=1.2, ls=ls, label=label)


def plot_gap_and_intersection(cfg, geo, wing="wing", body="body"):
    """Planform: the input wing with its gap to the body, and the intersection line (fig 3)."""
    w, b = cfg[wing], cfg[body]
    fig, (a0, a1) = plt.subplots(2, 1, figsize=(11, 9), layout="constrained", sharex=True)
    sec_all = w.section_points("upper")
    x0, x1 = sec_all[..., 0].min(), sec_all[..., 0].max()
    pad = 0.05 * (x1 - x0)
    ymax = min(sec_all[..., 1].max(), 4.0 * float(b.radius.max()) + b.origin[1])
    for ax in (a0, a1):
        _body_outline(ax, b)
        ax.set_xlabel("x (aft)")
        ax.set_ylabel("y (starboard)")
        ax.set_xlim(x0 - pad, x1 + pad)
        ax.set_ylim(min(0.0, sec_all[..., 1].min()) - 0.5, ymax)
        ax.grid(True, lw=0.3, alpha=0.5)
    for ax in (a0, a1):
        sec = w.section_points("upper")
        ax.plot(sec[..., 0].T, sec[..., 1].T, color="C0", lw=0.6)
        ax.plot(sec[..., 0], sec[..., 1], color="C0", lw=0.6)
    a0.set_title("(a) input data: the wing root and the gap to the body (root region)")
    iu = geo.intersections[f"{wing}/{body} upper"]
    lines = w.lofting_lines("upper")
    for j in range(len(iu)):
        a1.plot([iu[j, 0], lines[j, 1, 0]], [iu[j, 1], lines[j, 1, 1]], color="C1", lw=0.8)
    a1.plot(iu[:, 0], iu[:, 1], "o-", color="C3", ms=3, label="intersection line")
    a1.set_title("(b) upper surface extended to the intersection line")
    a1.legend(fontsize=8)
    return fig


def plot_lower_intersection(cfg, geo, wing="wing", body="body"):
    """Lower-surface intersection with the extended lofting lines (fig 4)."""
    w, b = cfg[wing], cfg[body]
    fig, ax = plt.subplots(figsize=(10, 5), layout="constrained")
    _body_outline(ax, b)
    il = geo.intersections[f"{wing}/{body} lower"]
    lines = w.lofting_lines("lower")
    for j in range(len(il)):
        ax.plot([il[j, 0], lines[j, -1, 0]], [il[j, 1], lines[j, -1, 1]], color="C0", lw=0.6)
    ax.plot(il[:, 0], il[:, 1], "s-", color="C3", ms=3, label="lower intersection")
    iu = geo.intersections.get(f"{wing}/{body} upper")
    if iu is not None:
        ax.plot(iu[:, 0], iu[:, 1], "o--", color="C2", ms=2, lw=0.8, label="upper intersection")
    fl = geo.fillets.get("fillet lower")
    if fl is not None:
        ax.plot(fl[:, 0, 0], fl[:, 0, 1], "^", color="C4", ms=3, label="lower fillet start")
    ax.set_xlabel("x (aft)")
    ax.set_ylabel("y (starboard)")
    ax.set_aspect("equal")
    ax.grid(True, lw=0.3, alpha=0.5)
    ax.legend(fontsize=8)
    ax.set_title("lower-surface intersection and lofting lines")
    return fig


def plot_fillet_sections(cfg, geo, n=6, wing="wing", body="body"):
    """Fillet lines at several stations, viewed along x (figs 6-9), with the body circles."""
    fu, fl = geo.fillets.get("fillet upper"), geo.fillets.get("fillet lower")
    w, b = cfg[wing], cfg[body]
    st = geo.stations
    m = len(st["x"])
    picks = np.unique(np.linspace(1, m - 2, min(n, max(m - 2, 1))).round().astype(int))
    cols = min(3, len(picks))
    rows = int(np.ceil(len(picks) / cols))
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.8 * rows), layout="constrained",
                             squeeze=False)
    th = np.linspace(-np.pi / 2, np.pi / 2, 200)
    for ax, j in zip(axes.ravel(), picks):
        x = st["x"][j]
        c = b.center_at(x)
        for r, ls, lab in ((st["radius_original"][j], "--", "original body"),
                           (st["radius_new"][j], "-", "body")):
            ax.plot(c[0] + r * np.cos(th), c[1] + r * np.sin(th), color="0.4", ls=ls, lw=1,
                    label=lab)
        for side, col in (("upper", "C0"), ("lower", "C1")):
            line = w.lofting_lines(side)[j]
            ax.plot(line[:, 1], line[:, 2], "o-", color=col, ms=2, lw=0.8)
        if fu is not None:
            ax.plot(fu[j, :, 1], fu[j, :, 2], color="C3", lw=1.6, label="fillet")
            ax.plot(fl[j, :, 1], fl[j, :, 2], color="C3", lw=1.6)
            ys = np.concatenate([fu[j, :, 1], fl[j, :, 1]])
            zs = np.concatenate([fu[j, :, 2], fl[j, :, 2]])
            pad = 0.6 * max(np.ptp(ys), np.ptp(zs), 1e-9)
            ax.set_xlim(ys.min() - pad, ys.max() + pad)
            ax.set_ylim(zs.min() - pad, zs.max() + pad)
        ax.set_aspect("equal")
        ax.set_title(f"x = {x:.4g}, added area {st['area_fillet'][j]:.3g} (both sides)",
                     fontsize=9)
        ax.grid(True, lw=0.3, alpha=0.5)
    for ax in axes.ravel()[len(picks):]:
        ax.set_visible(False)
    axes[0, 0].legend(fontsize=7)
    fig.suptitle("fillet lines at constant x (y horizontal, z up)")
    return fig


def plot_station_areas(geo):
    """Cross-sectional areas at the fillet stations: original, fillet, body, body + fillet."""
    st = geo.stations
    fig, (a0, a1) = plt.subplots(2, 1, figsize=(9, 6), layout="constrained", sharex=True)
    x = st["x"]
    a0.plot(x, st["area_original"], "k--", label="original body")
    a0.plot(x, st["area_body"], "C0-", label="re-designed body")
    a0.plot(x, st["area_body"] + st["area_fillet"], "C3:", lw=2, label="body + fillet")
    a0.set_ylabel("area")
    a0.legend(fontsize=8)
    a0.grid(True, lw=0.3, alpha=0.5)
    a1.plot(x, st["area_fillet"], "C1o-", ms=3, label="fillet (added)")
    a1.plot(x, st["area_original"] - st["area_body"], "C0s--", ms=3, label="taken from body")
    a1.set_xlabel("x (aft)")
    a1.set_ylabel("area")
    a1.legend(fontsize=8)
    a1.grid(True, lw=0.3, alpha=0.5)
    a0.set_title("cross-sectional area at the fillet stations")
    return fig
