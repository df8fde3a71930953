"""What a surface mesh is: closed or not, oriented or not, and its triangles' shape.

These are the quick topological checks :func:`juncture.surface.assemble.assemble`'s output is
held to before it is written: every edge in exactly two triangles, used once in each
direction (consistent orientation), positive enclosed volume, and the angles of the
triangles. They are exact (integer vertex ids), so they need no tolerance.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .rows import unique_pairs

__all__ = ["MeshSummary", "summarize", "triangle_angles"]


def triangle_angles(vertices, triangles):
    """(m, 3) interior angles [deg] of each triangle."""
    p = vertices[triangles]
    out = np.empty((len(triangles), 3))
    for k in range(3):
        u = p[:, (k + 1) % 3] - p[:, k]
        v = p[:, (k + 2) % 3] - p[:, k]
        den = np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1)
        cos = np.einsum("ij,ij->i", u, v) / np.where(den > 0, den, 1.0)
        out[:, k] = np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))
    return out


@dataclass(frozen=True, slots=True)
class MeshSummary:
    """Counts and measures of a surface mesh (see :func:`summarize`)."""

    n_vertices: int
    n_triangles: int
    open_edges: int
    nonmanifold_edges: int
    misoriented_edges: int
    open_loops: int
    volume: float
    wetted_area: dict
    min_angle: float
    share_20deg: float

    @property
    def closed(self):
        """Every edge in two triangles, used once each way, and a positive volume."""
        return (self.open_edges == 0 and self.nonmanifold_edges == 0
                and self.misoriented_edges == 0 and self.volume > 0)

    def lines(self):
        """Human-readable lines: what the mesh is, then what fails."""
        out = [f"{self.n_triangles} triangles, {self.n_vertices} vertices",
               f"enclosed volume {self.volume:.8g}",
               "wetted area " + ", ".join(f"{k} {v:.6g}" for k, v in self.wetted_area.items()),
               f"smallest angle {self.min_angle:.3g} deg; {100 * self.share_20deg:.1f} % of "
               "triangles have every angle >= 20 deg"]
        for count, what in ((self.open_edges, "open edges (in one triangle)"),
                            (self.nonmanifold_edges, "edges in more than two triangles"),
                            (self.misoriented_edges, "edges used twice in one direction "
                             "(inconsistent orientation)"),
                            (self.open_loops, "open boundary loops left (seams whose two "
                             "sides do not carry the same points)")):
            if count:
                out.append(f"FAIL: {count} {what}")
        if self.volume <= 0:
            out.append(f"FAIL: enclosed volume {self.volume:.6g} <= 0 (inward orientation)")
        return out


def summarize(mesh):
    """The :class:`MeshSummary` of a :class:`~juncture.surface.assemble.SurfaceMesh`."""
    t = mesh.triangles.astype(np.int64)
    directed = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    undirected = np.sort(directed, axis=1)
    _, inverse, uses = unique_pairs(undirected, return_inverse=True, return_counts=True)
    forward = directed[:, 0] < directed[:, 1]
    n_forward = np.bincount(inverse, weights=forward, minlength=len(uses))
    two = uses == 2
    angles = triangle_angles(mesh.vertices, mesh.triangles) if len(t) else np.zeros((0, 3))
    smallest = angles.min(axis=1) if len(t) else np.zeros(0)
    return MeshSummary(
        n_vertices=int(len(np.unique(t))), n_triangles=int(len(t)),
        open_edges=int(np.sum(uses == 1)), nonmanifold_edges=int(np.sum(uses > 2)),
        misoriented_edges=int(np.sum(two & (n_forward != 1))),
        open_loops=len(mesh.open_loops), volume=mesh.volume(),
        wetted_area=mesh.wetted_area(),
        min_angle=float(smallest.min()) if len(t) else 0.0,
        share_20deg=float(np.mean(smallest >= 20.0)) if len(t) else 0.0)
