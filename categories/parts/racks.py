"""Rack parts: steel pallet-rack frames, beam levels with decks, and the goods that stand on them.

Local frames: a frame of two uprights stands in the plane y = 0 (front upright at +x); a level's
beams run along y between its two ends; goods stand on the plane z = 0. Sizes of real selective
pallet racking and boltless shelving: 60-100 mm uprights, 60-140 mm beams, 0.6-1.2 m deep frames,
1.2 x 0.8-1.0 m pallets 144 mm high (EN 15635, EUR-pallet EN 13698-1; manufacturers' catalogues).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp

BEAM_D = 0.05  # beam depth (x)
BRACKET_H = 0.03  # height of the brackets a level's beam connectors rest on
DECK_T = {"wire": 0.03, "steel": 0.03, "wood": 0.018}  # deck thickness on the beams
UPRIGHT_SHEET = 0.002  # upright steel
BRACE_SHEET = 0.0015
BEAM_SHEET = 0.0015
CARTON = 0.004  # corrugated board


# -- the storage rack's layout (``categories/storage_rack.py`` reads these) ----------------------------
GAP = 0.005  # level <-> uprights
SIDE = 0.03  # goods keep this far from the uprights
ABOVE_TOP = 0.06  # uprights reach this far above the highest level
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
DRAWER_CAB = dict(widths=(0.572, 0.762, 1.143), depth=0.718, sheet=0.0015, gap=0.003, front=0.018, lip=0.02,
                  lip_proud=0.012)


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
    # the pull lip is what the drawer is taken by: pinched top to bottom from the front (the top edge is under
    # the drawer above, 3 mm away: no hand reaches it from above)
    proud, tall = DRAWER_CAB["lip_proud"], lip - 0.002
    zc, yc = z1 - 0.002 - tall / 2, (y0 + y1) / 2
    grasp = Grasp.make([x1 + proud, yc, zc], (-1, 0, 0), (0, 0, 1), tall, proud / 2, "line_fixed_handle",
                       ((x1 + proud / 2, yc, zc), (proud, y1 - y0 - 0.02, tall), np.eye(3)))
    pieces.append(g.box_between([x1, y0 + 0.01, z1 - lip], [x1 + proud, y1 - 0.01, z1 - 0.002], pull,
                                bevel=0.002).with_grasps(grasp))
    return pieces


# -- storage totes and small-parts bins ------------------------------------------------------------------
TOTE_WALL = 0.003  # polypropylene storage boxes: 2.5-3.5 mm walls (Really Useful Box, IKEA SAMLA)
TOTE_RIM = 0.008  # the stacking rim around the top
LID_T = 0.012  # lid: a 3 mm sheet on a 12 mm skirt (visual), one slab for collisions
LID_SHEET = 0.003
# moulded holds of a storage tote and its lid (Really Useful Box 35 L: a grip ledge moulded under the rim at each
# end and a lid whose edge stands proud of the box; IKEA SAMLA: hand holds under the rim): m
TOTE_GRIP = dict(width=0.1, proud=0.018, t=0.008, below=0.04)  # the ledge 40 mm under the rim: room for a finger
LID_TAB = dict(width=0.08, proud=0.022, t=0.005)  # the lid's lifting tab out of its front edge


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
    pieces.append(tote_grip(x1 - r + w, (y0 + y1) / 2, z + h, slot))
    return pieces


def tote_grip(x: float, y: float, z_rim: float, slot: str) -> g.Piece:
    """A tote's moulded hand hold: a ledge out of the front wall (face at ``x``) under the rim at ``z_rim``, which
    the fingers hook under to pull the tote off its shelf; a hand pinches it top to bottom from the front."""
    c = TOTE_GRIP
    zc, xc = z_rim - c["below"] - c["t"] / 2, x + c["proud"] / 2
    grasp = Grasp.make([x + c["proud"], y, zc], (-1, 0, 0), (0, 0, 1), c["t"], c["proud"] / 2, "line_fixed_handle",
                       ((xc, y, zc), (c["proud"], c["width"], c["t"]), np.eye(3)))
    lo, hi = [x, y - c["width"] / 2, zc - c["t"] / 2], [x + c["proud"], y + c["width"] / 2, zc + c["t"] / 2]
    return g.box_between(lo, hi, slot, bevel=0.002).with_grasps(grasp)


def tote_lid(x0: float, x1: float, y0: float, y1: float, z: float, slot: str) -> list[g.Piece]:
    """A flat lid lying on a tote's rim at ``z``: a slab with a raised label panel and a lifting tab standing out
    of its front edge (a lid flush with its tote's rim gives no hold: the tab is what it is lifted by, pinched top
    to bottom from the front)."""
    c, yc = LID_TAB, (y0 + y1) / 2
    zc = z + LID_T - c["t"] / 2
    grasp = Grasp.make([x1 + c["proud"], yc, zc], (-1, 0, 0), (0, 0, 1), c["t"], c["proud"] / 2, "line_fixed_handle",
                       ((x1 + c["proud"] / 2, yc, zc), (c["proud"], c["width"], c["t"]), np.eye(3)))
    return [g.box_between([x0, y0, z], [x1, y1, z + LID_T], slot, bevel=0.003).replace(sheet=LID_SHEET),
            g.box_between([x0 + 0.3 * (x1 - x0), y0 + 0.2 * (y1 - y0), z + LID_T],
                          [x1 - 0.1 * (x1 - x0), y1 - 0.2 * (y1 - y0), z + LID_T + 0.002], slot),
            g.box_between([x1 - 0.002, yc - c["width"] / 2, z + LID_T - c["t"]],
                          [x1 + c["proud"], yc + c["width"] / 2, z + LID_T], slot, bevel=0.001).with_grasps(grasp)]


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


# -- layout helpers of the storage rack: counts, spans and slots in the rack's frame ------------------------
def bay_span(width: float, u: float, n_bays: int) -> float:
    """The clear width of one bay between its uprights (section ``u``), less the gap at each side."""
    return (width - u) / n_bays - u - 2 * GAP


def upright_ys(width: float, u: float, n_bays: int) -> np.ndarray:
    """The y of every upright frame: both ends and between bays."""
    return np.linspace(-width / 2 + u / 2, width / 2 - u / 2, n_bays + 1)


def bay_spans(ys, u: float) -> list[tuple[float, float]]:
    """Each bay's clear (y0, y1) between the uprights at ``ys``."""
    return [(ys[b] + u / 2 + GAP, ys[b + 1] - u / 2 - GAP) for b in range(len(ys) - 1)]


def bracket_sides(k: int, n_frames: int) -> tuple[int, ...]:
    """The sides (+1: +y, -1: -y) of frame ``k`` of ``n_frames`` that face a bay, where stop brackets go."""
    return tuple(s for s, inner in ((1, k < n_frames - 1), (-1, k > 0)) if inner)


def goods_height(fill: float, level_height: float, beam_height: float, deck: str) -> float:
    """Goods height on a pallet-rack level: ``fill`` of the clear height between a deck and the beams above."""
    return fill * (level_height - beam_height - DECK_T[deck])


def goods_span(span: tuple[float, float]) -> tuple[float, float]:
    """Where goods stand on a level: clear of the uprights by :data:`SIDE`."""
    return span[0] + SIDE, span[1] - SIDE


def on_deck(z: float, deck: str) -> float:
    """The z goods stand at on a level whose beam top is at ``z``."""
    return z + DECK_T[deck] + GOODS_LIFT


def tote_count(span: float, rng: np.random.Generator) -> int:
    """Totes across a level: as many as fit at :data:`TOTE_W` wide each, at least 2, at most :data:`MAX_TOTES`."""
    lo = max(2, int(span // TOTE_W[1]))
    return int(rng.integers(lo, max(lo, min(MAX_TOTES, int(span // TOTE_W[0]))) + 1))


def bin_count(span: float, bin_width: float) -> int:
    """Bins across a level: as many ``bin_width`` bins as fit, 2 to :data:`MAX_BINS`."""
    return max(2, min(MAX_BINS, int(span // (bin_width + BIN_GAP))))


def cabinet_count(span: float, rng: np.random.Generator) -> int:
    """Drawer cabinets side by side on a bay of clear width ``span``: from as many 45 in ones as fit (at least
    one) to as many 30 in ones as fit."""
    width = span - 2 * SIDE
    lo = max(1, int(width // (DRAWER_CAB["widths"][-1] + CAB_GAP)))
    return int(rng.integers(lo, max(lo, int(width // (DRAWER_CAB["widths"][1] + CAB_GAP))) + 1))


def drawer_count(goods_h: float, rng: np.random.Generator) -> int:
    """Drawers of a cabinet ``goods_h`` high: fronts of :data:`DRAWER_FRONTS` filling it."""
    inner = goods_h - 2 * CAB_PANEL
    tallest, lowest, most = DRAWER_FRONTS
    lo = max(1, math.ceil(inner / tallest))
    return int(rng.integers(lo, max(lo, min(most, int(inner // lowest))) + 1))


def drawn_goods(kind: str, depth: float, ys: tuple[float, float], z: float, h: float, rng: np.random.Generator
                ) -> list[g.Piece]:
    """One item of goods centred in depth, ``GOODS_FILL_MIN``-100 % of ``h`` high (drawn)."""
    hk = h * float(rng.uniform(GOODS_FILL_MIN, 1.0))
    return GOODS[kind](-depth / 2, depth / 2, ys[0], ys[1], z, hk)


@dataclass(frozen=True)
class CabinetSlots:
    """Drawer cabinets side by side on a level: their x extent and each one's y extent."""

    xs: tuple[float, float]
    ys: list


def cabinet_slots(span: tuple[float, float], count: int, depth: float) -> CabinetSlots:
    """``count`` cabinets of the widest stock width that fits their pitch, fronts :data:`CAB_BACK` behind the
    front beam of a level ``depth`` deep."""
    width = span[1] - span[0]
    pitch = width / count
    w = next((cw for cw in reversed(DRAWER_CAB["widths"]) if cw + CAB_GAP <= pitch), pitch - CAB_GAP)
    x1 = depth / 2 - CAB_BACK[0]
    xs = (x1 - min(DRAWER_CAB["depth"], depth - CAB_BACK[1]), x1)
    centres = [span[0] + (k + 0.5) * pitch for k in range(count)]
    return CabinetSlots(xs, [(yc - w / 2, yc + w / 2) for yc in centres])


def drawer_slots(xs, ys, z: float, h: float, count: int) -> tuple[tuple, tuple, list]:
    """The drawers of a cabinet at ``xs`` x ``ys`` from ``z`` up ``h``: their x and y extents and each one's z's."""
    x0, x1 = xs[0] + CAB_PANEL + CAB_DRAWER[0], xs[1] - CAB_DRAWER[1]
    y0, y1 = ys[0] + CAB_PANEL + DRAWER_GAP, ys[1] - CAB_PANEL - DRAWER_GAP
    z0, z1 = z + CAB_PANEL + DRAWER_GAP, z + h - CAB_PANEL - DRAWER_GAP
    pitch = (z1 - z0) / count
    return (x0, x1), (y0, y1), [(z0 + k * pitch, z0 + k * pitch + pitch - DRAWER_GAP) for k in range(count)]


def slide_out(xs, ys, z: float) -> Frame:
    """The slide of a drawer, tote or bin: along +x from its front bottom edge's middle."""
    return Frame.at((xs[1], sum(ys) / 2, z), z=(1, 0, 0))


def pull_out(xs, fraction: float) -> float:
    """How far a box ``xs`` deep slides out: ``fraction`` of its depth."""
    return fraction * (xs[1] - xs[0])


def lid_hinge(xs, ys, z: float) -> Frame:
    """A tote lid's hinge at its back edge, axis -y: a positive turn lifts the front edge."""
    return Frame.at((xs[0], sum(ys) / 2, z), z=(0, -1, 0))


def lid_room(levels, z: float, h: float) -> float | None:
    """Room above a tote ``h`` high standing on a level at ``z``, under the next level up (None: the top level)."""
    above = [lv for lv in levels if lv > z + 1e-9]
    return min(above) - z - h if above else None
