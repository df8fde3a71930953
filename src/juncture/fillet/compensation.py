"""keep_area: the fuselage re-designed until body + fillet area is the original (TM-4406).

The fillets are rebuilt on each re-designed body (:mod:`juncture.fillet.redesign`,
:mod:`juncture.fillet.section_redesign`) and their added area measured
(:mod:`juncture.fillet.area`); a structured Newton step models each station's area on the
radius reductions under its two fillet lines.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..errors import ConvergenceError, GeometryError, JunctureWarning
from .area import fillet_added_area
from .redesign import _radius_of
from .section_redesign import reduction_for

__all__ = ["keep_area", "Compensation", "Compensate"]

#: What the re-designed body gives up (:func:`keep_area`).
Compensate = Literal["section", "fillet"]


@dataclass(frozen=True, slots=True, eq=False)
class Compensation:
    """Result of :func:`keep_area`.

    Attributes
    ----------
    body : CircularBody
        The re-designed body: the original stations plus every fillet station, radius reduced
        so that body area + fillet area equals the original area at each fillet station.
    x : (m,) float
        Fillet stations (x of the upper fillet lines' starts; of the lower ones where only
        the upper line passes over the body) of the final iteration.
    area_original, area_fillet, area_fillet_only, area_body : (m,) float
        pi r0(x)^2; the area the re-design takes from the body: the fillets' added area plus
        (``compensate="section"``) the wing root they uncover as the body shrinks; the
        fillets' area alone (TM-4406 eq 14); pi r_new(x)^2 [deck length^2]. All for
        ``sides`` fillets.
    radius_original, radius_new : (m,) float
    residual : (m,) float
        |area_body + area_fillet - area_original| / area_original per station.
    iterations : (m,) int
        Iteration at which each station first met the tolerance.
    n_iterations : int
    fillets : tuple
        (upper intersection, lower intersection, upper fillet, lower fillet) of the final body.
    """

    body: object
    x: np.ndarray
    area_original: np.ndarray
    area_fillet: np.ndarray
    area_fillet_only: np.ndarray
    area_body: np.ndarray
    radius_original: np.ndarray
    radius_new: np.ndarray
    residual: np.ndarray
    iterations: np.ndarray
    n_iterations: int
    fillets: tuple


#: Largest relative residual of an iteration that stops short of the tolerance that is
#: still returned (its best iterate, with a warning) instead of raising.
_ACCEPT = 1e-6
#: Substitutions in a row (the Newton model failing) after which the nodes are re-set.
_RENODE_AFTER = 5


def _structured_newton(history, c_upper, w_upper, w_lower):
    """Newton step for F(t) = G(t) - given(t) = 0 with a Jacobian built from its structure.

    A station's added area G_j depends on the body where its two fillet lines start: the
    radius reductions D_u = d(x_u,j) (upper, the station itself) and D_l = d(x_l,j) (the
    lower line of the same lofting line, at another x). Model G_j = const + alpha_j D_u +
    beta_j D_l, with alpha_j, beta_j fitted to the measured differences of the last
    iterates (least squares per station; minimum norm from a single difference); the given
    area depends on D_u through c_upper = d(given)/dD_u = 2 pi r - L. With w_upper, w_lower
    = dD/dt (exact, from the re-designed body) the Jacobian is

        J = diag(alpha - c_upper) w_upper + diag(beta) w_lower.

    ``history`` holds (t, F, (D_u, D_l, G)) per iterate, oldest first. Returns the step, or
    None if the model is singular (then the caller substitutes).
    """
    du = np.diff(np.array([h[2][0] for h in history]), axis=0)  # (k, n)
    dl = np.diff(np.array([h[2][1] for h in history]), axis=0)
    dg = np.diff(np.array([h[2][2] for h in history]), axis=0)
    # Per-station 2x2 normal equations, with a ridge so that one difference gives the
    # minimum-norm fit.
    suu, sul, sll = (du * du).sum(0), (du * dl).sum(0), (dl * dl).sum(0)
    sug, slg = (du * dg).sum(0), (dl * dg).sum(0)
    if len(du) == 1:
        # One difference cannot separate alpha from beta at a station; fit them as
        # constants across the stations (they vary slowly along the wing) instead.
        m = np.stack([du[0], dl[0]], axis=1)
        coef, _, rank, sv = np.linalg.lstsq(m, dg[0], rcond=None)
        if rank == 2 and sv[-1] > 1e-3 * sv[0]:
            suu, sul, sll = np.ones_like(suu), np.zeros_like(sul), np.ones_like(sll)
            sug, slg = np.full_like(sug, coef[0]), np.full_like(slg, coef[1])
    ridge = 1e-10 * (suu + sll)
    det = (suu + ridge) * (sll + ridge) - sul * sul
    moved = det > 0  # a station whose body never moved keeps alpha = beta = 0
    safe = np.where(moved, det, 1.0)
    alpha = np.where(moved, ((sll + ridge) * sug - sul * slg) / safe, 0.0)
    beta = np.where(moved, ((suu + ridge) * slg - sul * sug) / safe, 0.0)
    jac = (alpha - c_upper)[:, None] * w_upper + beta[:, None] * w_lower
    f = history[-1][1]
    try:
        with np.errstate(all="ignore"):
            step = np.linalg.solve(jac, -f)
    except np.linalg.LinAlgError:
        return None
    # A step far beyond the substitution's is a broken model, not a Newton step.
    if not np.all(np.isfinite(step)) or np.abs(step).max() > 10 * np.abs(f).max():
        return None
    return step


def _feasible(reduction, t, step, scale=1.0, tries=6):
    """t + scale step, halved towards t until the body has the area it asks for (the last
    try raises the GeometryError)."""
    for k in range(tries):
        trial = t + scale * 0.5 ** k * step
        try:
            reduction.body(trial)
            return trial
        except GeometryError:
            if k == tries - 1:
                raise
    return trial


def _fillets_on(make_fillets, current, previous, warm, it, x):
    """make_fillets on an iterate; on a re-designed body a failure (a lofting line that
    grazes it) is the iteration's, named by the body and the stations it had reached."""
    if x is None:
        return make_fillets(current, previous, warm)
    try:
        return make_fillets(current, previous, warm)
    except ConvergenceError as exc:
        raise ConvergenceError(f"area compensation stopped at iteration {it} (stations x = "
                               f"{x.min():.6g} to {x.max():.6g}): on the re-designed body, "
                               f"{exc.reason}", current.name) from None


def keep_area(body, make_fillets, tolerance=1e-9, max_iterations=150, sides=2, exposure=None,
              memory=1, initial=None, compensate: Compensate = "section"):
    """Shrink the body until body area + added area equals the original area (TM-4406).

    TM-4406 compensates the fillet's area (eq 14) only (``compensate="fillet"``). When the
    body shrinks, the wing's root extends into the space it leaves, which adds area too
    (about a fifth of the fillet's on the PDAS sample deck, where compensating the fillet
    alone left the slender-body wave drag 0.25 % high). By default (``"section"``) the added
    area compensated is therefore the fillet plus that uncovered wing root, so that the whole
    cross-section keeps its original area.

    Parameters
    ----------
    body : CircularBody
        The original body.
    make_fillets : callable
        ``make_fillets(body, previous, warm) -> (upper_inter, lower_inter, upper_fillet,
        lower_fillet)`` for a given body (the fillet is rebuilt on each re-designed body);
        ``previous`` is None (the original body) or that tuple from the previous iterate,
        whose blending region the new fillets keep; ``warm`` says whether its solutions may
        seed the root finders (only while every re-designed body lies inside the original).
    tolerance : float
        Relative area residual to reach at every fillet station.
    sides : {1, 2}
        How many fillets share each body cross-section: 2 for a wing with a mirror image (the
        body's pi r^2 is the whole section, so both sides' fillets are compensated), 1 for a
        surface on the plane of symmetry.
    exposure : callable, optional
        ``exposure(x) -> L``: body perimeter covered by wing-like roots at x (all of them,
        both sides; see :func:`reduced_body`). The fillets are then measured on their
        stations and the uncovered roots everywhere on the re-designed body, so the whole
        cross-section keeps its area between the fillet stations too. Without it the
        uncovered wing root is measured on the fillet stations only (fillet polygons).
    memory : int
        Past differences the Newton step's sensitivities are fitted to (1: the last one,
        with the sensitivities taken as constants across the stations).
    initial : tuple, optional
        ``make_fillets(body, None, False)`` if the caller already has it.
    compensate : {"section", "fillet"}
        What the body gives up: the fillets and the wing root they uncover (the whole
        cross-section keeps its area), or the fillets' area alone (TM-4406 eqs 11-14: the
        body area plus the fillets' equals the original; ``exposure`` is then not used).

    Returns
    -------
    Compensation
        ``area_fillet`` is the added area of all ``sides`` fillets at each station (with
        ``compensate="section"``, plus the uncovered root).

    Raises
    ------
    GeometryError
        An unknown ``compensate``; the fillets need more area than the body has.
    ConvergenceError
        The residual does not reach ``tolerance`` in ``max_iterations``, and the best
        iterate's is above 1e-6 (at or below it, that iterate is returned with a
        :class:`JunctureWarning`).

    Notes
    -----
    Each iteration removes an area t from the original body (not from the previous iterate)
    at fixed nodes (the stations on the original body), so the problem is the root of
    F(t) = A(body(t)) - given(body(t)), the added area against what the body gives up, both
    measured at the current stations. The first step is the paper's substitution (which
    alone converges linearly, about 0.07 per step on the benchmark wing). After it, a Newton
    step uses the structure of the Jacobian: a station's area depends on the body only
    where its upper and its lower fillet lines start (the lower one at another x), with
    sensitivities fitted to the measured differences (:func:`_structured_newton`) and the
    exact derivative of the re-designed body (:meth:`BodyReduction.jacobian`). The fillets
    keep the original body's blending region, and the re-designed body is a smooth function
    of t (Hermite pieces), so the model holds. The intersections are warm-started from the
    previous iterate while the body only shrinks.
    """
    if compensate not in ("section", "fillet"):
        raise GeometryError(f"compensate must be 'section' or 'fillet', found {compensate!r}",
                            body.name)
    if compensate == "fillet":
        exposure = None
    elif exposure is None and not hasattr(body, "radius_at"):
        raise GeometryError("keep_area on an arbitrary-section body measures the wing root "
                            "it uncovers by its covered perimeter: pass exposure, or "
                            "compensate='fillet'", body.name)

    radius = _radius_of(body)
    current = body
    first_met = None
    history = []
    previous, warm = None, False
    reduction = t = None
    stalled = 0  # Newton models that failed in a row
    best = None  # the iterate of least worst residual
    x = None  # the stations of the last iterate
    seen = []  # the last iterates' intersections (which lines met the body)
    for it in range(1, max_iterations + 1):
        parts = initial if (it == 1 and initial is not None) else \
            _fillets_on(make_fillets, current, previous, warm, it, x)
        seen = seen[-(_WINDOW - 1):] + [parts[:2]]
        if compensate == "fillet":
            # TM-4406: the fillets alone.
            x, only = fillet_added_area(current, *parts[2:], *parts[:2])
            r_orig, r_now = radius(x), _radius_of(current)(x)
            only = sides * only
            a_f, covered = only, 0.0
        elif exposure is not None:
            # Fillets by their areas; every uncovered root by its covered perimeter.
            x, only = fillet_added_area(current, *parts[2:], *parts[:2])
            r_orig, r_now = radius(x), _radius_of(current)(x)
            covered = exposure(x)
            only = sides * only
            a_f = only + covered * (r_orig - r_now)
        else:
            x, only, a_f = fillet_added_area(current, *parts[2:], *parts[:2],
                                             reference_body=body)
            only, a_f = sides * only, sides * a_f
            r_orig, r_now = radius(x), _radius_of(current)(x)
            covered = 0.0  # the polygons already hold the uncovered root
        a0 = np.pi * r_orig ** 2
        a_b = np.pi * r_now ** 2
        residual = np.abs(a_b + a_f - a0) / np.where(a0 > 0, a0, 1.0)
        met = residual <= tolerance
        first_met = np.where(met, it, 0) if first_met is None else \
            np.where((first_met == 0) & met, it, first_met)
        result = Compensation(current, x, a0, a_f, only, a_b, np.sqrt(a0 / np.pi), r_now,
                              residual, first_met, it, parts)
        if met.all():
            return result
        if best is None or residual.max() < best.residual.max():
            best = result
        # The unknown: the area t given up for the fillets (and, without an exposure model,
        # for the uncovered root too) at fixed nodes, the first iteration's stations. The
        # stations move a little as the body shrinks (the lofting lines meet it further
        # inboard), so the residual F = G - given is measured where they are now, on what
        # the body really gives up there; with the nodes fixed it is a function of t alone.
        g = only if (exposure is not None or compensate == "fillet") else a_f
        given = a0 - a_b - covered * (r_orig - r_now)
        x_low = parts[3].points[:, 0, 0]
        sample = (r_orig - r_now, radius(x_low) - _radius_of(current)(x_low), g)
        if reduction is None or stalled >= _RENODE_AFTER:
            # (Again, at the stations where they are now, when the Newton model has failed
            # that many times in a row: the nodes lag behind stations that moved, where t
            # barely changes the area and the substitution crawls.)
            reduction, t = reduction_for(body, x, exposure=exposure), given
            history, stalled = [], 0
        f = g - given
        size = np.abs(f).max()
        if history and size > np.abs(history[-1][1]).max():
            history = []  # no progress: start the model again from here
        history.append((t, f, sample))
        step = None
        if len(history) >= 2:
            w = reduction.jacobian(np.concatenate([x, x_low]))
            step = _structured_newton(history[-(memory + 1):], 2 * np.pi * r_now - covered,
                                      w[:x.size], w[x.size:])
        if step is not None:
            try:
                reduction.body(t + step)
            except GeometryError:
                # A Newton step that asks more than the body has: the paper's substitution.
                step, history = None, []
        # Count the Newton models that failed, not the substitutions that start a model
        # again: a residual that edges up and down resets the history every other step,
        # and the nodes must still be re-set when the model keeps failing in between.
        if step is not None:
            stalled = 0
        elif len(history) >= 2:
            stalled += 1
        t = _feasible(reduction, t, f if step is None else step)
        current = reduction.body(t)
        # Warm starts are safe while the body only shrinks (nothing new outboard to meet).
        previous, warm = parts, bool(np.all(t >= 0))
    worst = best.residual.max()
    where = f"{best.x[np.argmax(best.residual)]:.6g}"
    if worst <= _ACCEPT:
        # Stuck just above the tolerance (the fillets' own precision, or an added area that
        # jumps as the body moves): the best iterate, said once.
        warnings.warn(f"{body.name}: area compensation stopped at a residual of {worst:.3g} "
                      f"(x = {where}), not {tolerance:g}, after {max_iterations} iterations; "
                      "the best iterate is kept", JunctureWarning, stacklevel=3)
        return best
    why = _grazing(best, seen, body) or _crowded(best, body) or (
        "the added area there jumps as the body shrinks; a smaller theta_u, e.g. 10 deg, "
        "usually settles it")
    raise ConvergenceError(f"area compensation did not reach {tolerance:g} in {max_iterations} "
                           f"iterations (worst residual {worst:.3g} at x = {where}: {why})",
                           body.name)


#: Iterates over which :func:`_grazing` looks for a line that meets the body and misses it.
_WINDOW = 30


def _grazing(best, seen, body):
    """Why the iteration cannot settle when the worst station's lofting line meets the body
    on some of the last iterates and misses it on others (``seen``: their intersections,
    upper and lower): it grazes the body, and its fillet (and the root it uncovers) comes
    and goes as the body shrinks by a little, so no re-designed body keeps the area there;
    else None."""
    w = int(np.argmax(np.asarray(best.residual, float)))
    for k in range(2):
        found = np.array([np.asarray(pair[k].found, bool)[w] for pair in seen])
        if found.any() and not found.all():
            return (f"{seen[-1][k].name} lofting line {w + 1} grazes {body.name}: as the "
                    "body shrinks by a little the line meets it on some iterates and misses "
                    "it on others, and its fillet comes and goes, so no re-designed body "
                    "keeps the area there. Move the wing so that the line clearly meets or "
                    "clearly misses the body, or do without keep_area")
    return None


#: Two stations nearer than this (relative to the body's length) are one cross-section.
_SAME_X = 1e-3


def _crowded(best, body):
    """Why the iteration cannot settle when the worst station shares its cross-section with
    another: two lofting lines meet the body at (nearly) the same x, where the intersection
    line turns back in x, and their fillets ask different areas of the one section there;
    else None."""
    x, res = np.asarray(best.x, float), np.asarray(best.residual, float)
    w = int(np.argmax(res))
    gap = np.abs(x - x[w])
    gap[w] = np.inf
    k = int(np.argmin(gap))
    if not gap[k] <= _SAME_X * max(float(getattr(body, "length", 1.0)), 1e-300):
        return None
    return (f"the stations of lofting lines {min(w, k) + 1} and {max(w, k) + 1} lie at nearly "
            f"the same x ({x[w]:.6g} and {x[k]:.6g}; the intersection line turns back in x "
            "there), and their fillets ask different areas of that one cross-section "
            "(TM-4406 compensates one fillet per station). Move the wing so that its "
            "intersection runs aft along the chord, or do without keep_area")
