"""Grasp frames: where a gripper takes hold of a part, as the part that knows it declares it.

A :class:`Grasp` rides on a :class:`~infmob_usd.piece.Piece` (``Piece.grasps``) and moves with it through
every placement, so a handle fused into a door, a dial on a fascia or a button in its cut-out keeps its grasp
in whatever link it ends up in. :mod:`infmob_usd.interaction` reads them per operated joint.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

MAX_WIDTH = 0.08
"""m, the widest finger opening a grasp may ask for: a Franka Panda hand opens 80 mm (franka.de, Franka Hand
datasheet: 'max. 80 mm')."""

HANDLE_CLASSES = ("line_fixed_handle", "round_fixed_handle")
"""GAPartNet's fixed-handle classes (Geng et al., CVPR 2023, GAPartNet: 9 actionable part classes)."""


def _unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


@dataclass(frozen=True)
class Grasp:
    """One grasp frame in the frame of the piece that carries it.

    ``position`` lies on the part's surface where the gripper first meets it coming along ``approach``
    (unit); the finger pads close along ``closing`` (unit, perpendicular to ``approach``) ``depth`` past
    ``position`` and need ``width`` of opening. ``handle_class`` is a GAPartNet handle class
    (:data:`HANDLE_CLASSES`) or ``None``; ``box`` the handle's oriented box ``(centre, size, rotation)``
    (rotation columns: the box's axes) or ``None``.
    """

    position: tuple
    approach: tuple
    closing: tuple
    width: float
    depth: float
    handle_class: str | None = None
    box: tuple | None = None

    @classmethod
    def make(cls, position, approach, closing, width: float, depth: float, handle_class: str | None = None,
             box=None) -> Grasp:
        """A grasp from any array-likes; ``closing`` is made perpendicular to ``approach``."""
        a = _unit(approach)
        c = np.asarray(closing, float)
        c = _unit(c - (c @ a) * a)
        if box is not None:
            centre, size, rot = box
            box = (tuple(map(float, centre)), tuple(map(float, size)),
                   tuple(tuple(map(float, row)) for row in np.asarray(rot, float)))
        return cls(tuple(map(float, position)), tuple(a), tuple(c), float(width), float(depth), handle_class, box)

    def moved(self, r: np.ndarray, t: np.ndarray) -> Grasp:
        """Moved by ``x -> r x + t`` (rigid, or a stretch that keeps orientation: lengths along a stretched
        direction scale with it)."""
        a, c = r @ np.asarray(self.approach), r @ np.asarray(self.closing)
        width = self.width * float(np.linalg.norm(c))
        depth = self.depth * float(np.linalg.norm(a))
        box = None
        if self.box is not None:
            centre, size, rot = self.box
            axes = r @ np.asarray(rot)
            scale = np.linalg.norm(axes, axis=0)
            q, _ = np.linalg.qr(axes)  # the nearest right-handed frame to the stretched axes
            q = q * np.sign(np.sum(q * axes, axis=0))
            box = (r @ np.asarray(centre) + t, np.asarray(size) * scale, q)
        return Grasp.make(r @ np.asarray(self.position) + t, a, c, width, depth, self.handle_class, box)

    def translated(self, offset) -> Grasp:
        return self.moved(np.eye(3), np.asarray(offset, float))
