"""Bar chair: a tall swivel stool on a gas lift, on a wheeled star base or a disc base with a foot ring.

X is depth (the sitter faces +X), Y is width, Z is up. Two bases:

* ``wheeled``: the office chair's star base (3-10 legs, 5 most often, casters swivelling about
  Z with one or two wheels turning about a radial axle; the wheels touch the floor), with a
  tall column on the hub and, optionally, a foot ring on the column;
* ``disc``: a heavy domed disc with a tall column and a foot ring (no wheels).

The column is a hollow sleeve; the gas lift is a hollow tube in it around a fixed piston rod,
sliding up along +Z from its lowest (rest) position. The seat (round or square) swivels about
Z on top of the lift. An optional low back stands on a spine behind the seat, either fixed
or hinged (reclining about -Y with its hinge behind its centre of mass, so gravity holds it
upright against its q = 0 stop). The builders are shared with ``office_chair.py``.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Int, Schema

from .office_chair import GAP, back_rest, gas_lift, leg_count, materials, star_base, swivel_seat

GROWTH = Growth(
    bar_chair=Rule(required=("base", "lift", "seat"), optional={"back": 0.4},
                   one_of={"wheeled": 0.45, "disc": 0.55}),
    base=Rule(optional={"foot_ring": 0.6}),
    caster=Rule(required=("fork", "wheels"), one_of={"twin": 0.6, "single": 0.4}),
    seat=Rule(one_of={"round": 0.55, "square": 0.45}),
    back=Rule(one_of={"fixed": 0.5, "hinged": 0.5}),
)
"""Every ``one_of`` is object-wide: the ``base_type``, ``caster_style``, ``seat_shape`` and
``back_mount`` parameters (same weights). A disc base always has its foot ring; the
``has_foot_ring`` flag applies to the wheeled base."""


def _choice(name: str, doc: str, node: str) -> Choice:
    alts = GROWTH.rules[node].one_of
    return Choice(name, doc, choices=tuple(alts), weights=tuple(alts.values()))


SCHEMA = Schema((
    Float("seat_height", "seat top above the floor at rest (lift down)", "m", 0.6, 0.85),
    Float("seat_width", "seat width, or diameter of a round seat", "m", 0.34, 0.46),
    Float("seat_depth", "square seat depth (X)", "m", 0.32, 0.42),
    Float("seat_thickness", "seat cushion thickness", "m", 0.035, 0.08),
    _choice("seat_shape", "seat outline", "seat"),
    _choice("base_type", "star base on casters, or a disc with a foot ring", "bar_chair"),
    Int("leg_count", "legs of a wheeled base; auto = drawn, 5 most often", "", 3, 10, auto=True),
    Float("base_radius", "caster axes (wheeled) or disc radius from the centre", "m", 0.22, 0.3),
    Choice("leg_style", "leg shape", choices=("tapered", "straight"), weights=(0.65, 0.35)),
    _choice("caster_style", "one or two wheels per caster", "caster"),
    Float("wheel_radius", "wheel radius", "m", 0.022, 0.03),
    Float("lift_radius", "gas lift tube radius", "m", 0.022, 0.028),
    Float("lift_travel", "gas lift stroke", "m", 0.07, 0.12),
    Float("exposed_lift", "lift tube visible between the column and the seat at rest", "m", 0.05, 0.15),
    Float("ring_drop", "foot ring below the seat top", "m", 0.35, 0.5),
    Float("ring_radius", "foot ring radius", "m", 0.17, 0.23),
    Float("back_height", "backrest height", "m", 0.14, 0.3),
    Float("back_width", "backrest width as a fraction of the seat width", "", 0.6, 0.9),
    Float("back_thickness", "backrest thickness", "m", 0.03, 0.05),
    Float("back_gap", "backrest bottom above the seat top", "m", 0.06, 0.14),
    _choice("back_mount", "the back is fixed or reclines", "back"),
    Float("recline", "back recline range (hinged back)", "rad", 0.15, 0.3),
    Choice("base_finish", "base material", choices=("chrome", "brushed_metal", "plastic"),
           weights=(0.45, 0.25, 0.3)),
    Choice("lift_finish", "gas lift tube material", choices=("chrome", "plastic"), weights=(0.7, 0.3)),
    Choice("seat_finish", "seat upholstery", choices=("fabric", "plastic"), weights=(0.6, 0.4)),
    Choice("wheel_finish", "wheel tyres", choices=("plastic", "rubber"), weights=(0.6, 0.4)),
    *GROWTH.flags(),
))


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    bp = Blueprint("bar_chair", materials=materials(p))
    H, W = p["seat_height"], p["seat_width"]
    shape = p["seat_shape"]
    D = W if shape == "round" else p["seat_depth"]
    r_lift = p["lift_radius"]
    n_legs = leg_count(p, structure)
    bore = r_lift + GAP
    if p["base_type"] == "wheeled":
        base = star_base(bp, n_legs, p["base_radius"], p["wheel_radius"], r_lift, p["leg_style"],
                         p["caster_style"], metal=p["base_finish"] != "plastic")
        ring = p["has_foot_ring"]
    else:
        base = _disc_base(bp, p["base_radius"], bore, metal=p["base_finish"] != "plastic")
        ring = True
    hm = 0.035
    seat = swivel_seat(bp, "lift", H, W, D, p["seat_thickness"], shape, 0.0, r_lift, hm)
    lift_top = seat["lift_top"]
    z_ring = max(H - p["ring_drop"], base["top"] + 0.07, 0.22)
    col_top = lift_top - 0.03 - p["exposed_lift"]
    if ring:
        col_top = max(col_top, min(z_ring + 0.04, lift_top - 0.05))
        z_ring = min(z_ring, col_top - 0.03)
    col_r = bore + 0.006
    column = [g.shell([(col_r, base["top"] - 0.006), (col_r, col_top)], col_r - bore, "base", sections=48),
              g.shell([(col_r + 0.002, col_top - 0.012), (col_r + 0.002, col_top)], 0.008, "base", sections=48)]
    if ring:
        column += _foot_ring(z_ring, p["ring_radius"], col_r)
    bp.extend(base["name"], column)
    gas_lift(bp, base["name"], base["floor"], lift_top, r_lift, p["lift_travel"])
    bp.join(J.continuous("lift", "seat", (0.0, 0.0, lift_top), (0, 0, 1), role="swivel"))
    if p["has_back"]:
        q = dict(p, back_style="cushion", has_headrest=False)
        back_rest(bp, q, seat, W, H, hinged=p["back_mount"] == "hinged")
    return bp


def _disc_base(bp: Blueprint, radius: float, bore: float, metal: bool) -> dict:
    """A domed disc with a socket boss; its top is the socket floor."""
    t = 0.012 + 0.03 * (radius - 0.2)
    prof = [(0.0, 0.0), (radius - 0.012, 0.0)]
    for k in range(1, 8):
        a = -math.pi / 2 + math.pi / 2 * k / 7
        prof.append((radius - 0.012 + 0.012 * math.cos(a), 0.006 + 0.006 * math.sin(a)))
    for k in range(1, 9):
        f = k / 8
        r = radius - f * (radius - bore - 0.03)
        prof.append((r, 0.006 + t * (1 - (1 - f) ** 2)))
    top = 0.006 + t
    prof.append((0.0, top))
    disc = g.revolve(prof, "base", sections=64)
    boss = g.shell([(bore + 0.02, top - 0.004), (bore + 0.014, top + 0.03)], 0.014, "base", sections=48)
    felt = g.disc([0, 0, 0.0015], radius - 0.03, 0.003, "pad", 48).replace(convex=[])
    if metal:
        disc = disc.replace(sheet=0.0)  # a cast disc: solid on purpose (a heavy, stable foot)
    bp.add("base", "base", [disc, boss, felt])
    return {"name": "base", "floor": top, "top": top + 0.03}


def _foot_ring(z: float, radius: float, col_r: float) -> list[g.Piece]:
    """A round foot ring of 40 tube segments and three or four spokes to the column."""
    rr = 0.009
    n = 40
    pts = [np.array([radius * math.cos(2 * math.pi * k / n), radius * math.sin(2 * math.pi * k / n), z])
           for k in range(n + 1)]
    pieces = [g.cylinder(a, b, rr, "ring", 16) for a, b in zip(pts[:-1], pts[1:])]
    for k in range(n):
        pieces.append(g.sphere(pts[k], rr, "ring").replace(convex=[]))
    for k in range(4):
        a = 2 * math.pi * k / 4 + math.pi / 4
        d = np.array([math.cos(a), math.sin(a), 0.0])
        pieces.append(g.cylinder(d * (col_r - 0.002) + [0, 0, z], d * (radius - 0.004) + [0, 0, z], 0.006,
                                 "ring", 12))
    pieces.append(g.shell([(col_r + 0.008, z - 0.018), (col_r + 0.008, z + 0.018)], 0.008, "ring", sections=40))
    return pieces
