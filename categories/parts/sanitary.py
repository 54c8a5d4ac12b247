"""Sanitary ware: a close-coupled toilet's ceramic base, cistern and lid, seat and cover, flush
button and trip lever.

World-aligned frames: the bowl faces +x, the cistern is at -x. Sizes of real close-coupled WCs:
seat height 0.40-0.50 m, rims 0.34-0.40 x 0.40-0.48 m, cisterns 0.38-0.50 m wide, 0.15-0.21 m deep,
vitreous china walls 10-16 mm (EN 997; manufacturers' dimension sheets: Ideal Standard, Roca).
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.frames import Frame

CLEAR = 0.0025  # a button in its hole
GAP = 0.003
CISTERN_WALL = 0.012
LID = dict(overhang=0.008, lip=0.015, lip_t=0.008)  # cistern lid overhang, locating lip depth, thickness


# -- the toilet's layout (``categories/toilet.py`` reads these) -------------------------------------
LID_LIFT = 0.2  # the cistern lid lifts 0..0.2 m
PRESS = 0.006  # flush button travel
LEVER_TURN = math.pi / 4
TAB = 0.035  # the seat's rear tab, from the rim's back to the hinge line
FLUSH_BELOW = 0.06  # the flush control sits this far below the cistern's top


def DUAL_Y(rb: float) -> tuple[float, float]:  # noqa: N802
    """The y of a dual flush's small and large buttons on the cistern front (their rings 4 mm apart)."""
    d = rb + CLEAR + 0.008 + 0.002
    return (-d, d)


SHEET = 0.006  # a boxed frame's and a unit's boards count as shells this thick (hollow, for the mass)
# Proportions of the bowl and its neighbours (Ideal Standard / Roca / Duravit dimension sheets): the seat's
# rear tab is 34 % of the bowl's half width; a close-coupled deck reaches 2 cm into the cistern's foot and
# 75 % of the bowl's half length forward, as wide as 75 % of the cistern or 1.3 times the bowl's half width;
# a one-piece skirt 85 % of the cistern or 1.5 times the half width, a back-to-wall skirt 1.3 times; the seat
# 2 mm past the rim, the cover 4 mm past the seat, their tabs from 3 cm inside the rim; a flush plate's top
# 2.5 cm + 13 cm under a unit's top, 16 cm under a frame's.
TOILET = dict(tab=0.34, deck=(0.02, 0.75, 0.75, 1.3), one_piece=(0.85, 1.5), back_to_wall=1.3,
              seat=(0.002, 0.004, 0.03), unit_plate=(0.025, 0.13), frame_plate=0.16)
BUTTON_BEHIND = 0.004  # a cistern button's body reaches this far behind the cistern's wall
BUTTON_PROUD = 0.0125  # its slide starts this far in front of the cistern's face
# a flush lever's rose: 20 mm radius, 6 mm thick on the cistern's side wall, 12 mm behind the grip's reach
LEVER_ROSE = dict(radius=0.02, thickness=0.006, behind=0.012)


def oval(piece: g.Piece, cx: float, sx: float) -> g.Piece:
    """A piece built about the z axis, stretched by ``sx`` along x and its axis moved to x = ``cx``."""
    m = np.diag([sx, 1.0, 1.0, 1.0])
    m[0, 3] = cx
    return piece.transformed(m)


def ceramic_base(a: float, b: float, wall: float, z_r: float, x_c: float, deck, tab_w: float, hinge) -> list:
    """An oval bowl (a thin wall of revolution stretched along x: hollow for the simulator) with a flat
    rim and a trap, on a pedestal, a rear deck and column under the cistern, and hinge posts.

    ``deck``: (x0, x1, width); ``hinge``: (x, z) of the seat's hinge line.
    """
    sx = a / b
    z_bot = 0.42 * z_r  # bowl bottom (the trap)
    hb = z_r - z_bot
    outer = [(0.32 * b, z_bot), (0.55 * b, z_bot + 0.22 * hb), (0.82 * b, z_bot + 0.55 * hb),
             (0.96 * b, z_bot + 0.85 * hb), (b - 0.004, z_r - 0.03)]
    pieces = [oval(g.shell(outer, wall, "ceramic", sections=48), x_c, sx),
              oval(g.shell([(b, z_r - 0.035), (b, z_r)], 0.032, "ceramic", sections=48), x_c, sx),
              oval(g.disc((0, 0, z_bot - 0.005), 0.34 * b, 0.03, "ceramic", 32), x_c, sx)]
    ped = [(0.0, 0.0), (0.62 * b, 0.0), (0.62 * b, 0.012), (0.5 * b, 0.05), (0.4 * b, 0.5 * z_bot),
           (0.36 * b, z_bot + 0.01), (0.0, z_bot + 0.01)]
    x_p = x_c - 0.25 * a
    pieces.append(oval(g.revolve(ped, "ceramic", sections=40), x_p, 1.35 * sx))
    deck_x0, deck_x1, deck_w = deck
    z_deck0 = 0.55 * z_r
    pieces.append(g.box_between([deck_x0, -deck_w / 2, z_deck0], [deck_x1, deck_w / 2, z_r], "ceramic", bevel=0.01))
    col_x0 = max(deck_x0, x_p - 1.35 * a * 0.62 + 0.02)
    pieces.append(g.box_between([col_x0, -0.34 * b, 0.01], [deck_x1, 0.34 * b, z_deck0 + 0.01], "ceramic", bevel=0.01))
    x_h, z_h = hinge
    for s in (-1, 1):  # hinge posts beside the seat and cover tabs
        y0, y1 = sorted((s * (tab_w / 2 + 0.006), s * (tab_w / 2 + 0.026)))
        pieces.append(g.box_between([x_h - 0.018, y0, z_r], [x_h + 0.008, y1, z_h - 0.004], "chrome", bevel=0.003))
    return pieces


def cistern(xs, ys, z0: float, z1: float, holes) -> list[g.Piece]:
    """A hollow cistern of five walls (its front with ``holes`` in y, z)."""
    (x_tb, x_tf), (y0, y1), wt = xs, ys, CISTERN_WALL
    return [g.box_between([x_tb, y0, z0], [x_tf, y1, z0 + wt], "ceramic", bevel=0.004),
            g.panel([x_tf - wt, y0, z0 + wt], [x_tf, y1, z1], "ceramic", "x", holes=holes),
            g.box_between([x_tb, y0, z0 + wt], [x_tb + wt, y1, z1], "ceramic"),
            g.box_between([x_tb + wt, y0, z0 + wt], [x_tf - wt, y0 + wt, z1], "ceramic"),
            g.box_between([x_tb + wt, y1 - wt, z0 + wt], [x_tf - wt, y1, z1], "ceramic")]


def cistern_lid(xs, ys, z: float, thickness: float) -> list[g.Piece]:
    """An overhanging slab resting at ``z`` with a locating lip inside the cistern walls."""
    (x_tb, x_tf), (y0, y1) = xs, ys
    ov, lip, t = LID["overhang"], LID["lip"], LID["lip_t"]
    gi = CISTERN_WALL + 0.004  # lip inset from the outer faces
    return [g.box_between([x_tb - ov, y0 - ov, z], [x_tf + ov, y1 + ov, z + thickness], "ceramic", bevel=0.006),
            g.box_between([x_tb + gi, y0 + gi, z - lip], [x_tb + gi + t, y1 - gi, z], "ceramic"),
            g.box_between([x_tf - gi - t, y0 + gi, z - lip], [x_tf - gi, y1 - gi, z], "ceramic"),
            g.box_between([x_tb + gi + t, y0 + gi, z - lip], [x_tf - gi - t, y0 + gi + t, z], "ceramic"),
            g.box_between([x_tb + gi + t, y1 - gi - t, z - lip], [x_tf - gi - t, y1 - gi, z], "ceramic")]


def seat(a: float, b: float, x_c: float, z0: float, thick: float, ring: float, tab) -> list[g.Piece]:
    """An oval seat ring resting at ``z0`` and its rear tab (x0, x1, width) up to the hinge."""
    x0, x1, w = tab
    return [oval(g.shell([(b, z0), (b, z0 + thick)], ring, "seat", sections=48), x_c, a / b),
            g.box_between([x0, -w / 2, z0], [x1, w / 2, z0 + thick], "seat", bevel=0.004)]


def cover(a: float, b: float, x_c: float, z0: float, thick: float, tab) -> list[g.Piece]:
    """An oval cover lying at ``z0`` and its rear tab."""
    x0, x1, w = tab
    return [oval(g.disc((0, 0, z0 + thick / 2), b, thick, "seat", 48), x_c, a / b),
            g.box_between([x0, -w / 2, z0], [x1, w / 2, z0 + thick], "seat", bevel=0.003)]


def flush_ring(at, r: float) -> g.Piece:
    """A chrome ring around a flush button hole, on a face whose outward normal is ``at.z``."""
    ring = g.shell([(r + CLEAR + 0.008, 0.0), (r + CLEAR + 0.008, 0.004)], 0.008, "chrome", sections=32,
                   convex_sectors=12)
    return ring.transformed(at.matrix)


BUTTON_WALL = 0.0002
"""m of steel-equivalent wall of a flush button: chrome-plated ABS ~1.5 mm at 1050 kg/m^3 (push
buttons of Geberit, TOTO and Grohe cisterns weigh 10-30 g)."""


def flush_button(x_face: float, behind: float, z: float, r: float) -> list[g.Piece]:
    """A round flush button from ``behind`` the face to 12.5 mm proud of it, with a smaller cap;
    hollow chrome-plated plastic (:data:`BUTTON_WALL`)."""
    return [g.cylinder([x_face - behind, 0.0, z], [x_face + 0.011, 0.0, z], r, "chrome", 32).replace(wall=BUTTON_WALL),
            g.cylinder([x_face + 0.011, 0.0, z], [x_face + 0.0125, 0.0, z], r * 0.8, "chrome", 32)
            .replace(wall=BUTTON_WALL)]


def trip_lever(xa: float, ys: float, z: float, length: float) -> list[g.Piece]:
    """A flush lever turning about y through ``(xa, ys, z)`` on a left side wall (it stands off to -y):
    a hub and a grip to +x; the core adds the counterweight heel that balances it."""
    return [g.cylinder([xa, ys, z], [xa, ys - 0.016, z], 0.011, "chrome", 24),
            g.box_between([xa, ys - 0.015, z - 0.006], [xa + length, ys - 0.008, z + 0.006], "chrome", bevel=0.002)]


def on_face(x: float, z: float) -> Frame:
    """A frame on a +x-facing face at height ``z`` (its z along +x)."""
    return Frame.at((x, 0.0, z), z=(1, 0, 0), x=(0, 0, -1))


# -- the other designs: one-piece, back-to-wall, wall-hung --------------------------------------------------
# Sizes: one-piece WCs carry a low cistern 0.17-0.25 m above the rim on a skirted (concealed-trap) base
# (TOTO Ultramax, Kohler Santa Rosa); back-to-wall pans stand against a furniture unit 0.8-0.85 m high,
# 0.2-0.3 m deep (Roca, Ideal Standard Tesi); wall-hung pans are 0.52-0.56 m long, their seat at 0.40-0.43
# m on a pre-wall frame about 1.12 m high and 0.5 m wide with its flush plate (Geberit Duofix, plate
# 246 x 164 mm, dual flush: a small and a large key).

PLATE = dict(width=0.246, height=0.164, thickness=0.012, key_gap=0.004)
KEY_PROUD = 0.003  # a flush key stands this far proud of its plate
KEY_BEHIND = 0.006  # and reaches this far into it


def bowl(a: float, b: float, wall: float, z_r: float, x_c: float, z_bot: float) -> list[g.Piece]:
    """The oval bowl of ``ceramic_base`` alone: a thin wall of revolution, its rim and the trap's floor."""
    sx = a / b
    hb = z_r - z_bot
    outer = [(0.32 * b, z_bot), (0.55 * b, z_bot + 0.22 * hb), (0.82 * b, z_bot + 0.55 * hb),
             (0.96 * b, z_bot + 0.85 * hb), (b - 0.004, z_r - 0.03)]
    return [oval(g.shell(outer, wall, "ceramic", sections=48), x_c, sx),
            oval(g.shell([(b, z_r - 0.035), (b, z_r)], 0.032, "ceramic", sections=48), x_c, sx),
            oval(g.disc((0, 0, z_bot - 0.005), 0.34 * b, 0.03, "ceramic", 32), x_c, sx)]


def hinge_posts(tab_w: float, z_r: float, hinge) -> list[g.Piece]:
    """The chrome posts beside the seat and cover tabs."""
    x_h, z_h = hinge
    out = []
    for s in (-1, 1):
        y0, y1 = sorted((s * (tab_w / 2 + 0.006), s * (tab_w / 2 + 0.026)))
        out.append(g.box_between([x_h - 0.018, y0, z_r], [x_h + 0.008, y1, z_h - 0.004], "chrome", bevel=0.003))
    return out


def skirted_base(a: float, b: float, wall: float, z_r: float, x_c: float, x_back: float, tab_w: float,
                 hinge, back_width: float) -> list[g.Piece]:
    """A bowl on a skirt (the trapway concealed in a smooth oval wall down to the floor) whose back is a
    block as wide as ``back_width`` up to the rim, ending at ``x_back`` (a cistern or a wall unit)."""
    sx = a / b
    z_bot = 0.42 * z_r
    skirt = [(0.0, 0.0), (0.8 * b, 0.0), (0.8 * b, 0.01), (0.78 * b, z_bot + 0.02), (0.0, z_bot + 0.02)]
    pieces = bowl(a, b, wall, z_r, x_c, z_bot)
    pieces.append(oval(g.revolve(skirt, "ceramic", sections=48), x_c - 0.08 * a, 1.05 * sx))
    x1 = x_c - 0.55 * a
    pieces.append(g.box_between([x_back, -back_width / 2, 0.0], [x1, back_width / 2, z_r], "ceramic", bevel=0.02))
    return pieces + hinge_posts(tab_w, z_r, hinge)


def hung_base(a: float, b: float, wall: float, z_r: float, x_c: float, x_back: float, tab_w: float,
              hinge) -> list[g.Piece]:
    """A wall-hung pan: the bowl and a rear body to the wall at ``x_back`` (bolted through it), nothing to
    the floor; its underside is a short oval skirt under the bowl."""
    sx = a / b
    z_bot = z_r - 0.24  # the bowl is 0.24 m deep under its rim
    pieces = bowl(a, b, wall, z_r, x_c, z_bot)
    pieces.append(oval(g.revolve([(0.0, z_bot - 0.03), (0.62 * b, z_bot - 0.03), (0.8 * b, z_bot + 0.05),
                                  (0.0, z_bot + 0.05)], "ceramic", sections=48), x_c - 0.12 * a, 1.1 * sx))
    x1 = x_c - 0.5 * a
    pieces.append(g.box_between([x_back, -0.62 * b, z_bot - 0.03], [x1, 0.62 * b, z_r], "ceramic", bevel=0.025))
    return pieces + hinge_posts(tab_w, z_r, hinge)


def prewall(x_front: float, depth: float, width: float, height: float) -> list[g.Piece]:
    """A boxed-in installation frame (the wall a wall-hung pan or a back-to-wall unit stands against):
    a tiled box from the floor with a bevelled top."""
    return [g.box_between([x_front - depth, -width / 2, 0.0], [x_front, width / 2, height], "wall", bevel=0.006)]


def vanity_unit(x_front: float, depth: float, width: float, height: float) -> list[g.Piece]:
    """A back-to-wall furniture unit: a carcass hiding the cistern, a plinth recess and a worktop."""
    t = 0.025
    return [g.box_between([x_front - depth, -width / 2, 0.07], [x_front, width / 2, height - t], "unit", bevel=0.003),
            g.box_between([x_front - depth, -width / 2 + 0.01, 0.0], [x_front - 0.05, width / 2 - 0.01, 0.07], "unit"),
            g.box_between([x_front - depth, -width / 2 - 0.01, height - t], [x_front + 0.02, width / 2 + 0.01, height],
                          "top", bevel=0.004)]


def flush_plate(x_face: float, z: float) -> tuple[list[g.Piece], list[tuple[str, list[g.Piece]]]]:
    """A dual-flush plate on a +x face at height ``z`` (its centre): the plate with two key openings,
    and the two keys (small flush at -y, large at +y), each in its opening with ``CLEAR`` around it."""
    w, h, t, kg = PLATE["width"], PLATE["height"], PLATE["thickness"], PLATE["key_gap"]
    ki = 0.022  # the plate's rim around the keys
    holes = [(-w / 2 + ki, z - h / 2 + ki, -kg / 2, z + h / 2 - ki),
             (kg / 2, z - h / 2 + ki, w / 2 - ki, z + h / 2 - ki)]
    plate = [g.panel([x_face, -w / 2, z - h / 2], [x_face + t, w / 2, z + h / 2], "chrome", "x", holes=holes)]
    keys = []
    xf = x_face + t
    for side, (y0, z0, y1, z1) in zip(("small", "large"), holes):
        keys.append((side, [g.box_between([xf - KEY_BEHIND, y0 + CLEAR, z0 + CLEAR],
                                          [xf + KEY_PROUD, y1 - CLEAR, z1 - CLEAR], "chrome", bevel=0.0015)]))
    return plate, keys


def lever_rose(xa: float, y_wall: float, z: float) -> tuple[g.Piece, float]:
    """A flush lever's rose on a cistern's -y side wall ``y_wall`` at (``xa``, ``z``); returns it and the y of
    the lever's inner face (off the rose)."""
    r, t = LEVER_ROSE["radius"], LEVER_ROSE["thickness"]
    return g.cylinder([xa, y_wall, z], [xa, y_wall - t, z], r, "chrome", 32), y_wall - t - GAP
