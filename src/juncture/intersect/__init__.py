"""Intersection lines where components meet (TM-4406 eqs 1-6, TM-4607 eqs 7-8)."""

from .body import BodyIntersection, intersect_body, intersect_body_both
from .rays import Crossings, find_crossings, polyline_points

__all__ = ["intersect_body", "intersect_body_both", "BodyIntersection", "find_crossings",
           "Crossings",
           "polyline_points"]
