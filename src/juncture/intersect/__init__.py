"""Intersection lines where components meet (TM-4406 eqs 1-6, TM-4607 eqs 7-8)."""

from .body import BodyIntersection, intersect_body, intersect_body_both, side_label
from .pairs import Pair, find_intersections, touching_pairs
from .rays import Crossings, find_crossings, polyline_points
from .winglike import intersect_winglike, surface_height

__all__ = ["intersect_body", "intersect_body_both", "intersect_winglike", "surface_height",
           "BodyIntersection", "find_crossings", "Crossings", "polyline_points",
           "touching_pairs", "find_intersections", "Pair", "side_label"]
