"""Appliance parts: sheet casings with a cavity and a face frame, turntables, control panels with
push buttons and dials, glazed doors.

Local frames are world-aligned: fronts face +x, z is up. Sizes of real counter-top microwaves
(0.44-0.62 m wide, 0.32-0.46 m deep with the door, 0.25-0.36 m tall; 0.3-0.6 mm steel casings,
1.5-2.5 mm button travel; manufacturers' spec sheets: Panasonic, Samsung, Whirlpool).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from infmob_usd import geometry as g
from infmob_usd.frames import Frame, polar

LINER = 0.002  # cavity liner wall
BEZEL = 0.006  # front bezel thickness
SKIN = 0.003  # outer skin of a door or fascia; a dark inner frame behind it
CLEAR = 0.0025  # clearance of buttons and dial stems in their panel holes
BEHIND = 0.008  # buttons and stems reach this far behind the fascia's face


def casing(outer, cavity, wall: float, feet_r: float) -> list[g.Piece]:
    """A sheet casing (bottom, top, sides, back), a front bezel with the cavity opening, a cavity
    liner of five thin walls, four feet and louvres on the right side.

    ``outer``: (x back, x front, y left, y right, z bottom, z top); ``cavity`` likewise.
    """
    xb, xf, y0, y1, zc0, zc1 = outer
    cx0, cx1, cy0, cy1, cz0, cz1 = cavity
    t, L, xs = wall, LINER, xf - BEZEL
    pieces = [
        g.box_between([xb, y0, zc0], [xs, y1, zc0 + t], "body"),
        g.box_between([xb, y0, zc1 - t], [xs, y1, zc1], "body"),
        g.box_between([xb, y0, zc0 + t], [xs, y0 + t, zc1 - t], "body"),
        g.box_between([xb, y1 - t, zc0 + t], [xs, y1, zc1 - t], "body"),
        g.box_between([xb, y0 + t, zc0 + t], [xb + t, y1 - t, zc1 - t], "body"),
        g.panel([xs, y0, zc0], [xf, y1, zc1], "body", "x", holes=[(cy0, cz0, cy1, cz1)]),
        g.box_between([cx0 - L, cy0 - L, cz0 - L], [cx1, cy1 + L, cz0], "interior"),
        g.box_between([cx0 - L, cy0 - L, cz1], [cx1, cy1 + L, cz1 + L], "interior"),
        g.box_between([cx0 - L, cy0 - L, cz0], [cx1, cy0, cz1], "interior"),
        g.box_between([cx0 - L, cy1, cz0], [cx1, cy1 + L, cz1], "interior"),
        g.box_between([cx0 - L, cy0, cz0], [cx0, cy1, cz1], "interior"),
    ]
    for x in (xb + 0.04, xs - 0.04):
        for y in (y0 + 0.04, y1 - 0.04):
            pieces.append(g.cylinder([x, y, 0.0], [x, y, zc0], feet_r, "feet", 16))
    n, zt = int((zc1 - zc0) * 0.4 / 0.01), zc1 - t - 0.02  # louvres towards the back and the top
    for k in range(n):
        z = zt - k * 0.01
        pieces.append(g.box_between([xb + 0.04, y1, z - 0.0015], [xb + 0.04 + 0.3 * (xf - xb), y1 + 0.001, z + 0.0015],
                                    "display"))
    return pieces


def turntable(center, floor: float, radius: float) -> list[g.Piece]:
    """A glass tray with a rim on a roller ring (three wheels, three arms, a hub), all within
    ``radius`` of the axis and at least 3 mm above the ``floor`` and the spindle (8 mm)."""
    cx, cy = center
    z_wheel = floor + 0.003 + 0.006  # wheel centres; wheel radius 6 mm
    z_tray = z_wheel + 0.006
    r_ring = 0.5 * radius
    pieces = [
        g.disc([cx, cy, z_tray + 0.003], radius - 0.004, 0.006, "plate", 48),
        g.shell([(radius - 0.002, z_tray), (radius, z_tray + 0.015)], 0.004, "plate", center=(cx, cy, 0.0),
                sections=48),
        g.shell([(r_ring + 0.004, z_wheel - 0.002), (r_ring + 0.004, z_wheel + 0.002)], 0.008, "roller",
                center=(cx, cy, 0.0), sections=32, convex_sectors=12),
        g.cylinder([cx, cy, z_tray - 0.004], [cx, cy, z_tray], 0.018, "roller", 24),  # hub
    ]
    for arm in polar(Frame.at((cx, cy, z_wheel)).turned("z", math.pi / 6), 3, 0.0):
        c, d = arm.origin, arm.x
        pieces.append(g.cylinder(c + d * (r_ring - 0.005), c + d * (r_ring + 0.005), 0.006, "roller", 16))
        pieces.append(g.cylinder(c + d * 0.012 + [0, 0, 0.0005], c + d * (r_ring - 0.003) + [0, 0, 0.0005], 0.0015,
                                 "roller", 8))
    return pieces


def spindle(center, floor: float) -> g.Piece:
    """The turntable's drive spindle in the middle of the cavity floor (8 mm tall)."""
    return g.cylinder([*center, floor], [*center, floor + 0.008], 0.006, "roller", 16)


def glazed_door(x_front: float, thickness: float, ys, zs, hole, skin: str, inner: str) -> list[g.Piece]:
    """A door of a thin outer skin on a dark inner frame, both with a window ``hole`` (y0, z0, y1, z1),
    and the glass set in it."""
    x0 = x_front - thickness
    return [g.panel([x_front - SKIN, ys[0], zs[0]], [x_front, ys[1], zs[1]], skin, "x", holes=[hole]),
            g.panel([x0, ys[0], zs[0]], [x_front - SKIN, ys[1], zs[1]], inner, "x", holes=[hole]),
            g.box_between([x_front - 0.009, hole[0], hole[1]], [x_front - 0.004, hole[2], hole[3]], "glass")]


# -- control panels -------------------------------------------------------------------------------------
def push_button(x_face: float, y: float, z: float, half: tuple[float, float], shape: str, proud: float
                ) -> g.Piece:
    """A push button through a fascia hole: from ``BEHIND`` behind the face to ``proud`` in front."""
    if shape == "rect":
        return g.box_between([x_face - BEHIND, y - half[0], z - half[1]], [x_face + proud, y + half[0], z + half[1]],
                             "button", bevel=0.3 * half[1])
    return g.cylinder([x_face - BEHIND, y, z], [x_face + proud, y, z], half[0], "button", 24)


DIALS = {"ridge": 0.6, "round": 0.4}
"""Dial styles and their shares: a thin skirt with a grip bar, or a round cap on a skirt."""


def dial(x_face: float, y: float, z: float, r: float, stem: float, style: str) -> list[g.Piece]:
    """A dial 3 mm in front of the fascia face on a stem through a hole; a pointer mark in ``trim``."""
    x0 = x_face + 0.003
    pieces = [g.cylinder([x_face - BEHIND, y, z], [x0 + 0.001, y, z], stem, "knob", 16)]
    if style == "ridge":
        depth = max(0.014, 0.7 * r)
        pieces += [g.cylinder([x0, y, z], [x0 + 0.005, y, z], r, "knob", 32),
                   g.box_between([x0 + 0.0045, y - 0.18 * r, z - 0.85 * r], [x0 + depth, y + 0.18 * r, z + 0.85 * r],
                                 "knob", bevel=0.002),
                   g.box_between([x0 + depth - 0.0005, y - 0.0015, z + 0.45 * r], [x0 + depth + 0.001, y + 0.0015,
                                                                                   z + 0.8 * r], "trim")]
    else:
        depth = max(0.016, 0.8 * r)
        pieces += [g.cylinder([x0, y, z], [x0 + 0.004, y, z], r, "knob", 32),
                   g.cylinder([x0 + 0.0035, y, z], [x0 + depth, y, z], 0.8 * r, "knob", 32),
                   g.box_between([x0 + depth - 0.0005, y - 0.0015, z + 0.35 * r], [x0 + depth + 0.001, y + 0.0015,
                                                                                   z + 0.7 * r], "trim")]
    return pieces


@dataclass
class Panel:
    """A control panel laid out top-down: what it shows, its holes, and what moves in them."""

    holes: list = field(default_factory=list)  # (y0, z0, y1, z1)
    decor: list = field(default_factory=list)  # pieces fixed on the fascia
    buttons: list = field(default_factory=list)  # (name, piece, press frame, travel)
    dials: list = field(default_factory=list)  # (name, pieces, axis frame)


def hole_around(y: float, z: float, half) -> tuple[float, float, float, float]:
    return (y - half[0] - CLEAR, z - half[1] - CLEAR, y + half[0] + CLEAR, z + half[1] + CLEAR)
