"""Toilet: a close-coupled ceramic toilet with a seat, a cover, a cistern with a lift-off lid and a flush.

X is depth (the bowl faces +X, the cistern is at -X), Y is width, Z is up. The ceramic base is
an oval bowl (a thin wall of revolution stretched along X, so the bowl stays hollow for the
simulator) with a flat rim, on a pedestal with a wider foot, and a rear deck that carries the
cistern. The cistern (label ``tank``, fixed to the base) is a hollow box of five walls; its lid
rests on the walls with a locating lip inside them and lifts straight up (P along +Z, 0..0.2 m),
so gravity holds it on its seat.

Seat and cover share ONE hinge line at the back, parallel to Y, through the top rear edge of the
seat. The seat turns about (0, -1, 0), so a positive angle lifts its front up and back towards
the cistern; gravity presses it onto the rim (lower limit 0). The cover is the seat's child on
the same line (its angle is relative to the seat) and lies on the seat at rest; it can only
turn away from the seat, so the two never interpenetrate.

Product of joint ranges: simulators and the physics checks sample every combination of joint
states (all joints at their upper limits at once), while a real cover stops when it leans on
the cistern whatever the seat does. The seat and the cover declare a common mechanical
maximum of half a turn, split by ``cover_share``; the core's ``limit_to_clearance`` stops the
cover where it would lean on the cistern, alone and with everything open (both limits scaled
together: ``seat upper + cover upper`` is the leaning angle, about 92-102 degrees).

The flush is a push button on the cistern front (pressed along -X, horizontal, so gravity
has no say) or a side trip lever on the left wall near the front that turns about Y (pressing
its grip down is positive; it stays behind the cistern front, out of the cover's way); the
lever gets a counterweight heel from the core's ``rest_on_stops``, so its centre of mass lies
on its axis (neutral at rest).
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Schema

GROWTH = Growth(
    toilet=Rule(required=("base", "seat", "cover", "tank", "tank_lid", "flush")),
    flush=Rule(one_of={"button": 0.5, "lever": 0.5}),
)
"""``flush.one_of`` is object-wide: the ``flush`` parameter (same weights)."""

_FLUSH = GROWTH.rules["flush"].one_of

SCHEMA = Schema((
    Float("seat_height", "height of the seat top above the floor (the toilet's size)", "m", 0.40, 0.50),
    Float("bowl_width", "outer width of the rim (Y)", "m", 0.34, 0.40),
    Float("bowl_length", "outer length of the rim (X)", "m", 0.40, 0.48),
    Float("wall", "ceramic wall thickness of the bowl", "m", 0.010, 0.016),
    Float("tank_width", "cistern width (Y)", "m", 0.38, 0.50),
    Float("tank_depth", "cistern depth (X)", "m", 0.15, 0.21),
    Float("tank_height", "cistern height incl. the lid", "m", 0.30, 0.40),
    Float("tank_gap", "distance from the hinge line back to the cistern front", "m", 0.06, 0.10),
    Float("seat_thickness", "seat ring thickness", "m", 0.018, 0.03),
    Float("seat_ring", "seat ring width at the sides", "m", 0.055, 0.08),
    Float("cover_thickness", "cover thickness", "m", 0.012, 0.025),
    Float("lid_thickness", "cistern lid thickness", "m", 0.018, 0.03),
    Float("cover_share", "the cover's share of the common opening angle (the seat gets the rest)",
          "", 0.5, 0.65),
    Choice("flush", "flush control", choices=tuple(_FLUSH), weights=tuple(_FLUSH.values())),
    Float("button_radius", "flush button radius", "m", 0.018, 0.03),
    Float("lever_length", "trip lever grip length", "m", 0.06, 0.09),
    Choice("ceramic_colour", "ceramic colour", choices=("white", "cream", "ivory"),
           weights=(0.7, 0.15, 0.15)),
    Choice("seat_finish", "seat and cover material", choices=("plastic", "wood"), weights=(0.75, 0.25)),
    *GROWTH.flags(),
))

LID_LIFT = 0.2  # m, the cistern lid lifts 0..0.2
GAP = 0.003  # clearance of moving parts at rest
PRESS = 0.006  # button travel
LEVER_TURN = math.pi / 4


def _oval(piece: g.Piece, cx: float, sx: float) -> g.Piece:
    """Stretch a piece built about the Z axis by ``sx`` along X and move its axis to x = cx."""
    m = np.diag([sx, 1.0, 1.0, 1.0])
    m[0, 3] = cx
    return piece.transformed(m)


def _x_axis(piece: g.Piece, at) -> g.Piece:
    """Turn a piece built about +Z through the origin so its axis is +X through ``at``."""
    m = np.eye(4)
    m[:3, :3] = g.rotation_between((0, 0, 1), (1, 0, 0))
    m[:3, 3] = at
    return piece.transformed(m)


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    seat_slot = {"plastic": "plastic:white|light_grey|black", "wood": "wood"}
    bp = Blueprint("toilet", materials={
        "ceramic": f"ceramic:{p['ceramic_colour']}", "seat": seat_slot[p["seat_finish"]],
        "chrome": "chrome", "rubber": "rubber",
    })
    a, b = p["bowl_length"] / 2, p["bowl_width"] / 2
    sx = a / b
    ts, tc, tl, w = p["seat_thickness"], p["cover_thickness"], p["lid_thickness"], p["wall"]
    z_r = p["seat_height"] - ts - GAP  # rim top
    z_h = z_r + GAP + ts  # hinge line: the seat's top rear edge
    tab = 0.035  # the seat's rear tab, from the rim's back to the hinge line
    TD, TW, TH = p["tank_depth"], p["tank_width"], p["tank_height"]
    total = 2 * a + tab + p["tank_gap"] + TD
    x_front = total / 2
    x_c = x_front - a  # bowl axis
    x_h = x_c - a - tab  # hinge line
    x_tf = x_h - p["tank_gap"]  # cistern front face
    x_tb = x_tf - TD

    # --- ceramic base ------------------------------------------------------------------
    z_bot = 0.42 * z_r  # bowl bottom (the trap)
    hb = z_r - z_bot
    outer = [(0.32 * b, z_bot), (0.55 * b, z_bot + 0.22 * hb), (0.82 * b, z_bot + 0.55 * hb),
             (0.96 * b, z_bot + 0.85 * hb), (b - 0.004, z_r - 0.03)]
    pieces = [
        _oval(g.shell(outer, w, "ceramic", sections=48), x_c, sx),
        # the rim: a flat-topped band curling inward over the bowl wall
        _oval(g.shell([(b, z_r - 0.035), (b, z_r)], 0.032, "ceramic", sections=48), x_c, sx),
        # the trap at the bottom of the bowl
        _oval(g.disc((0, 0, z_bot - 0.005), 0.34 * b, 0.03, "ceramic", 32), x_c, sx),
    ]
    # pedestal: an oval foot narrowing to the bowl, set back a little
    ped = [(0.0, 0.0), (0.62 * b, 0.0), (0.62 * b, 0.012), (0.5 * b, 0.05), (0.4 * b, 0.5 * z_bot),
           (0.36 * b, z_bot + 0.01), (0.0, z_bot + 0.01)]
    x_p = x_c - 0.25 * a
    pieces.append(_oval(g.revolve(ped, "ceramic", sections=40), x_p, 1.35 * sx))
    # rear deck under the hinge and the cistern, on a back column down to the floor
    deck_x0 = x_tb + 0.02
    deck_x1 = x_c - 0.75 * a
    deck_w = min(0.75 * TW, 1.3 * b)
    z_deck0 = 0.55 * z_r
    pieces.append(g.box_between([deck_x0, -deck_w / 2, z_deck0], [deck_x1, deck_w / 2, z_r], "ceramic",
                                bevel=0.01))
    col_x0 = max(deck_x0, x_p - 1.35 * a * 0.62 + 0.02)
    pieces.append(g.box_between([col_x0, -0.34 * b, 0.01], [deck_x1, 0.34 * b, z_deck0 + 0.01],
                                "ceramic", bevel=0.01))
    # hinge posts beside the seat and cover tabs
    tab_w = 0.34 * b
    for s in (-1, 1):
        y0 = s * (tab_w / 2 + 0.006)
        y1 = s * (tab_w / 2 + 0.026)
        pieces.append(g.box_between([x_h - 0.018, min(y0, y1), z_r], [x_h + 0.008, max(y0, y1), z_h - 0.004],
                                    "chrome", bevel=0.003))
    base = bp.add("base", "body", pieces)

    # --- cistern -----------------------------------------------------------------------------
    z_t0 = z_r  # sits on the deck
    z_tt = z_t0 + TH - tl - GAP  # top of the walls
    wt = 0.012
    y0, y1 = -TW / 2, TW / 2
    flush = p["flush"]
    zf = z_tt - 0.06  # flush control height
    CLEAR = 0.0025
    holes = []
    if flush == "button":
        rb = p["button_radius"]
        holes.append((-rb - CLEAR, zf - rb - CLEAR, rb + CLEAR, zf + rb + CLEAR))
    tank = [
        g.box_between([x_tb, y0, z_t0], [x_tf, y1, z_t0 + wt], "ceramic", bevel=0.004),
        g.panel([x_tf - wt, y0, z_t0 + wt], [x_tf, y1, z_tt], "ceramic", "x", holes=holes),
        g.box_between([x_tb, y0, z_t0 + wt], [x_tb + wt, y1, z_tt], "ceramic"),
        g.box_between([x_tb + wt, y0, z_t0 + wt], [x_tf - wt, y0 + wt, z_tt], "ceramic"),
        g.box_between([x_tb + wt, y1 - wt, z_t0 + wt], [x_tf - wt, y1, z_tt], "ceramic"),
    ]
    bp.add("tank", "tank", tank)
    bp.join(J.fixed(base, "tank"))

    # lid: an overhanging slab with a locating lip inside the walls
    ov = 0.008
    zl = z_tt + GAP
    lip = 0.015
    gi = wt + 0.004  # lip inset from the outer faces
    lid = [
        g.box_between([x_tb - ov, y0 - ov, zl], [x_tf + ov, y1 + ov, zl + tl], "ceramic", bevel=0.006),
        g.box_between([x_tb + gi, y0 + gi, zl - lip], [x_tb + gi + 0.008, y1 - gi, zl], "ceramic"),
        g.box_between([x_tf - gi - 0.008, y0 + gi, zl - lip], [x_tf - gi, y1 - gi, zl], "ceramic"),
        g.box_between([x_tb + gi + 0.008, y0 + gi, zl - lip], [x_tf - gi - 0.008, y0 + gi + 0.008, zl],
                      "ceramic"),
        g.box_between([x_tb + gi + 0.008, y1 - gi - 0.008, zl - lip], [x_tf - gi - 0.008, y1 - gi, zl],
                      "ceramic"),
    ]
    bp.add("tank_lid", "lid", lid)
    bp.join(J.prismatic("tank", "tank_lid", (x_tf, 0.0, zl), (0, 0, 1), 0.0, LID_LIFT, role="lid"))

    # flush control
    if flush == "button":
        rb = p["button_radius"]
        ring = _x_axis(g.shell([(rb + CLEAR + 0.008, 0.0), (rb + CLEAR + 0.008, 0.004)], 0.008, "chrome",
                               sections=32, convex_sectors=12), (x_tf, 0.0, zf))
        bp.extend("tank", [ring])
        btn = [g.cylinder([x_tf - wt - 0.004, 0.0, zf], [x_tf + 0.011, 0.0, zf], rb, "chrome", 32),
               g.cylinder([x_tf + 0.011, 0.0, zf], [x_tf + 0.0125, 0.0, zf], rb * 0.8, "chrome", 32)]
        bp.add("flush_button", "button", btn)
        bp.join(J.prismatic("tank", "flush_button", (x_tf + 0.0125, 0.0, zf), (-1, 0, 0), 0.0, PRESS,
                            role="button"))
    else:
        # a side trip lever on the left (-Y) wall near the front; its grip points forward (+X)
        # and stays behind the cistern front, out of the cover's way
        length = p["lever_length"]
        xa = x_tf - length - 0.012
        ys = y0 - 0.006 - GAP  # the lever's inner face, off the rose
        rose = g.cylinder([xa, y0, zf], [xa, y0 - 0.006, zf], 0.02, "chrome", 32)
        bp.extend("tank", [rose])
        bp.add("flush_lever", "lever", _trip_lever(xa, ys, zf, length))
        # pressing the grip (+X of the axis) down: about +Y
        bp.join(J.revolute("tank", "flush_lever", (xa, ys, zf), (0, 1, 0), 0.0, LEVER_TURN, role="button"))

    # --- seat and cover on one hinge line ------------------------------------------------------
    a_s, b_s = a + 0.002, b + 0.002
    ring_w = p["seat_ring"]
    seat = [
        _oval(g.shell([(b_s, z_r + GAP), (b_s, z_r + GAP + ts)], ring_w, "seat", sections=48), x_c,
              a_s / b_s),
        g.box_between([x_h, -tab_w / 2, z_r + GAP], [x_c - a_s + 0.03, tab_w / 2, z_h], "seat", bevel=0.004),
    ]
    bp.add("seat", "seat", seat)
    zc = z_h + GAP
    a_c, b_c = a_s + 0.004, b_s + 0.004
    cover = [
        _oval(g.disc((0, 0, zc + tc / 2), b_c, tc, "seat", 48), x_c, a_c / b_c),
        g.box_between([x_h, -tab_w / 2, zc], [x_c - a_c + 0.03, tab_w / 2, zc + tc], "seat", bevel=0.003),
    ]
    bp.add("cover", "lid", cover)

    # mechanical maxima: the two leaves turn at most half a turn together, split by cover_share;
    # the core stops them where the cover leans on the cistern (its lid lifted or not)
    cover_up = p["cover_share"] * math.pi
    seat_up = math.pi - cover_up
    bp.join(J.revolute(base, "seat", (x_h, 0.0, z_h), (0, -1, 0), 0.0, seat_up, role="hinge"))
    bp.join(J.revolute("seat", "cover", (x_h, 0.0, z_h), (0, -1, 0), 0.0, cover_up, role="hinge"))
    return bp


def _trip_lever(xa: float, ys: float, z: float, length: float) -> list[g.Piece]:
    """A flush lever turning about Y through ``(xa, ys, z)`` on a left side wall (it stands off to -Y):
    hub and grip to +X. The core adds the counterweight heel to -X that puts the centre of mass
    on the axis (neutral at rest; :func:`infmob_usd.physical.rest_on_stops`).
    """
    hub = g.cylinder([xa, ys, z], [xa, ys - 0.016, z], 0.011, "chrome", 24)
    grip = g.box_between([xa, ys - 0.015, z - 0.006], [xa + length, ys - 0.008, z + 0.006], "chrome",
                         bevel=0.002)
    return [hub, grip]
