"""complete(): the wing-body juncture of a configuration as one set of output networks.

Steps (TM-4406): intersect the wing's upper and lower lofting lines with the fuselage
(eqs 1-6), optionally fillet the juncture (cubic arcs, eq 7, or circular arcs) with leading /
trailing-edge blending (eqs 8-10), optionally shrink the fuselage so that body + fillet area
equals the original area at every fillet station (eqs 11-14), and lay out the output blocks
(4 or 6 blocks, or a single fuselage network). Components other than the wing and the fuselage
are passed through as their own networks.

A lofting line that misses the fuselage ends where it reaches the plane of symmetry, with no
fillet (:mod:`juncture.misses`, which says why not at the body's bottom as TM-4406's special
case). The single fuselage network's lines are re-interpolated as
:mod:`juncture.single_network` describes.
"""

from __future__ import annotations

from typing import Literal

import numpy as np

from .crossings import refuse_crossing_regions
from .errors import GeometryError, OptionError
from .fillet.area import fillet_added_area
from .fillet.circular import circular_fillet
from .fillet.compensation import keep_area as _keep_area
from .fillet.cubic import FilletLines, cubic_fillet
from .geometry import Geometry, mirror_points
from .intersect import intersect_body_both
from .misses import ended_lines, line_ends
from .model import CircularBody, Configuration
from .options import CompleteOptions, check_combination
from .surface.networks import (
    body_range,
    half_points,
    juncture_networks,
    refined_stations,
    split_counts,
)

__all__ = ["complete", "CompleteOptions", "sharp_fillet"]

FilletKind = Literal["cubic", "circular"]


def sharp_fillet(inter, ends=None):
    """Degenerate one-point "fillet" lines at the intersection (no fillet).

    ``ends`` (:class:`juncture.misses.LineEnds`) gives where lines that miss the body end
    instead (continued to the plane of symmetry); without it their points are NaN.
    """
    pts = (inter.points if ends is None else ends.points).copy()
    theta = (inter.theta if ends is None else ends.theta).copy()
    u = (inter.u if ends is None else ends.u).copy()
    m = len(pts)
    return FilletLines(inter.side, pts[:, None, :], pts, pts, theta, u, np.zeros(m),
                       np.zeros(m, bool), "none", () if ends is None else ends.log)


def _pick(cfg, name, kind):
    try:
        comp = cfg[name]
    except GeometryError:
        raise GeometryError(f"complete() needs a {kind} named {name!r}; the configuration has "
                            f"{', '.join(cfg.components) or 'no components'}") from None
    return comp


def _largest_radius(body):
    """The largest radius of a fuselage; of an arbitrary-section one, its largest
    equivalent radius sqrt(A / pi) over the stations."""
    if isinstance(body, CircularBody):
        return float(np.max(body.radius))
    return float(np.sqrt(np.max(body.area_at(body.x_global)) / np.pi))


def _extended_roots(cfg, body, attached, log):
    """The configuration with every root on the fuselage continued inside it.

    The completed surfaces run along their extended lofting lines to the intersection lines
    (TM-4406 eq 4), which can lie inboard of a root section given on or outside the
    fuselage (or uncovered when the fuselage shrinks). For the model kept with the geometry
    (what area and mass analyses integrate) each such component gets a new root section on
    those lines, half a radius inside the fuselage from its innermost intersection point.
    """
    r = _largest_radius(body)
    for comp, inters in attached:
        pts = np.concatenate([i.points[i.found] for i in inters])
        if not len(pts):
            continue
        a = comp.span_axis
        target = float(pts[:, a].min()) - 0.5 * r
        if a == 1:
            target = max(target, float(body.origin[1]) if isinstance(body, CircularBody)
                         else 0.0)
        try:
            cfg = cfg.with_component(comp.extended_to(target))
        except GeometryError as exc:
            log.append(f"{comp.name}: root not extended into the fuselage ({exc.reason})")
    return cfg


def _root_exposure(cfg, wing, body0, sides, found, wing_lines):
    """``L(x)``: perimeter of the original fuselage covered by wing-like roots at x.

    ``wing_lines`` are the main wing's (upper, lower) intersections with ``body0``.

    The main wing's root spans its upper to lower intersection angles; every other wing-like
    component on the fuselage (a tail, a canard, a fin) likewise, each counted once per copy.
    Shrinking the fuselage by d at x uncovers about L(x) d of their area (TM-4406 ignores
    this; compensating it keeps the whole cross-section's area, not just the fillet's).
    """
    lines = [(sides, wing_lines)]
    for pair, (up, lo) in found.items():
        if pair.b == body0.name:
            comp = cfg[pair.a]
            lines.append((2 if (cfg.symmetric and comp.mirrored) else 1, (up, lo)))

    def angle_at(inter, x):
        ok = inter.found
        if ok.sum() < 2:
            return np.full(np.shape(x), np.nan)
        xs, th = inter.points[ok, 0], inter.theta[ok]
        order = np.argsort(xs)
        return np.interp(x, xs[order], th[order], left=np.nan, right=np.nan)

    def exposure(x):
        x = np.asarray(x, float)
        total = np.zeros(x.shape)
        if not isinstance(body0, CircularBody):
            # An arbitrary section scales about its centroid (fillet.section_redesign).
            from .fillet.section_redesign import root_exposure_rate

            for copies, (up, lo) in lines:
                a, b = angle_at(up, x), angle_at(lo, x)
                ok = np.isfinite(a) & np.isfinite(b)
                rate = root_exposure_rate(body0, x[ok], a[ok], b[ok]) if ok.any() else 0.0
                total[ok] += copies * rate
            return total
        r0 = body0.radius_at(x)
        for copies, (up, lo) in lines:
            dth = np.abs(angle_at(up, x) - angle_at(lo, x))
            total += copies * r0 * np.where(np.isfinite(dth), dth, 0.0)
        return total
    return exposure


def _fillet_maker(wing, fillet, opts, body0):
    theta_u = np.radians(opts.theta_u_deg)
    rho = opts.fillet_radius
    r_max = _largest_radius(body0)
    if fillet == "circular" and rho is None:
        rho = 0.1 * r_max

    def make(body, previous=None, warm=False):
        # previous: the last iterate's (iu, il, fu, fl) on a body it re-designs; its fillets'
        # blending region and how far their tangents went towards the paper's are kept,
        # and with warm=True its solutions seed the root finders.
        hints = (previous[0].u, previous[1].u) if warm else None
        iu, il = intersect_body_both(wing, body, hints=hints)
        ranges = (None, None) if previous is None else (previous[2].blend_range,
                                                        previous[3].blend_range)
        shares = (None, None) if previous is None else (previous[2].towards,
                                                        previous[3].towards)
        if fillet is None:
            return (iu, il, sharp_fillet(iu, line_ends(wing, body, iu)),
                    sharp_fillet(il, line_ends(wing, body, il)))
        if fillet == "cubic":
            end_value = opts.end_value
            if end_value is None:
                end_value = 0.25 * r_max if opts.end == "dy" else 0.5
            kw = dict(theta_u=theta_u, end=opts.end, end_value=end_value,
                      blend_length=opts.blend_length, n_points=opts.n_fillet_points,
                      remedy=opts.remedy, blending=opts.blending)
            # Lines that miss: continued to the plane of symmetry, no fillet (misses.py).
            up, lo = line_ends(wing, body, iu), line_ends(wing, body, il)
            return (iu, il,
                    ended_lines(cubic_fillet(wing, body, iu, blend_range=ranges[0],
                                             towards=shares[0], **kw), up, up.missed),
                    ended_lines(cubic_fillet(wing, body, il, upper_reference=iu,
                                             blend_range=ranges[1], towards=shares[1], **kw),
                                lo, lo.missed))
        if fillet == "circular":
            kw = dict(blend_length=opts.blend_length, n_points=opts.n_fillet_points,
                      tangent=opts.circular_tangent)
            up, lo = (previous[2].u_end, previous[3].u_end) if warm else (None, None)
            return (iu, il,
                    circular_fillet(wing, body, iu, rho, hint=up, blend_range=ranges[0], **kw),
                    circular_fillet(wing, body, il, rho, hint=lo, blend_range=ranges[1], **kw))
        raise GeometryError(f"fillet must be None, 'cubic' or 'circular', found {fillet!r}")
    return make


def _with_empennage(cfg, wing, opts):
    """``cfg`` with two-section canards, fins, tails and pylons interpolated (TM-4607)."""
    from .surface.component_networks import interpolated

    work = cfg
    for comp in cfg.wings:
        if comp.name != wing.name and comp.kind in ("canard", "tail", "fin", "pylon"):
            work = work.with_component(interpolated(comp, opts.empennage_sections))
    return work


def _other_components(cfg, wing, body, opts, log, known=None):
    """Intersections and networks of every component except the main wing and fuselage.

    ``known``: intersections found before the fuselage was re-designed; only the pairs with
    the fuselage are solved again.
    """
    from .intersect import find_intersections
    from .intersect.pairs import intersect_pair, settle_pairs
    from .model import WingLike
    from .surface.component_networks import nacelle_network, trimmed_networks

    work = _with_empennage(cfg, wing, opts)
    if known is None:
        found = find_intersections(work, explicit=opts.pairs, skip={(wing.name, body.name)})
    else:
        found = settle_pairs(work, {p: (intersect_pair(work, p) if p.b == body.name else res)
                                    for p, res in known.items()})
    inters, by_comp, pylons, attached, traces = {}, {}, {}, [], []
    for pair, (up, lo) in found.items():
        if pair.b == wing.name and pair.role in ("upper", "lower"):
            # TM-4607: two curves on the surface the fin/pylon stands on, one on the other.
            other = "lower" if pair.role == "upper" else "upper"
            traces += [(pair.role, up.points), (pair.role, lo.points),
                       (other, 0.5 * (up.points + lo.points))]
        inters[up.name], inters[lo.name] = up.points, lo.points
        log.extend(up.log + lo.log)
        if pair.b == body.name:
            if _continued(work[pair.a], cfg, opts):
                up, lo = _ended(work[pair.a], body, up, log), _ended(work[pair.a], body, lo, log)
            attached.append((work[pair.a], up, lo))
        by_comp.setdefault(pair.a, {"upper": [], "lower": []})
        by_comp[pair.a]["upper"].append(up)
        by_comp[pair.a]["lower"].append(lo)
        if pair.role == "body" and not isinstance(work[pair.b], WingLike) and \
                pair.b != body.name:
            pylons.setdefault(pair.b, []).append((up, lo, work[pair.a]))
    log.append("touching pairs: " + ", ".join(f"{p.a}/{p.b} ({p.role})" for p in found))
    nets = {}
    for comp in work:
        if comp.name in (wing.name, body.name):
            continue
        plane = "xz" if (cfg.symmetric and comp.mirrored) else None
        if comp.name in by_comp:
            mine = trimmed_networks(comp, by_comp[comp.name], log,
                                    {c.name: c for c in work})
        elif comp.name in pylons:
            mine = {comp.name: nacelle_network(comp, pylons[comp.name],
                                               n_points=36 * opts.refine + 1)}
        elif isinstance(comp, CircularBody):
            mine = comp.networks(stations=refined_stations(comp))
        else:
            mine = comp.networks()
            if plane is None and cfg.symmetric and not isinstance(comp, WingLike):
                plane = "xz"  # a centre-line body described by its y >= 0 half
        nets.update({k: (v, plane) for k, v in mine.items()})
    from .surface.body_split import seam_gap

    for pod_name, lines in pylons.items():
        pod_net = nets[pod_name][0]
        for out_i, in_i, _ in lines:
            for inter in (out_i, in_i):
                log.append(f"seam {pod_name} / {inter.name.split('/')[0]} ({inter.name} line): "
                           f"max gap {seam_gap(inter.points, pod_net):.3g}")
    return nets, inters, attached, traces


def _continued(comp, cfg, opts):
    """Whether ``comp``'s lofting lines that miss the fuselage are continued to the plane of
    symmetry (:mod:`juncture.misses`, as the main wing's): a canard or tail with a mirror
    image, in the split layout (whose fuselage blocks end their rows at such a point)."""
    return (getattr(comp, "span_axis", None) == 1 and comp.mirrored and cfg.symmetric
            and opts.blocks in (None, "split") and not opts.single_network)


def _ended(comp, body, inter, log):
    """``inter`` with each line that misses ``body`` ending at its point on the plane of
    symmetry (found there; :func:`juncture.misses.line_ends`)."""
    from dataclasses import replace

    if np.all(inter.found):
        return inter
    ends = line_ends(comp, body, inter)
    log.extend(ends.log)
    return replace(inter, points=ends.points, theta=ends.theta, u=ends.u,
                   found=np.ones(len(ends.points), bool))


def _net_stations(body, body0, upper, lower):
    """The body stations of the networks: the input body's (a re-designed body holds many
    more, only so that its area follows the compensation between them), and more where the
    body stands off the straight lines between them (refined_stations), outside the x range
    of the wing's junction, whose rows are the fillet lines' (a row added between the
    upper and lower lines' first points left the blocks there open)."""
    given = body0.x_global
    rows = refined_stations(body, given)
    ends = np.concatenate([upper.start[:, 0], lower.start[:, 0]])
    lo, hi = np.nanmin(ends), np.nanmax(ends)
    added = rows[~np.isin(rows, given)]
    return np.sort(np.concatenate([given, added[(added < lo) | (added > hi)]]), kind="stable")


def _turns_back(*lines):
    """Whether a fillet start line (the intersection line without a fillet) runs forward
    anywhere from its leading-edge point to its trailing-edge point (a high swept wing's
    upper line bulging forward and up ahead of the leading-edge point). TM-4406's 4 and 6
    blocks cannot follow it: the juncture blocks' body arcs lie at each line's own station,
    so the arcs of a run that turns back fold over the next ones, and the forward block,
    ending at the leading-edge station, covers the body under them too. The fuselage split
    by theta_b bounds its blocks by such a run instead
    (:func:`juncture.surface.body_split.footprint_chains`)."""
    return any(bool(np.any(np.diff(line.start[:, 0]) < 0.0)) for line in lines)


def _warn_folds(wing, body, layout, log):
    """Warn (and log) that the asked-for 4 or 6 blocks fold where a start line turns back."""
    import warnings

    from .errors import JunctureWarning

    msg = (f"{wing.name}/{body.name}: an intersection line runs forward of its leading-edge "
           f"point; the {layout}-block layout's juncture rows fold there (the surface crosses "
           "itself): use blocks='split' (--blocks split), the default for such a wing")
    log.append(msg)
    warnings.warn(msg, JunctureWarning, stacklevel=3)


def _split_layout(body, wing, fu, fl, attached, n_half, log, stations=None):
    """TM-4607 output: fuselage upper/lower split by theta_b, wing networks, seams."""
    from .surface.body_split import boundary_from_points, seam_gap, split_body

    upper, lower, chained = _wing_boundaries(wing, body, fu, fl)
    ups, los = [upper], [lower]
    fins, port = [], []
    for comp, up, lo in attached:
        if comp.span_axis == 1:
            ups.append(_region_boundary(comp, body, "upper", up))
            los.append(_region_boundary(comp, body, "lower", lo))
        elif not comp.mirrored:  # a centre-line fin: the upper surface starts at it
            fins.append(boundary_from_points(body, up.points, comp.name,
                                             _exact(comp, body, "upper", up.points)))
            port.append(boundary_from_points(body, mirror_points(lo.points), comp.name,
                                             _exact(comp, body, "lower", lo.points, True)))
    # The same point count per cross-section, split so the spacing is even at the wing's
    # leading-edge station (TM-4607): the shares follow the arcs below and above theta_w.
    b_lo, b_hi, _ = body_range(body)
    n_lower, n_upper = split_counts(float(fu.theta_start[0]), 2 * n_half - 1, b_lo, b_hi)
    unsymmetric = any(not np.array_equal(f.points, g.points) for f, g in zip(fins, port))
    if unsymmetric:  # both halves at every fin station, so they share the plane's points
        base = body.x_global if stations is None else stations
        stations = np.unique(np.concatenate([base] + [f.x for f in fins + port]))
    nets = split_body(body, ups, los, fins, n_upper=n_upper, n_lower=n_lower,
                      stations=stations)
    if unsymmetric:
        # A centre-line fin whose two sides differ (FINORD O and I): the fuselage's y < 0
        # half starts at the inboard line, so it is made on its own, not mirrored.
        left = split_body(body, ups, los, port, n_upper=n_upper, n_lower=n_lower,
                          stations=stations)["body upper"]
        nets["body upper image"] = mirror_points(left)[::-1]
        log.append("a centre-line fin's sides differ: the fuselage's upper block is made for "
                   "each half")
    six, _ = juncture_networks(wing, body, fu, fl, 6, n_half, stations)
    nets["wing upper"], nets["wing lower"] = six["wing upper"], six["wing lower"]
    # A line that turns back at an end lies partly on the other block's boundary.
    on_u, on_l = (upper.points, lower.points) if chained else (fu.start, fl.start)
    seams = [{"a": "body upper", "b": "wing upper", "seam": "fillet start line",
              "points": len(fu.start), "max_gap": seam_gap(on_u, nets["body upper"])},
             {"a": "body lower", "b": "wing lower", "seam": "fillet start line",
              "points": len(fl.start), "max_gap": seam_gap(on_l, nets["body lower"])}]
    for comp, up, lo in attached:
        for inter, net in ((up, "body upper"), (lo, "body lower")):
            if comp.span_axis == 2 and (net == "body lower" or comp.mirrored):
                continue
            seams.append({"a": net, "b": comp.name, "seam": f"{inter.name} line",
                          "points": int(inter.found.sum()),
                          "max_gap": seam_gap(inter.points, nets[net])})
    return nets, seams


def _wing_boundaries(wing, body, fu, fl):
    """(upper, lower, chained): the Boundary of the fuselage's blocks beside the wing, its
    upper and lower fillet start lines (the intersection lines without a fillet), each from
    its leading-edge point aft (:func:`juncture.surface.body_split.forward`); where one line
    turns back at an end (``chained``), that run is the other block's boundary ahead of
    (after) that block's own line (:func:`juncture.surface.body_split.footprint_chains`).
    Without a fillet the rows at body stations between the points end on the wing's exact
    intersection there."""
    from .surface.body_split import Boundary, footprint_chains, forward

    sharp = fu.kind == "none" and fl.kind == "none"   # rows end on the wing itself
    lines, names = (fu, fl), ("upper", "lower")
    chains = footprint_chains(fu.start, fl.start)
    chained = chains is not None
    if not chained:
        chains = [[(s, i) for i in np.flatnonzero(forward(line.start[:, 0]))]
                  for s, line in enumerate(lines)]
        exact = [_exact(wing, body, n, line.start) if sharp else None
                 for n, line in zip(names, lines)]
    else:
        exact = [_chain_exact(wing, body, lines, c) if sharp else None for c in chains]
    out = []
    for chain, ex in zip(chains, exact):
        pts = np.array([lines[s].start[i] for s, i in chain]).reshape(-1, 3)
        theta = np.array([lines[s].theta_start[i] for s, i in chain], float)
        out.append(Boundary(pts[:, 0], theta, "wing", pts, ex))
    return (*out, chained)


def _chain_exact(wing, body, lines, chain):
    """``exact(x)`` along a chain of :func:`_wing_boundaries`: on each piece of one side's
    neighbouring points, that surface's intersection in the planes x between them (they may
    run forward along the line)."""
    runs = [[chain[0]]]   # pieces of one side's neighbouring points
    for prev, cur in zip(chain[:-1], chain[1:]):
        if cur[0] == prev[0] and abs(cur[1] - prev[1]) == 1:
            runs[-1].append(cur)
        else:
            runs.append([cur])
    parts = []
    for run in runs:
        if len(run) < 2:
            continue
        s, idx = run[0][0], [i for _, i in run]
        pts = np.full(lines[s].start.shape, np.nan)
        pts[idx] = lines[s].start[idx]
        parts.append((pts[idx, 0].min(), pts[idx, 0].max(),
                      _exact(wing, body, ("upper", "lower")[s], pts, either=True)))

    def exact(x):
        x = np.asarray(x, float)
        out = np.full((x.size, 3), np.nan)
        for lo, hi, part in parts:
            inside = (x > lo) & (x < hi)
            if inside.any():
                out[inside] = part(x[inside])
        return out
    return exact


def _region_boundary(comp, body, side, inter):
    """The Boundary of the fuselage's block on ``comp``'s ``side`` (a canard or tail): its
    intersection points with their angles; a line continued to the plane of symmetry ends
    at its point there, with the angle of the body's top or bottom (:func:`_ended`)."""
    from .surface.body_split import boundary_from_points, forward

    k = forward(inter.points[:, 0])
    return boundary_from_points(body, inter.points[k], comp.name,
                                _exact(comp, body, side, inter.points), inter.theta[k])


def _exact(comp, body, side, points, mirrored=False, either=False):
    """``exact(x)`` of a :class:`~juncture.surface.body_split.Boundary`: where ``comp``'s
    ``side`` surface meets ``body`` in the planes x (its intersection ``points`` bracket
    them, with ``either`` also where x falls from one point to the next; mirrored in y with
    ``mirrored``)."""
    from .intersect.stations import plane_points

    solved = {}  # the same stations are asked again (both halves beside an unsymmetric
    #              fin, the middle block's ends): each set is solved once

    def exact(x):
        x = np.asarray(x, float)
        key = x.tobytes()
        if key not in solved:
            pts = plane_points(comp, body, side, points, x, either)
            solved[key] = mirror_points(pts) if mirrored else pts
        return solved[key].copy()
    return exact


def _refined(cfg, k):
    """``cfg`` with ``k`` times the chord stations of every wing-like component (each input
    interval divided evenly) and the section points of every circular body (option
    ``refine``)."""
    import dataclasses

    from .model import WingLike

    for comp in list(cfg):
        if isinstance(comp, WingLike):
            xc = comp.x_over_c
            t = np.arange(1, k) / k
            comp = comp.with_chord_stations((xc[:-1, None] + t * np.diff(xc)[:, None]).ravel())
        elif isinstance(comp, CircularBody):
            counts = comp.points_per_section or (19,) * len(comp.segments)
            comp = dataclasses.replace(comp, points_per_section=tuple(
                (int(m) - 1) * k + 1 for m in counts))
        else:
            continue
        cfg = cfg.with_component(comp)
    return cfg


def complete(cfg: Configuration, fillet: FilletKind | None = None, keep_area=False,
             options: CompleteOptions | None = None, **kwargs):
    """Complete the wing-body juncture of ``cfg`` into one set of networks (TM-4406).

    Parameters
    ----------
    cfg : Configuration
        Must hold a wing-type component (``options.wing``, default ``"wing"``) and a circular
        fuselage (``options.body``, default ``"body"``).
    fillet : {None, "cubic", "circular"}
        No fillet (sharp intersection), cubic-arc fillet (eq 7) or circular-arc fillet at the
        wing-body juncture. Every other touching pair (fins, tails and canards on the body,
        fins on the wing, pylons between wing and nacelles) is intersected too (TM-4607) and
        those components are trimmed at their intersection lines.
    keep_area : bool
        Re-design the fuselage radius so body + fillet area equals the original area at every
        fillet station (TM-4406, "Redesign To Compensate for Added Volume").

        Lofting lines that miss the fuselage (a high wing's upper surface passing over it,
        a low wing's lower surface under it) are continued to the plane of symmetry, where
        they meet their mirror image, with no fillet (:mod:`juncture.misses`).
    options : CompleteOptions, optional
        Every other choice; keyword arguments override its fields, e.g.
        ``complete(cfg, "cubic", theta_u_deg=30, blocks=6)``.

    Returns
    -------
    Geometry
        ``networks`` (4 or 6 juncture blocks, or a single fuselage network, plus the other
        components' own networks), ``intersections`` (``"wing/body upper"``,
        ``"wing/body lower"``), ``fillets`` (``"fillet upper"``, ``"fillet lower"``, each
        (n_stations, n_points, 3) from the body to the wing), ``stations`` (``x``,
        ``area_original``, ``area_fillet`` (the area added by filleting, on both sides of a
        mirrored wing: with ``keep_area`` the fillets plus the wing root they uncover as the
        body shrinks, which is what the body gives up), ``area_fillet_only`` (the fillets
        alone, TM-4406 eq 14), ``area_body``, ``radius_original``, ``radius_new``,
        ``residual``, ``iterations``), the ``configuration`` with the re-designed fuselage,
        and a ``log``.

    Examples
    --------
    >>> import juncture as jc
    >>> from juncture.cli import bundled_example
    >>> import warnings; warnings.simplefilter("ignore")
    >>> geo = jc.complete(jc.read(bundled_example()), fillet="cubic", keep_area=True)
    >>> bool(abs(geo.stations["residual"]).max() < 1e-9)
    True
    """
    opts = options or CompleteOptions()
    if kwargs:
        unknown = sorted(set(kwargs) - set(CompleteOptions.__dataclass_fields__))
        if unknown:
            raise OptionError(unknown[0], kwargs[unknown[0]], "no such option; the options are "
                              f"{', '.join(sorted(CompleteOptions.__dataclass_fields__))}")
        fields = {f: getattr(opts, f) for f in CompleteOptions.__dataclass_fields__}
        fields.update(kwargs)
        opts = CompleteOptions(**fields)
    check_combination(fillet, keep_area, opts)
    if opts.refine > 1:
        cfg = _refined(cfg, opts.refine)
    wing = _pick(cfg, opts.wing, "wing")
    body0 = _pick(cfg, opts.body, "fuselage")
    log = [f"complete: fillet={fillet}, keep_area={keep_area}, {opts}"]
    if keep_area and fillet is not None and wing.n_stations < opts.min_lofting_lines:
        # Subdivide every input interval evenly: no new station crowds an input one.
        k = int(np.ceil((opts.min_lofting_lines - 1) / (wing.n_stations - 1)))
        xc = wing.x_over_c
        t = np.arange(1, k) / k
        wing = wing.with_chord_stations((xc[:-1, None] + t * np.diff(xc)[:, None]).ravel())
        cfg = cfg.with_component(wing)
        log.append(f"{wing.name}: {wing.n_stations} chordwise stations (refined for keep_area)")
    make = _fillet_maker(wing, fillet, opts, body0)
    sides = 2 if (wing.mirrored and cfg.symmetric) else 1
    if keep_area and fillet is not None:
        from .intersect import find_intersections

        known = find_intersections(_with_empennage(cfg, wing, opts), explicit=opts.pairs,
                                   skip={(wing.name, body0.name)})
        first = make(body0)
        comp = _keep_area(body0, make, tolerance=opts.tolerance, sides=sides,
                          compensate=opts.compensation,
                          exposure=_root_exposure(cfg, wing, body0, sides, known, first[:2]),
                          initial=first)
        body = comp.body
        iu, il, fu, fl = comp.fillets
        stations = {"x": comp.x, "area_original": comp.area_original,
                    "area_fillet": comp.area_fillet, "area_fillet_only": comp.area_fillet_only,
                    "area_body": comp.area_body,
                    "radius_original": comp.radius_original, "radius_new": comp.radius_new,
                    "residual": comp.residual, "iterations": comp.iterations.astype(float)}
        log.append(f"keep_area: {comp.n_iterations} iterations, worst residual "
                   f"{comp.residual.max():.3g}; radius reduced by up to "
                   f"{np.max(comp.radius_original - comp.radius_new):.4g}")
    else:
        body = body0
        iu, il, fu, fl = make(body)
        if fillet is not None:
            x, a_f = fillet_added_area(body, fu, fl, iu, il)
            a_f = sides * a_f
        else:
            x, a_f = fu.start[:, 0], np.zeros(len(fu.start))
        a0 = body.area_at(x)
        r_eq = np.sqrt(a0 / np.pi)  # the radius, or the equivalent radius of an arbitrary body
        stations = {"x": x, "area_original": a0, "area_fillet": a_f,
                    "area_fillet_only": a_f, "area_body": a0,
                    "radius_original": r_eq, "radius_new": r_eq,
                    "residual": np.abs(a_f) / np.where(a0 > 0, a0, 1.0),
                    "iterations": np.zeros(len(x))}
    for part in (iu, il, fu, fl):
        log.extend(part.log)
    n_half = half_points(body)
    completed = cfg.with_component(body) if body is not body0 else cfg
    other_nets, other_inters, attached, traces = _other_components(
        completed, wing, body, opts, log, known if keep_area and fillet is not None else None)
    net_stations = _net_stations(body, body0, fu, fl)
    layout = opts.blocks
    if layout is None:
        layout = "split" if attached or _turns_back(fu, fl) else 4
    elif layout != "split" and not opts.single_network and _turns_back(fu, fl):
        _warn_folds(wing, body, layout, log)
    lower_points = il.points
    if opts.single_network:
        from .single_network import reinterpolated, single_network

        before = (len(fu.log), len(fl.log))
        fu, fl, lower_points = reinterpolated(wing, body, fu, fl, iu, il, fillet)
        log.extend(list(fu.log[before[0]:]) + list(fl.log[before[1]:]))
        nets, seams = single_network(wing, body, fu, fl, n_half, net_stations)
    elif layout == "split":
        nets, seams = _split_layout(body, wing, fu, fl, attached, n_half, log, net_stations)
    else:
        nets, seams = juncture_networks(wing, body, fu, fl, layout, n_half, net_stations)
    if traces and f"{wing.name} upper" in nets and layout != 4:
        from .surface.component_networks import add_trace_curves, trace_curve

        curves = [(side, trace_curve(wing, side, line)) for side, line in traces]
        nets.update(add_trace_curves(wing, {k: nets[k] for k in
                                            (f"{wing.name} upper", f"{wing.name} lower")},
                                     curves))
        log.append(f"{len(curves)} curves traced on {wing.name} where fins or pylons meet it")
        from .surface.body_split import polyline_gap

        for name, pts in other_inters.items():
            if name.split("/")[1].startswith(f"{wing.name} "):
                # The traced curves follow the line at the wing's own chord stations only.
                gap = min(polyline_gap(pts, nets[f"{wing.name} {side}"])
                          for side in ("upper", "lower"))
                seams.append({"a": f"{wing.name}", "b": name.split("/")[0],
                              "seam": f"{name} line (traced at the wing's stations)",
                              "points": len(pts), "max_gap": gap})
    for s in seams:
        log.append(f"seam {s['a']} / {s['b']} ({s['seam']}): max gap {s['max_gap']:.3g}")
    sym = {k: "xz" for k in nets if f"{k} image" not in nets and not k.endswith(" image")}
    intersections = {f"{wing.name}/{body.name} upper": iu.points,
                     f"{wing.name}/{body.name} lower": lower_points}
    intersections.update(other_inters)
    junctions = dict(intersections)
    if fillet is not None:  # the wing covers the body up to its fillet's start lines
        junctions = {k: v for k, v in junctions.items() if not k.startswith(f"{wing.name}/")}
        junctions[f"{wing.name} fillet/{body.name} upper"] = fu.start
        junctions[f"{wing.name} fillet/{body.name} lower"] = fl.start
    refuse_crossing_regions(completed, junctions)
    for k, (net, plane) in other_nets.items():
        nets[k] = net
        if plane is not None:
            sym[k] = plane
    fillets = {} if fillet is None else {"fillet upper": fu.points, "fillet lower": fl.points}
    completed = _extended_roots(completed, body, [(wing, (iu, il))] + [
        (comp, (up, lo)) for comp, up, lo in attached], log)
    return Geometry(networks=nets, symmetry=sym, title=cfg.title, intersections=intersections,
                    fillets=fillets, stations=stations, log=tuple(log), configuration=completed)
