"""Oven: a freestanding range or a built-in oven with a bottom-hinged glass door and racks.

X is depth (the door faces +X), Y is width, Z is up. Seen from the floor up the front is:
a recessed kick plinth, a storage drawer (a real drawer sliding out along +X, or a fixed
drawer front), a trim strip, the oven door, and above it either the cooktop edge (``range``:
the control panel is a backguard standing on the back of the cooktop) or the control panel
fascia (``wall``: a built-in oven standing on its own plinth, no cooktop).

The door hinges at its bottom front edge and falls forward: it turns about +Y through a pivot
on its front face (rotating +Z about +Y gives +X), 0..pi/2. Its hinge is as high above the
floor as the bar handle stands proud (plus a strip), so the open door, lying flat with the
handle hanging under it, never reaches the floor or the open drawer. The closed door's centre
of mass lies behind its hinge line (the slab is behind the front face, the handle is a light
tube), so gravity presses it shut against its closed limit.

The body is a sheet casing (sides, back, bottom, top or cooktop), a front frame that is a panel
with the cavity opening cut through it, and a cavity liner of five enamel walls, so the cavity
stays hollow. Wire racks rest on side rails (2 mm above them) and slide out along +X by
``rack_travel`` of their depth: their real pull-out, through the door's opening. The door is
solid (glass, skins and frame all collide), so a rack's joint declares
``requires_open="door"``: it moves only with the door fully open (lying flat, its inner face
well below the lowest rack), which the checks and a user honour by opening the door first.
The drawer under the door and the cooktop grates are not behind the door and move freely.

The control panel carries knobs (continuous, or revolute +-pi/4, about the panel normal +X,
symmetric about their axis so their centre of mass is on it) and optional push buttons
(pressed along -X). A range's cooktop has burners and optional cast grates side by side, each
on a ``limited_floating`` joint: x 0..``grate_slide`` D forward, y +-6 mm, z 0..lift up
(gravity holds them on the cooktop, their lower z limit). Grates start in front of the knobs
and their feet run along their side edges, clear of the burners, so they slide off freely.
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
    oven=Rule(required=("body", "door", "control_panel", "racks"),
              optional={"drawer": 0.45},
              one_of={"range": 0.65, "wall": 0.35}),
    door=Rule(required=("window", "bar_handle")),
    control_panel=Rule(required=("knobs",), optional={"buttons": 0.5}),
    cooktop=Rule(required=("burners",), optional={"grates": 0.8}),
    knob=Rule(one_of={"ridge": 0.6, "round": 0.4}),
)
"""``oven.one_of`` is the object-wide ``style``; ``knob.one_of`` the object-wide ``knob_style``.
A cooktop (burners, grates) exists on a ``range`` only."""

_STYLES = GROWTH.rules["oven"].one_of
_KNOBS = GROWTH.rules["knob"].one_of

SCHEMA = Schema((
    Choice("style", "freestanding range (cooktop, backguard panel) or built-in oven (front panel)",
           choices=tuple(_STYLES), weights=tuple(_STYLES.values())),
    Float("width", "overall width (Y)", "m", 0.5, 0.9),
    Float("depth", "body depth incl. the door, excl. the handle (X)", "m", 0.55, 0.7),
    Float("height", "floor to cooktop (range) or to the top (built-in)", "m", 0.85, 0.98),
    Float("panel_fraction", "control panel height as a fraction of the oven height above the hinge",
          "", 0.2, 0.4),
    Float("door_thickness", "door thickness", "m", 0.04, 0.06),
    Float("window_margin", "door frame width around the window", "m", 0.05, 0.09),
    Float("handle_length", "door handle length as a fraction of the door width", "", 0.6, 0.9),
    Float("plinth_height", "recessed kick plinth height", "m", 0.03, 0.07),
    Float("drawer_height", "storage drawer front height", "m", 0.1, 0.16),
    Float("drawer_travel", "drawer opening as a fraction of its depth", "", 0.55, 0.75),
    Int("rack_count", "wire racks", "", 2, 4),
    Float("rack_travel", "rack pull-out as a fraction of its depth (the door must be open)",
          "", 0.5, 0.75),
    Int("knob_count", "knobs; auto = burners + 1 (range) or 2-3 (built-in)", "", 2, 8, auto=True),
    Float("knob_radius", "knob radius (shrunk to fit the panel)", "m", 0.016, 0.026),
    Choice("knob_motion", "knobs turn freely or +-pi/4", choices=("continuous", "revolute")),
    Choice("knob_style", "knob shape", choices=tuple(_KNOBS), weights=tuple(_KNOBS.values())),
    Int("button_count", "push buttons under the display", "", 2, 6),
    Int("grate_count", "cooktop grates side by side; auto = 2 below 0.7 m width, else 3", "", 2, 3,
        auto=True),
    Float("grate_slide", "grate slide forward as a fraction of the depth", "", 0.5, 0.75),
    Float("grate_lift", "grate lift off the cooktop", "m", 0.02, 0.05),
    Choice("body_finish", "casing and door material", choices=("brushed_metal", "enamel", "painted"),
           weights=(0.5, 0.3, 0.2)),
    Choice("handle_finish", "handle material", choices=("chrome", "brushed_metal", "plastic")),
    *GROWTH.flags(),
))

MATERIALS = {
    "body": "body_finish", "door": "body_finish", "door_inner": "painted:black|charcoal",
    "interior": "enamel:black|cobalt", "glass": "glass", "rack": "chrome", "handle": "handle_finish",
    "knob": "plastic:black|dark_grey|light_grey", "button": "plastic:black|dark_grey",
    "display": "rubber:deep_black", "cooktop": "enamel:black", "grate": "enamel:black",
    "burner": "brushed_metal", "cap": "enamel:black", "trim": "chrome", "feet": "rubber",
    "plinth": "painted:black|charcoal",
}
"""Material slot -> family, or the name of the parameter that picks the family."""

DOOR_ANGLE = math.pi / 2
SHEET = 0.0008  # steel sheet of the casing, door and liner
T = 0.01  # casing panels (modelled solid, massed as sheet)
GAP_DOOR = 0.004  # door <-> body front
CLEAR = 0.0025  # knob stems and buttons in their panel holes
FACE = 0.004  # control panel face plate
HANDLE_STANDOFF, HANDLE_R = 0.04, 0.01
RACK_R = 0.0028  # rack wire radius
RAIL_W, RAIL_H = 0.012, 0.006
GRATE_GAP = 0.02  # between neighbouring grates
GRATE_SIDE = 0.006  # grate sideways play (+-)


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    bp = Blueprint("oven", materials={  # finishes real ovens are sold in
        slot: appliance(p[v] if v in SCHEMA.names else v) for slot, v in MATERIALS.items()})
    W, D, H, ft = p["width"], p["depth"], p["height"], p["door_thickness"]
    is_range = p["style"] == "range"

    # --- planes ------------------------------------------------------------------------
    xb, xd1 = -D / 2, D / 2  # back of the body, front face of the door
    xd0 = xd1 - ft  # door back face
    xf = xd0 - GAP_DOOR  # body front plane
    y0, y1 = -W / 2, W / 2
    z_pl = p["plinth_height"]
    z_dt = z_pl + p["drawer_height"]  # drawer top
    drop = HANDLE_STANDOFF + 2 * HANDLE_R  # how far the handle hangs under the open door
    z_h = z_dt + drop + 0.014  # hinge line (door bottom)
    z_div = z_dt + 0.004  # divider between the drawer bay and the oven
    panel_h = p["panel_fraction"] * (H - z_h)
    gap_top = 0.005 + ft * ft / (2 * 0.3)  # the top back edge of the door rises ~ft^2/2h when opening
    if is_range:
        z_dtop = H - 0.045  # door top; a trim strip under the cooktop edge above it
    else:
        z_dtop = H - panel_h - gap_top

    # cavity (inside the liner)
    cy0, cy1 = y0 + T + 0.03, y1 - T - 0.03
    cx0, cx1 = xb + T + 0.04, xf - T
    cz0 = z_h + max(ft + 0.015, 0.05)
    cz1 = z_dtop - 0.05

    body = bp.add("body", "body", _casing(p, (xb, xf, xd1, y0, y1, H), (z_pl, z_dt, z_div, z_h),
                                          (cx0, cx1, cy0, cy1, cz0, cz1), is_range))

    if is_range:  # trim strip between the door top and the cooktop edge
        bp.extend(body, [g.box_between([xf, y0, z_dtop + gap_top], [xd1, y1, H - T], "body")])

    # --- drawer -------------------------------------------------------------------------------
    if p["has_drawer"]:
        _drawer(bp, body, p, (xb, xf, xd1), (y0, y1), (z_pl, z_dt, z_div))
    else:
        bp.extend(body, [g.box_between([xf - T, y0, z_pl], [xd1, y1, z_dt], "body"),
                         g.box_between([xd1, -0.3 * W, z_dt - 0.03], [xd1 + 0.002, 0.3 * W, z_dt - 0.025],
                                       "trim")])

    # --- door ----------------------------------------------------------------------------------
    m = p["window_margin"]
    dy0, dy1 = y0 + 0.003, y1 - 0.003
    hole = (dy0 + m, z_h + 1.2 * m, dy1 - m, z_dtop - 1.6 * m)
    door = [
        g.panel([xd1 - 0.003, dy0, z_h], [xd1, dy1, z_dtop], "door", "x", holes=[hole]),
        g.panel([xd0 + 0.003, dy0, z_h], [xd1 - 0.003, dy1, z_dtop], "door_inner", "x", holes=[hole]),
        g.panel([xd0, dy0 + 0.02, z_h + 0.02], [xd0 + 0.003, dy1 - 0.02, z_dtop - 0.02], "interior", "x",
                holes=[hole]),
        g.box_between([xd1 - 0.008, hole[0], hole[1]], [xd1 - 0.003, hole[2], hole[3]], "glass"),
        g.box_between([xd0 + 0.003, hole[0], hole[1]], [xd0 + 0.007, hole[2], hole[3]], "glass"),
    ]
    for pc in door[:3]:
        pc.sheet = SHEET
    handle = g.bar_handle((xd1, 0.0, z_dtop - 0.045), (1, 0, 0), (0, 1, 0),
                          p["handle_length"] * (dy1 - dy0), "handle", standoff=HANDLE_STANDOFF, radius=HANDLE_R)
    for pc in handle:
        pc.sheet = 0.0012  # a tube
    bp.add("door", "door", door + handle)
    # hinge on the front face at the bottom edge; about +Y the top falls forward (+X)
    bp.join(J.revolute(body, "door", (xd1, 0.0, z_h), (0, 1, 0), 0.0, DOOR_ANGLE, role="hinge"))

    # --- racks on side rails ------------------------------------------------------------------------
    n = p["rack_count"]
    levels = n + 1
    lo, hi = cz0 + 0.045, cz1 - 0.07
    rails = [lo + k * (hi - lo) / (levels - 1) for k in range(levels)]
    empty = int(structure.integers(0, levels))  # one rail level stays free
    rx0, rx1 = cx0 + 0.02, cx1 - 0.035  # the racks' front wire sits ~5 cm behind the door
    for z_r in rails:
        for ya, yb in ((cy0, cy0 + RAIL_W), (cy1 - RAIL_W, cy1)):
            bp.extend(body, [g.box_between([cx0 + 0.01, ya, z_r - RAIL_H], [cx1 - 0.004, yb, z_r], "interior")])
    k = 0
    for lvl, z_r in enumerate(rails):
        if lvl == empty:
            continue
        name = f"rack_{k}"
        zc = z_r + 0.002 + RACK_R  # wires 2 mm above the rails
        bp.add(name, "rack", _rack((rx0, rx1), (cy0 + 0.004, cy1 - 0.004), zc))
        # behind the door: the rack slides out only once the door lies open
        travel = p["rack_travel"] * (rx1 - rx0)
        bp.join(J.prismatic(body, name, (rx1, 0.0, zc), (1, 0, 0), 0.0, travel, role="slide",
                            requires_open="door"))
        k += 1

    # --- control panel -------------------------------------------------------------------------------
    burners = []
    if is_range:
        n_grates = p["grate_count"] or (2 if W < 0.7 else 3)
        bgd = 0.06
        px0, px1, pz0, pz1 = xb, xb + bgd, H, H + panel_h
        burners = _burner_spots(n_grates, (y0 + 0.02, y1 - 0.02))
        n_knobs = p["knob_count"] or min(8, sum(len(s) for s in burners) + 1)
    else:
        px0, px1, pz0, pz1 = xf, xd1, z_dtop + gap_top, H
        n_knobs = p["knob_count"] or 2 + int(structure.integers(0, 2))
    knob_front = _control_panel(bp, body, p, (px0, px1), (y0 + 0.003, y1 - 0.003), (pz0, pz1), n_knobs)

    # --- cooktop: burners and grates ----------------------------------------------------------------
    if is_range:
        _cooktop(bp, body, p, (knob_front + 0.012, xd1 - 0.015), H, burners)
    return bp


# ---------------------------------------------------------------------------------------------------


def _casing(p, outer, zs, cavity, is_range):
    """Casing, front frame with the cavity opening, liner, strip, plinth and feet."""
    xb, xf, xd1, y0, y1, H = outer
    z_pl, z_dt, z_div, z_h = zs
    cx0, cx1, cy0, cy1, cz0, cz1 = cavity
    L = 0.003  # liner
    ztop = H - T
    pieces = [
        g.box_between([xb, y0, z_pl], [xf - T, y0 + T, ztop], "body"),  # left
        g.box_between([xb, y1 - T, z_pl], [xf - T, y1, ztop], "body"),  # right
        g.box_between([xb, y0 + T, z_pl], [xb + T, y1 - T, ztop], "body"),  # back
        g.box_between([xb + T, y0 + T, z_pl], [xf - T, y1 - T, z_pl + T], "body"),  # bottom
        g.box_between([xb + T, y0 + T, z_div], [xf - T, y1 - T, z_div + T], "body"),  # divider
        # front frame around the cavity opening
        g.panel([xf - T, y0, z_div], [xf, y1, ztop if is_range else H], "body", "x",
                holes=[(cy0, cz0, cy1, cz1)]),
        # trim strip under the door (the open door's handle hangs in front of it)
        g.box_between([xf, y0, z_div], [xd1, y1, z_h - GAP_DOOR], "body"),
        # cavity liner: floor, ceiling, sides, back
        g.box_between([cx0 - L, cy0 - L, cz0 - L], [cx1, cy1 + L, cz0], "interior"),
        g.box_between([cx0 - L, cy0 - L, cz1], [cx1, cy1 + L, cz1 + L], "interior"),
        g.box_between([cx0 - L, cy0 - L, cz0], [cx1, cy0, cz1], "interior"),
        g.box_between([cx0 - L, cy1, cz0], [cx1, cy1 + L, cz1], "interior"),
        g.box_between([cx0 - L, cy0, cz0], [cx0, cy1, cz1], "interior"),
        # recessed kick plinth and levelling feet
        g.box_between([xb + 0.03, y0 + 0.01, 0.0], [xf - 0.04, y1 - 0.01, z_pl], "plinth"),
    ]
    if is_range:  # cooktop over the whole depth, and the trim strip between door and cooktop
        pieces.append(g.box_between([xb, y0, ztop], [xd1, y1, H], "cooktop"))
    else:
        pieces.append(g.box_between([xb, y0, ztop], [xf - T, y1, H], "body"))
    for pc in pieces[:6]:
        pc.sheet = SHEET
    for pc in pieces[7:12]:
        pc.sheet = SHEET
    for x in (xb + 0.05, xf - 0.06):
        for y in (y0 + 0.05, y1 - 0.05):
            pieces.append(g.cylinder([x, y, 0.0], [x, y, z_pl], 0.015, "feet", 16))
    return pieces


def _drawer(bp, body, p, xs, ys, zs):
    """A storage drawer in the bay under the oven: a front and an open tray behind it."""
    xb, xf, xd1 = xs
    y0, y1 = ys
    z_pl, z_dt, z_div = zs
    c, wt = 0.004, 0.008
    fx0 = xf + 0.003
    tx0 = xb + T + 0.015
    ty0, ty1 = y0 + T + c, y1 - T - c
    tz0, tz1 = z_pl + T + c, z_dt - 0.012
    front = g.box_between([fx0, y0 + 0.003, z_pl + 0.002], [xd1, y1 - 0.003, z_dt], "body", bevel=0.002)
    tray = [
        g.box_between([tx0, ty0, tz0], [fx0, ty1, tz0 + wt], "body"),
        g.box_between([tx0, ty0, tz0 + wt], [fx0, ty0 + wt, tz1], "body"),
        g.box_between([tx0, ty1 - wt, tz0 + wt], [fx0, ty1, tz1], "body"),
        g.box_between([tx0, ty0 + wt, tz0 + wt], [tx0 + wt, ty1 - wt, tz1], "body"),
    ]
    for pc in [front, *tray]:
        pc.sheet = SHEET
    pull = g.pull_handle((xd1, 0.0, z_dt - 0.022), (1, 0, 0), (0, 1, 0), 0.5 * (y1 - y0), "handle",
                         depth=0.016, lip=0.014)
    bp.add("drawer", "drawer", [front, *tray, *pull])
    travel = p["drawer_travel"] * (fx0 - tx0)
    bp.join(J.prismatic(body, "drawer", (xd1, 0.0, z_pl), (1, 0, 0), 0.0, travel, role="slide"))


def _rack(xs, ys, zc):
    """A chrome wire rack: a rectangular frame, wires along X, two cross wires."""
    x0, x1 = xs
    ya, yb = ys[0] + RACK_R, ys[1] - RACK_R
    r = RACK_R
    pieces = [
        g.cylinder([x0, ya, zc], [x1, ya, zc], r, "rack", 8),
        g.cylinder([x0, yb, zc], [x1, yb, zc], r, "rack", 8),
        g.cylinder([x0, ya, zc], [x0, yb, zc], r, "rack", 8),
        g.cylinder([x1, ya, zc], [x1, yb, zc], r, "rack", 8),
    ]
    n = max(3, int((yb - ya) / 0.045))
    for k in range(1, n):
        y = ya + (yb - ya) * k / n
        pieces.append(g.cylinder([x0 + r, y, zc], [x1 - r, y, zc], 0.7 * r, "rack", 6))
    for f in (1 / 3, 2 / 3):
        x = x0 + (x1 - x0) * f
        pieces.append(g.cylinder([x, ya, zc], [x, yb, zc], 0.8 * r, "rack", 6))
    return pieces


def _burner_spots(n_grates, ys):
    """Burners per grate: (y, radius, front?) lists; the middle of three grates has one."""
    ya, yb = ys
    gw = (yb - ya - (n_grates - 1) * GRATE_GAP) / n_grates
    out = []
    for k in range(n_grates):
        g0 = ya + k * (gw + GRATE_GAP)
        out.append([(g0, g0 + gw)] * (1 if (n_grates == 3 and k == 1) else 2))
    return out


def _cooktop(bp, body, p, xs, H, spots):
    """Burners on the cooktop and, optionally, a grate over each column of burners."""
    gx0, gx1 = xs
    depth = gx1 - gx0
    gap = 0.002
    foot, feet_h, bar = 0.014, 0.03, 0.01
    for k, column in enumerate(spots):
        ga, gb = column[0]
        gw = gb - ga
        yc = (ga + gb) / 2
        n = len(column)
        r_burn = min(gw / 2 - foot - 0.008, 0.35 * depth / n, 0.055)
        xs_b = [gx0 + depth * (j + 0.5) / n for j in range(n)]
        for j, xc in enumerate(xs_b):
            rb = r_burn * (1.0 if (j + k) % 2 == 0 else 0.8)
            bp.extend(body, [
                g.cylinder([xc, yc, H], [xc, yc, H + 0.012], rb, "burner", 32),
                g.cylinder([xc, yc, H + 0.012], [xc, yc, H + 0.02], 0.65 * rb, "cap", 32),
            ])
        if not p["has_grates"]:
            continue
        z0 = H + gap
        zb0, zb1 = z0 + feet_h, z0 + feet_h + bar
        pieces = []
        for x in (gx0, gx1 - foot):
            for y in (ga, gb - foot):
                pieces.append(g.box_between([x, y, z0], [x + foot, y + foot, zb0], "grate"))
        pieces += [  # frame
            g.box_between([gx0, ga, zb0], [gx1, ga + bar, zb1], "grate"),
            g.box_between([gx0, gb - bar, zb0], [gx1, gb, zb1], "grate"),
            g.box_between([gx0, ga + bar, zb0], [gx0 + bar, gb - bar, zb1], "grate"),
            g.box_between([gx1 - bar, ga + bar, zb0], [gx1, gb - bar, zb1], "grate"),
        ]
        for j in range(1, n):  # divider between burners
            x = gx0 + depth * j / n
            pieces.append(g.box_between([x - bar / 2, ga + bar, zb0], [x + bar / 2, gb - bar, zb1], "grate"))
        for xc in xs_b:  # fingers over each burner, a cross through its centre
            pieces.append(g.box_between([xc - 0.005, ga + bar, zb1 - 0.008], [xc + 0.005, gb - bar, zb1],
                                        "grate"))
            span = depth / n / 2 - bar / 2
            pieces.append(g.box_between([xc - span, yc - 0.005, zb1 - 0.008], [xc + span, yc + 0.005, zb1],
                                        "grate"))
        name = f"grate_{k}"
        bp.add(name, "grate", pieces)
        D = p["depth"]
        bp.join(J.limited_floating(body, name, ((gx0 + gx1) / 2, yc, z0), ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
                                   ((0.0, p["grate_slide"] * D), (-GRATE_SIDE, GRATE_SIDE),
                                    (0.0, p["grate_lift"]))))


def _control_panel(bp, body, p, xs, ys, zs, n_knobs):
    """A hollow panel housing; knobs left and right, display and buttons in the middle.

    Returns the x of the knobs' (and buttons') front, for the cooktop layout.
    """
    xa, xp = xs  # back and front face of the housing
    ya, yb = ys
    za, zb = zs
    ph = zb - za
    buttons = p["button_count"] if p["has_buttons"] else 0
    zm = (za + zb) / 2
    margin = 0.03
    centre_w = (max(0.11, buttons * 0.028) + 0.03) if buttons else 0.0
    pitch = (yb - ya - 2 * margin - centre_w) / n_knobs
    r = min(p["knob_radius"], 0.4 * pitch, 0.5 * ph - 0.012)
    holes, decor, movers = [], [], []

    left = (n_knobs + 1) // 2 if buttons else n_knobs
    ys_k = []
    for i in range(n_knobs):
        if buttons and i >= left:
            ys_k.append(ya + margin + centre_w + (i + 0.5) * pitch)
        else:
            ys_k.append(ya + margin + (i + 0.5) * pitch)
    style = p["knob_style"]
    front = xp
    for i, y in enumerate(ys_k):
        stem = max(0.003, 0.2 * r)
        holes.append((y - stem - CLEAR, zm - stem - CLEAR, y + stem + CLEAR, zm + stem + CLEAR))
        pieces, depth = _knob(xp, y, zm, r, stem, style)
        front = max(front, xp + 0.003 + depth)
        movers.append((f"knob_{i}", "knob", pieces, (xp, y, zm), None))

    if buttons:
        yc = ya + margin + left * pitch + centre_w / 2
        dh = min(0.03, 0.3 * ph)
        bh = min(0.016, 0.22 * ph)
        zd = zm + 0.004 + dh / 2 if ph > 0.1 else zm + bh
        decor.append(g.box_between([xp - 0.001, yc - (centre_w - 0.03) / 2, zd - dh / 2],
                                   [xp + 0.0015, yc + (centre_w - 0.03) / 2, zd + dh / 2], "display"))
        zbt = zd - dh / 2 - 0.008 - bh / 2
        bw = min(0.02, (centre_w - 0.03) / buttons - 2 * CLEAR - 0.004)
        press = max(0.003, bh / 4)
        prot = press + 0.002
        for j in range(buttons):
            y = yc - (centre_w - 0.03) / 2 + (j + 0.5) * (centre_w - 0.03) / buttons
            piece = g.box_between([xp - 0.008, y - bw / 2, zbt - bh / 2], [xp + prot, y + bw / 2, zbt + bh / 2],
                                  "button", bevel=0.0015)
            holes.append((y - bw / 2 - CLEAR, zbt - bh / 2 - CLEAR, y + bw / 2 + CLEAR, zbt + bh / 2 + CLEAR))
            movers.append((f"button_{j}", "button", [piece], (xp + prot, y, zbt), press))
        front = max(front, xp + prot)

    w = 0.004
    housing = [
        g.panel([xp - FACE, ya, za], [xp, yb, zb], "body", "x", holes=holes),
        g.box_between([xa, ya, za], [xa + w, yb, zb], "body"),  # back
        g.box_between([xa + w, ya, zb - w], [xp - FACE, yb, zb], "body"),  # top
        g.box_between([xa + w, ya, za], [xp - FACE, yb, za + w], "body"),  # bottom
        g.box_between([xa + w, ya, za + w], [xp - FACE, ya + w, zb - w], "body"),  # sides
        g.box_between([xa + w, yb - w, za + w], [xp - FACE, yb, zb - w], "body"),
    ]
    for pc in housing:
        pc.sheet = SHEET
    panel = bp.add("control_panel", "control_panel", housing + decor)
    bp.join(J.fixed(body, panel))
    for name, label, pieces, origin, press in movers:
        bp.add(name, label, pieces)
        if label == "button":
            bp.join(J.prismatic(panel, name, origin, (-1, 0, 0), 0.0, press, role="button"))
        elif p["knob_motion"] == "continuous":
            bp.join(J.continuous(panel, name, origin, (1, 0, 0), role="knob"))
        else:
            bp.join(J.revolute(panel, name, origin, (1, 0, 0), -math.pi / 4, math.pi / 4, role="knob"))
    return front


def _knob(xp, y, z, r, stem, style):
    """A knob in front of the panel face (3 mm gap) on a stem through a hole; symmetric about its
    axis (the pointer line runs across the whole face), so its centre of mass is on the axis."""
    x0 = xp + 0.003
    pieces = [g.cylinder([xp - 0.008, y, z], [x0 + 0.001, y, z], stem, "knob", 16)]
    if style == "ridge":
        depth = max(0.016, 0.8 * r)
        pieces += [
            g.cylinder([x0, y, z], [x0 + 0.006, y, z], r, "knob", 32),
            g.box_between([x0 + 0.0055, y - 0.2 * r, z - 0.9 * r], [x0 + depth, y + 0.2 * r, z + 0.9 * r],
                          "knob", bevel=0.002),
            g.box_between([x0 + depth - 0.0005, y - 0.0012, z - 0.8 * r], [x0 + depth + 0.0008, y + 0.0012,
                                                                           z + 0.8 * r], "trim"),
        ]
    else:
        depth = max(0.018, 0.9 * r)
        pieces += [
            g.cylinder([x0, y, z], [x0 + 0.005, y, z], r, "knob", 32),
            g.cylinder([x0 + 0.0045, y, z], [x0 + depth, y, z], 0.82 * r, "knob", 32),
            g.box_between([x0 + depth - 0.0005, y - 0.0012, z - 0.7 * r], [x0 + depth + 0.0008, y + 0.0012,
                                                                           z + 0.7 * r], "trim"),
        ]
    return pieces, depth + 0.0008
