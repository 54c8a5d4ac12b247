"""Safes: a thick steel body open at the front, its heavy door (a hollow steel box with the lock's holes and its
bolts), a three-spoke bolt handle and an inner drawer.

The body stands on z = 0 centred on the z axis, its opening facing +x. Its anchors ``hinge_neg`` / ``hinge_pos``
are the door's hinge line at the front corner on the -y / +y side (z the axis a positive turn opens the door
about), ``drawer`` the front centre of the inner drawer's place under the ceiling (z out of the opening). The
door (:func:`door`) is a :func:`~.casing.sheet_casing` whose front face carries the lock's cut-outs, with the same
two hinge anchors; a category attaches the door's hinge anchor to the body's and places the controls on the
door's cut-out anchors (:class:`~.controls.ControlFace`).

Sizes per design are data (:data:`SIZES`, :data:`BUILD`), each figure beside the products it is read from.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from . import appliance as A
from . import hardware
from .casing import CasingSize, Cutout, LinerSize, edged_box, liner, sheet_casing
from .controls import MOUNT, Button, Dial

# Outer sizes (width Y, depth X, height Z; metres): home safes SentrySafe SFW082 37 x 41 x 44 cm to SFW205
# 47 x 49 x 61 cm, Honeywell 2087 / Yale 35-55 cm; hotel in-room safes (Elsafe, SAFEMARK, Onity) 40-45 x 30-38
# x 19-25 cm; gun cabinets Stack-On GCB-8 (21.5 x 9.5 x 55 in: 55 x 24 x 140 cm), 5-14 gun cabinets 30-55 cm
# wide, 22-40 cm deep, 1.30-1.50 m tall.
SIZES = {"home_safe": ((0.35, 0.55), (0.30, 0.50), (0.30, 0.60)),
         "hotel_safe": ((0.38, 0.45), (0.30, 0.38), (0.19, 0.25)),
         "gun_cabinet": ((0.30, 0.55), (0.22, 0.40), (1.30, 1.50))}


@dataclass(frozen=True)
class Build:
    """How a design is built: body ``wall`` and door ``thick``-ness as the simulator sees them (m), the body massed
    as ``sheet`` m of steel, each of the door's two skins as ``door_sheet``; the door's mechanical maximum
    ``opens`` (rad)."""

    wall: float
    thick: float
    sheet: float
    door_sheet: float
    opens: float
    bolt_r: float = 0.0
    bolts: int = 0
    hinge_r: float = 0.008
    hinges: int = 2


# Fire-rated home safes: 2-4 cm walls of steel skin round a gypsum/concrete fill and 6-8 cm doors, 35-60 kg
# (SentrySafe SFW123 ~39 kg): massed as ~6 mm of steel. Hotel safes: 2-3 mm body, a 6-8 mm door plate on a
# 3 cm door, 9-15 kg. Gun cabinets: 14-16 gauge (1.5-1.9 mm) steel, a 3 cm door of one folded sheet and a thin
# liner, 25-45 kg. Doors open 100-180 degrees on their external or concealed hinges.
# Bolts: the handle throws live bolts out of the door's free edge and dead bolts stand in its hinge edge
# (SentrySafe SFW123: 1 in / 25 mm live bolts, dead bolts on the hinge side; Elsafe hotel safes: two 20 mm
# bolts; Stack-On cabinets: 3-point locking, ~16 mm). Drawn withdrawn, their heads showing on both edges
# ``bolt_r`` round, ``bolts`` to an edge; they are not jointed (the handle's quarter turn stands for them).
# A gun cabinet's door is a folded box section deep enough for its 3-point locking bar and ~16 mm bolts to run
# inside it: 40-50 mm (a 30 mm door read as a sheet; gun safes proper have 75-125 mm doors).
# External barrel hinges: 2 on a home or hotel safe, 3 on a cabinet's tall door, 16-20 mm knuckles
# (``hinge_r``) on a fire safe, 12 mm on a hotel safe (SentrySafe, Stack-On, Elsafe product pictures).
BUILD = {"home_safe": Build(0.03, 0.065, 0.006, 0.005, math.radians(120), 0.0125, 2, 0.01, 2),
         "hotel_safe": Build(0.006, 0.03, 0.003, 0.0035, math.radians(110), 0.01, 2, 0.006, 2),
         "gun_cabinet": Build(0.004, 0.045, 0.0019, 0.0011, math.radians(120), 0.008, 3, 0.008, 3)}
BOLT = dict(depth=0.03, proud=0.005)  # m, a bolt's length in the door and its head past the edge (the live bolts'
# rounded heads stand 4-6 mm out of the free edge when withdrawn: SentrySafe, Stack-On doors)
EDGE = 0.35  # a steel body's rolled edges: chamfer as a share of its wall, at most :data:`EDGE_MAX`
EDGE_MAX = 0.006  # m (a fire safe's 5-8 mm rolled edge, a cabinet's 1-2 mm sheet bend)
HINGE_LEAF = 3.5  # a hinge leaf's width (m) as a multiple of its knuckle's radius

# Locks (SentrySafe, Sargent & Greenleaf, Elsafe listings): a 6-7 cm combination dial on a 6 mm spindle; a
# 12-key pad of ~10 x 8 mm keys pressing 2 mm on a 22 x 17 mm pitch; a three-spoke bolt handle ~10-14 cm
# across, turning a quarter turn to draw the bolts.
DIAL = Dial(radius=0.032, stem=0.006, style="round", turns=None)
KEY = Button(half=(0.0055, 0.0045), shape="rect", proud=0.003, travel=0.002)
KEY_PITCH = (0.022, 0.017)
KEY_GRID = (3, 4)  # columns, rows
HANDLE = dict(hub=0.014, spoke=0.006, reach=0.055, knob=0.01, proud=0.02, stem=0.007)
HANDLE_TURN = math.pi / 2
# An inner drawer under the ceiling (home safes, gun cabinets' top locker): 6-8 cm deep box of 1 mm steel.
DRAWER = dict(height=0.06, clearance=0.006, share=0.7, wall=0.003, sheet=0.001, front=0.006, pull=0.8)


def body(width: float, depth: float, height: float, b: Build, material: str) -> Assembly:
    """The open-front steel body (five walls ``b.wall`` thick). Anchors: ``hinge_neg``, ``hinge_pos``, ``drawer``
    (see the module), ``floor``."""
    hx, hy, t = depth / 2, width / 2, b.wall
    e = min(EDGE * t, EDGE_MAX)
    # the top and floor plates span the whole width, so their bevelled edges are the body's outer edges
    pieces = [edged_box(lo, hi, material, e) for lo, hi in (
        ((-hx, -hy + t, t), (-hx + t, hy - t, height - t)), ((-hx, -hy, t), (hx, -hy + t, height - t)),
        ((-hx, hy - t, t), (hx, hy, height - t)), ((-hx, -hy, 0), (hx, hy, t)),
        ((-hx, -hy, height - t), (hx, hy, height)))]
    pieces = [pc.replace(sheet=b.sheet) for pc in pieces] + lining(hx, hy, height, t)
    z_drawer = height - t - DRAWER["clearance"] - DRAWER["height"] / 2
    anchors = {"hinge_neg": Frame.at((hx, -hy, 0), x=(1, 0, 0), z=(0, 0, -1)),
               "hinge_pos": Frame.at((hx, hy, 0), x=(1, 0, 0), z=(0, 0, 1)),
               "drawer": Frame.at((hx - DRAWER["clearance"], 0, z_drawer), z=(1, 0, 0), x=(0, 0, 1)),
               "floor": Frame.at((0, 0, t))}
    supports = {f"foot_{i}": (x, y, 0) for i, (x, y) in enumerate(((-hx, -hy), (-hx, hy), (hx, -hy), (hx, hy)))}
    return Assembly.single("body", pieces, anchors, supports)


LINING = 0.003  # m, the felt / carpet lining glued inside a home safe or gun cabinet (SentrySafe, Stack-On photos)
# A gun cabinet's barrel rest: a felt-covered comb across the back at ~60 % of the height, its slots ~5-6 cm apart
# (Stack-On GCB-8: 8 guns in 55 cm; 5-14 gun cabinets), teeth 5-6 cm deep
COMB = dict(at=0.6, depth=0.065, bar=0.02, tooth=0.016, pitch=0.055, height=0.025)


def lining(hx: float, hy: float, height: float, t: float) -> list[g.Piece]:
    """The felt lining on the floor, back and sides inside the walls (drawn, no collision: it is 3 mm of cloth)."""
    a, L = t, LINING
    x0, x1, y0, y1, z0, z1 = -hx + a, hx - 0.002, -hy + a, hy - a, a, height - a
    return [g.box_between(lo, hi, "lining").replace(convex=()) for lo, hi in (
        ((x0, y0, z0), (x1, y1, z0 + L)), ((x0, y0, z0 + L), (x0 + L, y1, z1)),
        ((x0 + L, y0, z0 + L), (x1, y0 + L, z1)), ((x0 + L, y1 - L, z0 + L), (x1, y1, z1)))]


def barrel_comb(width: float, depth: float, height: float, t: float) -> list[g.Piece]:
    """A gun cabinet's barrel rest (:data:`COMB`): a bar across the back wall and the teeth between the slots
    the barrels lean into (drawn, no collision)."""
    c = COMB
    x0, y0, y1 = -depth / 2 + t + LINING, -width / 2 + t + LINING, width / 2 - t - LINING
    z0 = c["at"] * height
    z1 = z0 + c["height"]
    pieces = [g.box_between((x0, y0, z0), (x0 + c["bar"], y1, z1), "lining")]
    n = max(2, int((y1 - y0) / c["pitch"]))
    for k in range(n + 1):
        y = y0 + k * (y1 - y0) / n
        ya, yb = max(y0, y - c["tooth"] / 2), min(y1, y + c["tooth"] / 2)
        pieces.append(g.box_between((x0 + c["bar"], ya, z0), (x0 + c["depth"], yb, z1), "lining", bevel=0.004))
    return [pc.replace(convex=()) for pc in pieces]


def keypad_cutouts(at: tuple[float, float]) -> dict[str, Cutout]:
    """The 12 keys' holes on the door's front, a grid centred on ``at`` (face coordinates): ``key_0`` ..."""
    (cols, rows), (pu, pv) = KEY_GRID, KEY_PITCH
    return {f"key_{r * cols + c}": KEY.cutout("front", (at[0] + (c - (cols - 1) / 2) * pu,
                                                        at[1] - (r - (rows - 1) / 2) * pv))
            for r in range(rows) for c in range(cols)}


def handle_cutout(at: tuple[float, float]) -> Cutout:
    s = HANDLE["stem"]
    return Cutout.around("front", at, (2 * s, 2 * s), A.CLEAR)


def door(width: float, height: float, b: Build, material: str, cutouts: dict[str, Cutout]) -> Assembly:
    """The door: a hollow steel box ``b.thick`` deep covering the body's front, its lock's ``cutouts`` in its front
    face (anchors of their names), its bolts' heads on both upright edges. Anchors ``hinge_neg`` / ``hinge_pos``
    (as the body's)."""
    size = CasingSize(width, b.thick, height, min(0.004, b.thick / 4), b.door_sheet, 0.005)
    made = sheet_casing(size, material, cutouts, label="door")
    t2, w2 = b.thick / 2, width / 2
    bolts = [g.cylinder((0, s * (w2 - BOLT["depth"]), z), (0, s * (w2 + BOLT["proud"]), z), b.bolt_r, "handle")
             for s in (-1, 1) for z in (height * (k + 1) / (b.bolts + 1) for k in range(b.bolts))]
    made = made.with_pieces(made.root, bolts) if bolts else made
    anchors = {**made.anchors, "hinge_neg": Frame.at((-t2, -w2, 0), x=(1, 0, 0), z=(0, 0, -1)),
               "hinge_pos": Frame.at((-t2, w2, 0), x=(1, 0, 0), z=(0, 0, 1))}
    return Assembly(made.parts, anchors=anchors, supports=made.supports)


def hinges(depth: float, width: float, height: float, b: Build, side: int, material: str
           ) -> tuple[list[g.Piece], list[g.Piece]]:
    """The door's external barrel hinges (``b.hinges`` of ``b.hinge_r``) on its axis, the body's front corner on
    the ``side`` (-1: -y, +1: +y): each a leaf on the body's side, one on the door's, knuckles between
    (decoration, :func:`~.hardware.barrel_hinge`). Returns (body pieces, door pieces) at rest."""
    r, hx, hy = b.hinge_r, depth / 2, width / 2
    length, leaf = 8 * r, HINGE_LEAF * r
    y0, y1 = sorted((side * hy, side * (hy + 0.15 * r)))
    body, door = [], []
    for k in range(b.hinges):
        zc = height * (0.12 + 0.76 * k / (b.hinges - 1))
        fixed, moving = hardware.barrel_hinge(length, r, material, moving_share=0.4)
        at = Frame.at((hx, side * hy, zc)).matrix
        body += [pc.transformed(at) for pc in fixed]
        door += [pc.transformed(at) for pc in moving]
        body.append(hardware.leaf((hx - leaf, y0, zc - length / 2), (hx - 0.5 * r, y1, zc + length / 2), material))
        door.append(hardware.leaf((hx + 0.5 * r, y0, zc - 0.2 * length), (hx + leaf, y1, zc + 0.2 * length),
                                  material))
    return body, door


def spoke_handle(material: str) -> Assembly:
    """A three-spoke bolt handle on a stem through the door (control convention: face at x = 0, reaching +x);
    its spokes 120 degrees apart balance it about its axis. Anchors ``mount`` and ``axis``."""
    h = HANDLE
    x1 = h["proud"]
    pieces = [g.cylinder((-A.BEHIND, 0, 0), (0.003, 0, 0), h["stem"], material, 12),
              g.cylinder((0.003, 0, 0), (x1, 0, 0), h["hub"], material, None)]
    for k in range(3):
        a = math.pi / 2 + 2 * math.pi * k / 3
        tip = (x1 - h["spoke"], h["reach"] * math.cos(a), h["reach"] * math.sin(a))
        pieces += [g.cylinder((x1 - h["spoke"], 0, 0), tip, h["spoke"] / 2, material, 12),
                   g.sphere(tip, h["knob"], material)]
    return Assembly.single("handle", pieces, {"mount": MOUNT, "axis": MOUNT})


def drawer(inner_width: float, inner_depth: float, material: str) -> Assembly:
    """The inner drawer for a body ``inner_width`` x ``inner_depth`` inside: anchor ``front`` (as the body's
    ``drawer``)."""
    d = DRAWER
    size = LinerSize(inner_width - 2 * d["clearance"], d["share"] * inner_depth, d["height"], d["wall"], d["sheet"],
                     0.0, d["front"])
    return liner(size, material, label="drawer")
