"""Dishwasher: a built-in dishwasher with a bottom-hinged door and slide-out wire racks.

X is depth (the door faces +X), Y is width, Z is up. The machine stands on four
levelling feet behind a kick plinth; the stainless tub is built from panels
(insulated outer walls, a thin stainless liner: floor, ceiling, sides, back), so
the wash cavity is a real hollow. On the tub floor sit the filter and the lower
spray arm; a spray nozzle hangs from the ceiling.

The door is hinged at its bottom front edge, above the plinth, and falls forward
about +Y (right-hand rule: +Z turns into +X) from closed (0) to horizontal (pi/2).
Its centre of mass lies behind the hinge line (the stainless inner skin is at the
back, the front skin at the hinge), so gravity presses the closed door shut
against its lower limit. Optional: a control panel fixed along the top of the door
front (display and a row of push buttons sliding in along -X), and a handle (a
bar, or a low pocket pull) near the top edge.

1-4 racks (wire baskets modelled as thin bars: every wire is its own convex piece)
roll along +X on rails on the tub walls: a tall lower rack with plate tines, an
upper rack, a shallow cutlery tray on top when there are three or more. The lowest
rack may carry 1-4 cutlery baskets (fixed to it). Every rack runs above the open
door: its lowest point is higher than the door's inner face when the door lies flat.

The door is solid to a robot: its front skin, core and stainless inner skin (and the
dispenser moulded into it) all collide, over the whole leaf. A rack therefore declares
``requires_open="door"``: it slides out only with the door fully open (horizontal), as a
user opens the door before pulling a rack; the checks open it first too.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.geometry import Piece
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int, Schema

GROWTH = Growth(
    dishwasher=Rule(required=("body", "door", "racks"), optional={"handle": 0.8, "control_panel": 0.5}),
    rack=Rule(optional={"baskets": 0.7}),
    control_panel=Rule(required=("fascia", "display"), optional={"buttons": 0.7}),
    handle=Rule(one_of={"bar": 0.6, "pocket": 0.4}),
)
"""``handle.one_of`` is object-wide: the ``handle_style`` parameter (same weights)."""

_HANDLES = GROWTH.rules["handle"].one_of

SCHEMA = Schema((
    Float("width", "overall width (Y)", "m", 0.44, 0.66),
    Float("depth", "overall depth incl. the door, excl. the handle (X)", "m", 0.52, 0.66),
    Float("height", "overall height incl. the feet (Z)", "m", 0.76, 0.92),
    Float("wall", "tub wall thickness (insulation + liner)", "m", 0.018, 0.03),
    Float("door_thickness", "door thickness", "m", 0.045, 0.07),
    Float("kick_height", "kick plinth height under the door: the hinge height above the floor", "m",
          0.08, 0.14),
    Float("feet_height", "levelling feet height", "m", 0.01, 0.025),
    Int("rack_count", "sliding racks", "", 1, 4),
    Float("rack_travel", "rack slide-out as a fraction of its own depth", "", 0.6, 0.8),
    Float("wire_pitch", "spacing of the rack wires", "m", 0.045, 0.07),
    Int("basket_count", "cutlery baskets in the lowest rack (has_baskets)", "", 1, 4),
    Choice("handle_style", "door handle (has_handle)", choices=tuple(_HANDLES), weights=tuple(_HANDLES.values())),
    Float("handle_length", "handle length as a fraction of the width", "", 0.35, 0.7),
    Float("control_height", "control panel height (has_control_panel)", "m", 0.06, 0.1),
    Int("button_count", "push buttons on the control panel (has_buttons)", "", 2, 6),
    Float("button_size", "push button height (Z); press depth is 1/8 of it", "m", 0.012, 0.02),
    Choice("body_finish", "door front and cabinet finish", choices=("brushed_metal", "painted"),
           weights=(0.55, 0.45)),
    Choice("rack_finish", "rack wires: nylon coated or chrome", choices=("coated", "chrome"), weights=(0.7, 0.3)),
    Choice("handle_finish", "handle material", choices=("brushed_metal", "chrome", "plastic"),
           weights=(0.45, 0.35, 0.2)),
    *GROWTH.flags(),
))

GAP = 0.004  # door to cabinet and plinth
RACK_GAP = 0.004  # rack to rails, liner and neighbours
LINER = 0.0015
SHEET = 0.0008
CLEAR = 0.0025  # buttons in their fascia holes
FASCIA = 0.012  # control panel thickness (in front of the door)
DISPENSER = 0.003  # detergent dispenser standing proud of the door's inner skin
DOOR_ANGLE = math.pi / 2


def _finish(name: str) -> str:
    """A plastic handle is black or dark grey, never a toy colour."""
    return "plastic:black|dark_grey" if name == "plastic" else name


def _sheet(piece: Piece, t: float = SHEET) -> Piece:
    piece.sheet = t
    return piece


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    bp = Blueprint("dishwasher", materials={
        "body": appliance(p["body_finish"]), "tub": "brushed_metal:stainless", "door_inner": "plastic:dark_grey|black",
        "wire": "plastic:light_grey|white|dark_grey" if p["rack_finish"] == "coated" else "chrome",
        "wheel": "plastic:dark_grey|black", "basket": "plastic:light_grey|white",
        "arm": "plastic:light_grey|dark_grey", "handle": _finish(p["handle_finish"]),
        "panel": "plastic:black|dark_grey",
        "button": "plastic:black|dark_grey|light_grey", "display": "rubber", "feet": "rubber",
        "plinth": "plastic:black|dark_grey",
    })
    W, D, H, w, ft = p["width"], p["depth"], p["height"], p["wall"], p["door_thickness"]
    y0, y1 = -W / 2, W / 2
    xf = D / 2  # door front face
    xb1 = xf - ft - GAP  # cabinet front face
    xb0 = -D / 2
    zf = p["feet_height"]
    zh = zf + p["kick_height"]  # hinge and door bottom
    zt = H - 0.002  # door top

    # cavity (liner inner faces)
    cx0, cx1 = xb0 + w + LINER, xb1
    cy0, cy1 = y0 + w + LINER, y1 - w - LINER
    cz0 = zh + 0.02
    cz1 = H - w - LINER

    # the top band of the door carries the control panel and the handle; racks stay below it
    ctrl, handle = p["has_control_panel"], p["has_handle"]
    band = 0.025 + (p["control_height"] if ctrl else 0.0) + (0.03 if ctrl and handle else 0.0)
    if handle and not ctrl:
        band = 0.07
    z_use1 = min(cz1 - 0.032, zt - band - 0.01)  # racks' highest point: under the ceiling nozzle
    # lowest point of every rack: above the open (flat) door's inner face and its dispenser,
    # and above the spray arm
    z_use0 = max(zh + ft + DISPENSER + 0.012, cz0 + 0.05)

    body = bp.add("body", "body", _cabinet(p, (xb0, xb1, y0, y1, zf, H), (cx0, cx1, cy0, cy1, cz0, cz1), zh))

    # --- door ---------------------------------------------------------------------
    door = _door((xf - ft, xf, y0, y1, zh, zt))
    if handle:
        zh_handle = zt - band + 0.035 if ctrl else zt - 0.035
        door += _handle(p, xf + (FASCIA if ctrl else 0.0), W, zh_handle)
    bp.add("door", "door", door)
    bp.join(J.revolute(body, "door", (xf, 0.0, zh), (0, 1, 0), 0.0, DOOR_ANGLE, role="hinge"))
    if ctrl:
        _control_panel(bp, p, xf, (y0, y1), (zt - band + 0.02, zt - 0.004))

    # --- racks ------------------------------------------------------------------------
    n = p["rack_count"]
    weights = {1: [1.0], 2: [1.25, 1.0], 3: [1.25, 1.0, 0.42], 4: [1.1, 0.85, 0.75, 0.4]}[n]
    span = z_use1 - z_use0
    levels, z = [], z_use0
    for wk in weights:
        h = span * wk / sum(weights)
        levels.append((z, z + h))
        z += h
    rx0, rx1 = cx0 + 0.01, xb1 - 0.01
    for k, (za, zb) in enumerate(levels):
        tray = n >= 3 and k == n - 1
        zr = za - RACK_GAP  # rail top
        top = zb - (0.0 if k == n - 1 else RACK_GAP + 0.006)  # this rack's highest point
        pieces = _rack(p, (rx0, rx1), (cy0, cy1), za, top, tray, lower=(k == 0 and n >= 2))
        name = f"rack_{k}"
        bp.add(name, "rack", pieces)
        for s in (-1, 1):  # rails: channels on the side liners
            ya, yb = sorted((s * (cy1 - 0.013), s * (cy1 + LINER)))
            bp.extend(body, [g.box_between([cx0 + 0.03, ya, zr - 0.01], [cx1 - 0.004, yb, zr], "tub")])
        travel = p["rack_travel"] * (rx1 - rx0)
        bp.join(J.prismatic(body, name, (rx1, 0.0, za), (1, 0, 0), 0.0, travel, role="slide",
                            requires_open="door"))
        if k == 0 and p["has_baskets"] and not tray:
            _baskets(bp, name, p, (rx0, rx1), cy1 - 0.02, za, top)
    return bp


def _cabinet(p, outer, cavity, zh):
    """Insulated tub walls, stainless liner, base, plinth, feet, filter and spray arms."""
    xb0, xb1, y0, y1, zf, H = outer
    cx0, cx1, cy0, cy1, cz0, cz1 = cavity
    L = LINER
    wy0, wy1, wz0, wz1, wx0 = cy0 - L, cy1 + L, cz0 - L, cz1 + L, cx0 - L
    xf = xb1 + p["door_thickness"] + GAP
    pieces = [
        _sheet(g.box_between([xb0, y0, zf], [xb1, wy0, H], "body")),  # left
        _sheet(g.box_between([xb0, wy1, zf], [xb1, y1, H], "body")),  # right
        _sheet(g.box_between([xb0, wy0, wz1], [xb1, wy1, H], "body")),  # top
        _sheet(g.box_between([xb0, wy0, zh], [xb1, wy1, wz0], "body")),  # tub floor (insulated)
        _sheet(g.box_between([xb0, wy0, wz0], [wx0, wy1, wz1], "body")),  # back
        _sheet(g.box_between([xb0, wy0, zf], [xb1, wy1, zf + 0.004], "body")),  # base plate
        _sheet(g.box_between([xb0, wy0, zf + 0.004], [xb0 + 0.004, wy1, zh], "body")),  # rear cover
        # kick plinth under the door, a little behind the door front
        _sheet(g.box_between([xb1 - 0.004, y0, zf + 0.004], [xf - 0.012, y1, zh - GAP], "plinth")),
        # stainless liner: floor, ceiling, sides, back
        _sheet(g.box_between([wx0, wy0, wz0], [cx1, wy1, cz0], "tub")),
        _sheet(g.box_between([wx0, wy0, cz1], [cx1, wy1, wz1], "tub")),
        _sheet(g.box_between([wx0, wy0, cz0], [cx1, cy0, cz1], "tub")),
        _sheet(g.box_between([wx0, cy1, cz0], [cx1, wy1, cz1], "tub")),
        _sheet(g.box_between([wx0, cy0, cz0], [cx0, cy1, cz1], "tub")),
    ]
    # filter and lower spray arm on the floor, a nozzle from the ceiling
    xm = (cx0 + cx1) / 2
    pieces += [
        g.cylinder([cx0 + 0.08, 0.0, cz0], [cx0 + 0.08, 0.0, cz0 + 0.03], 0.035, "arm", 24),
        g.cylinder([xm, 0.0, cz0], [xm, 0.0, cz0 + 0.02], 0.022, "arm", 24),
    ]
    arm = min(cx1 - cx0, cy1 - cy0) / 2 - 0.03
    pieces.append(g.box_between([xm - 0.018, -arm, cz0 + 0.02], [xm + 0.018, arm, cz0 + 0.032], "arm", bevel=0.004))
    pieces.append(g.cylinder([xm, 0.0, cz1 - 0.025], [xm, 0.0, cz1], 0.016, "arm", 16))
    # levelling feet
    for x in (xb0 + 0.04, xb1 - 0.05):
        for y in (y0 + 0.04, y1 - 0.04):
            pieces.append(g.cylinder([x, y, 0.0], [x, y, zf], 0.015, "feet", 16))
    return pieces


def _door(box):
    """Front skin, inner core and stainless inner skin, each colliding over the whole leaf."""
    x0, x1, y0, y1, z0, z1 = box
    s = 0.0015
    front = _sheet(g.box_between([x1 - s, y0, z0], [x1, y1, z1], "body"))
    core = _sheet(g.box_between([x0 + s, y0, z0], [x1 - s, y1, z1], "door_inner"), 0.002)
    inner = _sheet(g.box_between([x0, y0 + 0.01, z0 + 0.01], [x0 + s, y1 - 0.01, z1 - 0.01], "tub"))
    # a detergent dispenser moulded into the inner skin
    yc, zc = 0.15 * (y1 - y0), z0 + 0.62 * (z1 - z0)
    dispenser = g.box_between([x0 - DISPENSER, yc - 0.06, zc - 0.04], [x0, yc + 0.06, zc + 0.04], "door_inner")
    return [front, core, inner, dispenser]


def _handle(p, xface, W, z):
    """A bar along Y (on the control panel's lower strip when there is one) or a pocket pull."""
    length = p["handle_length"] * W
    if p["handle_style"] == "bar":
        return g.bar_handle((xface, 0.0, z), (1, 0, 0), (0, 1, 0), length, "handle", standoff=0.028,
                            radius=0.007)
    return g.pull_handle((xface, 0.0, z), (1, 0, 0), (0, 1, 0), length, "handle", depth=0.016, lip=0.02)


def _control_panel(bp, p, xf, ys, zs):
    """A fascia on the top of the door front: display on the left, push buttons on the right."""
    y0, y1 = ys
    za, zb = zs
    xp = xf + FASCIA  # fascia front face
    W = y1 - y0
    # with a handle the lowest 3 cm of the fascia carry it; display and buttons sit above
    zl = za + (0.03 if p["has_handle"] else 0.0)
    zc = (zl + zb) / 2
    holes, movers = [], []
    extra = [g.box_between([xp - 0.001, y0 + 0.12 * W, zc - 0.011], [xp + 0.0015, y0 + 0.38 * W, zc + 0.011],
                           "display")]
    if p["has_buttons"]:
        nb = p["button_count"]
        bh = min(p["button_size"], zb - zl - 2 * CLEAR - 0.008)
        bw = min(1.6 * bh, 0.4 * W / nb - 2 * CLEAR - 0.004)
        pitch = 0.45 * W / nb
        for k in range(nb):
            yb = y0 + 0.5 * W + (k + 0.5) * pitch
            prot = 0.3 * bh + 0.002
            piece = g.box_between([xp - 0.008, yb - bw / 2, zc - bh / 2], [xp + prot, yb + bw / 2, zc + bh / 2],
                                  "button", bevel=0.15 * min(bh, bw))
            holes.append((yb - bw / 2 - CLEAR, zc - bh / 2 - CLEAR, yb + bw / 2 + CLEAR, zc + bh / 2 + CLEAR))
            movers.append((f"button_{k}", piece, (xp + prot, yb, zc), bh / 8))
    fascia = g.panel([xf, y0 + 0.004, za], [xp, y1 - 0.004, zb], "panel", "x", holes=holes)
    bp.add("control_panel", "control_panel", [fascia, *extra])
    bp.join(J.fixed("door", "control_panel"))
    for name, piece, origin, depth in movers:
        bp.add(name, "button", [piece])
        bp.join(J.prismatic("control_panel", name, origin, (-1, 0, 0), 0.0, depth, role="button"))


def _wire(a, b, r, slot="wire"):
    return g.cylinder(a, b, r, slot, 8)


def _rack(p, xs, cys, za, top, tray, lower):
    """A wire basket from ``za`` (its lowest point, the wheels) up to ``top``.

    Wheels ride over the rails next to the side liners; the basket sits between them.
    """
    rx0, rx1 = xs
    cy0, cy1 = cys
    ry = cy1 - 0.02  # basket half width (wheels reach out to cy1 - 0.006)
    rw = 0.011  # wheel radius
    r = 0.0025  # wire radius
    pitch = p["wire_pitch"]
    zc = za + rw  # wheel axle height; the basket bottom frame runs here
    pieces = []
    for x in (rx0 + 0.04, rx1 - 0.04):
        for s in (-1, 1):
            pieces.append(g.cylinder([x, s * ry, zc], [x, s * (cy1 - 0.006), zc], rw, "wheel", 16))
    height = max(top - zc, 0.02)
    wall_h = min(height, 0.05 if tray else (0.55 * height if lower else 0.7 * height))
    zt = zc + wall_h - r
    # bottom frame and top rim
    for z in (zc, zt):
        pieces += [
            _wire([rx0, -ry, z], [rx1, -ry, z], r), _wire([rx0, ry, z], [rx1, ry, z], r),
            _wire([rx0, -ry, z], [rx0, ry, z], r), _wire([rx1, -ry, z], [rx1, ry, z], r),
        ]
    # bottom grid: wires along X, a cross wire in the middle
    nx = max(3, int(2 * ry / pitch))
    for k in range(1, nx):
        y = -ry + k * 2 * ry / nx
        pieces.append(_wire([rx0, y, zc + 1.6 * r], [rx1, y, zc + 1.6 * r], 0.8 * r))
    pieces.append(_wire([(rx0 + rx1) / 2, -ry, zc], [(rx0 + rx1) / 2, ry, zc], r))
    # side walls: vertical wires
    ny = max(2, int(2 * ry / pitch))
    for k in range(1, ny):
        y = -ry + k * 2 * ry / ny
        for x in (rx0, rx1):
            pieces.append(_wire([x, y, zc], [x, y, zt], 0.8 * r))
    nxs = max(2, int((rx1 - rx0) / pitch))
    for k in range(1, nxs):
        x = rx0 + k * (rx1 - rx0) / nxs
        for y in (-ry, ry):
            pieces.append(_wire([x, y, zc], [x, y, zt], 0.8 * r))
    if lower and not tray:  # plate tines: two rows across the rack, behind the basket zone
        t_h = min(0.85 * height, 0.16)
        for xr in (rx0 + 0.3 * (rx1 - rx0), rx0 + 0.5 * (rx1 - rx0)):
            pieces.append(_wire([xr, -ry, zc + 1.6 * r], [xr, ry, zc + 1.6 * r], r))
            nt = max(3, int(2 * ry / 0.04))
            for k in range(1, nt):
                y = -ry + k * 2 * ry / nt
                pieces.append(_wire([xr, y, zc + 2 * r], [xr, y, zc + t_h], 0.7 * r))
    # a grip on the front rim
    pieces.append(g.box_between([rx1 - 0.006, -0.06, zt - 0.012], [rx1 + 0.004, 0.06, zt + r], "wheel",
                                bevel=0.002))
    return pieces


def _baskets(bp, rack, p, xs, ry, za, top):
    """1-4 open cutlery baskets side by side at the front of the lowest rack, fixed to it."""
    rx0, rx1 = xs
    n = p["basket_count"]
    r = 0.0025
    z0 = za + 0.011 + 2.6 * r + 0.001  # on the bottom grid
    h = min(0.14, top - z0 - 0.004)
    if h < 0.04:
        return
    depth = min(0.12, 0.35 * (rx1 - rx0))
    bw = min(0.12, (2 * ry - 0.02) / n - 0.004)
    xa, xb = rx1 - 0.012 - depth, rx1 - 0.012
    t = 0.003
    for k in range(n):
        yb1 = ry - 0.01 - k * (bw + 0.004)
        ya = yb1 - bw
        pieces = [
            g.box_between([xa, ya, z0], [xb, yb1, z0 + t], "basket"),
            g.box_between([xa, ya, z0 + t], [xa + t, yb1, z0 + h], "basket"),
            g.box_between([xb - t, ya, z0 + t], [xb, yb1, z0 + h], "basket"),
            g.box_between([xa + t, ya, z0 + t], [xb - t, ya + t, z0 + h], "basket"),
            g.box_between([xa + t, yb1 - t, z0 + t], [xb - t, yb1, z0 + h], "basket"),
        ]
        name = f"basket_{k}"
        bp.add(name, "basket", pieces)
        bp.join(J.fixed(rack, name))
