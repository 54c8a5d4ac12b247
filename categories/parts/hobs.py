"""Hob (cooktop) parts: a built-in hob's top plate over its housing or a counter-top cooker's casing, its
cooking zones (gas burners under cast grates, electric coils on drip pans, induction zones printed on
glass) and the anchors of its controls.

A hob is built on the ground plane, centred on the z axis, its front facing +X (world-aligned, like
:mod:`.appliance`). :func:`hob_body` returns an :class:`~infmob_usd.assembly.Assembly` whose anchors are
the controls' places (``knob_<k>``: z out of the face the knob stands on, x "up" on that face; ``key_<k>``
on the front fascia) and the grates' seats (``grate_<k>``: z up, where a grate lifts off). Burners reuse the
range's (:func:`.ovens.burner_columns`, :func:`.ovens.grate`), so a hob's gas zones are a range's.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from . import appliance as A
from . import controls
from . import ovens as OV

HOB = {
    # built-in hobs: 30 cm domino (2 zones) to 90 cm / 36 in (5-6 zones), 0.49-0.53 m deep; a 4-8 mm top
    # (ceramic glass or enamelled / stainless steel) over a housing 45-100 mm deep (Bosch PGH6B5B90, Bosch
    # PIE631FB1E, Frigidaire FFGC3026S, GE JP3030DJBB installation sheets)
    "built_in": {"width": (0.3, 0.9), "depth": (0.49, 0.53), "housing": (0.045, 0.1), "inset": 0.025,
                 "five": 0.75},
    # counter-top cookers: 2 zones, 0.5-0.6 m wide, 0.3-0.36 m deep, 0.06-0.11 m tall (Cuisinart CB-60 coil,
    # Duxtop 9600LS induction, Ramblewood GDC2-LN gas spec sheets); a front fascia carries the controls
    "counter": {"width": (0.5, 0.6), "depth": (0.3, 0.36), "height": (0.06, 0.11), "feet": 0.008,
                "room": 0.014},
    "plate": {"gas": 0.004, "coil": 0.004, "induction": 0.006},  # top plate thickness
    "sheet": 0.0008,  # a steel top's sheet (0.6-1 mm stainless or enamelled); a glass-ceramic top is solid
    "strip": 0.075,  # a built-in hob's control strip along its front edge (knobs on top)
    "margin": 0.03,  # zones keep this far inside the plate's edges
    # electric zones: 145-210 mm coils / induction zones (GE WB30M1 6 in and WB30M2 8 in coils; Bosch
    # PIE631FB1E: 145, 180 and 210 mm zones on a 592 x 522 mm glass); a smaller zone is ~0.75 of the larger.
    # Neighbouring zones (a coil with its drip pan) keep >= 50 mm of bare top between them, as on every hob in
    # those installation sheets (centres 250-290 mm apart on a 60 cm four-zone hob): pans never touch.
    "zone": {"radius": 0.105, "least": 0.0725, "small": 0.75, "gap": 0.05},
    # built-in widths by zone count (Bosch / NEFF / Frigidaire hob ranges): a 30 cm domino carries 2 zones,
    # 45-60 cm 3, 58-77 cm 4, 75-92 cm 5 or 6; the ``width`` parameter is mapped onto its count's range
    "widths": {3: (0.45, 0.6), 4: (0.58, 0.77), 5: (0.75, 0.92), 6: (0.75, 0.92)},
    # a coil element's sheath 8-9 mm wide wound at a 13-15 mm pitch, 4 turns on a 6 in coil, 5 on an 8 in one
    # (GE WB30M1, WB30M2), on a wire support 3-5 mm over a chrome drip pan with a 4 mm lip (GE WB31M19/20 pans)
    "coil": {"wire": 0.0045, "pitch": 0.014, "points": 32, "pan": 0.012, "over": 0.004, "lip": 0.004},
    "ring": 0.0008,  # an induction zone's printed ring (proud of the glass, massless in effect)
    # knobs: gas valve knobs 38-45 mm turning ~270 deg from off (push-to-turn); infinite switches 300 deg
    "knob": {"radius": 0.02, "stem": 0.004, "gas": math.radians(270), "electric": math.radians(300)},
    # touch keys on the glass's front edge, in a row across the middle (Duxtop 9600LS, Bosch PIE631FB1E
    # installation sheets: power, function, -, +, timer in a 50-60 mm band, keys ~40 mm apart); a key on
    # the top stays in view and reach on a hob sunk into a worktop, where a side skirt would be hidden
    "key": controls.Button(half=(0.011, 0.007), shape="rect", proud=0.003, travel=0.002),
    "key_strip": 0.055, "key_pitch": 0.04,
}
PAN_RIM = 0.014  # m, a coil's drip pan reaches this far past the coil (its flared lip)
KNOB = controls.Dial(radius=HOB["knob"]["radius"], stem=HOB["knob"]["stem"], style="ridge",
                     turns=HOB["knob"]["gas"])
COIL_KNOB = controls.Dial(radius=HOB["knob"]["radius"], stem=HOB["knob"]["stem"], style="round",
                          turns=HOB["knob"]["electric"])


def columns(n: int, W: float) -> list[int]:
    """Zones per column, left to right, for ``n`` zones (2: side by side, or front and back on a narrow
    domino; 3: two and a wok; 5: a wok between two pairs; 4 and 6: pairs), as on Bosch / Frigidaire 2-6
    burner hobs."""
    if n == 2 and W < HOB["built_in"]["five"] / 2:
        return [2]
    return {1: [1], 2: [1, 1], 3: [2, 1], 4: [2, 2], 5: [2, 1, 2], 6: [2, 2, 2]}[n]


def zones(xs, ys, n: int, rim: float = 0.0) -> list[tuple[float, float, float]]:
    """Electric zones (x, y, radius) in :func:`columns` over the area ``xs`` x ``ys`` (which each zone's outer
    edge, its radius plus ``rim``, e.g. a coil's drip pan, stays inside). Every zone is as large as the area
    lets up to :data:`HOB` ``zone`` radius, its neighbours at least ``gap`` away edge to edge; a column of two
    pairs a large zone with a small one, the room left spread evenly before, between and after them."""
    z = HOB["zone"]
    per = columns(n, ys[1] - ys[0] + 2 * HOB["margin"])
    gw, depth = (ys[1] - ys[0]) / len(per), xs[1] - xs[0]
    out = []
    for k, m in enumerate(per):
        if m == 1:
            r = min(gw / 2 - z["gap"] / 2, depth / 2) - rim
        else:  # a large and a small zone one behind the other, their radii summing to at most ``pair``
            pair = (depth - z["gap"]) / 2 - 2 * rim
            r = min(gw / 2 - z["gap"] / 2 - rim, pair / (1 + z["small"]))
        r = min(r, z["radius"])
        small = min(r, max(z["small"] * r, z["least"]), pair - r) if m == 2 else r  # no smaller than a real one
        radii = [r] if m == 1 else ([r, small] if k % 2 == 0 else [small, r])
        slack = (depth - sum(2 * (q + rim) for q in radii) - (m - 1) * z["gap"]) / (m + 1)
        x = xs[0]
        for j, q in enumerate(radii):
            x += slack + (z["gap"] if j else 0.0) + q + rim
            out.append((x, ys[0] + (k + 0.5) * gw, q))
            x += q + rim
    return out


def coil(x: float, y: float, z: float, r: float) -> list[g.Piece]:
    """An electric coil element on its chrome drip pan (:data:`HOB` ``coil``): the pan (the collision: it carries
    what stands on it) with a raised lip and its dark centre hole, a spiral of sheathed tube standing on a
    three-armed support over it, its straight tail running out to the terminal block at the pan's back edge
    (element, support and terminal drawn, no collision)."""
    c = HOB["coil"]
    w, top = c["wire"], z + c["pan"] / 2
    turns = max(3.0, math.floor(2 * 0.72 * r / c["pitch"]) / 2)  # as many half turns as the pitch lets
    t = np.linspace(0.0, 1.0, int(turns * c["points"]) + 1)
    rr = 0.2 * r + t * (0.92 * r - 0.2 * r)
    ang = 2 * math.pi * turns * t
    zc = top + c["over"] + w
    path = np.stack([x + rr * np.cos(ang), y + rr * np.sin(ang), np.full_like(t, zc)], axis=1)
    a = ang[-1]
    out = np.array([math.cos(a), math.sin(a), 0.0])
    tail = [path[-1], [x + (r + 0.004) * out[0], y + (r + 0.004) * out[1], zc], [x + (r + 0.014) * out[0],
                                                                                   y + (r + 0.014) * out[1], top]]
    pieces = [g.disc([x, y, z + c["pan"] / 4], r + 0.01, c["pan"] / 2, "trim", None),
              g.shell([(r + 0.01, top - 0.001), (r + PAN_RIM, top + c["lip"])], 0.003, "trim").translated((x, y, 0))
              .replace(convex=()),
              g.disc([x, y, top + 0.0003], 0.12 * r, 0.0006, "element", 24).replace(convex=()),
              g.tube(path, w, "element").replace(convex=()), g.tube(tail, w, "element").replace(convex=())]
    for k in range(3):  # the support arms under the coil
        b = a + (k + 0.5) * 2 * math.pi / 3
        d = np.array([math.cos(b), math.sin(b)])
        lo, hi = 0.18 * r, 0.95 * r
        arm = g.box(((hi - lo), 0.004, c["over"]), ((lo + hi) / 2, 0.0, 0.0), "burner")
        m = np.eye(4)
        m[:2, :2] = [[d[0], -d[1]], [d[1], d[0]]]
        m[:3, 3] = (x, y, top + c["over"] / 2)
        pieces.append(arm.transformed(m).replace(convex=()))
    return pieces


def induction_ring(x: float, y: float, z: float, r: float) -> list[g.Piece]:
    """An induction zone printed on the glass: a thin flat ring centred on the zone."""
    t = HOB["ring"]
    return [g.shell([(r, z), (r, z + t)], 0.003, "display", center=(x, y, 0.0))]


WIDTH = (0.58, 0.92)  # the stovetop category's ``width`` parameter range (mapped per zone count by :func:`size`)


def size(mount: str, n: int, W: float, D: float, H: float) -> tuple[float, float, float]:
    """A hob's (width, depth, height): a built-in two-zone hob is a 30 cm domino, more zones span their count's
    :data:`HOB` ``widths`` (``W`` mapped from :data:`WIDTH` onto it; Bosch PCR9A5B90, Frigidaire FFGC3626S); a
    counter cooker's own ranges mapped from the
    parameters' (``W``, ``D`` over the built-in ranges, ``H`` over the housing range)."""
    b, c = HOB["built_in"], HOB["counter"]
    if mount == "counter":
        return tuple(lo + (hi - lo) * (v - vlo) / (vhi - vlo) for v, (vlo, vhi), (lo, hi) in
                     ((W, b["width"], c["width"]), (D, b["depth"], c["depth"]), (H, b["housing"], c["height"])))
    if n == 2:
        return b["width"][0], D, H
    lo, hi = HOB["widths"][n]
    return lo + (hi - lo) * (W - WIDTH[0]) / (WIDTH[1] - WIDTH[0]), D, H


def hob_body(design: str, mount: str, W: float, D: float, H: float, n: int, n_keys: int = 0
             ) -> tuple[Assembly, list, list]:
    """A hob of ``design`` (gas, coil, induction) and ``mount`` (built_in, counter) ``W`` x ``D``, ``H`` tall,
    with ``n`` zones and ``n_keys`` touch keys (else knobs). Returns its body assembly (anchors ``knob_<k>`` per
    zone on a built-in top, or ``key_<k>`` per key on the top's front strip; ``grate_<k>`` per gas column), the
    gas columns (for :func:`grate`) and the cooking height."""
    plate_t = HOB["plate"][design]
    x0, x1, y0, y1 = -D / 2, D / 2, -W / 2, W / 2
    zt = H - plate_t  # plate's underside
    m = HOB["margin"]
    pieces, anchors = [], {}
    top_knobs = mount == "built_in" and not n_keys
    strip = HOB["strip"] if top_knobs else HOB["key_strip"] if n_keys else 0.0
    area_x, area_y = (x0 + m, x1 - m - strip), (y0 + m, y1 - m)
    holes = []
    if mount == "built_in":  # the housing stops short of the knob strip: the valves' stems reach under it
        ins = HOB["built_in"]["inset"]
        pieces.append(g.box_between([x0 + ins, y0 + ins, 0.0], [x1 - max(ins, strip), y1 - ins, zt], "housing")
                      .replace(sheet=A.OVEN_SHEET))
    else:  # a hollow behind the fascia (the controls' stems), closed at the sides
        ft, room = HOB["counter"]["feet"], HOB["counter"]["room"]
        xr = x1 - 0.004 - max(room, strip)  # and the keys' travel under the strip
        pieces += [g.box_between([x0, y0, ft], [xr, y1, zt], "housing").replace(sheet=A.OVEN_SHEET)]
        pieces += [g.box_between([xr, y, ft], [x1 - 0.004, y + 0.004, zt], "housing").replace(sheet=A.OVEN_SHEET)
                   for y in (y0, y1 - 0.004)]
        pieces += [g.cylinder([x, y, 0.0], [x, y, ft], 0.01, "feet", 16) for x in (x0 + 0.03, x1 - 0.03)
                   for y in (y0 + 0.03, y1 - 0.03)]
    spots = np.linspace(y0 + W / (2 * n), y1 - W / (2 * n), n) if n > 1 else [0.0]
    if top_knobs:
        xk = x1 - strip / 2
        for k, y in enumerate(spots):
            anchors[f"knob_{k}"] = Frame.at((xk, float(y), H), z=(0, 0, 1), x=(1, 0, 0))
            holes.append(_hole_xy(xk, float(y), KNOB.stem))
    if n_keys:
        key, xk = HOB["key"], x1 - strip / 2
        for k in range(n_keys):
            y = (k - (n_keys - 1) / 2) * HOB["key_pitch"]
            anchors[f"key_{k}"] = Frame.at((xk, y, H), z=(0, 0, 1), x=(1, 0, 0))
            c = A.CLEAR
            holes.append((xk - key.half[1] - c, y - key.half[0] - c, xk + key.half[1] + c, y + key.half[0] + c))
    top = g.panel([x0, y0, zt], [x1, y1, H], "top", "z", holes=holes)
    pieces.append(top if design == "induction" else top.replace(sheet=HOB["sheet"]))
    cols = []
    if design == "gas":
        burners, cols = OV.burner_columns(area_x, area_y, H, columns(n, W))
        pieces += burners
    else:
        for x, y, r in zones(area_x, area_y, n, PAN_RIM if design == "coil" else 0.0):
            pieces += coil(x, y, H, r) if design == "coil" else induction_ring(x, y, H, r)
    return Assembly.single("body", pieces, anchors), cols, (area_x, zt)


def _hole_xy(x: float, y: float, r: float) -> tuple[float, float, float, float]:
    c = A.CLEAR + r
    return (x - c, y - c, x + c, y + c)


def fascia(W: float, D: float, H: float, n_knobs: int, n_keys: int, plate_t: float) -> tuple[list, dict]:
    """A counter cooker's front fascia (the housing's front face, 4 mm thick) with holes for ``n_knobs``
    knob stems or ``n_keys`` touch keys in a row (none: a plain face); its pieces and the controls' anchors
    (z +X, x up)."""
    x1, ft = D / 2, HOB["counter"]["feet"]
    zc = (ft + H - plate_t) / 2
    anchors, holes = {}, []
    n = n_knobs or n_keys
    ys = [] if not n else np.linspace(-W / 2 + W / (2 * n), W / 2 - W / (2 * n), n) if n > 1 else [0.0]
    key = HOB["key"]
    for k, y in enumerate(ys):
        y = float(y)
        if n_knobs:
            anchors[f"knob_{k}"] = Frame.at((x1, y, zc), z=(1, 0, 0), x=(0, 0, 1))
            holes.append((y - KNOB.stem - A.CLEAR, zc - KNOB.stem - A.CLEAR, y + KNOB.stem + A.CLEAR,
                          zc + KNOB.stem + A.CLEAR))
        else:
            anchors[f"key_{k}"] = Frame.at((x1, y, zc), z=(1, 0, 0), x=(0, 0, 1))
            c = key.cutout("front", (y, zc))
            holes.append((c.lo[0], c.lo[1], c.hi[0], c.hi[1]))
    return [g.panel([x1 - 0.004, -W / 2, ft], [x1, W / 2, H - plate_t], "housing", "x", holes=holes)
            .replace(sheet=A.OVEN_SHEET)], anchors


def grate(xs, col, H) -> tuple[list[g.Piece], Frame]:
    """A loose cast grate over a burner column (:func:`.ovens.grate`) and its lift frame (z up)."""
    pieces, origin, _ = OV.grate(xs, col, H)
    return pieces, Frame.at(origin, z=(0, 0, 1))
LIFT = 0.03  # a grate is lifted ~30 mm off its feet before it is free (the core caps lift-offs there)
