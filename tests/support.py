"""Shared test references: the sample files in tests/data (provenance in
tests/data/PROVENANCE.md) and the bundled example."""

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data"
PDAS_DECK = DATA / "wavedrag" / "pdas_wdcase1_wing_3segment_circular_body.inp"
PDAS_WGS = DATA / "lawgs" / "pdas_wdcase1_wd2wgs_output.wgs"
LAWGS_DIR = DATA / "lawgs"
DECKS_DIR = DATA / "decks"
EXAMPLE_DECK = ROOT / "examples" / "supersonic_transport.inp"


def wing_body(z_root=0.0, dihedral_deg=0.0, root_y=1.0, radius=3.0, sweep_deg=40.0,
              n_sections=4, n_stations=11, thickness=4.0, camber=0.0, body_camber=0.0):
    """A configuration built in code: a swept, tapered wing on a cylinder with ogive ends.

    Stations and sections have different counts; everything is slightly perturbed away from
    symmetric cases. Units are arbitrary (body length 60).
    """
    import numpy as np

    from juncture.model import CircularBody, Configuration, WingLike

    x = np.array([0.0, 3.0, 7.0, 12.0, 18.0, 26.0, 34.0, 42.0, 48.0, 53.0, 57.0, 60.0])
    xi = x / 60.0
    r = radius * np.clip(np.minimum(xi / 0.3, (1 - xi) / 0.25), 0.0, 1.0) ** 0.6
    r[0] = 0.0
    body = CircularBody("body", x, r, body_camber * np.sin(np.pi * xi), segments=(12,))
    y = root_y + np.linspace(0.0, 14.0, n_sections) ** 1.02
    t = np.tan(np.radians(sweep_deg))
    chord = np.linspace(22.0, 7.0, n_sections)
    le = np.stack([16.0 + (y - root_y) * t, y,
                   z_root + (y - root_y) * np.tan(np.radians(dihedral_deg))], axis=1)
    xc = np.linspace(0.0, 100.0, n_stations) ** 1.0
    half = thickness / 2 * np.sqrt(np.maximum(4 * xc / 100 * (1 - xc / 100), 0.0))
    up = np.tile(half, (n_sections, 1)) * np.linspace(1.0, 0.8, n_sections)[:, None]
    cam = camber * chord[:, None] / 100.0 * 4 * xc / 100 * (1 - xc / 100)
    wing = WingLike("wing", "wing", le, chord, xc, up, up * 0.9, cam)
    return Configuration({"wing": wing, "body": body}, title="test wing-body",
                         reference_area=500.0)


def section_area(vertices, triangles, x):
    """The area a closed, consistently oriented triangulated surface encloses in the plane
    x = const: the triangles it cuts give the section's segments (oriented by their normals),
    and Green's theorem sums them. An independent slice, not juncture's."""
    import numpy as np

    p = np.asarray(vertices, float)[np.asarray(triangles)]
    s = p[:, :, 0] - x
    s = np.where(s == 0.0, 1e-300, s)
    above = s > 0
    cut = above.any(axis=1) & ~above.all(axis=1)
    p, s, above = p[cut], s[cut], above[cut]
    ends = []
    for a, b in ((0, 1), (1, 2), (2, 0)):
        crosses = above[:, a] != above[:, b]
        t = (s[:, a] / np.where(crosses, s[:, a] - s[:, b], 1.0))[:, None]
        ends.append((crosses, p[:, a] + t * (p[:, b] - p[:, a])))
    crossing = np.stack([c for c, _ in ends], axis=1)          # two per triangle
    points = np.stack([q for _, q in ends], axis=1)
    first = np.argmax(crossing, axis=1)
    second = 2 - np.argmax(crossing[:, ::-1], axis=1)
    rows = np.arange(len(p))
    u, v = points[rows, first], points[rows, second]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    flip = np.einsum("ij,ij->i", v - u, np.cross(n, [1.0, 0.0, 0.0])) < 0
    u[flip], v[flip] = v[flip].copy(), u[flip].copy()
    return abs(0.5 * np.sum(u[:, 1] * v[:, 2] - u[:, 2] * v[:, 1]))


def junctions_overlap(cfg, a, b, host):
    """Whether the junctions of components ``a`` and ``b`` with the body ``host`` overlap
    on it, tested point by point (not juncture.crossings' polygons): some point of one's
    intersection lines (their points and 19 more along each chord between them) lies round
    the body's axis strictly between the other's two lines at its x, each line's angle
    interpolated along x either along its 3-D chords or linearly between its points (the
    exact line runs between the two; where one junction's end touches the other's line,
    a fin's trailing edge on a tail's root, the two differ by 0.6 deg and only one says
    they overlap: a junction of three surfaces either way)."""
    import numpy as np

    from juncture.intersect.pairs import Pair, intersect_pair

    body = cfg[host]

    def angle(p):
        c = body.center_at(p[:, 0])
        return np.arctan2(p[:, 2] - c[:, 1], p[:, 1] - c[:, 0])

    def lines(name, dense):
        out = []
        for r in intersect_pair(cfg, Pair(name, host, "body")):
            p = r.points[np.all(np.isfinite(r.points), axis=1)]
            p = p[np.argsort(p[:, 0])]
            if dense and len(p) > 1:   # 20 points along each chord (bands can cross)
                t = np.linspace(0.0, 1.0, 20, endpoint=False)
                p = np.concatenate([(p[:-1, None] + t[:, None] * np.diff(p, axis=0)[:, None])
                                    .reshape(-1, 3), p[-1:]])
            out.append(p)
        return out

    def inside(points, two):
        if not len(points):
            return False
        if any(len(q) < 2 for q in two):
            return False
        lo_x, hi_x = max(q[:, 0].min() for q in two), min(q[:, 0].max() for q in two)
        p = points[(points[:, 0] >= lo_x) & (points[:, 0] <= hi_x)]
        if not len(p):
            return False
        t = [np.interp(p[:, 0], q[:, 0], np.unwrap(angle(q))) for q in two]
        a_p = angle(p)
        return bool(np.any((np.minimum(*t) < a_p) & (a_p < np.maximum(*t))))

    la, lb = lines(a, True), lines(b, True)
    if inside(np.concatenate(la), lb) or inside(np.concatenate(lb), la):
        return True
    sa, sb = lines(a, False), lines(b, False)      # each line's angle linear in x
    return inside(np.concatenate(la), sb) or inside(np.concatenate(lb), sa)


def plane_feet(q, p):
    """(signed distances of a point q (3,) from the planes of the triangles p (t, 3, 3),
    whether its foot on each plane falls inside the triangle): an independent test of
    planes and sides, for the distance of a point from a mesh."""
    import numpy as np

    a, b, c = p[:, 0], p[:, 1], p[:, 2]
    n = np.cross(b - a, c - a)
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    h = np.einsum("ij,ij->i", q - a, n)
    foot = q - h[:, None] * n
    inside = np.ones(len(p), bool)
    for u, v in ((a, b), (b, c), (c, a)):
        inside &= np.einsum("ij,ij->i", np.cross(v - u, foot - u), n) >= -1e-9
    return h, inside


def smallest_angles(vertices, triangles):
    """(t,) each triangle's smallest corner angle [deg] from its edge lengths (the law of
    cosines): independent of juncture's triangle_angles."""
    import numpy as np

    p = np.asarray(vertices, float)[np.asarray(triangles)]
    a, b, c = (np.linalg.norm(p[:, (k + 1) % 3] - p[:, (k + 2) % 3], axis=1) for k in range(3))
    cos = np.clip(np.stack([(b * b + c * c - a * a) / (2 * b * c),
                            (c * c + a * a - b * b) / (2 * c * a),
                            (a * a + b * b - c * c) / (2 * a * b)], 1), -1.0, 1.0)
    return np.degrees(np.arccos(cos)).min(axis=1)
