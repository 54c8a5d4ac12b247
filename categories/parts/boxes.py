"""Boxes: a board chest and its hasp, a corrugated shipping box and its flaps, a jewellery box with a drawer
and a lift-out tray, a shoe box and its lift-off lid.

Every body stands on z = 0 centred on the z axis, its front facing +x, its long side along y. Anchors follow the
project's convention: a hinge anchor's z is the joint axis and a positive turn opens; a ``seat`` or ``lid_seat``
anchor's z is the way a part lifts off; a slide anchor's z the way a drawer pulls out. Sizes are data
(:data:`SIZES` and the constants below), each figure beside the product it is read from.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from . import hardware, lids, panels


@dataclass(frozen=True)
class Range:
    """A design's outer width (y, m), depth (x) and wall height (z) as fractions of its width, and its board
    thickness (m), each ``(smallest, largest)``."""

    width: tuple[float, float]
    depth: tuple[float, float]
    height: tuple[float, float]
    board: tuple[float, float]


SIZES = {
    # Wooden chests: keepsake boxes with a hasp 30 x 20 x 15 cm (craft-shop pine boxes), toy and blanket chests
    # 76-100 x 40-50 x 40-50 cm (IKEA, Lane cedar chest 100 x 46 x 48 cm) in 9-18 mm boards.
    "chest": Range(width=(0.30, 0.95), depth=(0.5, 0.66), height=(0.45, 0.62), board=(0.009, 0.018)),
    # Regular slotted shipping and moving boxes (FEFCO 0201): 30 x 20 x 15 cm mailers to 46 x 46 x 41 cm
    # moving boxes (U-Haul small 41 x 32 x 32 cm, medium 46 x 46 x 41 cm), single-wall C-flute ~4 mm.
    "carton": Range(width=(0.28, 0.60), depth=(0.55, 0.8), height=(0.5, 0.9), board=(0.0035, 0.0045)),
    # Wooden jewellery boxes with a drawer and a lift-out tray: 22-34 cm wide, 14-24 cm deep, 10-17 cm high
    # (retail listings of two-tier boxes, e.g. 25 x 17 x 12 cm), 7-10 mm boards.
    "jewellery": Range(width=(0.22, 0.34), depth=(0.6, 0.72), height=(0.42, 0.52), board=(0.007, 0.010)),
    # Shoe boxes: 28 x 18 x 10 cm (children's) to 36 x 24 x 13 cm (men's US 12, trainers), folding boxboard
    # 1.5-2 mm (printed, E-flute 1.5 mm).
    "shoe_box": Range(width=(0.28, 0.36), depth=(0.6, 0.68), height=(0.34, 0.40), board=(0.0015, 0.002)),
}

KNUCKLE = dict(radius=0.005, share=0.18)  # butt hinges at the back: 10 mm barrels, each 18 % of the width
LID = dict(overhang=0.006, share=1.3)  # a lid 6 mm proud of the walls, 1.3 boards thick (a framed top)
LID_OPENS = math.radians(105)  # a chest or jewellery-box lid on its hinges' stop or a lid stay: 95-110 degrees
# Hasp and staple (3 in / 75 mm hasps: a 2-3 mm plate 25-30 mm wide with a slot over a wire staple): plate
# (length, width, thickness), slot (across, tall), the staple's wire radius, the knuckle radius. Scaled down
# with the chest (a keepsake box carries a 40 mm hasp).
HASP = dict(length=0.075, width=0.028, thickness=0.002, slot=(0.016, 0.009), wire=0.0018, knuckle=0.0035)
HASP_TURNS = math.radians(170)  # a hasp swings up over its knuckle until it meets the lid
# Chest drop handles (cast or pressed steel, hardware store listings): a 100-140 mm bail of 6-8 mm rod hanging
# 45-60 mm from two lugs on a back plate, swinging up past horizontal; at 75 % of the wall height. Scaled as
# the hasp.
DROP = dict(length=0.13, drop=0.05, rod=0.0035, plate=(0.16, 0.03, 0.003), lug=0.006, at=0.72)
DROP_TURNS = math.radians(110)
FLAP_OPENS = math.radians(270)  # a creased flap folds right back against its wall
FLAP_CLEARANCE = 0.0015  # m, a minor flap's ends clear of the major walls it folds in between
# Jewellery box: one drawer takes the lower 40 % of the walls (two, one over the other, 54 %), the tray the top
# 42 % of the well above it (tray 25-40 mm deep on two ledges); a 12 mm knob; the drawer pulls out 80 % of its depth.
JEWEL = dict(drawer=(0.4, 0.54), tray=0.42, clearance=0.0015, ledge=0.006, lining=0.002, knob=(0.007, 0.014), pull=0.8)
# A shoe box lid: a 30-50 mm skirt over the base, 1.5 mm clear of it all round (Nike, Adidas boxes).
SHOE_LID = dict(skirt=0.38, clearance=0.0015)


@dataclass(frozen=True)
class BoxSize:
    """A box body: outer ``width`` (y), ``depth`` (x), wall ``height`` (z), ``board`` thickness."""

    width: float
    depth: float
    height: float
    board: float

    @classmethod
    def of(cls, design: str, width: float, depth: float, height: float) -> BoxSize:
        """The size of a ``design`` box from three shares (0-1) of its :data:`SIZES` ranges; the board
        thickens with the width."""
        r = SIZES[design]
        w = _lerp(r.width, width)
        return cls(w, w * _lerp(r.depth, depth), w * _lerp(r.height, height), _lerp(r.board, width))


def _lerp(r: tuple[float, float], t: float) -> float:
    return r[0] + t * (r[1] - r[0])


def _walls(s: BoxSize, material: str, tops: tuple[float, float] | None = None, bevel: float = 0.0,
           front_from: float = 0.0) -> list[g.Piece]:
    """Bottom and four walls; ``tops`` the heights of the front/back and the side walls (default both the
    height); the front wall from ``front_from`` up (an opening for a drawer below it)."""
    x0, x1, y0, y1, t = -s.depth / 2, s.depth / 2, -s.width / 2, s.width / 2, s.board
    hl, hs = tops or (s.height, s.height)
    return [g.box_between((x0, y0, 0), (x1, y1, t), material, bevel=bevel),
            g.box_between((x0, y0, 0), (x0 + t, y1, hl), material, bevel=bevel),
            g.box_between((x1 - t, y0, front_from), (x1, y1, hl), material, bevel=bevel),
            g.box_between((x0 + t, y0, t), (x1 - t, y0 + t, hs), material, bevel=bevel),
            g.box_between((x0 + t, y1 - t, t), (x1 - t, y1, hs), material, bevel=bevel)]


def _back_hinges(s: BoxSize, metal: str) -> list[g.Piece]:
    """Two hinge barrels on the back wall's top edge, a quarter of the width in from each side."""
    r, half, x = KNUCKLE["radius"], KNUCKLE["share"] * s.width / 2, -s.depth / 2 - KNUCKLE["radius"]
    z = s.height - r - 0.001  # under the rim: clear of the lid turning about the rim's back edge
    return [g.cylinder((x, c - half, z), (x, c + half, z), r, metal, 12)
            for c in (-s.width / 4, s.width / 4)]


def _rim_anchors(s: BoxSize) -> dict[str, Frame]:
    return {"hinge": Frame.at((-s.depth / 2, 0, s.height), x=(1, 0, 0), z=(0, -1, 0)),
            "floor": Frame.at((0, 0, s.board)), "lid_seat": Frame.at((0, 0, s.height))}


def _supports(s: BoxSize) -> dict:
    x0, y0 = s.depth / 2, s.width / 2
    return {f"foot_{i}": (x, y, 0) for i, (x, y) in enumerate(((-x0, -y0), (-x0, y0), (x0, -y0), (x0, y0)))}


def hasp_scale(s: BoxSize) -> float:
    """A hasp's size relative to :data:`HASP`: a 34 mm clasp on a jewellery box, 75 mm from a 60 cm chest on."""
    return min(1.0, max(0.45, s.width / 0.6))


def chest(s: BoxSize, material: str, metal: str) -> Assembly:
    """A board chest open at the top: bevelled boards, a plinth round its foot, two hinge barrels at the back
    and a wire staple on the front under the hasp. Anchors: ``hinge`` (the back rim, as
    :func:`.panels.open_box`'s ``rim_back``), ``floor``, ``lid_seat``."""
    t, k = s.board, hasp_scale(s)
    pieces = _walls(s, material, bevel=0.2 * t)
    x0, x1, y0, y1, hp = -s.depth / 2, s.depth / 2, -s.width / 2, s.width / 2, 0.12 * s.height
    o = 0.3 * t  # the plinth stands proud of the walls
    pieces += [g.box_between((x0 - o, y0 - o, 0), (x0 + t, y1 + o, hp), material, bevel=0.5 * o),
               g.box_between((x1 - t, y0 - o, 0), (x1 + o, y1 + o, hp), material, bevel=0.5 * o),
               g.box_between((x0 + t, y0 - o, 0), (x1 - t, y0 + t, hp), material, bevel=0.5 * o),
               g.box_between((x0 + t, y1 - t, 0), (x1 - t, y1 + o, hp), material, bevel=0.5 * o)]
    pieces += _back_hinges(s, metal)
    # the staple: a wire loop out of the front, through the hasp's slot (its centre ``hasp_drop`` below the rim)
    zc, reach = s.height - hasp_drop(s), hasp_reach(s) + k * (HASP["thickness"] / 2 + 0.003)
    a, w = k * HASP["slot"][0] / 2 - 0.003, k * HASP["wire"]
    pieces.append(g.tube([(x1 - 0.002, -a, zc), (x1 + reach, -a, zc), (x1 + reach, a, zc), (x1 - 0.002, a, zc)],
                         w, metal))
    anchors = _rim_anchors(s)
    for side, y in (("left", y1), ("right", y0)):
        face = Frame.at((0, y, DROP["at"] * s.height), z=(0, math.copysign(1, y), 0), x=(math.copysign(1, y), 0, 0))
        pieces += drop_plate(k, metal, face)
        anchors[f"handle_{side}"] = face.moved(dz=DROP["plate"][2] + DROP["lug"] * k)
    return Assembly.single("body", pieces, anchors, _supports(s))


def drop_plate(k: float, metal: str, face: Frame) -> list[g.Piece]:
    """A drop handle's back plate with its two lugs on a face (``face``: z out of it, x along the pivot, y down),
    :data:`DROP` scaled by ``k``."""
    (pl, pw, pt), lug, a = (k * v for v in DROP["plate"]), k * DROP["lug"], k * DROP["length"] / 2
    pieces = [g.box_between((-pl / 2, -pw / 2, 0), (pl / 2, pw / 2, pt), metal, bevel=0.3 * pt)]
    pieces += [g.box_between((x - lug / 2, -lug / 2, pt), (x + lug / 2, lug / 2, pt + 2 * lug), metal, bevel=0.001)
               for x in (-a - lug, a + lug)]
    return [pc.transformed(face.matrix) for pc in pieces]


def drop_handle(k: float, metal: str) -> Assembly:
    """A drop handle's bail hanging from its pivot line (anchor ``pivot``: the line between the lugs, z along
    it; the bail hangs along local y, clear of the face behind it along -z): a positive turn swings it up
    and out."""
    a, drop, rod = k * DROP["length"] / 2, k * DROP["drop"], k * DROP["rod"]
    n = 9
    arc = [(a * math.cos(math.pi * i / (n - 1)), drop - 0.35 * drop * (1 - math.sin(math.pi * i / (n - 1))), 0)
           for i in range(n)]
    path = [(a + 0.5 * k * DROP["lug"], 0, 0), (a, 0.15 * drop, 0), *arc[1:-1], (-a, 0.15 * drop, 0),
            (-a - 0.5 * k * DROP["lug"], 0, 0)]
    piece = g.tube(path, rod, metal, name="handle")
    return Assembly.single("handle", [piece], {"pivot": Frame.at((0, 0, 0), x=(0, 1, 0), z=(1, 0, 0)),
                                               "mount": Frame.at((0, 0, 0))})


def hasp_drop(s: BoxSize) -> float:
    """m, from the rim down to the staple (the hasp's slot centre)."""
    k = hasp_scale(s)
    return k * (HASP["length"] - HASP["slot"][1] / 2 - 0.004) - lid_thickness(s) / 2 + _below(s)


def _below(s: BoxSize) -> float:
    """m, the hasp's knuckle axis below the lid's mid-plane: the knuckle clear of the leaf above it."""
    return hasp_scale(s) * HASP["knuckle"] + 0.001


def hasp_reach(s: BoxSize) -> float:
    """m, from the chest's front to the hasp plate's mid-plane."""
    return LID["overhang"] + hasp_scale(s) * HASP["knuckle"]


def lid_thickness(s: BoxSize) -> float:
    return LID["share"] * s.board


def board_lid(s: BoxSize, material: str, metal: str, hasp: bool, mirror: str | None = None,
              lining: str | None = None) -> Assembly:
    """A lid board over the rim, proud of the walls by :data:`LID` ``overhang`` at the front and sides, hinged
    at its back edge (anchor ``hinge``, as the body's); with ``hasp`` the hasp's fixed leaf on its front and an
    anchor ``hasp`` on the knuckle's axis (z along -y: a positive turn swings the hasp's foot out); with
    ``mirror`` a mirror plate under it (a jewellery box), framed by a ``lining``."""
    t, o, lt = s.board, LID["overhang"], lid_thickness(s)
    w = s.width / 2 + o
    pieces = [g.box_between((0, -w, 0), (s.depth + o, w, lt), material, bevel=0.3 * t)]
    anchors = {"hinge": Frame.at((0, 0, 0), x=(1, 0, 0), z=(0, -1, 0))}
    if hasp:
        k = hasp_scale(s)
        r, hw = k * HASP["knuckle"], k * HASP["width"] / 2
        xf = s.depth + o
        pieces.append(g.box_between((xf, -hw, lt / 2 + 0.001), (xf + k * HASP["thickness"], hw, 0.92 * lt), metal))
        anchors["hasp"] = Frame.at((xf + r, 0, lt / 2 - _below(s)), x=(1, 0, 0), z=(0, -1, 0))
    if mirror:
        m = 1.2 * t  # inset inside the walls
        pieces.append(g.box_between((m, -s.width / 2 + m, -0.0015), (s.depth - m, s.width / 2 - m, 0), mirror))
        if lining:
            pieces.append(g.box_between((t + 0.002, -s.width / 2 + t + 0.002, -0.001),
                                        (s.depth - t - 0.002, s.width / 2 - t - 0.002, 0), lining))
    return Assembly.single("lid", pieces, anchors)


def hasp_plate(s: BoxSize, metal: str) -> Assembly:
    """A hasp hanging from its knuckle (anchor ``pivot``: z along -y, x out of the chest's front): a plate with
    a slot at its foot for the staple."""
    k = hasp_scale(s)
    r, hw, ht = k * HASP["knuckle"], k * HASP["width"] / 2, k * HASP["thickness"] / 2
    length, (sw, sh) = k * HASP["length"], (k * HASP["slot"][0] / 2, k * HASP["slot"][1])
    zc = -(k * (HASP["length"] - HASP["slot"][1] / 2 - 0.004))  # the slot's centre below the pivot
    # local frame: x out of the chest, y up (z along -y)
    top, s0, s1 = -r, zc + sh / 2, zc - sh / 2
    pieces = [g.cylinder((0, 0, -hw), (0, 0, hw), r, metal, 12),
              g.box_between((-ht, s0, -hw), (ht, top, hw), metal),
              g.box_between((-ht, s1, -hw), (ht, s0, -sw), metal),
              g.box_between((-ht, s1, sw), (ht, s0, hw), metal),
              g.box_between((-ht, -length, -hw), (ht, s1, hw), metal, bevel=0.3 * ht)]
    return Assembly.single("latch", pieces, {"pivot": Frame.at((0, 0, 0), x=(1, 0, 0), z=(0, 0, 1))})


def carton(s: BoxSize, material: str) -> Assembly:
    """A slotted carton open at the top. Anchors: ``flap_front`` / ``flap_back`` / ``flap_left`` /
    ``flap_right`` (each wall's top outer edge, x inwards, z along it so that a positive turn lifts the flap up
    and out), ``floor``."""
    pieces = _walls(s, material, bevel=0.3 * s.board)
    x1, y1, h = s.depth / 2, s.width / 2, s.height
    anchors = {"flap_front": Frame.at((x1, 0, h), x=(-1, 0, 0), z=(0, 1, 0)),
               "flap_back": Frame.at((-x1, 0, h), x=(1, 0, 0), z=(0, -1, 0)),
               "flap_left": Frame.at((0, y1, h), x=(0, -1, 0), z=(-1, 0, 0)),
               "flap_right": Frame.at((0, -y1, h), x=(0, 1, 0), z=(1, 0, 0)),
               "floor": Frame.at((0, 0, s.board))}
    return Assembly.single("body", pieces, anchors, _supports(s))


def flap_size(s: BoxSize, side: str, four: bool) -> tuple[float, float]:
    """A carton flap's length along its crease and its reach from it. Two flaps: the front and back flaps
    span the whole length and meet in the middle. Four flaps: the end flaps reach half the depth in from the
    ends, and the front and back flaps take the length between them, so the four close edge to edge in one
    layer (none lies under another: each opens on its own)."""
    c = FLAP_CLEARANCE
    if side in ("left", "right"):
        return s.depth - 2 * c, s.depth / 2 - c
    return (s.width - s.depth - 2 * c if four else s.width - 2 * c), s.depth / 2 - c


def flap(length: float, reach: float, board: float, material: str) -> Assembly:
    """A carton flap ``length`` along its crease and ``reach`` from it, lying flat (anchor ``crease``: x from the
    crease across the flap, z along the crease, as the carton's flap anchors)."""
    piece = g.box_between((0, -length / 2, 0), (reach, length / 2, board), material, bevel=0.3 * board)
    return Assembly.single("flap", [piece], {"crease": Frame.at((0, 0, 0), x=(1, 0, 0), z=(0, -1, 0))})


def bay(s: BoxSize, drawers: int) -> float:
    """m, the top of a jewellery box's drawer bay (:data:`JEWEL` ``drawer``, by the number of drawers)."""
    return JEWEL["drawer"][drawers - 1] * s.height


def slot_height(s: BoxSize, drawers: int) -> float:
    """m, the opening of each of ``drawers`` drawers, one over the other with a board between."""
    return (bay(s, drawers) - drawers * s.board) / drawers


def jewellery_box(s: BoxSize, material: str, metal: str, lining: str, drawers: int = 1) -> Assembly:
    """A jewellery box: a bay of one or two ``drawers`` in the lower :data:`JEWEL` ``drawer`` share of the walls
    (open at the front), a lined well above it with a ledge on each side for the tray, hinge barrels at the back.
    Anchors: ``hinge``, ``drawer_0``, ``drawer_1`` ... (each opening's front centre, z out of it, from the
    bottom), ``tray_seat`` (the tray's bottom on the ledges, z up), ``floor``, ``lid_seat``."""
    t, c = s.board, JEWEL["clearance"]
    x0, x1, y0, y1 = -s.depth / 2, s.depth / 2, -s.width / 2, s.width / 2
    zb = bay(s, drawers)  # the bay's top: the well's floor board sits on it
    pieces = _walls(s, material, bevel=0.2 * t, front_from=zb)
    hs = slot_height(s, drawers)
    pieces += [g.box_between((x0 + t, y0 + t, t + k * (hs + t) + hs), (x1, y1 - t, (k + 1) * (hs + t) + t), material)
               for k in range(drawers - 1)]  # the boards between the drawers
    pieces.append(g.box_between((x0 + t, y0 + t, zb), (x1, y1 - t, zb + t), material))  # the well's floor
    pieces.append(g.box_between((x0 + t, y0 + t, zb + t), (x1 - t, y1 - t, zb + t + JEWEL["lining"]), lining))
    zl = s.height - tray_height(s, drawers) - c - 0.002  # the ledges' top: the tray stands 2 mm below the rim
    led = JEWEL["ledge"]
    for side in (-1, 1):
        ya, yb = sorted((side * (s.width / 2 - t), side * (s.width / 2 - t - led)))
        pieces.append(g.box_between((x0 + t, ya, zl - led), (x1 - t, yb, zl), material))
    pieces += _back_hinges(s, metal)
    anchors = {**_rim_anchors(s), "tray_seat": Frame.at((0, 0, zl + c))}
    for k in range(drawers):
        anchors[f"drawer_{k}"] = Frame.at((x1, 0, t + k * (hs + t) + hs / 2), z=(1, 0, 0), x=(0, 0, 1))
    return Assembly.single("body", pieces, anchors, _supports(s))


def jewellery_drawer(s: BoxSize, material: str, metal: str, lining: str, drawers: int = 1) -> Assembly:
    """The drawer of :func:`jewellery_box`'s bay, lined, with a knob on its front (anchor ``slide``: the
    front's centre, z out of it)."""
    t, c = s.board, JEWEL["clearance"]
    h = slot_height(s, drawers) - 2 * c
    w, d = s.width - 2 * t - 2 * c, s.depth - 2 * t - c
    made = panels.drawer_box(w, h, d, t, 0.6 * t, material)
    pieces = [*made.pieces, g.box_between((-d + 0.6 * t, -w / 2 + 0.6 * t, -h / 2 + 0.008),
                                          (-t, w / 2 - 0.6 * t, -h / 2 + 0.008 + JEWEL["lining"]), lining)]
    pieces += hardware.on_face(hardware.knob_handle(*JEWEL["knob"], metal), (0, 0, 0))
    return Assembly.single("drawer", pieces, {"slide": made.anchor("slide")})


def jewellery_tray(s: BoxSize, material: str, lining: str, drawers: int = 1) -> Assembly:
    """A lift-out tray for the well of :func:`jewellery_box`, lined, with two cross dividers making three
    compartments (anchor ``seat``: its bottom's centre, z up)."""
    t, c = s.board, JEWEL["clearance"]
    h = tray_height(s, drawers)
    w, d, wt = s.width - 2 * t - 2 * c, s.depth - 2 * t - 2 * c, 0.6 * t
    x0, x1, y0, y1 = -d / 2, d / 2, -w / 2, w / 2
    pieces = [g.box_between((x0, y0, 0), (x1, y1, wt), material),
              g.box_between((x0, y0, wt), (x0 + wt, y1, h), material, bevel=0.2 * wt),
              g.box_between((x1 - wt, y0, wt), (x1, y1, h), material, bevel=0.2 * wt),
              g.box_between((x0 + wt, y0, wt), (x1 - wt, y0 + wt, h), material, bevel=0.2 * wt),
              g.box_between((x0 + wt, y1 - wt, wt), (x1 - wt, y1, h), material, bevel=0.2 * wt),
              g.box_between((x0 + wt, y0 + wt, wt), (x1 - wt, y1 - wt, wt + JEWEL["lining"]), lining)]
    for y in (-w / 6, w / 6):
        pieces.append(g.box_between((x0 + wt, y - wt / 2, wt), (x1 - wt, y + wt / 2, 0.8 * h), material))
    return Assembly.single("tray", pieces, {"seat": Frame.at((0, 0, 0))})


def tray_height(s: BoxSize, drawers: int = 1) -> float:
    """m, a jewellery box's tray: :data:`JEWEL` ``tray`` of the well above the drawer bay."""
    return JEWEL["tray"] * (s.height - bay(s, drawers) - s.board)


def shoe_box(s: BoxSize, material: str) -> Assembly:
    """A shoe box's base: thin board walls open at the top (anchors ``lid_seat``: the rim's centre, z up;
    ``hinge``: the back rim, for a one-piece box's lid; ``floor``)."""
    pieces = _walls(s, material, bevel=0.4 * s.board)
    return Assembly.single("body", pieces, _rim_anchors(s), _supports(s))


def shoe_lid(s: BoxSize, material: str, hinged: bool = False) -> Assembly:
    """A shoe box's lid: a top over the base's rim and a skirt :data:`SHOE_LID` ``skirt`` of the base's height
    down round it (anchor ``seat``: the top's underside centre, z up). Grasped at its edge. ``hinged``: a
    one-piece box's lid, creased to the base's back wall (no back skirt; anchor ``hinge`` on the crease, as the
    base's)."""
    t, c = s.board, SHOE_LID["clearance"]
    hx, hy, skirt = s.depth / 2 + c + t, s.width / 2 + c + t, SHOE_LID["skirt"] * s.height
    xb = -s.depth / 2 if hinged else -hx
    b = 0.4 * t
    pieces = [g.box_between((xb, -hy, 0), (hx, hy, t), material, bevel=b),
              g.box_between((hx - t, -hy, -skirt), (hx, hy, 0), material, bevel=b),
              g.box_between((xb + t, -hy, -skirt), (hx - t, -hy + t, 0), material, bevel=b),
              g.box_between((xb + t, hy - t, -skirt), (hx - t, hy, 0), material, bevel=b)]
    anchors = {"seat": Frame.at((0, 0, 0)), "top": Frame.at((0, 0, t))}
    if hinged:
        anchors["hinge"] = Frame.at((xb, 0, 0), x=(1, 0, 0), z=(0, -1, 0))
    else:
        pieces.append(g.box_between((-hx, -hy, -skirt), (-hx + t, hy, 0), material, bevel=b))
    return lids.rimmed(Assembly.single("lid", pieces, anchors))


def skirt(s: BoxSize) -> float:
    """m, how far a shoe box lid's skirt runs down the base: its seat's engagement."""
    return SHOE_LID["skirt"] * s.height
