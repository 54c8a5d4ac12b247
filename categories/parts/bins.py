"""Waste bins: a round or square bin body, its hinged lid, a foot pedal, a swing flap, a lift-out inner
bucket and the bucket's wire bail.

Every part is built in its own frame with the anchors the others attach to, so a category says "the lid on
the body's ``hinge``, the pedal on its ``pedal``, the bucket on its ``floor``" and never computes a
coordinate. A body stands on z = 0 centred on the z axis, its front facing +x. Anchors follow the project's
convention: a hinge anchor's z is the joint axis and a positive turn opens; a ``seat`` anchor's z is the way a
part lifts off.

Sizes are data (:data:`RANGES` and the constants below), each figure beside the product it is read from.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from .casing import CasingSize, Cutout, rounded_sweep, sheet_casing
from .laptops import rounded


@dataclass(frozen=True)
class Ranges:
    width: tuple[float, float]
    depth_ratio: tuple[float, float]
    aspect: tuple[float, float]
    flap_height: tuple[float, float]


# Household bins (maker listings, outer sizes): Brabantia NewIcon pedal bins 5 L 20.6 cm dia. x 28.7 cm,
# 12 L 25 x 40 cm, 30 L 29.3 x 68 cm; simplehuman round step can 30 L ~30 x 34 x 65 cm, rectangular 45 L
# ~39 x 34 x 65 cm; Curver / Addis swing bins 25-50 L ~26-36 cm wide, 60-72 cm tall; sensor cans
# (simplehuman, EKO) 30-58 L ~30-40 cm wide, 65-72 cm tall; open office baskets ~28 cm wide, 30-35 cm tall:
# height / width 1.15 (a basket, a 5 L pedal bin 1.4) to 2.3 (a 30 L slim pedal bin).
TALLEST = 0.72  # m, the tallest household bins' walls (simplehuman 58 L, sensor cans 65-72 cm)
RANGES = Ranges(width=(0.21, 0.38), depth_ratio=(0.75, 1.0), aspect=(1.15, 2.3), flap_height=(0.10, 0.16))

WALL = 0.004  # m, a bin wall as the simulator sees it (massed as the family's sheet or moulded wall)
LID_T = 0.018  # m, a step-can lid: a 0.4-0.6 mm steel skin over a 15-20 mm plastic liner
OVERHANG = 0.006  # m, the lid's lip past the body's wall
KNUCKLE = 0.008  # m, the radius of the hinge knuckle at the back of the rim
# m, the moulded base ring a bin stands on; a pedal bin stands raised on four feet (radius ``foot``) over
# its pedal's lever (Brabantia, simplehuman: a 2-4 cm base, the lever inside it)
BASE = dict(height=0.03, out=0.006, foot=0.014)
# Pedals of step cans (Brabantia NewIcon, simplehuman spare-part listings): a 7-12 cm wide tread 5-7 cm in
# front of the body on a steel lever that runs back under the floor to the lid's lift rod; the tread travels
# 1.5-2 cm (about 18 degrees) and throws the lid up to about 90 degrees (upright, so the inner bucket lifts
# out past it). The lever behind the pivot outweighs the tread: the pedal rests up on its stop.
PEDAL = dict(width=0.09, reach=0.07, thickness=0.012, height=0.028, clear=0.004, inset=0.012, raised=0.072,
             lever=(0.09, 0.02, 0.01))
PEDAL_TURN = math.radians(18)
LID_OPENS = math.radians(90)
# Inner buckets (Brabantia / simplehuman liners): moulded plastic 2-3 mm, a few mm inside the body,
# 80-90 % of its height; a 3-4 mm galvanised wire bail.
BUCKET = dict(clearance=0.006, share=0.85, wire=0.0025, lug=0.012)
BAIL_TURN = math.radians(95)
# Swing-top flaps (Curver, Addis): a 3 mm moulded flap 60-75 % of the hood's width hung from its top edge,
# swinging about 60 degrees either way.
FLAP = dict(share=0.65, thickness=0.003, clearance=0.004, below_top=0.035)
FLAP_SWINGS = math.radians(60)
# Square bins are moulded or folded with rounded upright corners, 3-5 cm radius on household bins (simplehuman
# rectangular step cans, Brabantia and Curver square bins, product pictures, approximate): a share of the smaller
# side, at most ``corner``; their rims are rolled into a bead (``bead`` radius, the steel cans' curled edge or a
# moulded lip) and the lids' edges rounded (``lid_edge``).
ROUND = dict(share=0.14, corner=0.045, bead=0.003, lid_edge=0.005)
# A sensor can's infrared window: a dark strip on the lid's front (simplehuman ST2007 ~6 x 2 cm).
SENSOR = dict(length=0.06, width=0.02, proud=0.002)


@dataclass(frozen=True)
class BinSize:
    """A bin body: ``shape`` ``"round"`` (``width`` the diameter) or ``"square"``, ``width`` (y), ``depth`` (x),
    ``height`` (z) of the walls (the lid and the base ring included in none of them)."""

    shape: str
    width: float
    depth: float
    height: float

    @property
    def half(self) -> tuple[float, float]:
        """Half extents (x, y) of the body's footprint."""
        if self.shape == "round":
            return self.width / 2, self.width / 2
        return self.depth / 2, self.width / 2


def corner(s: BinSize) -> float:
    """A square body's upright corner radius (:data:`ROUND`)."""
    return min(ROUND["share"] * min(s.width, s.depth), ROUND["corner"])


def _outline_slab(hx: float, hy: float, r: float, z0: float, z1: float, edge: float, material: str,
                  cx: float = 0.0) -> g.Piece:
    """A convex slab over a rounded rectangle centred on (``cx``, 0), its top edge rounded ``edge``."""
    edge = min(edge, 0.45 * (z1 - z0))
    rings = [(0.0, z0), (0.0, z1 - edge), (0.3 * edge, z1 - 0.3 * edge), (edge, z1)]
    pts = [np.column_stack([rounded(2 * hy - 2 * d, 2 * hx - 2 * d, max(r - d, 1e-4), 7) + (cx, 0), np.full(28, z)])
           for d, z in rings]
    v, f = g.hull_arrays(np.vstack(pts))
    return g.Piece(v, f, material, [v])


def _square_walls(hx: float, hy: float, r: float, z0: float, top: float, material: str, bead: float
                  ) -> list[g.Piece]:
    """An open square body with rounded corners ``r``: the floor and the walls (drawn as one moulding, a rolled
    bead of radius ``bead`` round the rim; colliding as the floor and four wall boxes)."""
    t = WALL
    boxes = [((-hx, -hy, z0 + t), (-hx + t, hy, top)), ((hx - t, -hy, z0 + t), (hx, hy, top)),
             ((-hx + t, -hy, z0 + t), (hx - t, -hy + t, top)), ((-hx + t, hy - t, z0 + t), (hx - t, hy, top))]
    convex = [g.box_between(lo, hi, material).convex[0] for lo, hi in boxes]
    arc = [(bead * math.cos(a), top - bead + bead * math.sin(a)) for a in np.radians(np.linspace(-90, 90, 7))]
    profile = [(-t, z0), (0.0, z0), *arc, (-t, top)]
    floor = _outline_slab(hx, hy, r, z0, z0 + t, 0.0, material)
    return [floor, rounded_sweep(hx, hy, r, profile, material, convex)]


def _walls(s: BinSize, material: str, z0: float) -> list[g.Piece]:
    """The body's walls and floor from ``z0`` up, open at the top; on the ground (``z0`` = 0) a base ring
    round their foot."""
    hx, hy = s.half
    t, top, out, hb = WALL, z0 + s.height, BASE["out"], BASE["height"]
    if s.shape == "round":
        b = ROUND["bead"]
        bead = [(hx + b * math.cos(a), top - b + b * math.sin(a)) for a in np.radians(np.linspace(-90, 90, 7))]
        pieces = [g.shell([(hx, z0), (hx, top)], t, material), g.cylinder((0, 0, z0), (0, 0, z0 + t), hx - t, material,
                                                                         None),
                  g.shell(bead, b, material).replace(convex=())]  # the rolled rim, drawn
        if not z0:
            pieces.append(g.shell([(hx + out, 0.0), (hx + out, hb)], out, material))
        return pieces
    r = corner(s)
    pieces = _square_walls(hx, hy, r, z0, top, material, ROUND["bead"])
    if not z0:  # the lip round the foot, outside the walls, its top edge chamfered
        boxes = [((-hx - out, -hy - out, 0), (hx + out, -hy, hb)), ((-hx - out, hy, 0), (hx + out, hy + out, hb)),
                 ((-hx - out, -hy, 0), (-hx, hy, hb)), ((hx, -hy, 0), (hx + out, hy, hb))]
        convex = [g.box_between(lo, hi, material).convex[0] for lo, hi in boxes]
        profile = [(0.0, 0.0), (out, 0.0), (out, hb - 0.6 * out), (0.4 * out, hb), (0.0, hb)]
        pieces.append(rounded_sweep(hx, hy, r, profile, material, convex))
    return pieces


def _anchors(s: BinSize, z0: float) -> dict[str, Frame]:
    hx, hy = s.half
    back = -hx - OVERHANG
    return {
        # the lid's hinge line behind the rim: x to the front, z along -y (a positive turn lifts the front)
        "hinge": Frame.at((back, 0, z0 + s.height + KNUCKLE), x=(1, 0, 0), z=(0, -1, 0)),
        # the pedal's pivot under the front of the raised floor: z along +y (a positive turn presses its tread)
        "pedal": Frame.at((hx - PEDAL["inset"], 0, PEDAL["height"]), x=(1, 0, 0), z=(0, 1, 0)),
        "floor": Frame.at((0, 0, z0 + WALL)),
        "rim": Frame.at((0, 0, z0 + s.height)),
    }


def body(s: BinSize, material: str, trim: str, lid: bool, pedal: bool, sheet: float) -> Assembly:
    """An open bin body on its base ring; with ``lid`` a hinge knuckle at the back of the rim; with ``pedal``
    raised on four feet over the pedal's lever, with the pedal's two pivot brackets under its front. Anchors:
    ``hinge``, ``pedal``, ``floor``, ``rim`` (the rim's centre, z up). Supports: the footprint's corners."""
    hx, hy = s.half
    z0 = PEDAL["raised"] if pedal else 0.0
    pieces = [pc.replace(sheet=sheet) for pc in _walls(s, material, z0)]
    a = _anchors(s, z0)
    if lid:
        o = a["hinge"].origin
        pieces.append(g.box_between((o[0], -0.3 * hy, o[2] - KNUCKLE - 0.02), (-hx + 0.001, 0.3 * hy,
                                                                                o[2] - KNUCKLE), trim))
    if pedal:
        o, w = a["pedal"].origin, PEDAL["width"] / 2 + PEDAL["clear"]
        for side in (-1, 1):
            y0, y1 = sorted((side * w, side * (w + 0.01)))
            pieces.append(g.box_between((o[0] - 0.012, y0, o[2] - 0.012), (o[0] + 0.012, y1, z0), trim))
        r = BASE["foot"]
        k = math.sqrt(0.5) if s.shape == "round" else 1.0  # on the diagonals, inside a round footprint
        fx0, fy0 = k * (hx - 2 * r), k * (hy - 2 * r)
        pieces += [g.cylinder((fx * fx0, fy * fy0, 0), (fx * fx0, fy * fy0, z0), r, trim, None)
                   for fx in (-1, 1) for fy in (-1, 1)]
    supports = {f"foot_{i}": (x, y, 0) for i, (x, y) in enumerate(((-hx, -hy), (-hx, hy), (hx, -hy), (hx, hy)))}
    return Assembly.single("body", pieces, a, supports)


def lid(s: BinSize, material: str, trim: str, sheet: float, sensor: str | None = None) -> Assembly:
    """A lid that covers the rim, hinged at its back edge: anchor ``hinge`` (as the body's). With ``sensor`` a
    dark infrared window on its front (a sensor can)."""
    hx, hy = s.half
    hinge = Frame.at((0, 0, 0), x=(1, 0, 0), z=(0, -1, 0))
    cx, z0 = hx + OVERHANG, -KNUCKLE  # the lid's centre from its hinge line; its underside on the rim
    if s.shape == "round":
        r = hx + OVERHANG
        prof = [(0.0, 0.0), (r, 0.0), (r, 0.6 * LID_T), (0.85 * r, LID_T), (0.0, 1.1 * LID_T)]
        pieces = [g.revolve(prof, material, center=(cx, 0, z0)).replace(sheet=sheet)]
        front, top = cx + 0.55 * r, z0 + 1.04 * LID_T  # on the dome, where its profile is 1.03-1.05 LID_T
    else:
        o = OVERHANG
        pieces = [_outline_slab(hx + o, hy + o, corner(s) + o, z0, z0 + LID_T, ROUND["lid_edge"], material, cx)
                  .replace(sheet=sheet)]
        front, top = 2 * cx - 0.03, z0 + LID_T
    pieces.append(g.cylinder((0, -0.28 * hy, 0), (0, 0.28 * hy, 0), 0.6 * KNUCKLE, trim, 12))
    if sensor:
        L, W = SENSOR["length"], SENSOR["width"]
        pieces.append(g.box_between((front - W, -L / 2, top - 0.004), (front, L / 2, top + SENSOR["proud"]), sensor))
    return Assembly.single("lid", pieces, {"hinge": hinge})


def pedal(material: str, lever: str) -> Assembly:
    """A foot pedal: a tread from its pivot (anchor ``pivot``, z along the pivot, x to the front) out past the
    body, and a steel lever in ``lever`` running back from the pivot under the floor."""
    w, reach, t = PEDAL["width"] / 2, PEDAL["reach"], PEDAL["thickness"]
    length, lw, lt = PEDAL["lever"]
    pieces = [g.cylinder((0, -w, 0), (0, w, 0), t / 2, material, 12),
              g.box_between((0.003, -w, -t / 2), (reach, w, t / 2), material, bevel=0.002),
              g.box_between((-length, -lw / 2, -lt / 2), (-t / 2, lw / 2, lt / 2), lever)]
    return Assembly.single("pedal", pieces, {"pivot": Frame.at((0, 0, 0), x=(1, 0, 0), z=(0, 1, 0))})


def bucket_size(s: BinSize) -> BinSize:
    """The inner bucket that fits the body ``s`` with its clearance, :data:`BUCKET` ``share`` of its height."""
    c = 2 * (WALL + BUCKET["clearance"])
    return BinSize(s.shape, s.width - c, s.depth - c, BUCKET["share"] * (s.height - WALL))  # on the floor


def bucket(s: BinSize, material: str, sheet: float) -> Assembly:
    """A lift-out inner bucket of size ``s`` (:func:`bucket_size`) with two bail lugs inside its rim.
    Anchors: ``seat`` (its bottom's underside, z up: it lifts out along it), ``bail`` (the bail's pivot line,
    z along +y, x to the back)."""
    hx, hy = s.half
    t, lug = WALL, BUCKET["lug"]
    if s.shape == "round":
        pieces = [g.shell([(0.97 * hx, 0.0), (hx, s.height)], t, material),
                  g.cylinder((0, 0, 0), (0, 0, t), 0.97 * hx - t, material, None)]
    else:
        # concentric with the body's corners, inside them by its wall and clearance
        inset = WALL + BUCKET["clearance"]
        r = max(corner(BinSize(s.shape, s.width + 2 * inset, s.depth + 2 * inset, s.height)) - inset, 0.005)
        pieces = _square_walls(hx, hy, r, 0.0, s.height, material, 0.0015)
    zb = s.height - lug
    for side in (-1, 1):
        y0, y1 = sorted((side * (hy - t), side * (hy - t - 0.006)))
        pieces.append(g.box_between((-lug / 2, y0, zb - lug / 2), (lug / 2, y1, zb + lug / 2), material))
    bail = Frame.at((0, 0, zb), x=(-1, 0, 0), z=(0, 1, 0))
    pieces = [pc.replace(sheet=sheet) for pc in pieces]
    return Assembly.single("bucket", pieces, {"seat": Frame.at((0, 0, 0)), "bail": bail})


def bail(s: BinSize, material: str) -> Assembly:
    """A wire bail that lies folded over the back half of the bucket ``s`` and turns up about its pivot line
    (anchor ``pivot``: z along +y, x to the back, as the bucket's ``bail``)."""
    hx, hy = s.half
    y = hy - WALL - 0.006 - BUCKET["wire"]  # the bail's ends just inside the lugs
    if s.shape == "round":
        a = np.linspace(0.0, math.pi, 17)
        path = np.column_stack([-0.9 * hx * np.sin(a), y * np.cos(a), np.zeros_like(a)])
    else:
        x = -0.85 * hx
        path = np.array([(0, y, 0), (x, y, 0), (x, -y, 0), (0, -y, 0)])
    pieces = [g.tube(path, BUCKET["wire"], material)]
    return Assembly.single("handle", pieces, {"pivot": Frame.at((0, 0, 0), x=(-1, 0, 0), z=(0, 1, 0))})


def swing_body(s: BinSize, flap_height: float, material: str, sheet: float) -> Assembly:
    """A swing-top bin: a closed square body whose front carries an opening near the top for the flap.
    Anchors: ``flap`` (the opening's top edge, z along -y: a positive turn swings the flap's foot out),
    ``floor``, ``rim``."""
    hx, hy = s.half
    size = CasingSize(s.width, s.depth, s.height, WALL, sheet, 0.02)
    fw = FLAP["share"] * s.width
    top = s.height / 2 - FLAP["below_top"]
    c = FLAP["clearance"]
    cut = Cutout("front", (-fw / 2 - c, top - flap_height - c), (fw / 2 + c, top + c), (0.0, top))
    made = sheet_casing(size, material, {"flap": cut})
    at = made.anchors["flap"].moved(dz=-WALL / 2)  # in the wall's mid-plane: the hung flap balances on it
    anchors = {**made.anchors, "flap": Frame.at(at.origin, x=(1, 0, 0), z=(0, -1, 0)),
               "rim": Frame.at((0, 0, s.height))}
    return Assembly(made.parts, anchors=anchors, supports=made.supports)


def flap(s: BinSize, flap_height: float, material: str, sheet: float) -> Assembly:
    """The swing flap hung from its top edge (anchor ``pivot``, as the body's ``flap``), in the wall's plane: its
    centre of mass under the pivot, so it hangs shut and swings either way."""
    fw, t = FLAP["share"] * s.width / 2, WALL
    pieces = [g.box_between((-t / 2, -fw, -flap_height), (t / 2, fw, 0), material, bevel=0.001).replace(sheet=sheet)]
    return Assembly.single("flap", pieces, {"pivot": Frame.at((0, 0, 0), x=(1, 0, 0), z=(0, -1, 0))})
