"""Sanitary ware: a toilet's ceramic pan, cistern and lid, seat and cover, flush button, trip lever and
dual-flush plate, as :class:`~infmob_usd.assembly.Assembly` builders in their own frames.

Frames: every builder's front faces +x, z is up. The pan's frame stands on the floor under the seat's hinge
line (the bowl at +x, the cistern or the wall at -x); the cistern's, a furniture unit's and a boxed frame's
stand at the foot of their front face; a flush control's sits on the face it is mounted on. Sizes of real
close-coupled WCs: seat height 0.40-0.50 m, rims 0.34-0.40 x 0.40-0.48 m, cisterns 0.38-0.50 m wide,
0.15-0.21 m deep, vitreous china walls 10-16 mm (EN 997; manufacturers' dimension sheets: Ideal Standard,
Roca).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly, SubPart
from infmob_usd.frames import IDENTITY, Frame

from .lids import rimmed

CLEAR = 0.0025  # a button in its hole
GAP = 0.003
CISTERN_WALL = 0.012
LID = dict(overhang=0.008, lip=0.015, lip_t=0.008)  # cistern lid overhang, locating lip depth, thickness


@dataclass(frozen=True)
class Ranges:
    """Ranges of the toilet's sizes, m unless a fraction (lo, hi). Seats, rims, cisterns and walls: EN 997
    and Ideal Standard / Roca dimension sheets (above); one-piece cisterns 55-70 % as tall (TOTO Ultramax,
    Kohler Santa Rosa); back-to-wall units 0.80-0.86 m high, 0.2-0.3 m deep, 0.5-0.6 m wide (Roca, Ideal
    Standard Tesi); wall-hung pans' boxed frames 1.0-1.2 m high, seats at 0.40-0.44 m (Geberit Duofix);
    seats 18-30 mm thick with 55-80 mm rings, covers 12-25 mm, cistern lids 18-30 mm (seat makers' sheets:
    Croydex, Wirquin); flush buttons 36-60 mm across, trip levers 60-90 mm (Fluidmaster, Viva)."""

    seat_height: tuple[float, float] = (0.40, 0.50)
    bowl_width: tuple[float, float] = (0.34, 0.40)
    bowl_length: tuple[float, float] = (0.40, 0.48)
    wall: tuple[float, float] = (0.010, 0.016)
    tank_width: tuple[float, float] = (0.38, 0.50)
    tank_depth: tuple[float, float] = (0.15, 0.21)
    tank_height: tuple[float, float] = (0.30, 0.40)
    tank_gap: tuple[float, float] = (0.06, 0.10)
    seat_thickness: tuple[float, float] = (0.018, 0.03)
    seat_ring: tuple[float, float] = (0.055, 0.08)
    cover_thickness: tuple[float, float] = (0.012, 0.025)
    lid_thickness: tuple[float, float] = (0.018, 0.03)
    cover_share: tuple[float, float] = (0.5, 0.65)
    button_radius: tuple[float, float] = (0.018, 0.03)
    lever_length: tuple[float, float] = (0.06, 0.09)
    one_piece_tank: tuple[float, float] = (0.55, 0.7)
    unit_height: tuple[float, float] = (0.8, 0.86)
    unit_depth: tuple[float, float] = (0.2, 0.3)
    unit_width: tuple[float, float] = (0.5, 0.6)
    frame_height: tuple[float, float] = (1.0, 1.2)
    hung_seat_height: tuple[float, float] = (0.40, 0.44)


RANGES = Ranges()


@dataclass(frozen=True)
class Shape:
    """Proportions of the bowl and its neighbours (Ideal Standard / Roca / Duravit dimension sheets)."""

    tab: float = 0.34  # the seat's rear tab, of the bowl's half width
    deck_into_cistern: float = 0.02  # a close-coupled deck reaches this far into the cistern's foot, m
    deck_forward: float = 0.75  # ... and this much of the bowl's half length forward
    deck_of_cistern: float = 0.75  # ... as wide as this much of the cistern
    deck_of_bowl: float = 1.3  # ... or this many bowl half widths, whichever is less
    skirt_of_cistern: float = 0.85  # a one-piece skirt's back block: of the cistern's width
    skirt_of_bowl: float = 1.5  # ... or of the bowl's half width
    back_to_wall_of_bowl: float = 1.3  # a back-to-wall skirt's back block, bowl half widths
    seat_past: float = 0.002  # the seat reaches this far past the rim, m
    cover_past: float = 0.004  # the cover this far past the seat, m
    tab_inside: float = 0.03  # seat and cover tabs start this far inside the rim, m
    unit_top: float = 0.025  # a back-to-wall unit's worktop, m
    unit_plate: float = 0.13  # a flush plate's centre under the worktop, m
    frame_plate: float = 0.16  # ... under a boxed frame's top, m


SHAPE = Shape()


@dataclass(frozen=True)
class PanSize:
    """A pan with its seat and cover, m: rim length (x) and width (y), ceramic wall, seat top above the floor,
    seat and cover thicknesses, seat ring width, and the room from the hinge line back to what stands
    behind (a cistern's front, a unit's, a boxed frame's)."""

    length: float
    width: float
    wall: float
    seat_height: float
    seat_thickness: float
    seat_ring: float
    cover_thickness: float
    tank_gap: float

    @property
    def a(self) -> float:
        return self.length / 2

    @property
    def b(self) -> float:
        return self.width / 2

    @property
    def rim(self) -> float:
        return self.seat_height - self.seat_thickness - GAP

    @property
    def hinge_z(self) -> float:
        """The seat's hinge line: its top rear edge."""
        return self.rim + GAP + self.seat_thickness

    @property
    def tab_width(self) -> float:
        return SHAPE.tab * self.b

    @property
    def bowl_x(self) -> float:
        """The bowl's axis ahead of the hinge line."""
        return self.a + TAB


@dataclass(frozen=True)
class CisternSize:
    """A cistern, m: width (y), depth (x), height with its lid, lid thickness."""

    width: float
    depth: float
    height: float
    lid_thickness: float

    @property
    def top(self) -> float:
        """The walls' top above the cistern's foot (the lid rests a gap above)."""
        return self.height - self.lid_thickness - GAP

    @property
    def flush_z(self) -> float:
        return self.top - FLUSH_BELOW


@dataclass(frozen=True)
class BoxSize:
    """A back-to-wall furniture unit or a wall-hung pan's boxed frame, m."""

    depth: float
    width: float
    height: float


# -- the toilet's mechanisms ---------------------------------------------------------------------------
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


def _cistern(xs, ys, z0: float, z1: float, holes) -> list[g.Piece]:
    """A hollow cistern of five walls (its front with ``holes`` in y, z)."""
    (x_tb, x_tf), (y0, y1), wt = xs, ys, CISTERN_WALL
    return [g.box_between([x_tb, y0, z0], [x_tf, y1, z0 + wt], "ceramic", bevel=0.004),
            g.panel([x_tf - wt, y0, z0 + wt], [x_tf, y1, z1], "ceramic", "x", holes=holes),
            g.box_between([x_tb, y0, z0 + wt], [x_tb + wt, y1, z1], "ceramic"),
            g.box_between([x_tb + wt, y0, z0 + wt], [x_tf - wt, y0 + wt, z1], "ceramic"),
            g.box_between([x_tb + wt, y1 - wt, z0 + wt], [x_tf - wt, y1, z1], "ceramic")]


def _cistern_lid(xs, ys, z: float, thickness: float) -> list[g.Piece]:
    """An overhanging slab resting at ``z`` with a locating lip inside the cistern walls."""
    (x_tb, x_tf), (y0, y1) = xs, ys
    ov, lip, t = LID["overhang"], LID["lip"], LID["lip_t"]
    gi = CISTERN_WALL + 0.004  # lip inset from the outer faces
    return [g.box_between([x_tb - ov, y0 - ov, z], [x_tf + ov, y1 + ov, z + thickness], "ceramic", bevel=0.006),
            g.box_between([x_tb + gi, y0 + gi, z - lip], [x_tb + gi + t, y1 - gi, z], "ceramic"),
            g.box_between([x_tf - gi - t, y0 + gi, z - lip], [x_tf - gi, y1 - gi, z], "ceramic"),
            g.box_between([x_tb + gi + t, y0 + gi, z - lip], [x_tf - gi - t, y0 + gi + t, z], "ceramic"),
            g.box_between([x_tb + gi + t, y1 - gi - t, z - lip], [x_tf - gi - t, y1 - gi, z], "ceramic")]


def _seat(a: float, b: float, x_c: float, z0: float, thick: float, ring: float, tab) -> list[g.Piece]:
    """An oval seat ring resting at ``z0`` and its rear tab (x0, x1, width) up to the hinge."""
    x0, x1, w = tab
    return [oval(g.shell([(b, z0), (b, z0 + thick)], ring, "seat", sections=48), x_c, a / b),
            g.box_between([x0, -w / 2, z0], [x1, w / 2, z0 + thick], "seat", bevel=0.004)]


def _cover(a: float, b: float, x_c: float, z0: float, thick: float, tab) -> list[g.Piece]:
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


def _flush_button(x_face: float, behind: float, z: float, r: float) -> list[g.Piece]:
    """A round flush button from ``behind`` the face to 12.5 mm proud of it, with a smaller cap;
    hollow chrome-plated plastic (:data:`BUTTON_WALL`)."""
    return [g.cylinder([x_face - behind, 0.0, z], [x_face + 0.011, 0.0, z], r, "chrome", 32).replace(wall=BUTTON_WALL),
            g.cylinder([x_face + 0.011, 0.0, z], [x_face + 0.0125, 0.0, z], r * 0.8, "chrome", 32)
            .replace(wall=BUTTON_WALL)]


def _trip_lever(xa: float, ys: float, z: float, length: float) -> list[g.Piece]:
    """A flush lever turning about y through ``(xa, ys, z)`` on a left side wall (it stands off to -y):
    a hub and a grip to +x; the core adds the counterweight heel that balances it."""
    return [g.cylinder([xa, ys, z], [xa, ys - 0.016, z], 0.011, "chrome", 24),
            g.box_between([xa, ys - 0.015, z - 0.006], [xa + length, ys - 0.008, z + 0.006], "chrome", bevel=0.002)]


def on_face(x: float, z: float) -> Frame:
    """A frame on a +x-facing face at height ``z`` (its z along +x)."""
    return Frame.at((x, 0.0, z), z=(1, 0, 0), x=(0, 0, -1))


# -- the other designs: one-piece, back-to-wall, wall-hung ------------------------------------------------
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


def _prewall(x_front: float, depth: float, width: float, height: float) -> list[g.Piece]:
    """A boxed-in installation frame (the wall a wall-hung pan or a back-to-wall unit stands against):
    a tiled box from the floor with a bevelled top."""
    return [g.box_between([x_front - depth, -width / 2, 0.0], [x_front, width / 2, height], "wall", bevel=0.006)]


def _vanity_unit(x_front: float, depth: float, width: float, height: float) -> list[g.Piece]:
    """A back-to-wall furniture unit: a carcass hiding the cistern, a plinth recess and a worktop."""
    t = 0.025
    return [g.box_between([x_front - depth, -width / 2, 0.07], [x_front, width / 2, height - t], "unit", bevel=0.003),
            g.box_between([x_front - depth, -width / 2 + 0.01, 0.0], [x_front - 0.05, width / 2 - 0.01, 0.07], "unit"),
            g.box_between([x_front - depth, -width / 2 - 0.01, height - t], [x_front + 0.02, width / 2 + 0.01, height],
                          "top", bevel=0.004)]


def _flush_plate(x_face: float, z: float) -> tuple[list[g.Piece], list[tuple[str, list[g.Piece]]]]:
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


# -- builders: assemblies in their own frames ------------------------------------------------------------


def pan(design: str, size: PanSize, cistern: CisternSize, rear: float) -> Assembly:
    """The ceramic pan of a ``design`` (close_coupled, one_piece, back_to_wall, wall_hung) in its frame on the
    floor under the seat's hinge line; ``rear``: the depth of what stands behind it (the cistern, a unit, a
    boxed frame). Anchors: ``centre`` (the floor under the middle of the whole toilet's footprint),
    ``hinge`` (the seat's hinge line, z along -y: a positive turn lifts the front), ``back`` (the foot of the
    cistern's front face, at the rim) and ``wall`` (the floor at a unit's or a boxed frame's face)."""
    a, b, z_r = size.a, size.b, size.rim
    x_c, x_b = size.bowl_x, -size.tank_gap
    hinge, tab_w = (0.0, size.hinge_z), size.tab_width
    if design == "close_coupled":
        deck = (x_b - cistern.depth + SHAPE.deck_into_cistern, x_c - SHAPE.deck_forward * a,
                min(SHAPE.deck_of_cistern * cistern.width, SHAPE.deck_of_bowl * b))
        pieces = ceramic_base(a, b, size.wall, z_r, x_c, deck, tab_w, hinge)
    elif design == "one_piece":
        pieces = skirted_base(a, b, size.wall, z_r, x_c, x_b - cistern.depth, tab_w, hinge,
                              min(SHAPE.skirt_of_cistern * cistern.width, SHAPE.skirt_of_bowl * b))
    elif design == "back_to_wall":
        pieces = skirted_base(a, b, size.wall, z_r, x_c, x_b + GAP, tab_w, hinge, SHAPE.back_to_wall_of_bowl * b)
    else:
        pieces = hung_base(a, b, size.wall, z_r, x_c, x_b + GAP, tab_w, hinge)
    anchors = {"centre": Frame.at(((x_c + a + x_b - rear) / 2, 0.0, 0.0)),
               "hinge": Frame.at((0.0, 0.0, size.hinge_z), z=(0, -1, 0)),
               "back": Frame.at((x_b, 0.0, z_r)), "wall": Frame.at((x_b, 0.0, 0.0))}
    support = (x_b, 0.0, z_r) if design == "wall_hung" else (x_c, 0.0, 0.0)  # bolted to the wall, or on the floor
    return Assembly.single("body", pieces, anchors, {"support": support})


def seat(size: PanSize) -> Assembly:
    """The seat ring resting on the rim, in the hinge line's frame (origin on the line, x forward);
    anchor ``hinge`` (the pan's)."""
    a_s, b_s = size.a + SHAPE.seat_past, size.b + SHAPE.seat_past
    x_c = size.bowl_x
    pieces = _seat(a_s, b_s, x_c, -size.seat_thickness, size.seat_thickness, size.seat_ring,
                   (0.0, x_c - a_s + SHAPE.tab_inside, size.tab_width))
    return Assembly.single("seat", pieces, {"hinge": Frame.at((0.0, 0.0, 0.0), z=(0, -1, 0))},
                           {"rim": (x_c, 0.0, -size.seat_thickness)})


def cover(size: PanSize) -> Assembly:
    """The cover lying on the seat, in the hinge line's frame (as :func:`seat`); anchor ``hinge``."""
    past = SHAPE.seat_past + SHAPE.cover_past
    a_c, b_c, x_c = size.a + past, size.b + past, size.bowl_x
    pieces = _cover(a_c, b_c, x_c, GAP, size.cover_thickness, (0.0, x_c - a_c + SHAPE.tab_inside, size.tab_width))
    return Assembly.single("lid", pieces, {"hinge": Frame.at((0.0, 0.0, 0.0), z=(0, -1, 0))}, {"seat": (x_c, 0.0, GAP)})


def cistern(size: CisternSize, buttons: tuple[float, ...] = (), button_radius: float = 0.0) -> Assembly:
    """A hollow cistern in the frame at the foot of its front face, with a hole in its front for a button at
    each y of ``buttons``. Anchors: ``mount`` (the foot), ``lid_seat`` (where its lid rests: the front top,
    z up), ``flush`` (the front face at the flush height, :func:`on_face`) and ``left`` (the left wall's
    front edge at that height)."""
    rb, z1, zf = button_radius, size.top, size.flush_z
    holes = [(y - rb - CLEAR, zf - rb - CLEAR, y + rb + CLEAR, zf + rb + CLEAR) for y in buttons]
    pieces = _cistern((-size.depth, 0.0), (-size.width / 2, size.width / 2), 0.0, z1, holes)
    anchors = {"mount": IDENTITY, "lid_seat": Frame.at((0.0, 0.0, z1 + GAP)), "flush": on_face(0.0, zf),
               "left": Frame.at((0.0, -size.width / 2, zf))}
    return Assembly.single("tank", pieces, anchors, {"foot": (-size.depth / 2, 0.0, 0.0)})


def cistern_lid(size: CisternSize) -> Assembly:
    """The cistern's lid, one of the lift-off lid family (:mod:`.lids`): an overhanging slab with a locating
    lip, in the frame where it rests (anchor ``seat``: the front top edge's middle, z up, the way it lifts)."""
    w = size.width
    pieces = _cistern_lid((-size.depth, 0.0), (-w / 2, w / 2), 0.0, size.lid_thickness)
    return rimmed(Assembly.single("lid", pieces, {"seat": IDENTITY, "top": Frame.at((0.0, 0.0, size.lid_thickness))},
                                  {"lip": (-size.depth / 2, 0.0, 0.0)}))


def flush_button(radius: float) -> Assembly:
    """A round push button in its face's frame (x out of the face); anchors ``mount`` (:func:`on_face` at its
    centre) and ``press`` (its slide, z into the face). The ring round its hole is :func:`flush_ring`."""
    pieces = _flush_button(0.0, CISTERN_WALL + BUTTON_BEHIND, 0.0, radius)
    return Assembly.single("button", pieces, {"mount": on_face(0.0, 0.0),
                                              "press": Frame.at((BUTTON_PROUD, 0.0, 0.0), z=(-1, 0, 0))})


def trip_lever(length: float) -> Assembly:
    """A side trip lever in the frame of a cistern's left wall's front edge (anchor ``mount``): part ``lever``
    (its grip forward, pressed down about ``pivot``'s z = +y) and part ``rose`` (fixed to the cistern)."""
    xa = -length - LEVER_ROSE["behind"]
    rose, y_in = lever_rose(xa, 0.0, 0.0)
    parts = {"lever": SubPart("lever", tuple(_trip_lever(xa, y_in, 0.0, length))), "rose": SubPart("tank", (rose,))}
    return Assembly(parts, (), {"mount": IDENTITY, "pivot": Frame.at((xa, y_in, 0.0), z=(0, 1, 0))})


def furniture_unit(size: BoxSize) -> Assembly:
    """A back-to-wall furniture unit in the frame at the foot of its front face; anchor ``plate`` where its
    flush plate's centre sits on that face."""
    plate = size.height - SHAPE.unit_top - SHAPE.unit_plate
    pieces = [pc.replace(sheet=SHEET) for pc in _vanity_unit(0.0, size.depth, size.width, size.height)]
    return Assembly.single("cabinet", pieces, {"mount": IDENTITY, "plate": Frame.at((0.0, 0.0, plate))})


def boxed_frame(size: BoxSize) -> Assembly:
    """A wall-hung pan's boxed-in frame in the frame at the foot of its front face; anchor ``plate``."""
    pieces = [pc.replace(sheet=SHEET) for pc in _prewall(0.0, size.depth, size.width, size.height)]
    return Assembly.single("frame", pieces, {"mount": IDENTITY,
                                             "plate": Frame.at((0.0, 0.0, size.height - SHAPE.frame_plate))})


def flush_plate() -> Assembly:
    """A dual-flush plate in the frame at its centre on the +x face it is mounted on (anchor ``mount``):
    part ``plate`` (fixed to what carries it) and the keys ``small`` and ``large``, each in its opening."""
    plate, keys = _flush_plate(0.0, 0.0)
    parts = {"plate": SubPart("chrome", tuple(plate)), **{side: SubPart("button", tuple(pcs)) for side, pcs in keys}}
    return Assembly(parts, (), {"mount": IDENTITY})


def key_press(pieces, at: Frame) -> Frame:
    """The slide of a flush key (``pieces``, placed) pressed into the face of ``at``: from the key's front
    face, on the toilet's centre plane (y = 0) at ``at``'s height, z into the face."""
    face = max(pc.bounds[1, 0] for pc in pieces)
    return Frame.at((face, 0.0, at.origin[2]), z=(-1, 0, 0))
