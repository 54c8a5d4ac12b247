"""Storage rack: a steel pallet rack / shelving unit with adjustable levels and optional goods.

X is depth (the front faces +X), Y is width, Z is up. Frames of two uprights (front and back,
joined by horizontal and diagonal bracing) stand at both ends, and between bays when the rack
is wide: 4 or 6 uprights with decorative perforations and foot plates. Each level of each bay is
a pair of beams (front and back) with a deck on them (wire mesh, steel panel or wooden board).

The bottom level is fixed; every other level is adjustable: a vertical slide along +Z through
the uprights. It rests a few millimetres above a stop bracket on each upright (the joint's lower
limit, where gravity holds it: PhysX cannot hold a vertical slide anywhere else) and rises by
``a`` = min(level spacing / 3, the free height above its goods): the same ``a`` for every level,
so with all levels raised together nothing closes up, and a level raised alone never reaches the
level above, its brackets or their goods.

Goods (cardboard boxes, plastic crates or pallets with stacked boxes) stand on a level, each
fixed to it (a ``fixed`` joint), inside the bay and clear of the uprights.
"""

from __future__ import annotations

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Int, Schema

GROWTH = Growth(
    storage_rack=Rule(required=("frames", "levels"), optional={"goods": 0.75}),
    frame=Rule(required=("uprights", "bracing", "foot_plates")),
    level=Rule(required=("beams", "deck", "stop_brackets"), one_of={"wire": 0.45, "steel": 0.3, "wood": 0.25}),
    goods=Rule(one_of={"boxes": 0.4, "pallet": 0.35, "crates": 0.25}),
)
"""``level.one_of`` is the object-wide ``deck``; ``goods.one_of`` is drawn per level (structure
stream), and each level holds goods with chance ``goods_chance``."""

_DECKS = GROWTH.rules["level"].one_of

SCHEMA = Schema((
    Float("width", "overall width (Y)", "m", 1.5, 3.0),
    Float("depth", "overall depth (X)", "m", 0.6, 1.2),
    Float("level_height", "spacing between levels (beam top to beam top)", "m", 0.4, 1.8),
    Int("level_count", "levels of beams", "", 3, 5),
    Float("bottom_height", "top of the lowest (fixed) level above the floor", "m", 0.08, 0.3),
    Int("bay_count", "bays side by side; auto = 1 up to 2.2 m width, else 2", "", 1, 2, auto=True),
    Float("upright_size", "upright section (X and Y)", "m", 0.06, 0.1),
    Float("beam_height", "beam height", "m", 0.06, 0.14),
    Choice("deck", "shelf deck", choices=tuple(_DECKS), weights=tuple(_DECKS.values())),
    Float("goods_chance", "chance that a level holds goods", "", 0.5, 1.0),
    Float("goods_fill", "goods height as a fraction of the clear height of a level", "", 0.35, 0.7),
    Choice("frame_finish", "upright and beam finish", choices=("enamel", "brushed_metal"),
           weights=(0.7, 0.3)),
    *GROWTH.flags(),
))

MATERIALS = {
    "upright": "enamel:cobalt|green|black|white", "beam": "enamel:red|cobalt|black|white",
    "galvanised": "brushed_metal", "holes": "rubber:deep_black", "deck_wire": "chrome",
    "deck_steel": "brushed_metal", "deck_wood": "wood:birch|maple|oak", "feet": "brushed_metal",
    "box": "painted:off_white|pastel_yellow|light_grey", "crate": "plastic:blue|red|yellow|green|dark_grey",
    "pallet": "wood:birch|maple|oak|teak", "tape": "painted:off_white|light_grey",
}

GAP = 0.005  # level <-> uprights and stop brackets
DECK_T = {"wire": 0.03, "steel": 0.03, "wood": 0.018}  # deck thickness on the beams
BEAM_D = 0.05  # beam depth (X)
BRACKET_H = 0.03
SIDE = 0.03  # goods keep this far from the uprights


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    W, D, lh, n = p["width"], p["depth"], p["level_height"], p["level_count"]
    u, bh, deck = p["upright_size"], p["beam_height"], p["deck"]
    metal = p["frame_finish"] == "enamel"
    bp = Blueprint("storage_rack", materials=dict(MATERIALS))
    up_slot, beam_slot = ("upright", "beam") if metal else ("galvanised", "galvanised")
    bays = p["bay_count"] or (1 if W <= 2.2 else 2)
    dt = DECK_T[deck]

    # --- levels: heights, goods heights and the common travel --------------------------------------
    zs = [p["bottom_height"] + i * lh for i in range(n)]  # beam tops at rest
    clear = lh - bh - dt  # from a deck top to the beams above
    goods_h = p["goods_fill"] * clear
    # raised alone, a level (and its goods) stays below the level above and its stop brackets
    travel = min(lh / 3, clear - goods_h - 0.02, lh - bh - dt - GAP - BRACKET_H - 0.02)
    top = zs[-1] + travel + 0.06  # uprights reach above the highest raised level

    # --- frames ---------------------------------------------------------------------------------
    ys = np.linspace(-W / 2 + u / 2, W / 2 - u / 2, bays + 1)
    frame = []
    for yk in ys:
        frame += _frame(yk, D, u, top, up_slot)
    # stop brackets under every adjustable level's beam ends
    for yk in ys:
        for i in range(1, n):
            zb = zs[i] - bh - GAP
            for x0, x1 in ((D / 2 - BEAM_D, D / 2), (-D / 2, -D / 2 + BEAM_D)):
                for ya, yb in ((yk + u / 2, yk + u / 2 + 0.012), (yk - u / 2 - 0.012, yk - u / 2)):
                    if -W / 2 < ya and yb < W / 2:
                        frame.append(g.box_between([x0 + 0.01, ya, zb - BRACKET_H], [x1 - 0.01, yb, zb],
                                                   "galvanised"))
    body = bp.add("frame", "frame", frame)

    # --- levels ------------------------------------------------------------------------------------
    for b in range(bays):
        ya, yb = ys[b] + u / 2 + GAP, ys[b + 1] - u / 2 - GAP
        for i, z in enumerate(zs):
            name = f"level_{b}_{i}"
            bp.add(name, "shelf", _level((ya, yb), D, z, bh, dt, deck, beam_slot))
            if i == 0:
                bp.join(J.fixed(body, name))
            else:
                bp.join(J.prismatic(body, name, (0.0, (ya + yb) / 2, z - bh), (0, 0, 1), 0.0, travel,
                                    role="slide"))
            if p["has_goods"] and structure.random() < p["goods_chance"]:
                kind = GROWTH.choose("goods", structure)
                _goods(bp, name, kind, (ya + SIDE, yb - SIDE), D, z + dt, goods_h, geometry)
    return bp


def _frame(yk, D, u, top, slot):
    """Two uprights (front, back) at ``y = yk``, bracing between them, foot plates, perforations."""
    pieces = []
    for x0, x1 in ((D / 2 - u, D / 2), (-D / 2, -D / 2 + u)):
        post = g.box_between([x0, yk - u / 2, 0.008], [x1, yk + u / 2, top], slot)
        pieces.append(post.replace(sheet=0.002))
        pieces.append(g.box_between([x0 - 0.01, yk - u / 2 - 0.01, 0.0], [x1 + 0.01, yk + u / 2 + 0.01, 0.008],
                                    "feet"))
        face = x1 if x1 > 0 else x0
        out = 1.0 if x1 > 0 else -1.0
        pieces.append(_perforations(face, out, yk, u, 0.1, top - 0.05))
    # bracing in the plane of the frame: horizontals and a zigzag of diagonals
    xa, xb = -D / 2 + u, D / 2 - u
    r = min(0.012, 0.3 * u)
    levels = np.linspace(0.15, top - 0.1, max(2, int((top - 0.25) / 0.9) + 2))
    for k, z in enumerate(levels):
        pieces.append(g.cylinder([xa, yk, z], [xb, yk, z], r, slot, 10))
        if k + 1 < len(levels):
            z1 = levels[k + 1]
            a, b = ([xa, yk, z + 0.02], [xb, yk, z1 - 0.02]) if k % 2 == 0 else \
                ([xb, yk, z + 0.02], [xa, yk, z1 - 0.02])
            pieces.append(g.cylinder(a, b, 0.8 * r, slot, 10))
    pieces[-2 * len(levels) + 1:] = [pc.replace(sheet=0.0015) for pc in pieces[-2 * len(levels) + 1:]]
    return pieces


def _perforations(face, out, yk, u, z0, z1):
    """Two columns of small slots on an upright's front or back face (decoration, no collision)."""
    zs = np.arange(z0, z1, 0.05)
    offsets = np.array([[face + out * 0.0005, yk + dy, z] for z in zs for dy in (-0.25 * u, 0.25 * u)])
    verts, faces = g.instances(*g.box_arrays([0.0015, 0.008, 0.022]), offsets)
    return g.Piece(verts, faces, "holes", [], "perforation")


def _level(ys, D, z, bh, dt, deck, beam_slot):
    """Front and back beams (top at ``z``) with connector plates, and a deck on them."""
    ya, yb = ys
    pieces = []
    for x0, x1 in ((D / 2 - BEAM_D, D / 2), (-D / 2, -D / 2 + BEAM_D)):
        beam = g.box_between([x0, ya, z - bh], [x1, yb, z], beam_slot, bevel=0.003)
        pieces.append(beam.replace(sheet=0.0015))
        for ye, sgn in ((ya, 1), (yb, -1)):  # connector plates at the beam ends
            lo, hi = sorted((ye, ye + sgn * 0.006))
            pieces.append(g.box_between([x0 + 0.005, lo, z - bh], [x1 - 0.005, hi, z], "galvanised"))
    x0, x1 = -D / 2 + 0.01, D / 2 - 0.01
    if deck == "wood":
        pieces.append(g.box_between([x0, ya + 0.004, z], [x1, yb - 0.004, z + dt], "deck_wood", bevel=0.002))
    elif deck == "steel":
        plate = g.box_between([x0, ya + 0.004, z], [x1, yb - 0.004, z + dt], "deck_steel")
        pieces.append(plate.replace(sheet=0.001))
    else:  # wire mesh on channels: the mesh is visual, its collision one flat plate
        ys_bar = np.arange(ya + 0.02, yb - 0.015, 0.05)
        xs_bar = np.arange(x0 + 0.02, x1 - 0.015, 0.1)
        along_x = g.instances(*g.cylinder_arrays([x0, 0, 0], [x1, 0, 0], 0.0025, 6),
                              np.c_[np.zeros(len(ys_bar)), ys_bar, np.full(len(ys_bar), z + dt - 0.0025)])
        ym = yb - ya - 0.01
        along_y = g.instances(*g.cylinder_arrays([0, -ym / 2, 0], [0, ym / 2, 0], 0.0025, 6),
                              np.c_[xs_bar, np.full(len(xs_bar), (ya + yb) / 2), np.full(len(xs_bar), z + dt - 0.0075)])
        verts = np.vstack([along_x[0], along_y[0]])
        faces = np.vstack([along_x[1], along_y[1] + len(along_x[0])])
        plate = g.box_arrays([x1 - x0, yb - ya - 0.01, 0.01], [0.0, (ya + yb) / 2, z + dt - 0.005])[0]
        pieces.append(g.Piece(verts, faces, "deck_wire", [plate], "deck"))
        nch = max(2, int((yb - ya) / 0.45) + 1)
        for yv in np.linspace(ya + 0.04, yb - 0.04, nch):  # channels under the mesh, beam to beam
            ch = g.box_between([x0, yv - 0.015, z], [x1, yv + 0.015, z + dt - 0.01], "galvanised")
            pieces.append(ch.replace(sheet=0.0012))
    return pieces


def _goods(bp, level, kind, ys, D, z, h, rng):
    """Goods across a level between ``ys``, standing 1 mm above the deck top ``z``, ``h`` tall."""
    ya, yb = ys
    span = yb - ya
    z = z + 0.001
    depth = D - 0.06 if kind == "pallet" else min(D - 0.1, float(rng.uniform(0.45, 0.7)) * D + 0.1)
    x0, x1 = -depth / 2, depth / 2
    if kind == "pallet":
        count = max(1, int(span // 0.85))
        width = min(1.2, span / count - 0.05)
    else:
        count = max(1, min(4, int(span // float(rng.uniform(0.35, 0.6)))))
        width = span / count - 0.04
    pitch = span / count
    for k in range(count):
        yc = ya + (k + 0.5) * pitch
        lo, hi = yc - width / 2, yc + width / 2
        hk = h * float(rng.uniform(0.75, 1.0))
        if kind == "pallet":
            pieces = _pallet(x0, x1, lo, hi, z, hk)
            label = "pallet"
        elif kind == "crates":
            pieces = _crate(x0, x1, lo, hi, z, hk)
            label = "box"
        else:
            pieces = _box(x0, x1, lo, hi, z, hk)
            label = "box"
        name = f"{level}_{'pallet' if kind == 'pallet' else 'box'}_{k}"
        bp.add(name, label, pieces)
        bp.join(J.fixed(level, name))


def _box(x0, x1, y0, y1, z, h):
    box = g.box_between([x0, y0, z], [x1, y1, z + h], "box", bevel=0.004).replace(sheet=0.004)
    tape = g.box_between([x0 + 0.02, (y0 + y1) / 2 - 0.025, z + h - 0.001], [x1 - 0.02, (y0 + y1) / 2 + 0.025,
                                                                               z + h + 0.0005], "tape")
    return [box, tape]


def _crate(x0, x1, y0, y1, z, h):
    """An open plastic bin: a bottom and four walls (so it stays hollow)."""
    w = 0.006
    pieces = [
        g.box_between([x0, y0, z], [x1, y1, z + w], "crate"),
        g.box_between([x0, y0, z + w], [x0 + w, y1, z + h], "crate"),
        g.box_between([x1 - w, y0, z + w], [x1, y1, z + h], "crate"),
        g.box_between([x0 + w, y0, z + w], [x1 - w, y0 + w, z + h], "crate"),
        g.box_between([x0 + w, y1 - w, z + w], [x1 - w, y1, z + h], "crate"),
    ]
    return pieces


def _pallet(x0, x1, y0, y1, z, h):
    """A wooden pallet (bottom boards, blocks, top boards) carrying a stack of boxes."""
    ph = min(0.144, 0.35 * h)
    t = 0.022 * ph / 0.144
    pieces = []
    for yb in (y0, (y0 + y1) / 2 - 0.05, y1 - 0.1):  # bottom boards along X
        pieces.append(g.box_between([x0, yb, z], [x1, yb + 0.1, z + t], "pallet"))
    for xb in (x0, (x0 + x1) / 2 - 0.05, x1 - 0.1):  # blocks
        for yb in (y0, (y0 + y1) / 2 - 0.05, y1 - 0.1):
            pieces.append(g.box_between([xb, yb, z + t], [xb + 0.1, yb + 0.1, z + ph - t], "pallet"))
    n = max(3, int((y1 - y0) / 0.14))
    for k in range(n):  # top boards along X
        ya = y0 + k * (y1 - y0 - 0.1) / (n - 1)
        pieces.append(g.box_between([x0, ya, z + ph - t], [x1, ya + 0.1, z + ph], "pallet"))
    zs = z + ph + 0.001
    rows = 2 if h - ph > 0.5 else 1
    bh = (h - ph - 0.001) / rows
    for r in range(rows):
        for (a, b) in ((x0 + 0.01, 0.0 - 0.002), (0.002, x1 - 0.01)):
            for (c, d) in ((y0 + 0.01, (y0 + y1) / 2 - 0.002), ((y0 + y1) / 2 + 0.002, y1 - 0.01)):
                box = g.box_between([a, c, zs + r * bh], [b, d, zs + (r + 1) * bh - 0.002], "box", bevel=0.004)
                pieces.append(box.replace(sheet=0.004))
    return pieces
