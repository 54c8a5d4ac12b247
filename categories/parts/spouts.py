"""Spouts: a thin-walled, open, tapering tube swept along a curve, its section an ellipse that narrows from a
wide root (flattened against the vessel it grows from, so it reads moulded into the wall) to a small tip.

Real spouts are never constant-width tubes: a jug kettle's is a beak pressed into its upper front, ~6-8 cm
tall where it leaves the body and ~2 cm across at the lip; a stovetop kettle's is a cone curving up from low
on the body, 4-5 cm across at the root and 1.5-2 cm at the tip; a pour-over kettle's gooseneck is a slender
S-curve. Any vessel with a spout (kettle, carafe, watering can, teapot) sweeps one with :func:`spout`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.measures import mass_properties


@dataclass(frozen=True)
class Spout:
    """A spout's centreline as a cubic Bezier through ``ctrl`` (root first, in the XZ plane: the spout leans
    along +X), its section's half-widths ``across`` (Y) and ``along`` (in the plane, square to the line) at the
    root and at the tip, how fast it narrows (``flare``: 1 a straight cone, 2-3 a trumpet that blends into the
    wall) and its ``wall`` thickness."""

    ctrl: tuple[tuple[float, float, float], ...]
    across: tuple[float, float]
    along: tuple[float, float]
    flare: float
    wall: float

    def point(self, t: np.ndarray) -> np.ndarray:
        """Points of the centreline at parameters ``t`` in [0, 1], ``(n, 3)``."""
        p = np.asarray(self.ctrl, float)
        t = np.asarray(t, float)[:, None]
        return ((1 - t) ** 3) * p[0] + 3 * ((1 - t) ** 2) * t * p[1] + 3 * (1 - t) * t * t * p[2] + t ** 3 * p[3]

    def tangent(self, t: np.ndarray) -> np.ndarray:
        """Unit tangents of the centreline at ``t``, ``(n, 3)``."""
        p = np.asarray(self.ctrl, float)
        t = np.asarray(t, float)[:, None]
        d = 3 * ((1 - t) ** 2) * (p[1] - p[0]) + 6 * (1 - t) * t * (p[2] - p[1]) + 3 * t * t * (p[3] - p[2])
        return d / np.linalg.norm(d, axis=1, keepdims=True)

    def half_widths(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The outer section's half-widths across and along at ``t``."""
        w = (1 - np.asarray(t, float)) ** self.flare  # 1 at the root, 0 at the tip
        return (self.across[1] + w * (self.across[0] - self.across[1]),
                self.along[1] + w * (self.along[0] - self.along[1]))

    @property
    def tip(self) -> np.ndarray:
        """The centre of the open end."""
        return np.asarray(self.ctrl[-1], float)

    @property
    def tip_axis(self) -> np.ndarray:
        """The direction the spout points at its tip."""
        return self.tangent(np.array([1.0]))[0]


def spout(s: Spout, slot: str, rings: int = 14, sections: int = 24) -> g.Piece:
    """The spout's wall, open at both ends (closed as a solid: outer skin, inner skin and the two end
    annuli); one convex collision piece per band between rings, solid (a spout's bore is too narrow for
    anything a simulator drops in it)."""
    t = np.linspace(0.0, 1.0, rings)
    c, tan = s.point(t), s.tangent(t)
    across = np.array([0.0, 1.0, 0.0])
    normal = np.cross(across, tan)  # in the XZ plane, square to the line: +Z-ish on a rising spout
    a, b = s.half_widths(t)
    th = 2 * np.pi * np.arange(sections) / sections
    cos, sin = np.cos(th)[None, :, None], np.sin(th)[None, :, None]

    def ring(da: float) -> np.ndarray:
        return (c[:, None, :] + (a[:, None, None] - da) * cos * across
                + (b[:, None, None] - da) * sin * normal[:, None, :])

    outer, inner = ring(0.0), ring(s.wall)
    n, m = rings, sections
    verts = np.vstack([outer.reshape(-1, 3), inner.reshape(-1, 3)])
    faces = []
    for k in range(n - 1):
        for i in range(m):
            j = (i + 1) % m
            o0, o1, p0, p1 = k * m + i, k * m + j, (k + 1) * m + i, (k + 1) * m + j
            faces += [(o0, p0, p1), (o0, p1, o1)]  # outer skin
            faces += [(n * m + o0, n * m + o1, n * m + p1), (n * m + o0, n * m + p1, n * m + p0)]  # inner skin
    for k, flip in ((0, True), (n - 1, False)):  # the end annuli, run against the skins they close
        for i in range(m):
            j = (i + 1) % m
            quad = [(k * m + i, n * m + k * m + i, n * m + k * m + j), (k * m + i, n * m + k * m + j, k * m + j)]
            faces += [q[::-1] for q in quad] if flip else quad
    faces = np.asarray(faces, np.int64)
    if mass_properties(verts, faces)[0] < 0:  # wound inward
        faces = faces[:, ::-1].copy()
    convex = [np.vstack([outer[k], outer[k + 1]]) for k in range(n - 1)]
    return g.Piece(verts, faces, slot, convex)
