"""Buckets: a household pail and a paint can (round, tapered or straight) with a wire bail, a paint can's
press-in lid, and a commercial mop bucket with a down-press wringer and its lever, on casters.

Every body stands centred on the z axis, its front facing +x; a round bucket's bail turns about the y axis
through its two ears. Anchors follow the project's convention: a hinge anchor's z is the joint axis and a
positive turn opens (a bail swings up from where it lies, a wringer lever presses down); a ``lid_seat``
anchor's z is the way a lid lifts off. Sizes are data (:data:`ROUND`, :data:`MOP` and the constants below),
each figure beside the product it is read from.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from . import lids


@dataclass(frozen=True)
class RoundRange:
    """A round bucket's top diameter (m), height as a fraction of it, bottom diameter as a fraction of the top,
    each ``(smallest, largest)``."""

    diameter: tuple[float, float]
    height: tuple[float, float]
    taper: tuple[float, float]


ROUND = {
    # Household pails (plastic 5-15 L, galvanised steel 10-14 L; retailer listings): 5 L 22 cm across the top and
    # 20 cm tall, 10 L ~29 x 26 cm, 14 L galvanised ~32 x 28 cm; the foot 75-85 % of the top.
    "pail": RoundRange(diameter=(0.22, 0.32), height=(0.85, 0.95), taper=(0.75, 0.85)),
    # Paint containers: a US gallon can 16.8 cm x 19 cm (straight tinplate), 2.5 L and 5 L plastic paint pails
    # 17-21 cm across and as tall, 10 L 25-27 cm (a 2-3 % taper to stack).
    "paint": RoundRange(diameter=(0.165, 0.27), height=(0.95, 1.15), taper=(0.93, 1.0)),
}
WALL = 0.003  # m, a bucket wall as the simulator sees it (massed as the finish's sheet, SHEET)
SHEET = {"plastic": 0.0018, "brushed_metal": 0.0004}  # moulded PP pail 1.5-2 mm; tinplate / galvanised 0.25-0.6 mm
BEAD = 0.005  # m, the rolled rim bead's radius past the wall (a pail's stiffening lip, a can's chime)
# Bails (pail and paint-can handles): 3-4 mm galvanised wire in two ears 1.5-2.5 cm under the rim, a 10-12 cm
# plastic grip on it, arching 1.2-1.3 times as high as it is wide; it lies back against the wall at rest and swings
# over to the front.
BAIL = dict(wire=0.0022, below=0.022, out=0.012, ear=0.009, grip=(0.05, 0.01), rise=1.25)
BAIL_REST = math.radians(100)  # from upright: lying down past horizontal over the back
BAIL_TURNS = math.radians(200)  # over the top to the other side
# A paint can's lid: a steel plug 6-8 mm into the rim (gallon can), a plastic pail's snap-on lid ~1 cm; a printed
# label round 60-75 % of the can's height.
LID = dict(plug=0.007, thickness=0.004, lip=0.004, label=(0.12, 0.8), paper=0.0001)


@dataclass(frozen=True)
class Round:
    """A round bucket: ``top`` and ``bottom`` outer radii and ``height`` (m) of its wall."""

    top: float
    bottom: float
    height: float

    @classmethod
    def of(cls, kind: str, diameter: float, height: float, taper: float) -> Round:
        """The size of a ``kind`` bucket from three shares (0-1) of its :data:`ROUND` ranges."""
        r = ROUND[kind]
        d = _lerp(r.diameter, diameter)
        return cls(d / 2, d / 2 * _lerp(r.taper, taper), d * _lerp(r.height, height))

    def radius(self, z: float) -> float:
        return self.bottom + (self.top - self.bottom) * z / self.height


def _lerp(r: tuple[float, float], t: float) -> float:
    return r[0] + t * (r[1] - r[0])


def round_body(s: Round, material: str, sheet: float, label: str | None = None) -> Assembly:
    """A round bucket open at the top with a rolled bead round its rim and two bail ears; with ``label`` a
    printed band round it. Anchors: ``bail`` (the ears' axis, z along +y, x to the back: a positive turn lifts
    a bail lying over the back), ``lid_seat`` (the rim's centre, z up), ``floor``."""
    t, h = WALL, s.height
    pieces = [g.shell([(s.bottom, 0.0), (s.top, h)], t, material).replace(sheet=sheet),
              g.cylinder((0, 0, 0), (0, 0, t), s.bottom - t, material, None).replace(sheet=sheet),
              g.shell([(s.radius(h - 2 * BEAD), h - 2 * BEAD), (s.top + BEAD, h - BEAD), (s.top + 0.2 * BEAD, h)],
                      t, material).replace(sheet=sheet)]  # its inside no further in than the wall's
    zp = h - BAIL["below"]
    r, e = s.radius(zp), BAIL["ear"]
    for side in (-1, 1):
        y0, y1 = sorted((side * (r - t), side * (r + BAIL["out"] - BAIL["wire"] - 0.0015)))
        pieces.append(g.box_between((-e / 2, y0, zp - e), (e / 2, y1, zp + e), material, bevel=0.001))
    if label:
        z0, z1 = (LID["label"][0] * h, LID["label"][1] * h)
        band = g.shell([(s.radius(z0) + 0.0008, z0), (s.radius(z1) + 0.0008, z1)], 0.001, label)
        pieces.append(band.replace(sheet=LID["paper"]))
    anchors = {"bail": Frame.at((0, 0, zp), x=(-1, 0, 0), z=(0, 1, 0)), "lid_seat": Frame.at((0, 0, h)),
               "floor": Frame.at((0, 0, t))}
    supports = {f"foot_{i}": (s.bottom * math.cos(a), s.bottom * math.sin(a), 0)
                for i, a in enumerate((0.0, 2.1, 4.2))}
    return Assembly.single("body", pieces, anchors, supports)


def bail(s: Round, wire: str, grip: str) -> Assembly:
    """A wire bail on the ears of the round bucket ``s`` (anchor ``pivot``: as the body's ``bail``), a
    half circle just outside the rim with a plastic grip at its top, lying :data:`BAIL_REST` over the back."""
    zp = s.height - BAIL["below"]
    rb = s.radius(zp) + BAIL["out"]
    n = 17
    top = BAIL["rise"] * rb  # a bail arches higher than it is wide: its grip clears a lid as it swings over
    arc = [(0.0, rb * math.cos(math.pi * i / (n - 1)), top * math.sin(math.pi * i / (n - 1))) for i in range(n)]
    gl, gr = BAIL["grip"]
    pieces = [g.tube(arc, BAIL["wire"], wire, name="handle"),
              g.cylinder((0, -gl, top), (0, gl, top), gr, grip, name="handle")]
    lying = Frame.at((0, 0, 0)).turned("y", -BAIL_REST)  # upright, turned back over the -x side
    pieces = [pc.transformed(lying.matrix) for pc in pieces]
    return Assembly.single("handle", pieces, {"pivot": Frame.at((0, 0, 0), x=(-1, 0, 0), z=(0, 1, 0))})


def paint_lid(s: Round, material: str, sheet: float) -> Assembly:
    """A paint can's press-in lid: a disc over the rim bead with a plug ring :data:`LID` ``plug`` into the can
    (anchor ``seat``: the underside of its disc on the rim, z up). Grasped at its edge."""
    t, lip, plug = LID["thickness"], LID["lip"], LID["plug"]
    r = s.top + BEAD
    ri = s.top - WALL - 0.001  # the plug ring inside the rim
    pieces = [g.revolve([(0.0, 0.0), (r, 0.0), (r, t), (0.8 * r, t + lip), (0.0, t + 0.6 * lip)], material),
              g.shell([(ri, -plug), (ri, 0.0)], 0.002, material)]
    pieces = [pc.replace(sheet=sheet) for pc in pieces]
    return lids.rimmed(Assembly.single("lid", pieces, {"seat": Frame.at((0, 0, 0)), "top": Frame.at((0, 0, t))}))


def plug_depth() -> float:
    return LID["plug"]


@dataclass(frozen=True)
class MopSize:
    """A mop bucket: ``depth`` (x), ``width`` (y), ``height`` (z) of its tub, standing ``raised`` on casters."""

    depth: float
    width: float
    height: float
    raised: float


# Commercial mop buckets with a down-press wringer (Rubbermaid WaveBrake 26 / 35 qt, Vileda / Numatic kentucky
# buckets, retailer listings): tubs 40-55 cm long, 33-40 cm wide, 30-36 cm deep on four 3 in (76 mm) casters,
# 8-11 kg with the wringer; the wringer a box over the back 40 % of the tub standing ~12 cm proud of the rim,
# its lever's grip ~80-95 cm above the floor, pressed down ~55 degrees and sprung back.
MOP = dict(depth=(0.40, 0.55), width=(0.33, 0.40), height=(0.30, 0.36), wall=0.006, sheet=0.003, bevel=0.012,
           lip=0.008, wringer=(0.4, 0.12, 0.14), wringer_wall=0.006, lever=(0.4, 0.016, 0.14, 0.017),
           lever_rest=math.radians(78), caster=0.038)
LEVER_PRESS = math.radians(55)
PRESS = dict(thickness=0.008, clearance=0.004, squeeze=0.05)  # the press plate; a wrung mop head is ~5 cm thick


def mop_tub(s: MopSize, material: str, wringer: str) -> Assembly:
    """A mop bucket's tub from ``s.raised`` up, its edges rounded, a lip round its rim, and its wringer box over
    the back. Anchors: ``lever`` (the wringer's back top edge, z along +y: a positive turn presses the lever
    forward and down), ``press`` (the press plate's back face at rest, z to the front: the way it squeezes),
    ``tip_0`` ... ``tip_3`` (where the casters go, z up, at the ground), ``floor``."""
    t, b, z0 = MOP["wall"], MOP["bevel"], s.raised
    x0, x1, y0, y1, z1 = -s.depth / 2, s.depth / 2, -s.width / 2, s.width / 2, s.raised + s.height
    pieces = [g.box_between((x0, y0, z0), (x1, y1, z0 + t), material, bevel=b),
              g.box_between((x1 - t, y0, z0), (x1, y1, z1), material, bevel=b),
              g.box_between((x0, y0, z0), (x0 + t, y1, z1), material, bevel=b),
              g.box_between((x0 + t, y1 - t, z0 + t), (x1 - t, y1, z1), material, bevel=b),
              g.box_between((x0 + t, y0, z0 + t), (x1 - t, y0 + t, z1), material, bevel=b)]
    # a rolled lip round the rim, proud of the walls
    lip = MOP["lip"]
    pieces += [g.box_between((x0 - lip, y0 - lip, z1 - 2 * lip), (x1 + lip, y0 + t, z1), material, bevel=lip / 2),
               g.box_between((x0 - lip, y1 - t, z1 - 2 * lip), (x1 + lip, y1 + lip, z1), material, bevel=lip / 2),
               g.box_between((x1 - t, y0 + t, z1 - 2 * lip), (x1 + lip, y1 - t, z1), material, bevel=lip / 2)]
    pieces = [pc.replace(sheet=MOP["sheet"]) for pc in pieces]
    share, above, below = MOP["wringer"]
    w, xw = MOP["wringer_wall"], x0 + share * s.depth
    za, zb = z1 - below, z1 + above
    pieces += [g.box_between((x0 + t, y0 + t, za), (xw, y0 + t + w, zb), wringer, bevel=0.002),
               g.box_between((x0 + t, y1 - t - w, za), (xw, y1 - t, zb), wringer, bevel=0.002),
               g.box_between((xw - w, y0 + t + w, za), (xw, y1 - t - w, zb), wringer, bevel=0.002),
               g.box_between((x0 - 0.01, y0 + t, zb - 0.03), (x0 + t, y1 - t, zb), wringer, bevel=0.002)]
    c = PRESS["clearance"]
    press = Frame.at((x0 + t + c, 0, (za + zb) / 2), z=(1, 0, 0), x=(0, 0, 1))
    k = MOP["caster"] * 1.3  # the casters' footprint in from the corners
    pivot = zb + 0.6 * MOP["lever"][1] + 0.003  # the lever's pivot rod clear over the wringer's back bar
    anchors = {"lever": Frame.at((x0 - 0.01, 0, pivot), x=(-1, 0, 0), z=(0, 1, 0)),
               "floor": Frame.at((0, 0, z0 + t)), "press": press}
    for i, (x, y) in enumerate(((x0 + k, y0 + k), (x0 + k, y1 - k), (x1 - k, y0 + k), (x1 - k, y1 - k))):
        anchors[f"tip_{i}"] = Frame.at((x, y, 0))
    return Assembly.single("body", pieces, anchors)


def mop_lever(s: MopSize, material: str, grip: str) -> Assembly:
    """The wringer's lever: two side arms from its pivot (anchor ``pivot``: as the tub's ``lever``) rising back
    at :data:`MOP` ``lever_rest`` over the horizontal to a grip bar across."""
    length, arm, grip_len, grip_r = MOP["lever"]
    half = s.width / 2 - MOP["wall"] - MOP["wringer_wall"] - arm
    pieces = [g.box_between((0, -half - arm / 2, -arm / 2), (length, -half + arm / 2, arm / 2), material, bevel=0.003),
              g.box_between((0, half - arm / 2, -arm / 2), (length, half + arm / 2, arm / 2), material, bevel=0.003),
              g.cylinder((0, -half, 0), (0, half, 0), 0.6 * arm, material, 12),
              g.cylinder((length, -half - arm / 2, 0), (length, half + arm / 2, 0), 0.7 * grip_r, material, 16),
              g.cylinder((length, -grip_len / 2, 0), (length, grip_len / 2, 0), grip_r, grip, 16, name="handle")]
    up = Frame.at((0, 0, 0)).turned("y", -(math.pi - MOP["lever_rest"]))  # from +x round over the top to the back
    pieces = [pc.transformed(up.matrix) for pc in pieces]
    return Assembly.single("lever", pieces, {"pivot": Frame.at((0, 0, 0), x=(-1, 0, 0), z=(0, 1, 0))})


def press_plate(s: MopSize, material: str) -> Assembly:
    """The wringer's press plate, across the wringer box at its back (anchor ``slide``: its back face's centre, z to
    the front, as the tub's ``press``): the lever drives it forward against the box's front wall."""
    share, above, below = MOP["wringer"]
    c, th = PRESS["clearance"], PRESS["thickness"]
    half = s.width / 2 - MOP["wall"] - MOP["wringer_wall"] - c
    h = (above + below) / 2 - 2 * c
    piece = g.box_between((0, -half, -h), (th, half, h), material, bevel=0.002)
    return Assembly.single("press", [piece], {"slide": Frame.at((0, 0, 0), z=(1, 0, 0), x=(0, 0, 1))})


def press_travel(s: MopSize) -> float:
    """m, how far the press plate goes: to a wrung mop head's thickness from the wringer's front wall."""
    share = MOP["wringer"][0]
    return share * s.depth - MOP["wall"] - MOP["wringer_wall"] - 2 * PRESS["clearance"] - PRESS["thickness"] \
        - PRESS["squeeze"]
