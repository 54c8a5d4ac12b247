"""Rack parts: steel pallet-rack frames, beam levels with decks, and the goods that stand on them.

Local frames: a frame of two uprights stands in the plane y = 0 (front upright at +x); a level's
beams run along y between its two ends; goods stand on the plane z = 0. Sizes of real selective
pallet racking and boltless shelving: 60-100 mm uprights, 60-140 mm beams, 0.6-1.2 m deep frames,
1.2 x 0.8-1.0 m pallets 144 mm high (EN 15635, EUR-pallet EN 13698-1; manufacturers' catalogues).
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g

BEAM_D = 0.05  # beam depth (x)
BRACKET_H = 0.03  # stop bracket height
DECK_T = {"wire": 0.03, "steel": 0.03, "wood": 0.018}  # deck thickness on the beams
UPRIGHT_SHEET = 0.002  # upright steel
BRACE_SHEET = 0.0015
BEAM_SHEET = 0.0015
CARTON = 0.004  # corrugated board


# -- the storage rack's layout (``categories/storage_rack.py`` reads these) ----------------------------
GAP = 0.005  # level <-> uprights and stop brackets
SIDE = 0.03  # goods keep this far from the uprights
ABOVE_TOP = 0.06  # uprights reach this far above the highest raised level
HEADROOM = 0.02  # between raised goods or brackets and the level above
GOODS_LIFT = 0.001  # goods stand this far above the deck
SHELF_U = 0.04  # boltless shelving / bin rack upright (38-40 mm angle posts)
SHELF_BEAM = 0.04  # and its beams
BIN_GAP = 0.004  # between neighbouring bins
# AkroBins 30220 (4-1/8 in wide): 8 across a 36 in shelf, 11 across a 48 in one; a 60 in bay takes 12-13
MAX_BINS = 12
TOTE_W = (0.28, 0.45)  # tote widths across the shelf (see totes)
CAB_GAP = 0.02  # between drawer cabinets side by side
CAB_PANEL = 0.012  # a drawer cabinet's top and bottom panels
DRAWER_GAP = 0.003  # between drawer fronts
DRAWER_OUT = 0.95  # full-extension slides: a drawer comes out by ~95 % of its depth
LID_OPEN = 1.9  # a tote lid swings back up to ~110 degrees
MAX_TOTES = 5  # totes across a level at most
GOODS_FILL_MIN = 0.75  # goods on a pallet-rack level fill 75-100 % of the height allowed them
DRAWER_FRONTS = (0.3, 0.075, 10)  # drawer fronts 75-300 mm high (Lista / Vidmar), at most 10 to a cabinet
CAB_BACK = (0.02, 0.06)  # a drawer cabinet's front 2 cm behind the front beam; it leaves 6 cm of the level
CAB_DRAWER = (0.01, 0.002)  # its drawers' boxes: 1 cm off its back panel, fronts 2 mm behind its front
# Totes on a shelf (IKEA SAMLA, Really Useful Box): 6 cm shorter than the shelf is deep, at most 30 cm or
# 60 % of the clear height tall (room to lift the lid once pulled out), 1 cm in from the bay's ends and
# 8 mm apart each side; a lid's tip stays 1 cm under the level above (opening at least asin 0.05)
TOTE_ROW = dict(short=0.06, tall=0.3, fill=0.6, end=0.01, apart=0.008, under=0.01, least=0.05)
# Bins on a bin rack (AkroBins 30220: 5 in = 127 mm tall): 2 cm under the level above, 5 mm in from the bay's
# ends, 1 cm in from the shelf's front and back
BIN_ROW = dict(tall=0.127, under=0.02, end=0.005, edge=0.01)
# an open tote's label card: 80 x 30 mm, 2 mm thick, 6-9 cm under the rim, on the front wall
TOTE_LABEL = dict(half_w=0.04, z=(0.09, 0.06), t=0.002)


# -- the plate rack's layout (``categories/plate_rack.py`` reads these) -------------------------------
LIFT = 0.1  # lift of a plate along +Z
TURN = math.pi / 2  # turn of a plate about its axis (X) either way
END = 0.03  # rack length beyond the first and last fence
PAD = 0.006  # rubber pad height under a wood or plastic rack
WIRE = 0.6  # a wire rack's wire radius as a fraction of prong_radius
SIDE_GAP = 0.015  # the side board starts this far beyond a plate slid fully sideways
CADDY_LIFT = 0.2  # a caddy lifts clear of its board
TIER_GAP = 0.02  # between a lower plate lifted fully and the upper tier's lowest wire
TRAY_OUT = 0.8  # the drip tray slides out by this fraction of its length
TRAY_END_WALL = 0.004  # a plastic tray's end wall (the spout hangs on it)
SPOUT_ABOVE = 0.003  # the spout's bottom just above the tray floor's underside
BOARD_STAND = 0.002  # mugs, tumblers and caddies stand this far above the side board
CADDY_APART, CADDY_END = 0.02, 0.01  # caddies 2 cm apart, the last 1 cm from the board's end
# The side board (a drip board beside the rack): 12 mm thick, 4 mm under the rack's side, two rows of cups
# (one CUP_PITCH each, 1 cm spare) and caddies along it, 15 mm spare at its end; a wire rack's is a
# chrome-plated steel drip tray of 0.8 mm sheet
SIDE_BOARD = dict(t=0.012, under=0.004, spare_y=0.01, spare_x=0.015, sheet=0.0008)
CUP_ROWS = (0.25, 0.75)  # the two rows of cup pegs across the board
CUP_START = 0.005  # the first peg this far past half a pitch from the board's end
# A wire rack's upper tier: its cross wires (3 rail radii under the rails' axis) are its lowest members; its
# posts stand 12 mm in from the rack's ends, reaching 7 mm into the leg feet; a wood tier's dowel posts are
# at least 6 mm or 1.5 prong radii
TIER = dict(cross=3, post_in=0.012, post_into=0.007, dowel=(0.006, 1.5))
# A wire rack's drip tray: inside the legs' 5.5 mm rubber caps with 4 mm to spare, from 5 mm inside the back
# legs to 1 cm past the front ones, 1 mm over the floor
RACK_TRAY = dict(caps=0.0055, clear=0.004, back=0.005, front=0.01, floor=0.001)


def upright_frame(depth: float, u: float, top: float, slot: str) -> list[g.Piece]:
    """Two uprights (front, back) in the plane y = 0 with foot plates, perforations and bracing."""
    pieces = []
    for x0, x1 in ((depth / 2 - u, depth / 2), (-depth / 2, -depth / 2 + u)):
        pieces.append(g.box_between([x0, -u / 2, 0.008], [x1, u / 2, top], slot).replace(sheet=UPRIGHT_SHEET))
        pieces.append(g.box_between([x0 - 0.01, -u / 2 - 0.01, 0.0], [x1 + 0.01, u / 2 + 0.01, 0.008], "feet"))
        face, out = (x1, 1.0) if x1 > 0 else (x0, -1.0)
        pieces.append(perforations(face, out, u, 0.1, top - 0.05))
    # bracing in the plane of the frame: horizontals and a zigzag of diagonals
    xa, xb = -depth / 2 + u, depth / 2 - u
    r = min(0.012, 0.3 * u)
    levels = np.linspace(0.15, top - 0.1, max(2, int((top - 0.25) / 0.9) + 2))
    for k, z in enumerate(levels):
        pieces.append(g.cylinder([xa, 0, z], [xb, 0, z], r, slot, 10).replace(sheet=BRACE_SHEET))
        if k + 1 < len(levels):
            z1 = levels[k + 1]
            a, b = ([xa, 0, z + 0.02], [xb, 0, z1 - 0.02]) if k % 2 == 0 else ([xb, 0, z + 0.02], [xa, 0, z1 - 0.02])
            pieces.append(g.cylinder(a, b, 0.8 * r, slot, 10).replace(sheet=BRACE_SHEET))
    return pieces


def perforations(face: float, out: float, u: float, z0: float, z1: float) -> g.Piece:
    """Two columns of small slots on an upright's front or back face (decoration, no collision): each a
    flat pyramid (6 triangles, not a box's 12) whose 8 x 22 mm base stands 0.3 mm proud of the face and
    whose apex is hidden in the upright."""
    zs = np.arange(z0, z1, 0.05)
    offsets = np.array([[face, dy, z] for z in zs for dy in (-0.25 * u, 0.25 * u)])
    slot = np.array([[out * 0.0003, y, z] for y in (-0.004, 0.004) for z in (-0.011, 0.011)] + [[-out * 0.001, 0, 0]])
    verts, faces = g.instances(*g.hull_arrays(slot), offsets)
    return g.Piece(verts, faces, "holes", [], "perforation")


def stop_brackets(depth: float, u: float, z: float, sides: tuple[int, ...]) -> list[g.Piece]:
    """Brackets on the sides ``sides`` (+1: +y, -1: -y) of an upright pair at y = 0, their tops at ``z``."""
    out = []
    for x0, x1 in ((depth / 2 - BEAM_D, depth / 2), (-depth / 2, -depth / 2 + BEAM_D)):
        for s in sides:
            ya, yb = sorted((s * u / 2, s * (u / 2 + 0.012)))
            out.append(g.box_between([x0 + 0.01, ya, z - BRACKET_H], [x1 - 0.01, yb, z], "galvanised"))
    return out


def level(ys: tuple[float, float], depth: float, z: float, bh: float, deck: str, beam_slot: str) -> list[g.Piece]:
    """Front and back beams (tops at ``z``) from ``ys[0]`` to ``ys[1]`` with connector plates, and a deck."""
    ya, yb = ys
    dt = DECK_T[deck]
    pieces = []
    for x0, x1 in ((depth / 2 - BEAM_D, depth / 2), (-depth / 2, -depth / 2 + BEAM_D)):
        pieces.append(g.box_between([x0, ya, z - bh], [x1, yb, z], beam_slot, bevel=0.003).replace(sheet=BEAM_SHEET))
        for ye, sgn in ((ya, 1), (yb, -1)):  # connector plates at the beam ends
            lo, hi = sorted((ye, ye + sgn * 0.006))
            pieces.append(g.box_between([x0 + 0.005, lo, z - bh], [x1 - 0.005, hi, z], "galvanised"))
    x0, x1 = -depth / 2 + 0.01, depth / 2 - 0.01
    if deck == "wood":
        pieces.append(g.box_between([x0, ya + 0.004, z], [x1, yb - 0.004, z + dt], "deck_wood", bevel=0.002))
    elif deck == "steel":
        pieces.append(g.box_between([x0, ya + 0.004, z], [x1, yb - 0.004, z + dt], "deck_steel").replace(sheet=0.001))
    else:
        pieces += wire_deck(x0, x1, ya, yb, z, dt)
    return pieces


def wire_deck(x0: float, x1: float, ya: float, yb: float, z: float, dt: float) -> list[g.Piece]:
    """Wire mesh on channels: the mesh is visual, its collision one flat plate."""
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
    pieces = [g.Piece(verts, faces, "deck_wire", [plate], "deck")]
    nch = max(2, int((yb - ya) / 0.45) + 1)
    for yv in np.linspace(ya + 0.04, yb - 0.04, nch):  # channels under the mesh, beam to beam
        pieces.append(g.box_between([x0, yv - 0.015, z], [x1, yv + 0.015, z + dt - 0.01], "galvanised")
                      .replace(sheet=0.0012))
    return pieces


# -- goods ------------------------------------------------------------------------------------------------
PALLET = dict(width=1.2, height=0.144, board=0.022, slot=0.85)  # EUR pallet: 1.2 m long, 144 mm high


def carton(x0: float, x1: float, y0: float, y1: float, z: float, h: float) -> list[g.Piece]:
    """A taped cardboard box."""
    yc = (y0 + y1) / 2
    return [g.box_between([x0, y0, z], [x1, y1, z + h], "box", bevel=0.004).replace(sheet=CARTON),
            g.box_between([x0 + 0.02, yc - 0.025, z + h - 0.001], [x1 - 0.02, yc + 0.025, z + h + 0.0005], "tape")]


def crate(x0: float, x1: float, y0: float, y1: float, z: float, h: float) -> list[g.Piece]:
    """An open plastic bin: a bottom and four walls (so it stays hollow)."""
    w = 0.006
    return [g.box_between([x0, y0, z], [x1, y1, z + w], "crate"),
            g.box_between([x0, y0, z + w], [x0 + w, y1, z + h], "crate"),
            g.box_between([x1 - w, y0, z + w], [x1, y1, z + h], "crate"),
            g.box_between([x0 + w, y0, z + w], [x1 - w, y0 + w, z + h], "crate"),
            g.box_between([x0 + w, y1 - w, z + w], [x1 - w, y1, z + h], "crate")]


def pallet(x0: float, x1: float, y0: float, y1: float, z: float, h: float) -> list[g.Piece]:
    """A wooden pallet (bottom boards, blocks, top boards) carrying a stack of boxes, ``h`` tall in all."""
    ph = min(PALLET["height"], 0.35 * h)
    t = PALLET["board"] * ph / PALLET["height"]
    pieces = []
    thirds = (y0, (y0 + y1) / 2 - 0.05, y1 - 0.1)
    for yb in thirds:  # bottom boards along X
        pieces.append(g.box_between([x0, yb, z], [x1, yb + 0.1, z + t], "pallet"))
    for xb in (x0, (x0 + x1) / 2 - 0.05, x1 - 0.1):  # blocks
        for yb in thirds:
            pieces.append(g.box_between([xb, yb, z + t], [xb + 0.1, yb + 0.1, z + ph - t], "pallet"))
    n = max(3, int((y1 - y0) / 0.14))
    for k in range(n):  # top boards along X
        ya = y0 + k * (y1 - y0 - 0.1) / (n - 1)
        pieces.append(g.box_between([x0, ya, z + ph - t], [x1, ya + 0.1, z + ph], "pallet"))
    zs = z + ph + 0.001
    rows = 2 if h - ph > 0.5 else 1
    bh = (h - ph - 0.001) / rows
    for r in range(rows):
        for a, b in ((x0 + 0.01, -0.002), (0.002, x1 - 0.01)):
            for c, d in ((y0 + 0.01, (y0 + y1) / 2 - 0.002), ((y0 + y1) / 2 + 0.002, y1 - 0.01)):
                pieces.append(g.box_between([a, c, zs + r * bh], [b, d, zs + (r + 1) * bh - 0.002], "box",
                                            bevel=0.004).replace(sheet=CARTON))
    return pieces


GOODS = {"boxes": carton, "crates": crate, "pallet": pallet}


def goods_row(kind: str, span: tuple[float, float], depth: float, rng: np.random.Generator
              ) -> tuple[float, list[tuple[float, float]]]:
    """How goods of one kind fill a level: their depth and the y extent of each."""
    ya, yb = span
    width = yb - ya
    if kind == "pallet":
        d = depth - 0.06
        count = max(1, int(width // PALLET["slot"]))
        w = min(PALLET["width"], width / count - 0.05)
    else:
        d = min(depth - 0.1, float(rng.uniform(0.45, 0.7)) * depth + 0.1)
        count = max(1, min(4, int(width // float(rng.uniform(0.35, 0.6)))))
        w = width / count - 0.04
    pitch = width / count
    return d, [(ya + (k + 0.5) * pitch - w / 2, ya + (k + 0.5) * pitch + w / 2) for k in range(count)]


# -- modular drawer cabinets on a pallet-rack level ----------------------------------------------------------
# Lista / Stanley Vidmar pallet-rack drawer systems: a steel housing 22-1/2, 30 or 45 in wide (narrowest
# first), 28-1/4 in deep, whose drawers (front heights 3-12 in, 75-300 mm) run on full-extension slides;
# 1.2-1.5 mm sheet steel
DRAWER_CAB = dict(widths=(0.572, 0.762, 1.143), depth=0.718, sheet=0.0015, gap=0.003, front=0.018, lip=0.02)


def drawer_housing(x0: float, x1: float, y0: float, y1: float, z: float, h: float, slot: str) -> list[g.Piece]:
    """The housing of a drawer cabinet: bottom, top, two sides and a back of sheet steel, open at the front."""
    t = 0.012  # panels are folded channels; one slab each for collisions
    s = DRAWER_CAB["sheet"]
    return [g.box_between([x0, y0, z], [x1, y1, z + t], slot).replace(sheet=s),
            g.box_between([x0, y0, z + h - t], [x1, y1, z + h], slot).replace(sheet=s),
            g.box_between([x0, y0, z + t], [x1, y0 + t, z + h - t], slot).replace(sheet=s),
            g.box_between([x0, y1 - t, z + t], [x1, y1, z + h - t], slot).replace(sheet=s),
            g.box_between([x0, y0 + t, z + t], [x0 + t, y1 - t, z + h - t], slot).replace(sheet=s)]


def cabinet_drawer(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float, slot: str,
                   pull: str) -> list[g.Piece]:
    """A steel drawer between ``x0`` (back) and ``x1`` (its front face), ``z0``-``z1`` tall: a tray of
    bottom, sides and back behind a front panel with a full-width pull lip along its top edge."""
    s, f, w = DRAWER_CAB["sheet"], DRAWER_CAB["front"], 0.01
    hs = max(0.6 * (z1 - z0), min(z1 - z0, 0.05))  # the tray's walls are lower than the front
    xf = x1 - f
    pieces = [g.box_between([xf, y0, z0], [x1, y1, z1], slot, bevel=0.002).replace(sheet=s),
              g.box_between([x0, y0 + 0.005, z0], [xf, y1 - 0.005, z0 + w], slot).replace(sheet=s),
              g.box_between([x0, y0 + 0.005, z0 + w], [xf, y0 + 0.005 + w, z0 + hs], slot).replace(sheet=s),
              g.box_between([x0, y1 - 0.005 - w, z0 + w], [xf, y1 - 0.005, z0 + hs], slot).replace(sheet=s),
              g.box_between([x0, y0 + 0.005 + w, z0 + w], [x0 + w, y1 - 0.005 - w, z0 + hs], slot).replace(sheet=s)]
    lip = min(DRAWER_CAB["lip"], 0.3 * (z1 - z0))
    pieces.append(g.box_between([x1, y0 + 0.01, z1 - lip], [x1 + 0.012, y1 - 0.01, z1 - 0.002], pull, bevel=0.002))
    return pieces


# -- dish racks and plates -----------------------------------------------------------------------------
SEAT_GAP = 0.004  # a plate's lowest point above the support surface at rest
PLATE_SLIDE = 0.1  # how far a plate may slide along its slot, either way (the plastic tray's walls clear it)


def _smooth(u):
    u = np.clip(u, 0.0, 1.0)
    return u * u * u * (u * (6 * u - 15) + 10)


def plate(radius: float, height: float, wall: float, foot_r: float, material: str) -> g.Piece:
    """A dinner plate stood on edge: axis along +x, foot at x = 0, centre on the x axis.

    A solid of revolution with a foot ring, a flat well, a smooth cavetto and a rolled rim;
    its collision is two thick frustums around it (foot ring to mid-cavetto, on to the rim).
    """
    from infmob_usd.frames import Frame

    R, H, t, rf = radius, height, wall, foot_r
    wf = max(0.006, 0.08 * rf)  # foot ring width
    hf = max(0.003, 0.18 * H)  # foot ring height
    Rc = R - t / 2  # centre of the rolled rim
    rw = rf + 0.3 * wf + 0.004  # the well is flat out to here, then the cavetto rises
    c0, c1 = hf + t / 2, H - t / 2  # mid-surface height in the well and at the rim

    def mid(r):
        return c0 + (c1 - c0) * _smooth((np.asarray(r) - rw) / (Rc - rw))

    foot = [(0.0, hf), (rf - wf, hf), (rf - 0.75 * wf, 0.0), (rf - 0.1 * wf, 0.0)]
    under = [(r, mid(r) - t / 2) for r in np.linspace(rf + 0.3 * wf, Rc, 24)]
    rim = [(Rc + t / 2 * np.cos(x), c1 + t / 2 * np.sin(x)) for x in np.linspace(-np.pi / 2, np.pi / 2, 9)[1:-1]]
    top = [(r, mid(r) + t / 2) for r in np.linspace(Rc, 0.0, 28)]
    fine = g.revolve(g.simplify_profile(foot + under + rim + top), material)  # sections and points from tolerances
    rh = rw + 0.5 * (Rc - rw)
    # two thick frustums (foot ring to mid-cavetto, on to the rim): the six 2-3 mm bands of the profile made
    # PhysX report a plate sliding along its slot 16-18 mm deep in a prong cap 5 mm away (plate_rack seed 32)
    coarse = g.revolve([(0.0, 0.0), (rf - 0.1 * wf, 0.0), (rh, float(mid(rh)) - t / 2), (R, H), (0.0, H)],
                       material)
    on_edge = Frame.at(z=(1, 0, 0), x=(0, 0, -1))
    return fine.with_collision_of(coarse).transformed(on_edge.matrix)


def dowel(x: float, y: float, z_lo: float, z_hi: float, r: float, material: str) -> list[g.Piece]:
    """A prong: a cylinder with a domed top."""
    return [g.cylinder([x, y, z_lo], [x, y, z_hi - r], r, material, None),
            g.sphere([x, y, z_hi - r], r, material)]


BATTEN_W = 0.024  # a wooden rack's cross battens


def wood_rack(fences, xs, b, rp, z0, hp, base_h) -> tuple[list[g.Piece], float]:
    """Two rails on two cross battens, dowels in the rails. Returns pieces and the support height."""
    xa, xb = xs
    hb = 0.4 * base_h + 0.006  # battens
    wr = max(0.018, 3.2 * rp)
    bw = BATTEN_W
    pieces = [g.box_between([x, -b - wr, z0], [x + bw, b + wr, z0 + hb], "frame", bevel=0.002) for x in (xa, xb - bw)]
    zr = z0 + hb
    zs = zr + base_h
    for y in (-b, b):
        pieces.append(g.box_between([xa, y - wr / 2, zr], [xb, y + wr / 2, zs], "frame", bevel=0.002))
        for x in fences:
            pieces += dowel(x, y, zs - 0.004, zs + hp, rp, "prong")
    return pieces, zs


def plastic_tray(fences, xs, b, rp, z0, hp, base_h, plate_r) -> tuple[list[g.Piece], float]:
    """A moulded tray with round pegs; its side walls stand where a plate slid PLATE_SLIDE still clears them."""
    xa, xb = xs
    tf, wt = 0.004, 0.004  # floor and wall thickness
    need = 0.002  # clearance kept from the wall's top edge
    yw = PLATE_SLIDE + np.sqrt(max(0.0, (plate_r + need) ** 2 - (plate_r + SEAT_GAP - base_h) ** 2))
    yw = max(yw, b + rp + 0.015)
    zs = z0 + tf
    pieces = [
        g.box_between([xa - wt, -yw - wt, z0], [xb + wt, yw + wt, zs], "frame"),  # floor
        g.box_between([xa - wt, -yw - wt, zs], [xb + wt, -yw, zs + base_h], "frame"),  # side walls
        g.box_between([xa - wt, yw, zs], [xb + wt, yw + wt, zs + base_h], "frame"),
        g.box_between([xa - wt, -yw, zs], [xa, yw, zs + base_h], "frame"),  # end walls
        g.box_between([xb, -yw, zs], [xb + wt, yw, zs + base_h], "frame"),
    ]
    for y in (-b, b):
        for x in fences:
            pieces.append(g.cylinder([x, y, zs - 0.001], [x, y, zs + 0.006], rp * 1.6, "prong", 16))  # boss
            pieces += dowel(x, y, zs, zs + hp, rp, "prong")
    return pieces, zs


def wire_rack(fences, xs, b, rw, hp, base_h) -> tuple[list[g.Piece], float]:
    """Chrome wire: rails on rubber-capped legs, a cross wire and an arch at every fence."""
    xa, xb = xs
    cap = 0.007  # rubber cap height
    zr = cap + base_h  # rail axis height
    zs = zr + rw  # support: the rail tops
    top = zs + hp - rw  # axis of the arch's top bar
    pieces = []
    for y in (-b, b):
        pieces.append(g.cylinder([xa, y, zr], [xb, y, zr], rw, "frame", None))  # wire: sections_for(rw)
        for x in (xa + 0.012, xb - 0.012):
            pieces.append(g.cylinder([x, y, cap - 0.001], [x, y, zr], rw, "frame", None))
            pieces.append(g.cylinder([x, y, 0.0], [x, y, cap], 0.0055, "feet", None))
    for x in fences:
        pieces.append(g.cylinder([x, -b - 0.01, zr - rw], [x, b + 0.01, zr - rw], rw, "frame", None))
        for y in (-b, b):
            pieces += [g.cylinder([x, y, zr], [x, y, top], rw, "prong", None), g.sphere([x, y, top], rw, "prong")]
        pieces.append(g.cylinder([x, -b, top], [x, b, top], rw, "prong", None))
    return pieces, zs


def tier_posts(xs, b, r: float, z0: float, z1: float, slot: str = "frame") -> list[g.Piece]:
    """Four posts carrying a rack's upper tier, at ``xs`` (two) and y = +-b, from ``z0`` up to ``z1``."""
    return [g.cylinder([x, y, z0], [x, y, z1], r, slot, 12) for x in xs for y in (-b, b)]


# a moulded drainer tray's swivel spout (Rubbermaid, OXO, simplehuman drainer trays): a 25-30 mm wide trough
# 40-60 mm long on a round hub through the tray's end wall; it swings 180 degrees to point water at the sink
SPOUT = dict(length=0.05, width=0.026, h=0.012, hub=0.012, wall=0.002)
SPOUT_OFF = SPOUT["hub"] + 0.004  # the spout's hub axis beyond the tray's end wall


def swivel_spout(x: float, y: float, z: float, slot: str) -> list[g.Piece]:
    """A spout with its hub axis at (x, y), its bottom at ``z``, pointing along -Y at rest: a round hub and a
    trough (bottom and two side walls) running from it."""
    L, w, h, t = SPOUT["length"], SPOUT["width"], SPOUT["h"], SPOUT["wall"]
    return [g.cylinder([x, y, z], [x, y, z + h], SPOUT["hub"], slot, 24).replace(sheet=t),
            g.box_between([x - w / 2, y - L, z], [x + w / 2, y, z + t], slot).replace(sheet=t),
            g.box_between([x - w / 2, y - L, z + t], [x - w / 2 + t, y, z + h], slot),
            g.box_between([x + w / 2 - t, y - L, z + t], [x + w / 2, y, z + h], slot)]


# a drainer's drip tray: a 1.5 mm polypropylene tray 8-12 mm deep (simplehuman, Joseph Joseph, Kitsure)
DRIP_TRAY = dict(h=0.009, wall=0.0015, tab=0.012)


def drip_tray(x0: float, x1: float, y0: float, y1: float, z: float, h: float, slot: str) -> list[g.Piece]:
    """A shallow tray: a bottom, four low walls and a finger tab on its front (+X) wall."""
    t = 0.003  # walls and bottom as 3 mm slabs for collisions, 1.5 mm sheet for mass
    s = DRIP_TRAY["wall"]
    yc = (y0 + y1) / 2
    return [g.box_between([x0, y0, z], [x1, y1, z + t], slot).replace(sheet=s),
            g.box_between([x0, y0, z + t], [x0 + t, y1, z + h], slot).replace(sheet=s),
            g.box_between([x1 - t, y0, z + t], [x1, y1, z + h], slot).replace(sheet=s),
            g.box_between([x0 + t, y0, z + t], [x1 - t, y0 + t, z + h], slot).replace(sheet=s),
            g.box_between([x0 + t, y1 - t, z + t], [x1 - t, y1, z + h], slot).replace(sheet=s),
            g.box_between([x1, yc - 0.02, z + h - t], [x1 + DRIP_TRAY["tab"], yc + 0.02, z + h], slot)]


def pads(pieces, xs) -> list[g.Piece]:
    """Four rubber pads under the corners of a rack body (it stands on them)."""
    lo = np.array([pc.bounds[0] for pc in pieces]).min(0)
    hi = np.array([pc.bounds[1] for pc in pieces]).max(0)
    return [g.cylinder([x, y, lo[2] - 0.006], [x, y, lo[2] + 0.001], 0.007, "feet", 16)
            for x in (xs[0] + 0.012, xs[1] - 0.012) for y in (lo[1] + 0.012, hi[1] - 0.012)]


# -- storage totes and small-parts bins ------------------------------------------------------------------
TOTE_WALL = 0.003  # polypropylene storage boxes: 2.5-3.5 mm walls (Really Useful Box, IKEA SAMLA)
TOTE_RIM = 0.008  # the stacking rim around the top
LID_T = 0.012  # lid: a 3 mm sheet on a 12 mm skirt (visual), one slab for collisions
LID_SHEET = 0.003


def tote(x0: float, x1: float, y0: float, y1: float, z: float, h: float, slot: str) -> list[g.Piece]:
    """A storage box: a bottom, four walls and a stacking rim, with a hand grip on the front wall."""
    w = TOTE_WALL
    r = TOTE_RIM
    pieces = [g.box_between([x0 + r, y0 + r, z], [x1 - r, y1 - r, z + w], slot),
              g.box_between([x0 + r - w, y0 + r - w, z], [x0 + r, y1 - r + w, z + h - 0.015], slot),
              g.box_between([x1 - r, y0 + r - w, z], [x1 - r + w, y1 - r + w, z + h - 0.015], slot),
              g.box_between([x0 + r, y0 + r - w, z], [x1 - r, y0 + r, z + h - 0.015], slot),
              g.box_between([x0 + r, y1 - r, z], [x1 - r, y1 - r + w, z + h - 0.015], slot),
              # the rim: four flat bars flaring out to the full footprint at the top
              g.box_between([x0, y0, z + h - 0.015], [x0 + r + w, y1, z + h], slot, bevel=0.002),
              g.box_between([x1 - r - w, y0, z + h - 0.015], [x1, y1, z + h], slot, bevel=0.002),
              g.box_between([x0 + r + w, y0, z + h - 0.015], [x1 - r - w, y0 + r + w, z + h], slot),
              g.box_between([x0 + r + w, y1 - r - w, z + h - 0.015], [x1 - r - w, y1, z + h], slot)]
    yc = (y0 + y1) / 2  # a moulded grip on the front wall
    pieces.append(g.box_between([x1 - r + w, yc - 0.05, z + h - 0.05], [x1 - r + w + 0.006, yc + 0.05, z + h - 0.03],
                                slot))
    return pieces


def tote_lid(x0: float, x1: float, y0: float, y1: float, z: float, slot: str) -> list[g.Piece]:
    """A flat lid lying on a tote's rim at ``z``: a slab with a raised label panel."""
    return [g.box_between([x0, y0, z], [x1, y1, z + LID_T], slot, bevel=0.003).replace(sheet=LID_SHEET),
            g.box_between([x0 + 0.3 * (x1 - x0), y0 + 0.2 * (y1 - y0), z + LID_T],
                          [x1 - 0.1 * (x1 - x0), y1 - 0.2 * (y1 - y0), z + LID_T + 0.002], slot)]


def louvred_bin(x0: float, x1: float, y0: float, y1: float, z: float, h: float, slot: str,
                label: str) -> list[g.Piece]:
    """A small-parts bin with an open hopper front: a bottom, sides sloping down to a low front
    wall, a back wall, and a label holder (Akro-Mils AkroBins: 2 mm walls, front at ~45 % of the
    height)."""
    w = 0.002
    hf = 0.45 * h
    xm = x1 - 0.35 * (x1 - x0)  # the sides slope down from here to the front
    pieces = [g.box_between([x0, y0, z], [x1, y1, z + w], slot),
              g.box_between([x0, y0, z + w], [x0 + w, y1, z + h], slot),
              g.box_between([x1 - w, y0 + w, z + w], [x1, y1 - w, z + hf], slot)]
    for ya, yb in ((y0, y0 + w), (y1 - w, y1)):
        pieces += [g.box_between([x0 + w, ya, z + w], [xm, yb, z + h], slot),
                   g.from_trimesh(g.convex_hull([[xm, ya, z + w], [xm, yb, z + w], [xm, ya, z + h], [xm, yb, z + h],
                                                 [x1, ya, z + w], [x1, yb, z + w], [x1, ya, z + hf],
                                                 [x1, yb, z + hf]]), slot)]
    yc = (y0 + y1) / 2
    pieces.append(g.box_between([x1, yc - 0.3 * (y1 - y0), z + hf - 0.03], [x1 + 0.003, yc + 0.3 * (y1 - y0),
                                                                             z + hf - 0.005], label))
    return pieces


# -- dish-rack accessories: cutlery caddy, cups on pegs ------------------------------------------------------
# a drainer's cutlery caddy: ~11 x 13 cm, 14 cm high, 3 compartments (simplehuman, Joseph Joseph drainers)
CADDY = dict(x=0.11, y=0.13, h=0.14, wall=0.003)
# a 300 ml mug: 80-85 mm across, 95 mm high, 4 mm stoneware wall (catalogue sizes)
MUG = dict(r=0.041, h=0.095, wall=0.004)
PEG = dict(r=0.008, h=0.055)  # the cup pegs of a drainer's cup rail
CUP_LIFT = PEG["h"] + 0.025  # a mug lifts off its peg
CUP_PITCH = 0.11  # centre to centre along a row of cups (a mug and its handle: 82 + 22 mm)


def caddy(x0: float, x1: float, y0: float, y1: float, z: float, slot: str, metal: str) -> list[g.Piece]:
    """An open cutlery caddy with two dividers and a few knives, forks and spoons standing in it."""
    w, h = CADDY["wall"], CADDY["h"]
    pieces = [g.box_between([x0, y0, z], [x1, y1, z + w], slot),
              g.box_between([x0, y0, z + w], [x0 + w, y1, z + h], slot, bevel=0.001),
              g.box_between([x1 - w, y0, z + w], [x1, y1, z + h], slot, bevel=0.001),
              g.box_between([x0 + w, y0, z + w], [x1 - w, y0 + w, z + h], slot, bevel=0.001),
              g.box_between([x0 + w, y1 - w, z + w], [x1 - w, y1, z + h], slot, bevel=0.001)]
    ys = np.linspace(y0, y1, 4)
    for yd in ys[1:-1]:  # dividers
        pieces.append(g.box_between([x0 + w, yd - w / 2, z + w], [x1 - w, yd + w / 2, z + 0.8 * h], slot))
    for k, (ya, yb) in enumerate(zip(ys[:-1], ys[1:])):  # a handle or two standing in each compartment
        for i, xc in enumerate(np.linspace(x0 + 0.03, x1 - 0.03, 2)):
            yc = (ya + yb) / 2
            top = z + h + 0.05 + 0.01 * ((k + i) % 2)
            pieces.append(g.box_between([xc - 0.0075, yc - 0.002, z + w], [xc + 0.0075, yc + 0.002, top], metal,
                                        bevel=0.001))
    return pieces


def cup_peg(x: float, y: float, z: float, slot: str) -> g.Piece:
    return g.cylinder([x, y, z - 0.001], [x, y, z + PEG["h"]], PEG["r"], slot, 12)


def mug(x: float, y: float, z: float, slot: str, handle_dir: float = 1.0) -> list[g.Piece]:
    """A mug standing upside down with its rim at ``z`` (a hollow wall, its base on top, a handle
    on the ``handle_dir`` side along +-x)."""
    r, h, t = MUG["r"], MUG["h"], MUG["wall"]
    wall = g.shell([(r, 0.0), (r * 1.02, h - t)], t, slot, center=(x, y, z), sections=32)
    base = g.cylinder([x, y, z + h - t], [x, y, z + h], r * 1.02, slot, 32)
    s = handle_dir
    hx0, hx1 = sorted((x + s * (r - 0.002), x + s * (r + 0.022)))
    bar0, bar1 = sorted((x + s * (r + 0.016), x + s * (r + 0.022)))
    handle = [g.box_between([hx0, y - 0.005, z + 0.018], [hx1, y + 0.005, z + 0.026], slot, bevel=0.002),
              g.box_between([hx0, y - 0.005, z + h - 0.03], [hx1, y + 0.005, z + h - 0.022], slot, bevel=0.002),
              g.box_between([bar0, y - 0.005, z + 0.026], [bar1, y + 0.005, z + h - 0.03], slot, bevel=0.002)]
    return [wall, base] + handle


# a 300 ml tumbler: 70-75 mm across, 100-110 mm high, 3 mm wall on an 8 mm base (catalogue sizes)
TUMBLER = dict(r=0.036, h=0.105, wall=0.003, base=0.008)


def tumbler(x: float, y: float, z: float, slot: str) -> list[g.Piece]:
    """A tumbler standing upside down with its rim at ``z``: a thin wall narrowing to a thick base."""
    r, h, t, b = TUMBLER["r"], TUMBLER["h"], TUMBLER["wall"], TUMBLER["base"]
    wall = g.shell([(r, 0.0), (0.88 * r, h - b)], t, slot, center=(x, y, z), sections=32)
    return [wall, g.cylinder([x, y, z + h - b], [x, y, z + h], 0.88 * r, slot, 32)]


# -- rows of totes and bins on a storage-rack level --------------------------------------------------------
def tote_row(span, count: int, shelf_depth: float, clear: float):
    """``count`` totes across a level ``span`` (y) of a shelf ``shelf_depth`` deep with ``clear`` height over
    its deck: returns their x range, each one's y range and their height (``TOTE_ROW``)."""
    r = TOTE_ROW
    d = shelf_depth - r["short"]
    h = min(r["tall"], r["fill"] * clear)  # totes leave room above the lid to lift it once pulled out
    cells_ = np.linspace(span[0] + r["end"], span[1] - r["end"], count + 1)
    return (-d / 2, d / 2), [(cells_[k] + r["apart"], cells_[k + 1] - r["apart"]) for k in range(count)], h


def tote_lid_opening(room: float | None, depth: float) -> float:
    """How far a tote lid ``depth`` deep may swing up under ``room`` of height above the tote (None: no level
    above, ``LID_OPEN``): its tip stays ``TOTE_ROW["under"]`` under the level above."""
    if room is None:
        return LID_OPEN
    return math.asin(max(TOTE_ROW["least"], min(1.0, (room - LID_T - TOTE_ROW["under"]) / depth)))


def bin_row(span, count: int, shelf_depth: float, clear: float):
    """``count`` bins across a level ``span`` (y) of a shelf ``shelf_depth`` deep with ``clear`` height over its
    deck, ``BIN_GAP`` apart: returns their x range, each one's y range and their height (``BIN_ROW``)."""
    r = BIN_ROW
    D = shelf_depth
    h = min(r["tall"], clear - r["under"])  # 5 in bins
    pitch = (span[1] - span[0] - 2 * r["end"]) / count
    rows = []
    for k in range(count):
        y0 = span[0] + r["end"] + k * pitch
        rows.append((y0 + BIN_GAP / 2, y0 + pitch - BIN_GAP / 2))
    return (-D / 2 + r["edge"], D / 2 - r["edge"]), rows, h


def tote_label(x_front: float, y: float, z_rim: float) -> g.Piece:
    """An open tote's label card clipped on its front wall (the tote's front at ``x_front``, rim at ``z_rim``)."""
    c = TOTE_LABEL
    x = x_front - TOTE_RIM + TOTE_WALL
    return g.box_between([x, y - c["half_w"], z_rim - c["z"][0]], [x + c["t"], y + c["half_w"], z_rim - c["z"][1]],
                         "label")


# -- plate-rack fittings --------------------------------------------------------------------------------
def side_board(pieces, xs, plate_r: float, caddies: int, cups: int, wire: bool):
    """The side board beside a rack of ``pieces`` over ``xs``: beyond the reach of a plate (``plate_r``) slid
    fully sideways, at the rack's foot, running past the rack's end where ``caddies`` caddies and two rows of
    ``cups`` need it. Returns its extent (x range, y range, bottom, top) and its piece."""
    lo = np.array([pc.bounds[0] for pc in pieces]).min(0)
    hi = np.array([pc.bounds[1] for pc in pieces]).max(0)
    y0 = max(hi[1], plate_r + PLATE_SLIDE + SIDE_GAP)
    sb = SIDE_BOARD
    need = caddies * (CADDY["x"] + CADDY_APART) + math.ceil(cups / 2) * CUP_PITCH + sb["spare_x"]
    board = ((xs[0], max(xs[1], xs[0] + need)), (y0, y0 + 2 * CUP_PITCH + sb["spare_y"]), lo[2], lo[2] + sb["t"])
    side = g.box_between([xs[0], hi[1] - sb["under"], lo[2]], [board[0][1], board[1][1], board[3]], "frame",
                         bevel=0.002)
    return board, side.replace(sheet=sb["sheet"]) if wire else side


def cup_spots(board, count: int):
    """Where the pegs of ``count`` cups stand on a side ``board``: two rows along it. Returns the (x, y) of
    each and the board's top."""
    (x0, x1), (y0, y1), _, z = board
    rows = (y0 + CUP_ROWS[0] * (y1 - y0), y0 + CUP_ROWS[1] * (y1 - y0))
    start = x0 + CUP_PITCH / 2 + CUP_START
    per_row = math.ceil(count / 2)
    return [(start + i * CUP_PITCH, y) for y in rows for i in range(per_row)], z


def wire_tier(pieces, zs: float, top: float, xs, b: float, rp: float):
    """A wire rack's upper tier: its ``pieces`` (rails at ``zs``) without their leg caps, raised so its cross
    wires are at ``top``, and the posts from the lower tier's rails to its legs. Returns the pieces, the posts
    and the rise."""
    dz = top - (zs - TIER["cross"] * rp)
    pieces = [pc for pc in pieces if pc.material != "feet"]
    posts = tier_posts((xs[0] + TIER["post_in"], xs[1] - TIER["post_in"]), b, rp, zs - rp,
                       dz + TIER["post_into"])  # rail axis to leg foot
    return pieces, posts, dz


def rack_drip_tray(xs, b: float):
    """A wire rack's drip tray between its legs (at +-``b``), under the cross wires: returns its x range and
    pieces."""
    t = RACK_TRAY
    y = b - t["caps"] - t["clear"]  # inside the legs' 5.5 mm rubber caps
    x0, x1 = xs[0] + t["back"], xs[1] + t["front"]
    return (x0, x1), drip_tray(x0, x1, -y, y, t["floor"], DRIP_TRAY["h"], "tray")
