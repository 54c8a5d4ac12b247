"""Plate rack: a dish-drying rack with rows of prongs and ceramic plates standing in its slots.

X is the rack's length (the front end faces +X), Y its width, Z up. Along X stand
``slot_count + 1`` fences of prongs; each fence is a pair of prongs at ``y = +-b``
(``b = prong_spread x plate_radius``), so every slot between two fences is bounded
by a prong pair on each side of its plate. A plate stands upright in its slot, its
axis along X (the dish opens toward +X), its lowest point a few millimetres above
the support surface (the rail tops, the tray floor or the wire rails).

Three kinds of rack:

* ``wood``: two wooden rails along X on two cross battens (a sled), dowel prongs
  with domed tops, optional rubber pads;
* ``plastic``: a moulded tray (floor and four low walls) with round pegs;
* ``wire``: chrome wire: two rails on four legs with rubber caps, a cross wire and
  an arch (two prongs and a top bar) at every fence.

Each plate hangs from the rack by a ``limited_planar`` joint: the plane of the motion
is the plate's own plane (Y-Z): a lift along +Z (0..0.1 m: gravity holds it on its
lower limit, the plate rests on its seat), a slide along Y within the slot (+-0.1 m,
horizontal: neutral) and a turn about X (the plate's own axis) through its centre,
so its centre of mass is on the axis (neutral). Moving in its own plane, a plate
never leaves its slot's slab between the two fences, so it never meets a prong; the
plate's lowest point never drops below its rest height (the collision hulls are
inscribed in the true circle), so it never meets the support. On the plastic tray
the side walls are placed far enough out that the plate clears them over the whole
slide.

Plates are real dishes: a solid of revolution with a foot ring, a flat well, a
smooth cavetto and a rolled rim (smooth profile, 64 sections), revolved about Z
and stood on edge with a rotation; their collision is a handful of frustums.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Int, Schema

GROWTH = Growth(
    plate_rack=Rule(required=("rack", "slots"), optional={"feet": 0.5}),
    rack=Rule(required=("base", "prongs")),
    slot=Rule(one_of={"plate": 0.5, "empty": 0.5}),
)
"""``slot.one_of`` is drawn per slot from the structure stream (at least one plate);
``plate_count`` overrides it. ``feet`` are rubber pads (wood, plastic); a wire rack
always stands on its capped legs."""

SCHEMA = Schema((
    Int("slot_count", "slots (fences of prong pairs = slots + 1)", "", 3, 7),
    Int("plate_count", "plates; auto = each slot holds one with chance 0.5 (at least one)", "", 1, 7,
        auto=True),
    Choice("style", "rack construction", choices=("wood", "plastic", "wire"), weights=(0.35, 0.3, 0.35)),
    Float("prong_height", "prong height above the support surface", "m", 0.08, 0.15),
    Float("prong_radius", "prong radius (a wire rack uses 0.6 of it)", "m", 0.003, 0.006),
    Float("prong_spread", "half distance between the two prongs of a pair, / plate radius", "", 0.45, 0.75),
    Float("plate_radius", "plate outer radius", "m", 0.08, 0.15),
    Float("plate_depth", "plate height (foot to rim), / plate radius", "", 0.12, 0.2),
    Float("plate_thickness", "plate wall thickness", "m", 0.0035, 0.006),
    Float("foot_fraction", "foot ring radius / plate radius", "", 0.4, 0.55),
    Float("clearance", "gap between a plate and the prongs on each side", "m", 0.003, 0.008),
    Float("base_height", "rail / tray wall / wire leg height", "m", 0.015, 0.03),
    Choice("plate_set", "plates all alike or two alternating colours", choices=("matching", "mixed")),
    *GROWTH.flags(),
))

FRAME = {"wood": "wood", "plastic": "plastic", "wire": "chrome"}
MATERIALS = {"frame": "style", "prong": "style", "plate": "ceramic", "plate_alt": "ceramic",
             "feet": "rubber:black|soft_black"}
"""Material slot -> family; ``style`` means the rack's family (wood, plastic or chrome)."""

LIFT = 0.1  # m, lift of a plate along +Z
SLIDE = 0.1  # m, slide of a plate along Y either way
TURN = math.pi / 2  # rad, turn of a plate about its axis (X) either way
SEAT_GAP = 0.004  # m, plate's lowest point above the support surface at rest
END = 0.03  # m, rack length beyond the first and last fence
PROFILE_SECTIONS = 64


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    style = p["style"]
    bp = Blueprint("plate_rack", materials={
        slot: FRAME[style] if fam == "style" else fam for slot, fam in MATERIALS.items()})
    n, R = p["slot_count"], p["plate_radius"]
    hp, c = p["prong_height"], p["clearance"]
    rp = p["prong_radius"] * (0.6 if style == "wire" else 1.0)
    b = p["prong_spread"] * R

    # --- which slots hold a plate --------------------------------------------
    if p["plate_count"] is None:
        filled = [GROWTH.choose("slot", structure) == "plate" for _ in range(n)]
        if not any(filled):
            filled[int(structure.integers(n))] = True
    else:
        k = min(p["plate_count"], n)
        chosen = set(structure.choice(n, size=k, replace=False).tolist())
        filled = [i in chosen for i in range(n)]

    # --- one plate at the origin: foot at x = 0, dish opening toward +X ----------
    plate0 = _plate(R, p["plate_depth"] * R, p["plate_thickness"], p["foot_fraction"] * R)
    pts = np.vstack([plate0.vertices, *plate0.convex])
    x_lo, x_hi = pts[:, 0].min(), pts[:, 0].max()
    slab = x_hi - x_lo
    pitch = slab + 2 * c + 2 * rp
    fences = (np.arange(n + 1) - n / 2) * pitch
    xa, xb = fences[0] - END, fences[-1] + END

    # --- the rack ----------------------------------------------------------------
    feet = p["has_feet"] or style == "wire"
    z0 = 0.006 if feet else 0.0  # underside of the rack body
    if style == "wood":
        pieces, zs, slide = _wood(p, fences, (xa, xb), b, rp, z0, hp)
    elif style == "plastic":
        pieces, zs, slide = _plastic(p, fences, (xa, xb), b, rp, z0, hp, R)
    else:
        pieces, zs, slide = _wire(p, fences, (xa, xb), b, rp, hp)
    if feet and style != "wire":
        pieces += _pads(pieces, (xa, xb))
    rack = bp.add("rack", "rack", pieces)

    # --- plates ---------------------------------------------------------------------
    zc = zs + SEAT_GAP + R  # plate centre height: lowest point SEAT_GAP above the support
    for i in range(n):
        if not filled[i]:
            continue
        x_foot = fences[i] + rp + c - x_lo
        slot = "plate_alt" if p["plate_set"] == "mixed" and i % 2 else "plate"
        piece = plate0.translated((x_foot, 0.0, zc)).replace(material=slot)
        name = bp.add(f"plate_{i}", "plate", [piece])
        pivot = (fences[i] + pitch / 2, 0.0, zc)  # plate centre: its centre of mass is on the X axis
        bp.join(J.limited_planar(
            rack, name, pivot, slide_axes=((0, 0, 1), (0, 1, 0)),
            slides=((0.0, LIFT), (-slide, slide)), axis=(1, 0, 0), turn=(-TURN, TURN), role="plate"))
    return bp


# -- plates ---------------------------------------------------------------------------------


def _smooth(u):
    u = np.clip(u, 0.0, 1.0)
    return u * u * u * (u * (6 * u - 15) + 10)


def _plate(R, H, t, rf):
    """A plate lying on its foot (axis Z), then stood on edge: axis along +X, foot at x = 0."""
    wf = max(0.006, 0.08 * rf)  # foot ring width
    hf = max(0.003, 0.18 * H)  # foot ring height
    Rc = R - t / 2  # centre of the rolled rim
    rw = rf + 0.3 * wf + 0.004  # the well is flat out to here, then the cavetto rises
    c0, c1 = hf + t / 2, H - t / 2  # mid-surface height in the well and at the rim

    def mid(r):
        return c0 + (c1 - c0) * _smooth((np.asarray(r) - rw) / (Rc - rw))

    foot = [(0.0, hf), (rf - wf, hf), (rf - 0.75 * wf, 0.0), (rf - 0.1 * wf, 0.0)]
    under_r = np.linspace(rf + 0.3 * wf, Rc, 24)
    under = [(r, mid(r) - t / 2) for r in under_r]
    a = np.linspace(-math.pi / 2, math.pi / 2, 9)[1:-1]
    rim = [(Rc + t / 2 * math.cos(x), c1 + t / 2 * math.sin(x)) for x in a]
    top_r = np.linspace(Rc, 0.0, 28)
    top = [(r, mid(r) + t / 2) for r in top_r]
    fine = g.revolve(foot + under + rim + top, "plate", sections=PROFILE_SECTIONS)

    rh = rw + 0.5 * (Rc - rw)
    coarse = g.revolve(foot + [(rw, hf), (rh, float(mid(rh)) - t / 2), (Rc, H - t), (R, c1), (Rc, H),
                               (0.0, H)], "plate")
    fine = fine.with_collision_of(coarse)  # their hulls, known from construction
    m = np.eye(4)
    m[:3, :3] = g.rotation_between((0, 0, 1), (1, 0, 0))
    return fine.transformed(m)


# -- racks ------------------------------------------------------------------------------------


def _dowel(x, y, z_lo, z_hi, r, material):
    """A prong: a cylinder with a domed top."""
    return [g.cylinder([x, y, z_lo], [x, y, z_hi - r], r, material, 16),
            g.sphere([x, y, z_hi - r], r, material)]


def _wood(p, fences, xs, b, rp, z0, hp):
    """Two rails on two cross battens; dowels in the rails. Returns pieces, support height, slide."""
    xa, xb = xs
    hb = 0.4 * p["base_height"] + 0.006  # battens
    hr = p["base_height"]  # rails
    wr = max(0.018, 3.2 * rp)
    bw = 0.024
    pieces = []
    for x in (xa, xb - bw):
        pieces.append(g.box_between([x, -b - wr, z0], [x + bw, b + wr, z0 + hb], "frame", bevel=0.002))
    zr = z0 + hb
    zs = zr + hr
    for y in (-b, b):
        pieces.append(g.box_between([xa, y - wr / 2, zr], [xb, y + wr / 2, zs], "frame", bevel=0.002))
        for x in fences:
            pieces += _dowel(x, y, zs - 0.004, zs + hp, rp, "prong")
    return pieces, zs, SLIDE


def _plastic(p, fences, xs, b, rp, z0, hp, R):
    """A moulded tray with round pegs. The side walls stand where a plate slid SLIDE still clears them."""
    xa, xb = xs
    tf, wt = 0.004, 0.004  # floor and wall thickness
    h = p["base_height"]  # wall height above the floor
    need = 0.002  # clearance kept from the wall's top edge
    yw = SLIDE + math.sqrt(max(0.0, (R + need) ** 2 - (R + SEAT_GAP - h) ** 2))
    yw = max(yw, b + rp + 0.015)
    zs = z0 + tf
    pieces = [
        g.box_between([xa - wt, -yw - wt, z0], [xb + wt, yw + wt, zs], "frame"),  # floor
        g.box_between([xa - wt, -yw - wt, zs], [xb + wt, -yw, zs + h], "frame"),  # side walls
        g.box_between([xa - wt, yw, zs], [xb + wt, yw + wt, zs + h], "frame"),
        g.box_between([xa - wt, -yw, zs], [xa, yw, zs + h], "frame"),  # end walls
        g.box_between([xb, -yw, zs], [xb + wt, yw, zs + h], "frame"),
    ]
    for y in (-b, b):
        for x in fences:
            pieces.append(g.cylinder([x, y, zs - 0.001], [x, y, zs + 0.006], rp * 1.6, "prong", 16))  # boss
            pieces += _dowel(x, y, zs, zs + hp, rp, "prong")
    return pieces, zs, SLIDE


def _wire(p, fences, xs, b, rw, hp):
    """Chrome wire: rails on capped legs, a cross wire and an arch at every fence."""
    xa, xb = xs
    cap = 0.007  # rubber cap height
    zr = cap + p["base_height"]  # rail axis height
    zs = zr + rw  # support: the rail tops
    top = zs + hp - rw  # axis of the arch's top bar
    pieces = []
    for y in (-b, b):
        pieces.append(g.cylinder([xa, y, zr], [xb, y, zr], rw, "frame", 12))
        for x in (xa + 0.012, xb - 0.012):
            pieces.append(g.cylinder([x, y, cap - 0.001], [x, y, zr], rw, "frame", 12))
            pieces.append(g.cylinder([x, y, 0.0], [x, y, cap], 0.0055, "feet", 16))
    for x in fences:
        pieces.append(g.cylinder([x, -b - 0.01, zr - rw], [x, b + 0.01, zr - rw], rw, "frame", 12))
        for y in (-b, b):
            pieces.append(g.cylinder([x, y, zr], [x, y, top], rw, "prong", 12))
            pieces.append(g.sphere([x, y, top], rw, "prong"))
        pieces.append(g.cylinder([x, -b, top], [x, b, top], rw, "prong", 12))
    return pieces, zs, SLIDE


def _pads(pieces, xs):
    """Four rubber pads under the corners of the rack body (it stands on them)."""
    lo = np.array([pc.bounds[0] for pc in pieces]).min(0)
    hi = np.array([pc.bounds[1] for pc in pieces]).max(0)
    z = lo[2]
    out = []
    for x in (xs[0] + 0.012, xs[1] - 0.012):
        for y in (lo[1] + 0.012, hi[1] - 0.012):
            out.append(g.cylinder([x, y, z - 0.006], [x, y, z + 0.001], 0.007, "feet", 16))
    return out
