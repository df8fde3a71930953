"""References from Moulton & Hunsaker (2024) and from the authors' code, for test_wing_paper.

Everything here is in the PAPER's aircraft axes: x forward, y right, z down, with the
inertia tensor's off-diagonal elements = -integral x y dm (the paper's eq 36). juncture's
project axes are x aft, y right, z up: a point [x, y, z] there is [-x, y, -z] here, and the
tensor's xy and yz elements change sign (``juncture.massprops.wing.paper_to_project``).

Three kinds of reference:

* ``paper_segment_exact``: the paper's printed closed forms (eqs 18-19, 28-29, 32-33, 36,
  43-46, 51-54, 59, with eq 46's ``4 c_r c_r^3`` read as ``4 c_r c_t^3``) and the NACA
  v-integrals (eqs 20, 30, 47, 48) evaluated in exact rational arithmetic (``Fraction``)
  from the float inputs taken exactly. It imports nothing from juncture.
* ``MMOIPY_*``: numbers printed by the authors' code, MMoIpy (github.com/benjaminmoulton/
  MMoIpy, the repository the paper cites; commit f95401b "remove anhedral from cases"), run
  as ``AircraftSystem({"components": {"w": wing}}, verbose=False).get_mass_properties()``
  with ``"type": "symmetric_airfoil"`` (its default thickness coefficients are Table 1's
  traditional NACA 4-digit row) or ``"diamond_airfoil"``, ``"mass": 3.0``,
  ``"semispan": 4.0``, ``"chord": [[0, 1.0], [1, c_t]]``, ``"thickness": [[0, 0.08],
  [1, 0.10]]``, sweep and dihedral in degrees, and the root given by
  ``"connect_to": {"dx", "dy", "dz"}`` (or ``"y_offset"``, which a "both" wing mirrors for
  its left half). Values are Python reprs of its float64 results.
* ``SECTION3_*``: the data behind the paper's section 3 figures 3-6 (Table 2 wing), from the
  same repository, ``eval/``: the "Exact" curve as ``eval/compare_lanham.py`` computes it
  (``symmetric_airfoil``), the "Lanham" curve (``lanham_wing``), and the "CAD" points, the
  SolidWorks 2022 mass-properties reports ``eval/RT00.txt`` ... ``RT10.txt`` (taper ratio
  0.0 ... 1.0; printed to 8 decimals; SolidWorks prints the products "in positive tensor
  notation", Lxy = +integral x y dm, and labels the slug masses "pounds"). The paper prints
  none of these numbers, it plots them.
"""

from __future__ import annotations

import math
from fractions import Fraction as F

# ----------------------------------------------------------------- the paper's closed forms
# Table 1, traditional NACA 4-digit series (a0..a4), the section of Table 2's wing.
NACA4_TRADITIONAL = (2.969, -1.260, -3.516, 2.843, -1.015)


def naca_v_exact(a):
    """(v0, v1, v2, v3) of eqs 20, 30, 47 and 48 as Fractions (eq 48: its 35 printed terms
    are the expansion of integral mu^3 dx, summed here as the 125-term triple sum)."""
    a = [F(c) for c in a]
    v0 = (40 * a[0] + 30 * a[1] + 20 * a[2] + 15 * a[3] + 12 * a[4]) / 60            # eq 20
    v1 = (56 * a[0] + 50 * a[1] + 40 * a[2] + 33 * a[3] + 28 * a[4]) / 60            # eq 30
    v2 = (856 * a[0] + 770 * a[1] + 644 * a[2] + 553 * a[3] + 484 * a[4]) / 980      # eq 47
    p = [F(1, 2), F(1), F(2), F(3), F(4)]
    v3 = sum(a[i] * a[j] * a[k] / (p[i] + p[j] + p[k] + 1)                            # eq 48
             for i in range(5) for j in range(5) for k in range(5))
    return v0, v1, v2, v3


def paper_segment_exact(b, cr, ct, tr, tt, tan_sweep, v, delta, root, mass):
    """Volume, CG and inertia about the CG of an undihedralled segment, paper axes, exact.

    ``delta`` is eq 24's side (1 right, -1 left); ``root`` the root quarter-chord point in
    the aircraft frame (section 2.1: the wing frame's origin), added to the CG as it is.
    Returns (V, [x, y, z], 3x3 nested list), all Fractions.
    """
    b, cr, ct, tr, tt, t, m = (F(q) for q in (b, cr, ct, tr, tt, tan_sweep, mass))
    v0, v1, v2, v3 = (F(q) for q in v)
    ka = tr * (3 * cr**2 + 2 * cr * ct + ct**2) + tt * (cr**2 + 2 * cr * ct + 3 * ct**2)  # 19
    kb = (tr * (4 * cr**3 + 3 * cr**2 * ct + 2 * cr * ct**2 + ct**3)                      # 28
          + tt * (cr**3 + 2 * cr**2 * ct + 3 * cr * ct**2 + 4 * ct**3))
    kc = tr * (3 * cr**2 + 4 * cr * ct + 3 * ct**2) + 2 * tt * (cr**2 + 3 * cr * ct + 6 * ct**2)
    kd = (tr * (cr + ct) * (2 * cr**2 + cr * ct + 2 * ct**2)                              # 43
          + tt * (cr**3 + 3 * cr**2 * ct + 6 * cr * ct**2 + 10 * ct**3))
    ke = (tr * (5 * cr**4 + 4 * cr**3 * ct + 3 * cr**2 * ct**2 + 2 * cr * ct**3 + ct**4)  # 44
          + tt * (cr**4 + 2 * cr**3 * ct + 3 * cr**2 * ct**2 + 4 * cr * ct**3 + 5 * ct**4))
    kf = tr * (cr**2 + 2 * cr * ct + 2 * ct**2) + tt * (cr**2 + 4 * cr * ct + 10 * ct**2)  # 45
    kg = (tr**3 * (35 * cr**4 + 20 * cr**3 * ct + 10 * cr**2 * ct**2 + 4 * cr * ct**3 + ct**4)
          + tr**2 * tt * (15 * cr**4 + 20 * cr**3 * ct + 18 * cr**2 * ct**2 + 12 * cr * ct**3
                          + 5 * ct**4)
          + tr * tt**2 * (5 * cr**4 + 12 * cr**3 * ct + 18 * cr**2 * ct**2 + 20 * cr * ct**3
                          + 15 * ct**4)
          + tt**3 * (cr**4 + 4 * cr**3 * ct + 10 * cr**2 * ct**2 + 20 * cr * ct**3
                     + 35 * ct**4))                                                         # 46
    vol = b / 12 * ka * v0                                                                  # 18
    x = -(3 * kb * v1 + 4 * b * kc * v0 * t) / (20 * ka * v0)                               # 32
    y = delta * b * kc / (5 * ka)                                                           # 33
    ixx = m * (56 * b**2 * kf * v0 + kg * v3) / (280 * ka * v0)                             # 51
    iyy = m * (84 * b * (2 * b * kf * v0 * t**2 + kd * v1 * t) + 49 * ke * v2
               + 3 * kg * v3) / (840 * ka * v0)                                             # 52
    izz = m * (12 * b * (2 * b * (t**2 + 1) * kf * v0 + kd * v1 * t)
               + 7 * ke * v2) / (120 * ka * v0)                                             # 53
    ixy = -delta * b * m * (4 * b * kf * v0 * t + kd * v1) / (20 * ka * v0)                 # 54
    inertia = [[ixx - m * y * y, -ixy + m * x * y, F(0)],                           # 36, 59
               [-ixy + m * x * y, iyy - m * x * x, F(0)],
               [F(0), F(0), izz - m * (x * x + y * y)]]
    cg = [F(root[0]) + x, F(root[1]) + y, F(root[2])]                                      # 34
    return vol, cg, inertia


# ------------------------------------------------------------------ the authors' code
#: The wing of issue 11: Table 2's wing at taper 0.5 as a LEFT wing with its root at
#: y = -0.5. Keys: MMoIpy inputs; "volume", "cg", "inertia" its outputs (paper axes).
MMOIPY_TABLE2 = dict(semispan=4.0, chord_root=1.0, chord_tip=0.5, thickness_root=0.08,
                     thickness_tip=0.10, mass=3.0)

MMOIPY_CASES = {
    # name: (side, airfoil, sweep_deg, dihedral_deg, root (paper axes), volume, cg, inertia)
    "left, root y = -0.5 (issue 11)": (
        "left", "naca4", 10.0, 0.0, (0.0, -0.5, 0.0), 0.1404420833333333,
        (-0.4245212056119465, -2.1390243902439026, 0.0),
        ((3.6489558307291325, -0.5655399575648321, 0.0),
         (-0.5655399575648321, 0.19636361445393347, 0.0),
         (0.0, 0.0, 3.843636219179883))),
    "left, dihedral 5, root (2, -3, -1)": (
        "left", "naca4", 10.0, 5.0, (2.0, -3.0, -1.0), 0.1404420833333333,
        (1.5754787943880535, -4.632787407604032, -1.1428503881132348),
        ((3.6489558307291325, -0.5633879072851166, -0.049290055055042026),
         (-0.5633879072851166, 0.2240687475753354, -0.31667112063258973),
         (-0.049290055055042026, -0.3166711206325898, 3.815931086058481))),
    "right, dihedral 5, root (2, 3, -1)": (
        "right", "naca4", 10.0, 5.0, (2.0, 3.0, -1.0), 0.1404420833333333,
        (1.5754787943880535, 4.632787407604032, -1.1428503881132348),
        ((3.6489558307291325, 0.5633879072851166, -0.049290055055042026),
         (0.5633879072851166, 0.2240687475753354, 0.31667112063258973),
         (-0.049290055055042026, 0.3166711206325898, 3.815931086058481))),
    # MMoIpy "both" with "connect_to": {"dx": 2, "y_offset": 3, "dz": -1}: the pair
    "both, dihedral 5, right root (2, 3, -1)": (
        "both", "naca4", 10.0, 5.0, (2.0, 3.0, -1.0), 0.2808841666666666,
        (1.5754787943880535, 0.0, -1.1428503881132348),
        ((68.0371133228926, 0.0, -0.049290055055042026),
         (0.0, 0.2240687475753354, 0.0),
         (-0.049290055055042026, 0.0, 68.20408857822194))),
    # "diamond_airfoil" with "max_thickness_location": 0.3
    "left diamond 0.3, sweep 25, anhedral 4, root (-1.5, -0.7, 0.4)": (
        "left", "diamond 0.3", 25.0, -4.0, (-1.5, -0.7, 0.4), 0.1025,
        (-2.410061982797136, -2.3350318092063453, 0.5143325618440298),
        ((3.648723847518484, -1.6136007315307925, 0.11283395490566457),
         (-1.6136007315307925, 0.8213052631094778, 0.25381726213460126),
         (0.11283395490566457, 0.25381726213460126, 4.433312587131473))),
}

# ------------------------------------------------------ section 3: Table 2, figures 3-6
#: Table 2: right wing, root location [2, 3, -1] ft (paper axes), c_r = 1 ft, tau_r = 0.08,
#: tau_t = 0.10 (NACA 0008 -> 0010), b = 4 ft, m = 3 slugs, sweep 10 deg, dihedral 0.
TABLE2 = dict(root=(2.0, 3.0, -1.0), chord_root=1.0, thickness_root=0.08, thickness_tip=0.10,
              semispan=4.0, mass=3.0, sweep_deg=10.0, dihedral_deg=0.0)

#: "Exact" curve: (taper c_t/c_r, volume, cg, (Ixx, Iyy, Izz, tensor xy element) about CG).
SECTION3_EXACT = [
    (0.0, 0.07764277777777776, (1.6911269538705358, 4.035294117647059, -1.0),
     (1.8675585883448962, 0.13150721144215116, 1.9976510452425824, 0.24963182152142338)),
    (0.2, 0.09755586666666666, (1.6480088992225619, 4.276404494382023, -1.0),
     (2.717595089631473, 0.15354370381968108, 2.8696867785613973, 0.3864471503772642)),
    (0.4, 0.12441113333333333, (1.599680670921196, 4.524816446402349, -1.0),
     (3.4150186367299273, 0.1811482364836431, 3.5945930539898363, 0.514735243446339)),
    (0.6, 0.15820857777777778, (1.5517565642130038, 4.7441108545034645, -1.0),
     (3.8118676892998113, 0.21258893223256303, 4.022626314696955, 0.6070216055629021)),
    (0.8, 0.19894819999999996, (1.5063430398477997, 4.926170798898072, -1.0),
     (3.971547561491464, 0.2487218649131674, 4.218023516817878, 0.6662579238052722)),
    (1.0, 0.24662999999999996, (1.4638493106153607, 5.074074074074074, -1.0),
     (3.98495413922225, 0.290881286320136, 4.273005336398292, 0.7024054210938036)),
]

#: "CAD" points (SolidWorks): (taper, volume, cg, (Lxx, Lyy, Lzz, Lxy, Lxz, Lyz) about the
#: CG in positive tensor notation, i.e. the tensor's xy element is -Lxy).
SECTION3_CAD = [
    (0.0, 0.07340720, (1.69481586, 4.00113064, -0.99990297),
     (1.80474664, 0.13249572, 1.93591205, -0.24081258, -0.00004953, 0.00020675)),
    (0.2, 0.09343635, (1.65036691, 4.25433705, -0.99990154),
     (2.70988616, 0.15450233, 2.86302162, -0.38463646, -0.00005808, 0.00025104)),
    (0.4, 0.12085316, (1.60055599, 4.51417128, -0.99991082),
     (3.43894626, 0.18207139, 3.61952174, -0.51745989, -0.00005884, 0.00024289)),
    (0.6, 0.15557548, (1.55172393, 4.73998825, -0.99993323),
     (3.83634773, 0.21321078, 4.04778844, -0.60996640, -0.00004881, 0.00018635)),
    (0.8, 0.19760283, (1.50592964, 4.92468402, -0.99996673),
     (3.98446972, 0.24894192, 4.23119819, -0.66746086, -0.00002877, 0.00010558)),
    (1.0, 0.24693537, (1.46341712, 5.07285638, -1.00000854),
     (3.98565410, 0.29070885, 4.27352833, -0.70158923, 0.00000022, 0.00001763)),
]

#: "Lanham" curve (Lanham, ASD-TR-79-5004, as MMoIpy's ``lanham_wing`` evaluates it):
#: (taper, volume, x_cg). Its volume is that of a prismoid whose sections are rectangles of
#: the local chord by the local maximum thickness, thickness linear in span.
SECTION3_LANHAM = [
    (0.0, 0.10666666666666666, 1.4302851046877496),
    (0.2, 0.136, 1.4512463785040042),
    (0.4, 0.176, 1.4722076523202585),
    (0.6, 0.22666666666666666, 1.493168926136513),
    (0.8, 0.28800000000000003, 1.5141301999527679),
    (1.0, 0.36, 1.5350914737690227),
]

TAN_10_DEG = math.tan(math.radians(10.0))
