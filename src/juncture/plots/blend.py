"""Figures of the long-strake blend in the manner of Song, Ma & Wang (2008) figs 1-10.

Matplotlib with the Agg back end, one PNG per figure; 3-D views are wireframes (matplotlib
does not depth-sort between surfaces, see dependencies.md). Axes carry the length unit
``units`` (default ``"ft"``), a label only: the spec's lengths are never converted.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ._backend import pyplot
from .style import DEFAULT_UNITS, axis_label

__all__ = ["write_figures", "FIGURES"]

#: File names written by :func:`write_figures`, with the paper figure they follow.
FIGURES = {
    "fig01_lines.png": "fig 1: blending and boundary lines",
    "fig02_parameter_domain.png": "fig 2: rho1, rho2 in the body parameter plane",
    "fig03_base_surfaces.png": "fig 3: B1, B2 and the plane S3",
    "fig04_auxiliary_s4.png": "fig 4: auxiliary surface S4",
    "fig05_s5_b3.png": "fig 5: auxiliary base surface S5 and wing base surface B3",
    "fig07_r1.png": "fig 7: wing-body blend R1",
    "fig08_strake.png": "fig 8: plane T and the strake R2",
    "fig09_sections.png": "cross-sections (y, z) of R1, R2 and W, body and wing",
    "fig10_blend.png": "fig 10: R1, R2 and the forward patch W",
}


def _axes3d(fig, units, pos=111):
    ax = fig.add_subplot(pos, projection="3d")
    ax.set_xlabel(axis_label("x", units))
    ax.set_ylabel(axis_label("y", units))
    ax.set_zlabel(axis_label("z", units))
    return ax


def _wire(ax, surf, color, n=(21, 13), label=None, u=(0, 1), v=(0, 1)):
    g = surf.grid(np.linspace(*u, n[0]), np.linspace(*v, n[1]))
    ax.plot_wireframe(g[..., 0], g[..., 1], g[..., 2], color=color, linewidth=0.6,
                      label=label)
    return g


def _equal(ax, pts):
    """Fit the axes to ``pts`` at true scale, except that thin extents are stretched."""
    pts = np.concatenate([p.reshape(-1, 3) for p in pts])
    lo, hi = pts.min(0), pts.max(0)
    span = np.maximum(hi - lo, 1e-9)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(np.maximum(span, 0.3 * span.max()))
    ax.view_init(elev=28, azim=-125)


def _context(ax, model, x_range):
    lines = model.lines
    body = lines.body
    v_lo = min(lines.v_e, float(lines.rho1(np.array([0.0]))[0][0, 1]))
    g = body.grid(np.linspace(*x_range, 25), np.linspace(v_lo - 0.05, lines.v_g + 0.1, 7))
    ax.plot_wireframe(g[..., 0], g[..., 1], g[..., 2], color="0.75", linewidth=0.4)
    wing = lines.wing
    vw = np.linspace(wing.v_at_y(lines.junction[0]), lines.v_ab + 0.15, 7)
    g2 = np.swapaxes(wing.grid(np.linspace(0, 1, 15), vw), 0, 1)
    ax.plot_wireframe(g2[..., 0], g2[..., 1], g2[..., 2], color="0.6", linewidth=0.4)
    return [g, g2]


def _line3(ax, pts, **kw):
    ax.plot(pts[:, 0], pts[:, 1], pts[:, 2], **kw)


def write_figures(model, out_dir, units=DEFAULT_UNITS):
    """Write the figures of :data:`FIGURES` into ``out_dir``; return the paths written.

    Parameters
    ----------
    model : BlendModel
        The built blend (:func:`juncture.blend.build_blend`).
    out_dir : str or path-like
        An existing directory.
    units : str
        Length unit written on the axes (default ``"ft"``; a label only, nothing is
        converted).

    Returns
    -------
    list of str
    """
    plt = pyplot()

    out = Path(out_dir)
    lines, wb, r2, w = model.lines, model.wing_body, model.strake, model.patch
    body, wing = lines.body, lines.wing
    P = lines.points
    x_range = (lines.x_e - 0.3, P["H"][0] + 0.3)
    s = np.linspace(0, 1, 101)
    written = []

    def save(fig, name):
        path = out / name
        fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(str(path))

    # fig 1: lines
    fig = plt.figure(figsize=(8, 6))
    ax = _axes3d(fig, units)
    ctx = _context(ax, model, x_range)
    _line3(ax, wing.points(*lines.rho3(s)[0].T), color="b", label="AB (wing)")
    uv = lines.rho1(s)[0]
    _line3(ax, body.points(uv[:, 0], uv[:, 1]), color="g", label="MGH (body)")
    uv = lines.fe(s)[0]
    _line3(ax, body.points(uv[:, 0], uv[:, 1]), color="g")
    _line3(ax, np.array([P["G"], P["F"]]), color="g")
    _line3(ax, np.array([P["C"], P["D"]]), color="r", label="CDE (strake edge)")
    _line3(ax, lines.de(s)[0], color="r")
    for k, p in P.items():
        ax.text(*p, k)
    ax.legend(loc="upper left", fontsize=8)
    _equal(ax, ctx)
    ax.set_title("Blending and boundary lines")
    save(fig, "fig01_lines.png")

    # fig 2: parameter domain
    fig, ax = plt.subplots(figsize=(7, 4))
    for f, lab, c in ((lines.rho1, "rho1", "g"), (lines.rho2, "rho2", "m")):
        uv = f(s)[0]
        ax.plot(uv[:, 0], np.degrees(uv[:, 1]), c, label=lab)
    for k, sk in (("M", 0.0), ("G", lines.s_g), ("H", 1.0)):
        for f, suf in ((lines.rho1, "1"), (lines.rho2, "2")):
            uv = f(np.array([sk]))[0][0]
            ax.plot(uv[0], np.degrees(uv[1]), "ko", ms=3)
            ax.annotate(k + suf, (uv[0], np.degrees(uv[1])))
    ax.set_xlabel(axis_label("u = x", units))
    ax.set_ylabel("v (body section parameter) [deg]")
    ax.legend()
    ax.set_title("Body blending line MGH in the body parameter plane")
    save(fig, "fig02_parameter_domain.png")

    # fig 3 - 5, 7
    specs = [("fig03_base_surfaces.png", "B1, B2 and S3",
              [(wb.b1, "g", "B1"), (wb.b2, "c", "B2"), (wb.s3, "m", "S3")]),
             ("fig04_auxiliary_s4.png", "Auxiliary surface S4", [(wb.s4, "m", "S4")]),
             ("fig05_s5_b3.png", "S5 and B3", [(wb.s5, "m", "S5"), (wb.b3, "b", "B3")]),
             ("fig07_r1.png", "Wing-body blend R1", [(wb.r1, "r", "R1")])]
    for name, title, surfs in specs:
        fig = plt.figure(figsize=(8, 6))
        ax = _axes3d(fig, units)
        grids = _context(ax, model, x_range)
        for surf, col, lab in surfs:
            grids.append(_wire(ax, surf, col, label=lab))
        ax.legend(loc="upper left", fontsize=8)
        _equal(ax, grids[2:])
        ax.set_title(title)
        save(fig, name)

    # fig 8: plane T and R2
    fig = plt.figure(figsize=(8, 6))
    ax = _axes3d(fig, units)
    grids = _context(ax, model, x_range)
    size = 2.2 * body.size
    grids.append(_wire(ax, r2, "r", label="R2"))
    t_plane = r2.plane_t(size)
    _wire(ax, t_plane, "0.4", n=(5, 5), label="plane T")
    _wire(ax, wb.s4, "m", label="S4", n=(11, 9))
    ax.legend(loc="upper left", fontsize=8)
    _equal(ax, grids[2:])
    ax.set_title("Plane T and the long strake R2")
    save(fig, "fig08_strake.png")

    # sections: iso-lines of the patches seen along the axis
    fig, axs = plt.subplots(1, 3, figsize=(13, 4.2))
    cmap = plt.get_cmap("viridis")
    tt = np.linspace(0, 1, 81)
    for ax, surf, title, fixed in ((axs[0], wb.r1, "R1: t-lines (body/strake -> wing)",
                                    "s"),
                                   (axs[1], r2, "R2 section (CG) and S4 t-lines", "s"),
                                   (axs[2], w, "W: w-lines (FE -> DE)", "u")):
        for k, c in enumerate(np.linspace(0, 1, 9)):
            a = np.full_like(tt, c)
            g = surf.points(a, tt) if fixed == "s" else surf.points(a * 0.98, tt)
            ax.plot(g[:, 1], g[:, 2], color=cmap(k / 8), lw=1)
        th = np.linspace(-0.6, 1.2, 100)
        yb, zb, _, _ = body.section.evaluate(th)
        ax.plot(yb, zb, "0.5", lw=0.8)
        ax.set_aspect("equal")
        ax.set_title(title, fontsize=9)
        ax.set_xlabel(axis_label("y", units))
        ax.set_ylabel(axis_label("z", units))
    g = wing.grid(np.linspace(-1, 1, 81), np.array([lines.v_ab]))[:, 0]
    axs[0].plot(g[:, 1], g[:, 2], "k.", ms=2)
    fig.tight_layout()
    save(fig, "fig09_sections.png")

    # fig 10: all patches
    fig = plt.figure(figsize=(9, 6))
    ax = _axes3d(fig, units)
    grids = _context(ax, model, x_range)
    grids.append(_wire(ax, wb.r1, "r", label="R1"))
    grids.append(_wire(ax, r2, "b", label="R2"))
    grids.append(_wire(ax, w, "g", label="W (thin plate)", n=(13, 13)))
    ax.legend(loc="upper left", fontsize=8)
    _equal(ax, grids[2:])
    ax.set_title("Long-strake wing-body blend: R1, R2 and the forward patch W")
    save(fig, "fig10_blend.png")
    return written
