"""Microwave: a counter-top oven with a hinged glass door, a turntable and a control panel.

X is depth (the door faces +X), Y is width, Z is up. Seen from the front, the
door covers the left part of the front and hinges at its LEFT edge (min Y): it
turns about -Z through a pivot on its front face, so it swings outward and to
the left, never through the body. The control panel is a fascia on the right
(+Y) part of the front, fixed to the body; its push buttons slide in along -X,
its dials turn about X. The turntable (a glass tray with a rim, on a roller
ring with three wheels and a hub) spins about Z over a spindle in the middle
of the cavity floor.

The body is a sheet casing (top, bottom, sides, back) with a front bezel that
is a panel with the cavity opening cut through it, and a cavity liner of five
thin walls, so the cooking cavity stays hollow for the simulator.
The door and the panel fascia are a thin skin (the casing finish, or a contrasting
plastic) on a dark inner frame, so a metal finish does not make them solid steel.

Sizes are those of real counter-top microwaves (about 0.44-0.62 m wide,
0.32-0.46 m deep including the door, 0.25-0.36 m tall), not the reference
method's unscaled D U(0.5, 0.7), W U(0.6, 1.0), H U(0.35, 0.45).
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
    microwave=Rule(required=("body", "door", "plate", "control_panel"),
                   optional={"buttons": 0.75, "knob": 0.8}),
    door=Rule(required=("frame", "window"),
              one_of={"bar": 0.4, "recessed": 0.3, "release_button": 0.3}),
    plate=Rule(required=("glass_tray", "roller_ring", "hub")),
    control_panel=Rule(required=("fascia",)),
    knob=Rule(one_of={"ridge": 0.6, "round": 0.4}),
)
"""``door.one_of`` is object-wide, so it is the ``door_opener`` parameter (same weights);
``knob.one_of`` is drawn per dial from the structure stream."""

_OPENERS = GROWTH.rules["door"].one_of

SCHEMA = Schema((
    Float("width", "overall width (Y)", "m", 0.44, 0.62),
    Float("depth", "overall depth incl. the door, excl. the handle (X)", "m", 0.32, 0.46),
    Float("height", "overall height incl. the feet (Z)", "m", 0.25, 0.36),
    Float("panel_fraction", "control panel width as a fraction of the width", "", 0.2, 0.4),
    Float("wall", "casing sheet thickness", "m", 0.003, 0.006),
    Float("door_thickness", "door thickness", "m", 0.03, 0.045),
    Float("window_margin", "door frame width around the window (hinge side, top, bottom)", "m",
          0.025, 0.055),
    Float("plate_fraction", "turntable diameter as a fraction of the largest that fits", "",
          0.8, 0.95),
    Int("button_rows", "rows of three push buttons", "", 1, 3),
    Float("button_height", "push button height (Z); press depth is 1/8 of it", "m", 0.012, 0.02),
    Choice("button_shape", "push button shape", choices=("rect", "round"), weights=(0.65, 0.35)),
    Int("knob_count", "dials; auto = 2 without push buttons, else 1", "", 1, 2, auto=True),
    Float("knob_radius", "dial radius (capped at 0.38 x panel width)", "m", 0.016, 0.028),
    Choice("door_opener", "how the door is opened", choices=tuple(_OPENERS),
           weights=tuple(_OPENERS.values())),
    Float("handle_length", "door handle length as a fraction of the door height", "", 0.45, 0.8),
    Choice("body_finish", "casing material", choices=("painted", "brushed_metal", "plastic"),
           weights=(0.45, 0.3, 0.25)),
    Choice("door_finish", "door frame and panel: match the casing or contrast (plastic)",
           choices=("match", "contrast")),
    Choice("interior_finish", "cavity liner material", choices=("enamel", "painted")),
    Choice("handle_finish", "door handle material", choices=("chrome", "brushed_metal", "plastic")),
    Float("feet_height", "rubber feet height", "m", 0.006, 0.015),
    *GROWTH.flags(),
))

MATERIALS = {
    "body": "body_finish", "door": "plastic", "interior": "interior_finish", "glass": "glass",
    "plate": "glass:clear", "roller": "plastic", "button": "plastic", "knob": "plastic",
    "handle": "handle_finish", "door_inner": "rubber", "display": "rubber", "feet": "rubber", "trim": "chrome",
}
"""Material slot -> family, or the name of the parameter that picks the family."""

DOOR_ANGLE = math.pi / 2  # the door opens 0..pi/2
CLEAR = 0.0025  # clearance of buttons and dial stems in their panel holes
LINER = 0.002  # cavity liner wall thickness
BEZEL = 0.006  # front bezel thickness
SKIN = 0.003  # outer skin of the door and the panel fascia; behind it is the dark inner frame


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    bp = Blueprint("microwave", materials={  # finishes real microwaves are sold in
        slot: appliance(p[v] if v in SCHEMA.names else v) for slot, v in MATERIALS.items()})
    W, D, H, t, ft = p["width"], p["depth"], p["height"], p["wall"], p["door_thickness"]
    # door and fascia: a thin outer skin (casing or contrast finish) on a dark inner frame
    skin, inner = ("body", "door_inner") if p["door_finish"] == "match" else ("door", "door")

    # --- the front, left to right: door | gap | control panel ----------------
    y0, y1 = -W / 2, W / 2
    zc0, zc1 = p["feet_height"], H  # casing bottom and top
    zd0, zd1 = zc0 + 0.002, zc1 - 0.002  # door and panel
    panel_w = p["panel_fraction"] * W
    door_w_est = W - panel_w
    # the door's back corner on the free edge swings out by ~ft^2 / (2 width) in +Y
    gap_dp = max(0.003, 0.02 * door_w_est) + ft * ft / (2 * door_w_est) + 0.001
    yd1 = y1 - panel_w - gap_dp
    yp0 = y1 - panel_w
    gap_door = max(0.003, 0.02 * min(yd1 - y0, zd1 - zd0))
    xd1 = D / 2  # door front face (= panel front face)
    xd0 = xd1 - ft
    xf = xd0 - gap_door  # body front face (bezel)
    xb = -D / 2

    # --- cavity ------------------------------------------------------------
    cx0, cx1 = xb + t + 0.02, xf - BEZEL
    cy0, cy1 = y0 + t + 0.012, yd1 - 0.03
    cz0, cz1 = zc0 + t + 0.012, zc1 - t - 0.012

    body = bp.add("body", "body", _casing(p, (xb, xf, y0, y1, zc0, zc1), (cx0, cx1, cy0, cy1, cz0, cz1)))

    # --- turntable ---------------------------------------------------------
    pc = ((cx0 + cx1) / 2, (cy0 + cy1) / 2)
    r_fit = min(cx1 - cx0, cy1 - cy0) / 2
    radius = p["plate_fraction"] * (r_fit - max(0.004, 0.04 * r_fit))
    bp.extend(body, [g.cylinder([*pc, cz0], [*pc, cz0 + 0.008], 0.006, "roller", 16)])  # spindle
    bp.add("plate", "plate", _turntable(pc, cz0, radius))
    bp.join(J.continuous(body, "plate", (*pc, cz0), (0, 0, 1), role="turntable"))

    # --- door ----------------------------------------------------------------
    opener = p["door_opener"]
    m = p["window_margin"]
    m_right = max(1.5 * m, {"bar": 0.06, "recessed": 0.045}.get(opener, 0.0))
    hole = (y0 + m, zd0 + 1.15 * m, yd1 - m_right, zd1 - m)
    door = [
        g.panel([xd1 - SKIN, y0, zd0], [xd1, yd1, zd1], skin, "x", holes=[hole]),
        g.panel([xd0, y0, zd0], [xd1 - SKIN, yd1, zd1], inner, "x", holes=[hole]),
        g.box_between([xd1 - 0.009, hole[0], hole[1]], [xd1 - 0.004, hole[2], hole[3]], "glass"),
    ]
    zm, length = (zd0 + zd1) / 2, p["handle_length"] * (zd1 - zd0)
    if opener == "bar":
        door += g.bar_handle((xd1, yd1 - 0.03, zm), (1, 0, 0), (0, 0, 1), length, "handle",
                             standoff=0.025, radius=0.0065)
    elif opener == "recessed":
        door += g.pull_handle((xd1, yd1 - 0.014, zm), (1, 0, 0), (0, 0, 1), length, "handle",
                              depth=0.014, lip=0.016)
    bp.add("door", "door", door)
    # hinge on the front face at the left edge; about -Z the door swings out (+X) and left
    bp.join(J.revolute(body, "door", (xd1, y0, zd0), (0, 0, -1), 0.0, DOOR_ANGLE, role="hinge"))

    # --- control panel ---------------------------------------------------------
    _control_panel(bp, body, p, (xf, xd1), (yp0, y1), (zd0, zd1), (skin, inner), structure, geometry)
    return bp


def _casing(p, outer, cavity):
    """Casing, front bezel with the cavity opening, cavity liner, feet and side vents."""
    xb, xf, y0, y1, zc0, zc1 = outer
    cx0, cx1, cy0, cy1, cz0, cz1 = cavity
    t, L, xs = p["wall"], LINER, xf - BEZEL
    pieces = [
        g.box_between([xb, y0, zc0], [xs, y1, zc0 + t], "body"),  # bottom
        g.box_between([xb, y0, zc1 - t], [xs, y1, zc1], "body"),  # top
        g.box_between([xb, y0, zc0 + t], [xs, y0 + t, zc1 - t], "body"),  # left
        g.box_between([xb, y1 - t, zc0 + t], [xs, y1, zc1 - t], "body"),  # right
        g.box_between([xb, y0 + t, zc0 + t], [xb + t, y1 - t, zc1 - t], "body"),  # back
        g.panel([xs, y0, zc0], [xf, y1, zc1], "body", "x", holes=[(cy0, cz0, cy1, cz1)]),
        # cavity liner: floor, ceiling, left, right (divider), back
        g.box_between([cx0 - L, cy0 - L, cz0 - L], [cx1, cy1 + L, cz0], "interior"),
        g.box_between([cx0 - L, cy0 - L, cz1], [cx1, cy1 + L, cz1 + L], "interior"),
        g.box_between([cx0 - L, cy0 - L, cz0], [cx1, cy0, cz1], "interior"),
        g.box_between([cx0 - L, cy1, cz0], [cx1, cy1 + L, cz1], "interior"),
        g.box_between([cx0 - L, cy0, cz0], [cx0, cy1, cz1], "interior"),
    ]
    r = min(0.014, 0.6 * zc0 + 0.006)
    for x in (xb + 0.04, xs - 0.04):
        for y in (y0 + 0.04, y1 - 0.04):
            pieces.append(g.cylinder([x, y, 0.0], [x, y, zc0], r, "feet", 16))
    # louvres on the right side, towards the back and the top
    n, zt = int((zc1 - zc0) * 0.4 / 0.01), zc1 - t - 0.02
    for k in range(n):
        z = zt - k * 0.01
        pieces.append(g.box_between([xb + 0.04, y1, z - 0.0015], [xb + 0.04 + 0.3 * (xf - xb), y1 + 0.001,
                                                                  z + 0.0015], "display"))
    return pieces


def _turntable(pc, floor, radius):
    """Glass tray with a rim on a roller ring (three wheels, three arms, a hub).

    Everything is within ``radius`` of the axis and at least 3 mm above the floor
    and the spindle (spindle top = floor + 8 mm).
    """
    cx, cy = pc
    z_wheel = floor + 0.003 + 0.006  # wheel centres; wheel radius 6 mm
    z_tray = z_wheel + 0.006
    r_ring = 0.5 * radius
    pieces = [
        g.disc([cx, cy, z_tray + 0.003], radius - 0.004, 0.006, "plate", 48),
        g.shell([(radius - 0.002, z_tray), (radius, z_tray + 0.015)], 0.004, "plate",
                center=(cx, cy, 0.0), sections=48),
        g.shell([(r_ring + 0.004, z_wheel - 0.002), (r_ring + 0.004, z_wheel + 0.002)], 0.008,
                "roller", center=(cx, cy, 0.0), sections=32, convex_sectors=12),
        g.cylinder([cx, cy, z_tray - 0.004], [cx, cy, z_tray], 0.018, "roller", 24),  # hub
    ]
    for k in range(3):
        a = 2 * math.pi * k / 3 + math.pi / 6
        d = np.array([math.cos(a), math.sin(a), 0.0])
        c = np.array([cx, cy, z_wheel])
        pieces.append(g.cylinder(c + d * (r_ring - 0.005), c + d * (r_ring + 0.005), 0.006, "roller", 16))
        # arm from under the hub to the ring
        pieces.append(g.cylinder(c + d * 0.012 + [0, 0, 0.0005], c + d * (r_ring - 0.003) + [0, 0, 0.0005],
                                 0.0015, "roller", 8))
    return pieces


def _control_panel(bp, body, p, xs, ys, zs, slots, structure, geometry):
    """The fascia with holes; display, buttons, dials and the door release laid out top-down."""
    xf, xp = xs  # back and front face of the fascia
    ya, yb = ys
    pw, ph = yb - ya, zs[1] - zs[0]
    yc = (ya + yb) / 2
    buttons = p["has_buttons"]
    knobs = (p["knob_count"] or (1 if buttons else 2)) if p["has_knob"] else 0
    display = buttons or not knobs
    keypad = not buttons and not knobs  # a flat membrane keypad instead
    release = p["door_opener"] == "release_button"
    rows = p["button_rows"] if buttons else 0

    col_pitch = 0.82 * pw / 3
    bh = p["button_height"]
    kr = min(p["knob_radius"], 0.38 * pw)
    dh = min(max(0.12 * ph, 0.022), 0.04)
    rh = 0.022  # door release height

    def heights(f):
        return ([dh * f] if display else []) + [1.7 * bh * f] * rows + \
               ([0.3 * ph] if keypad else []) + [2 * kr * f + 0.012] * knobs + ([rh] if release else [])

    avail = ph - 0.04
    f = 1.0  # shrink buttons, dials and display together on a short panel
    while f > 0.5 and sum(heights(f)) + 0.008 * (len(heights(f)) - 1) > avail:
        f *= 0.95
    gap = min(0.014, max(0.006, (avail - sum(heights(f))) / (len(heights(f)) + 1)))
    bh, kr, dh = bh * f, kr * f, dh * f

    holes: list[tuple[float, float, float, float]] = []
    extra = []  # decoration on the fascia
    movers = []  # (name, label, pieces, origin, press depth)
    z = zs[1] - 0.02  # top of the next item
    if display:
        extra.append(g.box_between([xp - 0.001, yc - 0.39 * pw, z - dh], [xp + 0.0015, yc + 0.39 * pw, z],
                                   "display"))
        z -= dh + gap

    prot = 0.3 * bh + 0.002  # a pressed button (1/8 of its height in) still stands proud
    for r in range(rows):
        zb = z - 0.85 * bh
        for c in range(3):
            yb_c = yc + (c - 1) * col_pitch
            if p["button_shape"] == "rect":
                bw = min(col_pitch - 2 * CLEAR - 0.005, 1.8 * bh)
                piece = g.box_between([xp - 0.008, yb_c - bw / 2, zb - bh / 2],
                                      [xp + prot, yb_c + bw / 2, zb + bh / 2], "button",
                                      bevel=0.15 * bh)
                half = (bw / 2, bh / 2)
            else:
                rad = min(0.6 * bh, (col_pitch - 2 * CLEAR - 0.005) / 2)
                piece = g.cylinder([xp - 0.008, yb_c, zb], [xp + prot, yb_c, zb], rad, "button", 24)
                half = (rad, rad)
            holes.append((yb_c - half[0] - CLEAR, zb - half[1] - CLEAR,
                          yb_c + half[0] + CLEAR, zb + half[1] + CLEAR))
            movers.append((f"button_{r}_{c}", "button", [piece], (xp + prot, yb_c, zb), half[1] / 4))
        z -= 1.7 * bh + gap

    if keypad:
        extra.append(g.box_between([xp - 0.001, ya + 0.12 * pw, z - 0.3 * ph],
                                   [xp + 0.001, yb - 0.12 * pw, z], "display"))
        z -= 0.3 * ph + gap

    z_floor = zs[0] + 0.02 + (rh + gap if release else 0.0)
    if release:
        rw = 0.62 * pw
        zr = zs[0] + 0.02 + rh / 2
        piece = g.box_between([xp - 0.008, yc - rw / 2, zr - rh / 2], [xp + 0.006, yc + rw / 2, zr + rh / 2],
                              "button", bevel=0.003)
        holes.append((yc - rw / 2 - CLEAR, zr - rh / 2 - CLEAR, yc + rw / 2 + CLEAR, zr + rh / 2 + CLEAR))
        movers.append(("door_release", "button", [piece], (xp + 0.006, yc, zr), rh / 8))

    knob_parts = []
    if knobs:
        span = (z - z_floor) / knobs
        for k in range(knobs):
            zk = z - span * (k + 0.5)
            r_k = kr * (1.0 if k == 0 else float(geometry.uniform(0.8, 0.95)))
            r_k = min(r_k, 0.5 * span - 0.004)
            style = GROWTH.choose("knob", structure)
            stem = max(0.003, 0.2 * r_k)
            holes.append((yc - stem - CLEAR, zk - stem - CLEAR, yc + stem + CLEAR, zk + stem + CLEAR))
            knob_parts.append((f"knob_{k}", _dial(xp, yc, zk, r_k, stem, style), (xp, yc, zk)))

    panel = bp.add("control_panel", "control_panel",
                   [g.panel([xp - SKIN, ya, zs[0]], [xp, yb, zs[1]], slots[0], "x", holes=holes),
                    g.panel([xf, ya, zs[0]], [xp - SKIN, yb, zs[1]], slots[1], "x", holes=holes), *extra])
    bp.join(J.fixed(body, panel))
    for name, label, pieces, origin, depth in movers:
        bp.add(name, label, pieces)
        bp.join(J.prismatic(panel, name, origin, (-1, 0, 0), 0.0, depth, role="button"))
    for name, pieces, origin in knob_parts:
        bp.add(name, "knob", pieces)
        bp.join(J.continuous(panel, name, origin, (1, 0, 0), role="knob"))


def _dial(xp, y, z, r, stem, style):
    """A dial in front of the panel face (3 mm gap) on a stem through a panel hole."""
    x0 = xp + 0.003
    pieces = [g.cylinder([xp - 0.008, y, z], [x0 + 0.001, y, z], stem, "knob", 16)]
    if style == "ridge":  # a thin skirt and a grip bar across it
        depth = max(0.014, 0.7 * r)
        pieces += [
            g.cylinder([x0, y, z], [x0 + 0.005, y, z], r, "knob", 32),
            g.box_between([x0 + 0.0045, y - 0.18 * r, z - 0.85 * r], [x0 + depth, y + 0.18 * r, z + 0.85 * r],
                          "knob", bevel=0.002),
            g.box_between([x0 + depth - 0.0005, y - 0.0015, z + 0.45 * r],
                          [x0 + depth + 0.001, y + 0.0015, z + 0.8 * r], "trim"),
        ]
    else:  # a round cap on a skirt with a pointer mark
        depth = max(0.016, 0.8 * r)
        pieces += [
            g.cylinder([x0, y, z], [x0 + 0.004, y, z], r, "knob", 32),
            g.cylinder([x0 + 0.0035, y, z], [x0 + depth, y, z], 0.8 * r, "knob", 32),
            g.box_between([x0 + depth - 0.0005, y - 0.0015, z + 0.35 * r],
                          [x0 + depth + 0.001, y + 0.0015, z + 0.7 * r], "trim"),
        ]
    return pieces
