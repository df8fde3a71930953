"""``juncture.mesh``: the assembled surface, checked, re-triangulated for quality.

:func:`mesh` assembles a completed geometry (:func:`juncture.surface.assemble.assemble`),
refuses in one line a surface that is not closed and valid (naming the cause in the user's
terms where it is known: :func:`overlapping_regions`), and re-triangulates it
(:func:`quality`, :func:`juncture.surface.remesh.remesh`).
"""

from __future__ import annotations

import numpy as np

from .assemble import assemble

__all__ = ["mesh", "finish", "half_checked", "quality", "overlapping_regions"]


def overlapping_regions(geometry):
    """One line per pair of horizontal surfaces (wing, canards, tails) whose intersections
    with the same body overlap in x at one height (a pair one above the other, staggered or
    one inside the other's range, has a middle block), or [].

    The fuselage's upper and lower blocks (TM-4607) are bounded by one region after another
    along the body: two regions side by side over the same stations (a canard whose root
    runs on over the wing's) leave the body between them without a layout, and the surfaces
    usually cross each other there too.
    """
    comps = {c.name: c for c in getattr(geometry, "configuration", None) or ()}
    # The layout makes a middle block only for one pair, one above the other, and only
    # when no other pair overlaps (juncture.surface.overlap_blocks.find_overlap).
    stacked = "body middle" in geometry.networks
    spans = {}
    for name, pts in geometry.intersections.items():
        a, rest = name.split("/", 1)
        host = rest.rsplit(" ", 1)[0]
        if getattr(comps.get(a), "span_axis", None) != 1:
            continue
        p = np.asarray(pts, float)
        x = p[np.all(np.isfinite(p), axis=1), 0]
        if x.size:
            lo, hi = spans.setdefault(host, {}).get(a, (np.inf, -np.inf))
            spans[host][a] = (min(lo, float(x.min())), max(hi, float(x.max())))
    out = []
    for host, by in spans.items():
        names = sorted(by, key=lambda n: by[n][0])
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                (la, ha), (lb, hb) = by[a], by[b]
                if lb < ha and la < hb and not stacked:
                    out.append(f"{a} and {b} meet {host} over the same stations (x {la:.6g} to "
                               f"{ha:.6g} and {lb:.6g} to {hb:.6g}): the fuselage layout needs "
                               f"one after the other; move {_smaller(a, b, by)} clear of the "
                               f"other in x")
    return out


def _smaller(a, b, spans):
    """Of two region names, the one with the shorter span (the one to move)."""
    return a if spans[a][1] - spans[a][0] < spans[b][1] - spans[b][0] else b


def mesh(geometry, mirror=True, cap=True, check=True, min_angle=25.0, edge_length=None,
         tolerance=1e-4, curvature=None, depth=None, half=False, flow_through=False,
         growth=None, seam_size=None):
    """One closed, consistently oriented triangulated surface of a completed geometry.

    ``juncture.mesh(geo)``: :func:`~juncture.surface.assemble.assemble` (both halves unless
    ``mirror=False``, planar open loops capped unless ``cap=False``); with ``check``, every
    check of :func:`juncture.surface.check.check_mesh` (closed, manifold, oriented, positive
    volume, no self-intersection under exact predicates): a surface that fails one is
    refused with a :class:`~juncture.errors.GeometryError` that says what fails, in one line.
    Then :func:`quality` (triangles of at least ``min_angle`` degrees where the corners
    allow, new points on the exact surfaces of circular bodies and wing-like components
    (:mod:`juncture.surface.lift`), at most ``tolerance`` times the airplane's size off
    them, no larger than equilateral triangles of ``edge_length``, each edge turning by at
    most ``curvature`` degrees of an exact surface and standing off it by at most ``depth``
    times its size (a body's radius, a wing section's thickness; defaults
    :data:`~juncture.surface.remesh.CURVATURE`, :data:`~juncture.surface.remesh.DEPTH`: the
    volume converges as they shrink); ``min_angle=0`` keeps the networks' own triangles).
    With ``half``, the y >= 0 half closed by its section in the plane of symmetry, the
    component ``"symmetry"`` (:func:`juncture.surface.half.half_model`; checked the same
    way; refused where the airplane is not its own mirror image). ``seam_size`` (a length)
    and ``growth`` (a ratio, e.g. 1.2) grade the triangles: finer at the lines where
    components meet, growing away from them and from the seams' shortest pieces no faster
    than ``growth`` per unit of their size (:mod:`juncture.surface.sizing`). With
    ``flow_through``,
    each nacelle's inlet is joined to its exit by a duct of the inlet's radius instead of
    being capped (:mod:`juncture.surface.ducts`; a handle each).

    Returns
    -------
    SurfaceMesh
        ``vertices``, ``triangles``, component and surface ids; ``volume()`` and
        ``wetted_area()``.
    """
    surface = assemble(geometry, mirror=mirror, cap=cap, flow_through=flow_through)
    lift = None
    if min_angle:
        from .lift import surface_lift

        lift = surface_lift(geometry, surface)
    whole = finish(geometry, surface, check, min_angle, edge_length, tolerance, lift,
                   curvature, depth, (growth, seam_size))[0]
    if not half:
        return whole
    return half_checked(whole, min_angle, check, geometry.configuration)[0]


def half_checked(surface, min_angle=25.0, check=True, configuration=None):
    """(half model, report) of a closed, mirror-symmetric surface
    (:func:`juncture.surface.half.half_model`, symmetric as ``configuration`` says), checked
    like the whole (report None without ``check``); a half that fails a check is refused
    (:class:`~juncture.errors.GeometryError`)."""
    from ..errors import GeometryError
    from .check import check_mesh
    from .ducts import handles
    from .half import SYMMETRY, half_model

    half = half_model(surface, min_angle or 25.0, configuration)
    if not check:
        return half, None
    report = check_mesh(half.vertices, half.triangles, handles=handles(half))
    if not report.ok:
        raise GeometryError("the half model fails its check: " + "; ".join(report.failures()),
                            component=SYMMETRY)
    return half, report


def finish(geometry, surface, check=True, min_angle=25.0, edge_length=None,
           tolerance=1e-4, lift=None, curvature=None, depth=None, grading=None):
    """(surface, report): the assembled ``surface`` re-triangulated by :func:`quality` (with
    ``min_angle``) and checked (with ``check``; report None without). The assembled surface
    itself is checked only where the re-triangulation is not kept (a re-triangulation that
    passes every check needs no second one): one that fails is refused
    (:class:`~juncture.errors.GeometryError`, the cause first where known); one that passes
    is returned with the :class:`~juncture.errors.JunctureWarning` of :func:`quality`.
    Before re-triangulating, the seams on the exact curves where wing-like components meet
    bodies are split to follow them (:func:`juncture.surface.seam_curves.follow_curves`,
    with ``lift.seam``); where that re-triangulation fails a check (the chart of a low
    wing's root block folding beside the dense seam), the assembled surface as it came is
    re-triangulated instead, as without the curves."""
    from .check import check_mesh
    from .ducts import handles

    failures = None
    if min_angle:
        followed, flift = _followed(geometry, surface, lift)
        if followed is not surface:
            better, report, _ = _remeshed(followed, min_angle, edge_length, tolerance,
                                          check, flift, curvature, depth,
                                          _line_points(geometry, followed, flift), retries=0,
                                          grading=grading)
            if report is not None or (better is not followed and not check):
                return better, report
        better, report, failures = _remeshed(surface, min_angle, edge_length, tolerance,
                                             check, lift, curvature, depth,
                                             _line_points(geometry, surface), grading=grading)
        if report is not None or (better is not surface and not check):
            return better, report
    report = None
    if check:
        report = check_mesh(surface.vertices, surface.triangles, handles=handles(surface))
        _refuse(geometry, surface, report.failures() + _crossing_surfaces(surface, report),
                _kept_roots(geometry, surface, report) + _split_roots(geometry, surface,
                                                                      report))
    if failures:
        _not_kept(failures, stacklevel=4)
    return surface, report


def _not_kept(failures, stacklevel):
    """The warning that the re-triangulation was not kept, with why."""
    import warnings

    from ..errors import JunctureWarning

    warnings.warn("the re-triangulation for triangle quality was not kept ("
                  + "; ".join(failures) + "): the networks' own triangles are used",
                  JunctureWarning, stacklevel=stacklevel)


def _crossing_surfaces(surface, report, most=3):
    """[one line naming the surfaces whose triangles cross, with a point of each pair] or
    [] (the report names triangle ids only)."""
    pairs = report.pairs
    if pairs is None or not len(pairs):
        return []
    names = np.asarray(surface.surfaces)[surface.surface[pairs]]          # (k, 2)
    names = np.sort(names, axis=1)
    groups, first, count = np.unique(names, axis=0, return_index=True, return_counts=True)
    order = np.argsort(-count)[:most]
    where = surface.vertices[surface.triangles[pairs[first[order], 0]]].mean(axis=1)
    said = [f"{a} crosses {b} ({n} pairs, near [{', '.join(f'{c:.6g}' for c in p)}])"
            for (a, b), n, p in zip(groups[order], count[order], where)]
    more = f" and {len(groups) - most} more" if len(groups) > most else ""
    return ["surfaces that cross: " + "; ".join(said) + more]


def _kept_roots(geometry, surface, report):
    """[one line per component whose root keeps input points, off what it stands on, and
    whose surfaces cross something] (the cause of those crossings, first), or []."""
    from .component_networks import kept_roots

    if report.pairs is None or not len(report.pairs):
        return []
    kept = kept_roots(getattr(geometry, "log", ()))
    names = set(np.asarray(surface.surfaces)[surface.surface[report.pairs.ravel()]].tolist())
    out = []
    for (a, b), lines in kept.items():
        if any(n.startswith(f"{a} ") for n in names):
            out.append(f"{a}: lofting lines {', '.join(map(str, sorted(lines)))} never meet "
                       f"{b}, so its root keeps its input points there, off {b}, and the "
                       f"surface closing it crosses {b}; juncture does not yet close a root "
                       f"partly off what it stands on: move {a} so that its root section "
                       f"lies on or inside {b}")
    return out


def _split_roots(geometry, surface, report):
    """[one line per component whose root stands on two components or more, line by line,
    and whose surfaces cross something or border an open loop] (the cause, first), or []."""
    from .component_networks import split_roots

    split = split_roots(getattr(geometry, "log", ()))
    if not split:
        return []
    rows = [] if report.pairs is None else [surface.surface[np.asarray(report.pairs).ravel()]]
    if surface.open_loops:
        near = np.isin(surface.triangles, np.concatenate(surface.open_loops)).any(axis=1)
        rows.append(surface.surface[near])
    if not rows:
        return []
    names = set(np.asarray(surface.surfaces)[np.concatenate(rows)].tolist())
    return [f"{a} stands partly on {' and partly on '.join(hosts)}: its root crosses their "
            "junction, where three surfaces meet at a point juncture does not construct; "
            f"move {a} so that its root lies on one of them"
            for a, hosts in split.items() if any(n.startswith(f"{a} ") for n in names)]


def _refuse(geometry, surface, failures, causes=()):
    """A one-line GeometryError for a surface that fails, the cause first where known
    (``causes``: lines naming it, put before what it leads to)."""
    from ..errors import GeometryError

    if surface.open_loops:
        failures.insert(0, f"{len(surface.open_loops)} open boundary loops (seams whose "
                           "two sides do not carry the same points)")
    if not failures:
        return
    failures = list(causes) + failures
    overlap = overlapping_regions(geometry)
    if overlap:  # the cause, in the user's terms, before what it leads to
        raise GeometryError("the completed surface is not closed and valid: "
                            + "; ".join(overlap) + f" ({failures[0]})")
    raise GeometryError("the completed surface is not closed and valid: "
                        + "; ".join(failures))


def quality(surface, min_angle=25.0, edge_length=None, tolerance=1e-4, check=True,
            lift=None, curvature=None, depth=None, grading=None):
    """(surface, report): ``surface`` re-triangulated by
    :func:`juncture.surface.remesh.remesh` and, with ``check``, its
    :func:`~juncture.surface.check.check_mesh` report.

    Where re-triangulated surfaces cross (a pod's tip, curved faster than the new triangles
    follow; a wing passing just under a narrowing tail cone), the triangles there are
    re-triangulated again with their new points left on the assembled surface, not lifted
    (:func:`_held_near`), then, where they still cross, kept as they are; where that fails
    too, or surfaces share a triangle (two surfaces that make the same one across a narrow
    corner between them), those surfaces keep their own triangles and the rest is
    re-triangulated again (up to ``RETRIES`` times). Where it still fails, the surface as it
    was (report None), with a :class:`~juncture.errors.JunctureWarning`. An open surface is
    returned as it is. ``lift`` (:func:`juncture.surface.lift.surface_lift`) puts new points
    on the exact surfaces; ``curvature`` and ``depth`` (None: the defaults) size the
    triangles on them; ``grading`` (growth, seam size) grades them
    (:mod:`juncture.surface.sizing`).
    """
    better, report, failures = _remeshed(surface, min_angle, edge_length, tolerance, check,
                                         lift, curvature, depth, grading=grading)
    if failures:
        _not_kept(failures, stacklevel=3)
    return better, report


def _line_points(geometry, surface, lift=None):
    """(n,) int8: 1 where a vertex of ``surface`` is an intersection point of ``geometry``
    (:func:`juncture.surface.imprint.on_lines`) or lies on an exact curve of ``lift.seam``
    (:mod:`juncture.surface.seam_curves`): a network may turn at a crease only there
    (:data:`juncture.surface.patches.CREASE`); :data:`~juncture.surface.creases.CORNER_LINE`
    where it lies on a corner line of an arbitrary section (kept as an edge,
    :func:`juncture.surface.creases.mark_creases`); else 0."""
    from .creases import CORNER_LINE, corner_points
    from .imprint import on_lines

    lines = np.zeros(len(surface.vertices), np.int8)
    lines[corner_points(geometry, surface)] = CORNER_LINE
    lines[list(on_lines(geometry, surface.vertices))] = 1
    curves = getattr(lift, "seam", None)
    for *_, on in (curves.lines if curves is not None else ()):
        lines[on] = 1
    return lines


def _followed(geometry, surface, lift):
    """(surface, lift): the surface with its seams on exact curves split to follow them
    (:func:`juncture.surface.seam_curves.follow_curves`) and its lift, made for it; as they
    are where ``lift`` has no curves or nothing is split."""
    curves = getattr(lift, "seam", None)
    if curves is None:
        return surface, lift
    from .lift import surface_lift
    from .seam_curves import follow_curves

    out = follow_curves(surface, curves, fixed=_line_points(geometry, surface, lift) != 0)
    return (surface, lift) if out is surface else (out, surface_lift(geometry, out))


def _remeshed(surface, min_angle, edge_length, tolerance, check, lift, curvature, depth,
              lines=None, retries=None, grading=None):
    """(surface, report, failures) of :func:`quality`, without its warning: failures None
    where the re-triangulation was kept or the surface is open (returned as it is).
    ``lines``: see :func:`juncture.surface.remesh.remesh`; ``retries``: how many times
    surfaces that crossed keep their triangles and the rest is tried again (default
    :data:`RETRIES`)."""
    from ..errors import GeometryError
    from .check import check_mesh
    from .ducts import handles
    from .remesh import remesh

    sizing = {k: v for k, v in (("curvature", curvature), ("depth", depth)) if v is not None}
    if grading is not None:
        sizing.update(growth=grading[0], seam_size=grading[1])
    if surface.open_loops:
        return surface, None, None
    keep, held, frozen, local, crossings = set(), None, None, HELD_TRIES + 1, None
    tries = (RETRIES if retries is None else retries) + 1
    while tries:
        tries -= 1
        try:
            better = remesh(surface, min_angle=min_angle, edge_length=edge_length,
                            tolerance=tolerance, keep=keep, lift=lift, lines=lines,
                            held=held, frozen=frozen, crossings=crossings, **sizing)
        except GeometryError as exc:
            failures = [str(exc)]
            break
        if not check:
            return better, None, None
        report = check_mesh(better.vertices, better.triangles, handles=handles(better))
        failures = report.failures()
        if not failures:
            return better, report, None
        if local and tries and _crossing_only(report):
            # first only where they crossed: re-triangulated unlifted, then kept
            held, frozen, crossings = _hold(surface, better, report, held, crossings, local)
            local, tries = local - 1, tries + 1
            continue
        more = _troubled_surfaces(better, report) - keep
        if not more:
            break
        keep |= more
        held = frozen = crossings = None
    return surface, None, failures


#: Tries in which the triangles near where re-triangulated surfaces crossed are
#: re-triangulated unlifted (:func:`_hold`), each holding the crossings of the tries before,
#: before they keep their assembled triangles (a wing and fuselage as one network, charted
#: across the crease at the wing's root, crossed in 14 and 8 triangle pairs, then none).
HELD_TRIES = 4


def _hold(surface, better, report, held, crossings, local):
    """(held, frozen, crossings) for the try after one whose surfaces crossed: the
    triangles near the crossing held (:func:`_held_near`), with those held before and the
    crossings before while a held try is left (``local`` > 1: a held try can cross again
    beside the first crossing, where its new points were lifted), then kept as assembled
    (frozen)."""
    near, found = _held_near(surface, better, report)
    if held is None:
        return near, None, found
    if local > 1:
        return held | near, None, np.concatenate([crossings, found])
    return held, held | near, crossings


def _crossing_only(report):
    """Whether the only failure is triangles that cross."""
    return bool(report.intersecting_pairs) and not (
        report.open_edges or report.misoriented_edges or report.nonmanifold_edges)


#: Input triangles within this many of its longest edges of a crossing triangle are held
#: (:func:`_held_near`).
NEAR_CROSSING = 2.0


def _held_near(surface, better, report):
    """(m,) bool over ``surface.triangles``: those that come within :data:`NEAR_CROSSING`
    times its longest edge of a re-triangulated triangle that crosses another, and their
    neighbours. In the next try their patches are charted in pieces, these re-triangulated
    with their new points left on the assembled triangles
    (:func:`juncture.surface.remesh.remesh`, ``held``)."""
    from scipy.spatial import cKDTree

    from .check import self_intersections

    pairs = report.pairs if report.pairs is not None else \
        self_intersections(better.vertices, better.triangles)
    p = better.vertices[better.triangles[np.unique(pairs)]]
    reach = NEAR_CROSSING * np.linalg.norm(p - np.roll(p, 1, axis=1), axis=2).max(axis=1)
    q = surface.vertices[surface.triangles]
    centre, radius = q.mean(axis=1), _radius(q)
    near = np.zeros(len(surface.triangles), bool)
    found = cKDTree(centre).query_ball_point(p.mean(axis=1), reach + radius.max())
    for c, r, rows in zip(p.mean(axis=1), reach, found):
        rows = np.asarray(rows, int)
        near[rows[np.linalg.norm(centre[rows] - c, axis=1) <= r + radius[rows]]] = True
    ring = np.zeros(len(surface.vertices), bool)
    ring[surface.triangles[near].ravel()] = True
    return ring[surface.triangles].any(axis=1), np.column_stack([p.mean(axis=1), reach])


def _radius(q):
    """(m,) the largest distance of a triangle's corners from its centre."""
    return np.linalg.norm(q - q.mean(axis=1, keepdims=True), axis=2).max(axis=1)


#: Re-triangulations after the first, each keeping the surfaces that crossed.
RETRIES = 2


def _troubled_surfaces(surface, report):
    """Surface ids of the triangles on edges in more than two triangles and of the triangle
    pairs that cross; empty when anything else fails (open, misoriented: not a matter of
    some surfaces)."""
    from .chart import patch_edges
    from .check import self_intersections

    if report.open_edges or report.misoriented_edges:
        return set()
    out = set()
    if report.nonmanifold_edges:
        _, _, uses, inverse = patch_edges(surface.triangles)
        many = uses[inverse] > 2          # per directed edge: rows 01, then 12, then 20
        out |= set(np.tile(surface.surface, 3)[many].tolist())
    if report.intersecting_pairs:
        crossing = report.pairs
        if crossing is None:
            crossing = self_intersections(surface.vertices, surface.triangles)
        out |= set(surface.surface[crossing.ravel()].tolist())
    return out
