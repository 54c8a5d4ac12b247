"""Cocktail (coffee) table: a round or square top on legs or on a single pedestal stand.

X is depth (the front faces +X), Y is width, Z is up. The top is a bevelled slab,
round or square, ``width`` across. ``support`` decides what carries it:

* ``legs``: 3 or 4 legs (a square top always has 4) under an apron, with an
  optional lower shelf. Then either

  - ``lift_top``: the legs and the apron form a storage box (the apron with a
    bottom panel); the top rests 3 mm above the apron rim and lifts off it on a
    prismatic joint along +Z, or, with ``lift_forward``, along a direction tilted
    toward the front (+X), as a scissor lift-top does. Gravity holds it on its
    seat (lower limit 0); or
  - otherwise the legs are telescopic: each is a metal sleeve standing on the
    floor with an inner post sliding in it. The top, the apron and the posts are
    one part lifted along +Z from its resting bottom (height adjustment).

* ``pedestal``: a base disc with a hollow column tube; an inner column carrying
  the top slides up out of the tube and turns in it (revolute_prismatic: lift
  along +Z from its resting bottom, turn about Z, which is neutral under gravity).
  The inner column keeps a radial clearance from the tube along its whole travel
  (a compound joint's child collides with its real parent in a simulator).

Every vertical slide rests at its bottom (lower limit 0) and moves up; the turn is
about a vertical axis. Sleeves and the column tube are hollow walls of revolution
(``g.shell``), so posts and columns slide inside them for the simulator too.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Int, Schema

GROWTH = Growth(
    cocktail_table=Rule(required=("top", "support"), optional={"shelf": 0.4, "lift_top": 0.55}),
    support=Rule(one_of={"legs": 0.6, "pedestal": 0.4}),
    lift_top=Rule(optional={"lift_forward": 0.5}),
)
"""``support.one_of`` is object-wide, so it is the ``support`` parameter (same weights).
``shelf`` and ``lift_top`` only grow on a legged table; without a lift-top its legs are telescopic."""

_SUPPORTS = GROWTH.rules["support"].one_of

SCHEMA = Schema((
    Float("width", "top diameter (round) or side (square)", "m", 0.5, 1.0),
    Float("height", "overall height at rest", "m", 0.4, 0.75),
    Choice("top_shape", "shape of the top", choices=("round", "square")),
    Float("top_thickness", "thickness of the top", "m", 0.02, 0.045),
    Float("bevel", "bevel of the top's edges, as a fraction of its thickness", "", 0.1, 0.4),
    Choice("support", "what carries the top", choices=tuple(_SUPPORTS), weights=tuple(_SUPPORTS.values())),
    Int("leg_count", "legs under a round top (a square top has 4); auto = drawn 3 or 4", "", 3, 4,
        auto=True),
    Choice("leg_style", "shape of fixed legs", choices=("turned", "tapered", "square"),
           weights=(0.35, 0.4, 0.25)),
    Float("leg_radius", "leg radius (half side of a square leg) at its top", "m", 0.015, 0.03),
    Float("leg_inset", "distance of the leg centres in from the top's edge", "m", 0.05, 0.12),
    Float("apron_height", "height of the apron under the top", "m", 0.05, 0.11),
    Float("shelf_height", "lower shelf height as a fraction of the height", "", 0.12, 0.3),
    Float("lift_travel", "how far a lift-top rises", "m", 0.12, 0.25),
    Float("lift_forward_ratio", "forward (+X) over upward motion of a forward lift-top", "", 0.3, 0.8),
    Float("stand_travel", "how far telescopic legs or a pedestal column extend", "m", 0.06, 0.18),
    Float("stand_turn", "turn limit (+-) of a pedestal top", "rad", math.pi / 2, math.pi),
    Float("base_radius", "pedestal base radius as a fraction of the width", "", 0.3, 0.42),
    Float("column_radius", "pedestal inner column radius", "m", 0.025, 0.045),
    Choice("top_finish", "material of the top", choices=("wood", "painted", "glass"),
           weights=(0.55, 0.25, 0.2)),
    Choice("frame_finish", "material of the legs and apron", choices=("wood", "painted", "brushed_metal"),
           weights=(0.5, 0.3, 0.2)),
    Choice("metal_finish", "sleeves, column and pedestal base", choices=("brushed_metal", "chrome", "painted")),
    *GROWTH.flags(),
))

MATERIALS = {"top": "top_finish", "frame": "frame_finish", "metal": "metal_finish", "foot": "rubber"}
"""Material slot -> family, or the name of the parameter that picks the family."""

SEAT = 0.003  # gap between a lift-top and the apron rim it rests on
CLEAR = 0.004  # radial clearance of posts and columns in their tubes
WALL = 0.003  # tube wall
BOARD = 0.018  # apron and shelf board thickness


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    bp = Blueprint("cocktail_table", materials={
        slot: p[v] if v in SCHEMA.names else v for slot, v in MATERIALS.items()})
    W, H, tt = p["width"], p["height"], p["top_thickness"]
    round_top = p["top_shape"] == "round"
    legs = p["support"] == "legs"
    n_legs = 4 if not round_top else (p["leg_count"] or int(structure.integers(3, 5)))
    lift = legs and p["has_lift_top"]

    top = _top(W, H - tt, H, round_top, p["bevel"] * tt)
    if not legs:
        _pedestal(bp, p, top)
        return bp

    # leg centres
    inset = min(p["leg_inset"], 0.2 * W)
    if round_top:
        r = W / 2 - inset
        angles = [2 * math.pi * k / n_legs + (math.pi / 4 if n_legs == 4 else 0.0) for k in range(n_legs)]
        centres = [(r * math.cos(a), r * math.sin(a)) for a in angles]
    else:
        a = W / 2 - inset
        centres = [(sx * a, sy * a) for sx in (-1, 1) for sy in (-1, 1)]
    rl = p["leg_radius"]
    za1 = H - tt - (SEAT if lift else 0.0)  # apron top
    ah = p["apron_height"]
    za0 = za1 - ah
    apron = _apron(W, inset, rl, za0, za1, round_top)

    if lift:
        body = [*apron, *_bottom(W, inset, rl, za0, round_top)]
        for c in centres:
            body += _leg(p["leg_style"], c, rl, 0.0, za1)
        if p["has_shelf"]:
            body.append(_shelf(W, inset, rl * 0.8, p["shelf_height"] * H, round_top))
        bp.add("body", "body", body)
        bp.add("top", "lid", top)
        fwd = p["lift_forward_ratio"] if p["has_lift_forward"] else 0.0
        axis = np.array([fwd, 0.0, 1.0]) / math.hypot(fwd, 1.0)
        bp.join(J.prismatic("body", "top", (0.0, 0.0, H - tt), tuple(axis), 0.0, p["lift_travel"],
                            role="slide"))
        return bp

    # telescopic legs: sleeves (root) and the top with its apron and posts (lifted)
    rp = 0.75 * rl  # inner post
    ri = rp + CLEAR  # sleeve inner radius
    ro = ri + WALL  # sleeve outer radius
    zs1 = 0.7 * za0  # sleeve top
    travel = min(p["stand_travel"], zs1 - 0.1)
    zp0 = zs1 - travel - 0.05  # post bottom at rest (>= 0.05 above the floor)
    root = []
    for cx, cy in centres:
        root.append(g.shell([(ro, 0.012), (ro, zs1)], WALL, "metal", center=(cx, cy, 0.0), sections=48,
                            convex_sectors=24))
        root.append(g.cylinder([cx, cy, 0.0], [cx, cy, 0.012], ro + 0.003, "foot", 32))  # foot cap
    if p["has_shelf"]:
        root.append(_shelf(W, inset, ro, min(p["shelf_height"] * H, zs1 - 0.04), round_top))
    else:  # low stretchers between neighbouring sleeves, ending in the sleeve walls
        zr = 0.06
        pairs = list(zip(centres, centres[1:] + centres[:1]))
        if n_legs == 4 and not round_top:
            pairs = [(centres[0], centres[1]), (centres[2], centres[3]), (centres[0], centres[2]),
                     (centres[1], centres[3])]
        for c0, c1 in pairs:
            a0, a1 = np.array([*c0, zr]), np.array([*c1, zr])
            d = (a1 - a0) / np.linalg.norm(a1 - a0)
            root.append(g.cylinder(a0 + d * (ro - 0.0015), a1 - d * (ro - 0.0015), 0.008, "metal", 16))
    bp.add("body", "body", root)
    moving = [*top, *apron]
    for cx, cy in centres:
        moving.append(g.cylinder([cx, cy, zp0], [cx, cy, za1], rp, "metal", 32))
    bp.add("top", "top", moving)
    bp.join(J.prismatic("body", "top", (0.0, 0.0, zs1), (0, 0, 1), 0.0, travel, role="telescope"))
    return bp


# ---------------------------------------------------------------------------
# pieces


def _top(W, z0, z1, round_top, bevel):
    if not round_top:
        return [g.box_between([-W / 2, -W / 2, z0], [W / 2, W / 2, z1], "top", bevel=bevel)]
    R = W / 2
    b = min(bevel, 0.45 * (z1 - z0))
    th = np.linspace(0, 2 * math.pi, 72, endpoint=False)
    ring = np.c_[np.cos(th), np.sin(th)]
    pts = np.vstack([np.c_[(R - b) * ring, np.full(len(th), z0)], np.c_[R * ring, np.full(len(th), z0 + b)],
                     np.c_[R * ring, np.full(len(th), z1 - b)], np.c_[(R - b) * ring, np.full(len(th), z1)]])
    return [g.from_trimesh(g.convex_hull(pts), "top")]


def _apron(W, inset, rl, z0, z1, round_top):
    """A frame of boards (square) or a ring (round) running through the leg tops."""
    if round_top:
        r = W / 2 - inset
        return [g.shell([(r + BOARD / 2, z0), (r + BOARD / 2, z1)], BOARD, "frame", sections=64)]
    a = W / 2 - inset + rl  # flush with the legs' outside
    return [
        g.box_between([-a, -a, z0], [a, -a + BOARD, z1], "frame"),
        g.box_between([-a, a - BOARD, z0], [a, a, z1], "frame"),
        g.box_between([-a, -a + BOARD, z0], [-a + BOARD, a - BOARD, z1], "frame"),
        g.box_between([a - BOARD, -a + BOARD, z0], [a, a - BOARD, z1], "frame"),
    ]


def _bottom(W, inset, rl, z0, round_top):
    """The floor of a lift-top's storage box, at the bottom of the apron."""
    if round_top:
        r = W / 2 - inset
        return [g.disc([0, 0, z0 + 0.006], r, 0.012, "frame", 64)]
    a = W / 2 - inset + rl - BOARD
    return [g.box_between([-a, -a, z0], [a, a, z0 + 0.012], "frame")]


def _shelf(W, inset, r_leg, z, round_top):
    """A lower shelf between the legs, touching them from inside."""
    if round_top:
        return g.disc([0, 0, z], W / 2 - inset - r_leg, BOARD, "top", 64)
    a = W / 2 - inset - r_leg
    return g.box_between([-a, -a, z - BOARD / 2], [a, a, z + BOARD / 2], "top")


def _leg(style, c, r, z0, z1):
    cx, cy = c
    if style == "square":
        return [g.box_between([cx - r, cy - r, z0], [cx + r, cy + r, z1], "frame", bevel=0.002)]
    if style == "tapered":
        rb = 0.6 * r
        pts = np.array([[cx + sx * rr, cy + sy * rr, z] for rr, z in ((rb, z0), (r, z1))
                        for sx in (-1, 1) for sy in (-1, 1)])
        return [g.from_trimesh(g.convex_hull(pts), "frame")]
    # turned: a smooth profile swelling above a narrow foot, a square block at the top
    L = z1 - z0
    block = min(0.12 * L, 0.08)
    zz = np.linspace(0.0, L - block, 14)
    t = zz / (L - block)
    rad = r * (0.55 + 0.25 * t + 0.22 * np.sin(math.pi * np.clip(t * 1.4, 0, 1)) ** 2)
    rad = np.minimum(rad, r)
    prof = [(0.0, 0.0), *zip(rad, zz), (0.7 * r, L - block), (0.0, L - block)]
    return [g.revolve(prof, "frame", center=(cx, cy, z0), sections=48),
            g.box_between([cx - r, cy - r, z0 + L - block - 0.001], [cx + r, cy + r, z1], "frame")]


def _pedestal(bp, p, top):
    """Base disc and column tube (root); inner column with the top (lift + turn)."""
    W, H, tt = p["width"], p["height"], p["top_thickness"]
    Rb = p["base_radius"] * W
    zb = 0.03  # base top
    rc = p["column_radius"]
    ri = rc + CLEAR
    ro = ri + WALL
    zt1 = 0.55 * (H - tt)  # tube top
    travel = min(p["stand_travel"], zt1 - zb - 0.08)
    zc0 = zt1 - travel - 0.06  # column bottom at rest (>= 0.02 above the base)
    prof = [(0.0, 0.0), (Rb, 0.0), (Rb, 0.008), (0.85 * Rb, 0.016), (0.45 * Rb, zb - 0.004),
            (ro + 0.01, zb), (0.0, zb)]
    root = [
        g.revolve(prof, "metal", sections=64),
        g.shell([(ro, zb - 0.002), (ro, zt1)], WALL, "metal", sections=64, convex_sectors=24),
        g.shell([(ro + 0.006, zt1 - 0.015), (ro + 0.006, zt1)], 0.006, "metal", sections=64,
                convex_sectors=24),  # collar
    ]
    bp.add("body", "stand", root)
    zs = H - tt  # underside of the top
    plate_r = min(0.35 * W, 0.2)
    moving = [
        *top,
        g.cylinder([0, 0, zc0], [0, 0, zs - 0.012], rc, "metal", 48),
        g.cylinder([0, 0, zs - 0.012], [0, 0, zs], plate_r, "metal", 48),  # mounting plate
    ]
    bp.add("top", "top", moving)
    bp.join(J.revolute_prismatic("body", "top", (0.0, 0.0, zt1), (0, 0, 1),
                                 (-p["stand_turn"], p["stand_turn"]), (0, 0, 1), (0.0, travel),
                                 role="telescope"))
