"""Beverage fridge: an insulated cabinet with a framed glass door and slide-out racks.

X is depth (the door faces +X), Y is width, Z is up. The cabinet stands on four
levelling feet; at the bottom of the front is a ventilation kick grille (the
compressor lives behind it), above it the glass door, and optionally a control
strip (display and touch keys) above the door. The cabinet walls are thick
insulated panels (sheet steel outside, foam inside: modelled as solid boxes with
``sheet`` set so they weigh what sheet steel weighs) lined with a thin plastic
liner, so the cooled cavity is a real hollow built from panels.

The door is a frame around a double glass pane, hinged on one side (``hinge_side``)
about a vertical axis through its front face at the hinge edge: left hinge turns
about -Z, right hinge about +Z, both swing outward (+X) 0..pi/2. The handle (a bar
or a low edge pull) is on the free edge.

Inside there are either 3-5 racks (wire racks with a wooden or metal front trim, or
glass shelves in a trim) that slide out along +X on ledge rails moulded into the
liner, or a fixed divider plate that splits the cavity into two zones.

The door is solid to a robot: the frame, both glass panes and the gasket all collide.
A rack therefore declares ``requires_open="door"``: it slides out only with the door fully
open (pi/2), as a user opens the door before pulling a rack; the checks open it first too.
The open door stands at the hinge side, its inner face ``door_thickness`` (+ the gasket)
inside the cabinet's side; the racks are kept far enough from the hinge-side wall
(``hypot(frame, door_thickness)`` + 6 mm of the outer side) that a pulled-out rack never
meets the open door.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int, Schema

GROWTH = Growth(
    beverage_fridge=Rule(required=("body", "door"), optional={"control_panel": 0.6},
                         one_of={"racks": 0.8, "divider": 0.2}),
    door=Rule(required=("frame", "glass"), one_of={"bar": 0.6, "recessed": 0.4}),
    rack=Rule(one_of={"wire": 0.65, "glass": 0.35}),
)
"""The object-wide ``one_of`` choices are the parameters ``interior``, ``handle_style`` and
``rack_style`` (same weights)."""

_INTERIOR = GROWTH.rules["beverage_fridge"].one_of
_HANDLES = GROWTH.rules["door"].one_of
_RACKS = GROWTH.rules["rack"].one_of

SCHEMA = Schema((
    Float("width", "overall width (Y)", "m", 0.45, 0.7),
    Float("depth", "overall depth incl. the door, excl. the handle (X)", "m", 0.5, 0.68),
    Float("height", "overall height incl. the feet (Z)", "m", 0.5, 0.9),
    Float("wall", "insulated wall thickness", "m", 0.035, 0.055),
    Float("door_thickness", "glass door thickness (frame depth)", "m", 0.03, 0.045),
    Float("kick_height", "height of the ventilation kick grille below the door", "m", 0.05, 0.1),
    Float("feet_height", "levelling feet height", "m", 0.008, 0.02),
    Float("control_height", "height of the control strip above the door", "m", 0.035, 0.06),
    Choice("hinge_side", "side of the door hinge, seen from the front", choices=("left", "right")),
    Choice("handle_style", "door handle", choices=tuple(_HANDLES), weights=tuple(_HANDLES.values())),
    Float("handle_length", "handle length as a fraction of the door height", "", 0.35, 0.75),
    Choice("interior", "sliding racks or a fixed divider plate", choices=tuple(_INTERIOR),
           weights=tuple(_INTERIOR.values())),
    Int("rack_count", "sliding racks (interior = racks)", "", 3, 5),
    Choice("rack_style", "wire racks or glass shelves", choices=tuple(_RACKS), weights=tuple(_RACKS.values())),
    Float("rack_travel", "rack slide-out as a fraction of its own depth", "", 0.6, 0.85),
    Float("divider_height", "divider plate height as a fraction of the cavity height", "", 0.35, 0.65),
    Choice("body_finish", "cabinet material", choices=("painted", "brushed_metal"), weights=(0.6, 0.4)),
    Choice("door_finish", "door frame: match the cabinet or black plastic", choices=("match", "black"),
           weights=(0.5, 0.5)),
    Choice("trim_finish", "front trim of the racks", choices=("wood", "chrome", "plastic"),
           weights=(0.45, 0.35, 0.2)),
    Choice("handle_finish", "handle material", choices=("brushed_metal", "chrome", "plastic"),
           weights=(0.45, 0.35, 0.2)),
    *GROWTH.flags(),
))

GAP = 0.004  # door to cabinet, door to control strip and kick grille
RACK_GAP = 0.004  # rack to rails, liner, back wall and neighbours
LINER = 0.002
SHEET = 0.0008  # steel sheet of the cabinet walls (mass)
DOOR_ANGLE = math.pi / 2


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    frame_slot = appliance(p["body_finish"]) if p["door_finish"] == "match" else "plastic:black"
    handle_slot = "plastic:black|dark_grey" if p["handle_finish"] == "plastic" else p["handle_finish"]
    bp = Blueprint("beverage_fridge", materials={
        "body": appliance(p["body_finish"]), "liner": "plastic:black|dark_grey|white", "frame": frame_slot,
        "glass": "glass:clear|clear_blue", "handle": handle_slot, "trim": appliance(p["trim_finish"]),
        "wire": "chrome", "grille": "plastic:black|dark_grey", "feet": "rubber", "display": "rubber",
        "gasket": "rubber",
    })
    W, D, H, w, ft = p["width"], p["depth"], p["height"], p["wall"], p["door_thickness"]
    y0, y1 = -W / 2, W / 2
    xf = D / 2  # door front face
    xb1 = xf - ft - GAP  # cabinet front face
    xb0 = -D / 2
    zf = p["feet_height"]
    zk = zf + p["kick_height"]  # top of the kick grille
    ctrl = p["has_control_panel"]
    zd0 = zk + GAP  # door bottom
    zd1 = H - (p["control_height"] + GAP if ctrl else 0.0)  # door top
    zc = zd1 + GAP  # control strip bottom

    # cavity (liner inner faces)
    cx0, cx1 = xb0 + w + LINER, xb1
    cy0, cy1 = y0 + w + LINER, y1 - w - LINER
    cz0 = zk + w + LINER
    cz1 = H - w - LINER
    # glass opening of the door: the cavity opening grown by 3 mm, inside the door's frame
    hole = (cy0 - 0.003, max(cz0 - 0.003, zd0 + 0.02), cy1 + 0.003, min(cz1 + 0.003, zd1 - 0.02))
    m_side = hole[0] - y0  # frame stile width

    body = bp.add("body", "body", _cabinet(p, (xb0, xb1, y0, y1, zf, H), (cx0, cx1, cy0, cy1, cz0, cz1),
                                           zk, zc if ctrl else None))

    # --- door ------------------------------------------------------------------
    hinge_left = p["hinge_side"] == "left"
    door = _door(p, (xf - ft, xf, y0, y1, zd0, zd1), hole, hinge_left)
    bp.add("door", "door", door)
    hy, axis = (y0, (0, 0, -1)) if hinge_left else (y1, (0, 0, 1))
    bp.join(J.revolute(body, "door", (xf, hy, zd0), axis, 0.0, DOOR_ANGLE, role="hinge"))

    # --- interior ----------------------------------------------------------------
    if p["interior"] == "racks":
        # the racks keep clear of the open door's hinge-side edge (see the module docstring)
        reach = math.hypot(m_side, ft) + 0.006
        ry = min(-(y0 + reach), cy1 - 0.018)  # rack half width
        n = p["rack_count"]
        z_top = min(cz1, hole[3] - 0.004)  # racks stay behind the glass, clear of the top rail
        pitch = (z_top - cz0) / (n + 0.6)
        hr = min(0.03, pitch - 0.02)  # rack height
        rx0, rx1 = cx0 + RACK_GAP, xb1 - 0.006
        for k in range(n):
            z_rail = cz0 + pitch * (k + 0.8)  # top of the ledge rails of this level
            pieces, label = _rack(p, (rx0, rx1), ry, z_rail + RACK_GAP, hr, geometry)
            name = f"rack_{k}"
            bp.add(name, label, pieces)
            # ledge rails moulded into the side liner, under the rack's side runners
            for s in (-1, 1):
                ya, yb = sorted((s * (ry - 0.008), s * (cy1 + LINER)))
                bp.extend(body, [g.box_between([cx0, ya, z_rail - 0.008], [cx1 - 0.004, yb, z_rail], "liner")])
            travel = p["rack_travel"] * (rx1 - rx0)
            bp.join(J.prismatic(body, name, (rx1, 0.0, z_rail + RACK_GAP), (1, 0, 0), 0.0, travel,
                                role="slide", requires_open="door"))
    else:
        zp = cz0 + p["divider_height"] * (cz1 - cz0)
        plate = [
            g.box_between([cx0, cy0, zp - 0.003], [cx1 - 0.01, cy1, zp + 0.003], "glass"),
            g.box_between([cx1 - 0.03, cy0, zp - 0.008], [cx1 - 0.01, cy1, zp + 0.008], "trim"),
        ]
        bp.add("divider", "shelf", plate)
        bp.join(J.fixed(body, "divider"))
    return bp


def _cabinet(p, outer, cavity, zk, zc):
    """Insulated walls, liner, machine compartment with kick grille, feet and control strip."""
    xb0, xb1, y0, y1, zf, H = outer
    cx0, cx1, cy0, cy1, cz0, cz1 = cavity
    L = LINER
    wy0, wy1, wz0, wz1, wx0 = cy0 - L, cy1 + L, cz0 - L, cz1 + L, cx0 - L  # wall inner faces

    def wall(lo, hi):
        piece = g.box_between(lo, hi, "body")
        piece.sheet = SHEET
        return piece

    pieces = [
        wall([xb0, y0, zf], [xb1, wy0, H]),  # left
        wall([xb0, wy1, zf], [xb1, y1, H]),  # right
        wall([xb0, wy0, wz1], [xb1, wy1, H]),  # top
        wall([xb0, wy0, zk], [xb1, wy1, wz0]),  # insulated floor
        wall([xb0, wy0, wz0], [wx0, wy1, wz1]),  # back
        wall([xb0, wy0, zf], [xb1 - 0.02, wy1, zf + 0.003]),  # base plate of the machine compartment
        wall([xb0, wy0, zf + 0.003], [xb0 + 0.004, wy1, zk]),  # rear cover of the compressor
        # liner: floor, ceiling, sides, back
        g.box_between([wx0, wy0, wz0], [cx1, wy1, cz0], "liner"),
        g.box_between([wx0, wy0, cz1], [cx1, wy1, wz1], "liner"),
        g.box_between([wx0, wy0, cz0], [cx1, cy0, cz1], "liner"),
        g.box_between([wx0, cy1, cz0], [cx1, wy1, cz1], "liner"),
        g.box_between([wx0, cy0, cz0], [cx0, cy1, cz1], "liner"),
        # gasket seat around the opening (a thin dark band on the front face)
        g.box_between([xb1 - 0.001, wy0 - 0.01, wz0 - 0.01], [xb1 + 0.001, wy0, wz1 + 0.01], "gasket"),
        g.box_between([xb1 - 0.001, wy1, wz0 - 0.01], [xb1 + 0.001, wy1 + 0.01, wz1 + 0.01], "gasket"),
    ]
    # kick grille: a recessed slotted panel across the front of the machine compartment
    gx = xb1 - 0.012
    pieces.append(g.box_between([gx - 0.004, wy0, zf + 0.003], [gx, wy1, zk], "grille"))
    n_slots = max(3, int((wy1 - wy0) / 0.02))
    for k in range(n_slots):
        ya = wy0 + 0.012 + k * (wy1 - wy0 - 0.024) / n_slots
        pieces.append(g.box_between([gx, ya, zf + 0.012], [gx + 0.002, ya + 0.006, zk - 0.01], "grille"))
    # four levelling feet
    r = 0.014
    for x in (xb0 + 0.035, xb1 - 0.045):
        for y in (y0 + 0.035, y1 - 0.035):
            pieces.append(g.cylinder([x, y, 0.0], [x, y, zf], r, "feet", 16))
    if zc is not None:  # control strip above the door, flush with the door front
        xf = xb1 + p["door_thickness"] + GAP
        W = y1 - y0
        pieces += [
            g.box_between([xb1, y0, zc], [xf, y1, H], "frame"),
            g.box_between([xf, -0.12 * W, zc + 0.25 * (H - zc)], [xf + 0.001, 0.12 * W, H - 0.25 * (H - zc)],
                          "display"),
        ]
        for k in range(3):  # touch keys printed on the strip
            yk = 0.17 * W + k * 0.045 * W
            pieces.append(g.box_between([xf, yk, zc + 0.35 * (H - zc)], [xf + 0.0008, yk + 0.03 * W,
                                                                           H - 0.35 * (H - zc)], "display"))
    return pieces


def _door(p, box, hole, hinge_left):
    """Frame (four members) around a double glass pane, and a gasket; all collide."""
    x0, x1, y0, y1, z0, z1 = box
    h0, v0, h1, v1 = hole
    ft = x1 - x0
    frame = g.panel([x0, y0, z0], [x1, y1, z1], "frame", "x", holes=[hole])
    frame.sheet = SHEET
    glass = []
    for xg in (x1 - 0.3 * ft, x0 + 0.2 * ft):  # two panes: the insulated glazing
        pane = g.box_between([xg - 0.002, h0 - 0.004, v0 - 0.004], [xg + 0.002, h1 + 0.004, v1 + 0.004], "glass")
        glass.append(pane)
    gasket = g.panel([x0 - 0.0015, y0 + 0.006, z0 + 0.006], [x0, y1 - 0.006, z1 - 0.006], "gasket", "x",
                     holes=[(h0 + 0.004, v0 + 0.004, h1 - 0.004, v1 - 0.004)])
    pieces = [frame, *glass, gasket]
    zm = (z0 + z1) / 2
    length = p["handle_length"] * (z1 - z0)
    free_mid = (y1 - (y1 - h1) / 2) if hinge_left else (y0 + (h0 - y0) / 2)
    if p["handle_style"] == "bar":
        pieces += g.bar_handle((x1, free_mid, zm), (1, 0, 0), (0, 0, 1), length, "handle",
                               standoff=0.03, radius=0.007)
    else:  # a low pull along the free edge
        pieces += g.pull_handle((x1, free_mid, zm), (1, 0, 0), (0, 0, 1), length, "handle",
                                depth=0.016, lip=min(0.02, 0.6 * (y1 - h1)))
    return pieces


def _rack(p, xs, ry, zb, hr, geometry):
    """A wire rack (or a glass shelf) between ``xs`` in X, ``-ry..ry`` in Y, from ``zb`` up by ``hr``."""
    rx0, rx1 = xs
    r = 0.0025  # wire radius
    trim_d = 0.018
    if p["rack_style"] == "glass":
        return [
            g.box_between([rx0, -ry, zb], [rx1 - trim_d, ry, zb + 0.006], "glass"),
            g.box_between([rx0, -ry, zb], [rx1 - trim_d, -ry + 0.01, zb + 0.012], "trim"),
            g.box_between([rx0, ry - 0.01, zb], [rx1 - trim_d, ry, zb + 0.012], "trim"),
            g.box_between([rx1 - trim_d, -ry, zb], [rx1, ry, zb + min(0.022, hr)], "trim", bevel=0.002),
        ], "shelf"
    zc = zb + r
    pieces = [
        # side runners (over the ledge rails), back rail and back stop
        g.box_between([rx0, -ry, zb], [rx1 - trim_d, -ry + 0.008, zb + 0.01], "wire"),
        g.box_between([rx0, ry - 0.008, zb], [rx1 - trim_d, ry, zb + 0.01], "wire"),
        g.cylinder([rx0 + r, -ry + 0.008, zc], [rx0 + r, ry - 0.008, zc], r, "wire", 8),
        g.cylinder([rx0 + r, -ry + 0.008, zb + hr], [rx0 + r, ry - 0.008, zb + hr], r, "wire", 8),
        # front trim (the face you pull)
        g.box_between([rx1 - trim_d, -ry, zb], [rx1, ry, zb + hr - 0.002], "trim", bevel=0.002),
    ]
    for y in (-ry + 0.004, ry - 0.004):  # back stop posts
        pieces.append(g.cylinder([rx0 + r, y, zb + 0.01], [rx0 + r, y, zb + hr], r, "wire", 8))
    # wires along X, bent into a shallow cradle for bottles
    pitch = float(geometry.uniform(0.028, 0.04))
    n = max(3, int((2 * ry - 0.02) / pitch))
    for k in range(n):
        y = -ry + 0.01 + (k + 0.5) * (2 * ry - 0.02) / n
        lift = 0.006 * (1 - math.cos(2 * math.pi * (k + 0.5) / n * 2)) / 2  # waves across the rack
        pieces.append(g.cylinder([rx0 + 2 * r, y, zc + lift], [rx1 - trim_d, y, zc + lift], r * 0.8, "wire", 8))
    return pieces, "rack"
