"""Window parts: frames with glazing stops and tracks, casement and sliding sashes, levers, shutters
(louvred, panelled, boarded; bifold on wide windows), curtain rods and pleated curtain halves.

World-aligned frames: the room side faces +x. Sizes of real windows: frames 0.6-2.5 m, 70-140 mm
deep, 40-90 mm faces; sashes 0.4-0.85 m wide; 6 mm float glass; shutters 25-40 mm; curtain rods
50-200 mm above the frame (manufacturers' catalogues; BS 644, EN 14351-1).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import trimesh

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp

from . import hardware

CLR = 0.004  # m: clearance around every moving part
GLASS = 0.006  # glass pane thickness
LIP = 0.012  # glazing stop / track lip overlap into the opening
TRACK_GAP = 0.016  # sliding: back sash front face to front sash back face
DIVIDER = 0.006  # sliding: track divider width (X)
PULL = 0.007  # sliding: finger pull depth on a back-track sash (fits in TRACK_GAP)


@dataclass(frozen=True)
class Ranges:
    """Ranges of a window's parameters (lo, hi), m, rad, a count or a fraction. Frames 0.6-2.5 m, 70-140 mm
    deep with 40-90 mm faces, mullions 40-80 mm, sashes 0.4-0.85 m wide with 35-70 mm stiles, 2-4 x 1-2
    glazing bars, transoms 18-30 % of the height, sills 30-100 mm deep and 25-50 mm thick (manufacturers'
    catalogues; BS 644, EN 14351-1); shutters 25-40 mm thick, leaves 0.55-0.8 m, opening 72-86 degrees;
    curtains 60-200 mm clear of the sash handles on rods 50-200 mm above the frame and 50-250 mm past it, 60-98 %
    of the drop and 45-75 % gathered when open (curtain and shutter makers' fitting guides)."""

    width: tuple[float, float] = (0.6, 2.5)
    height: tuple[float, float] = (0.6, 2.5)
    sash_width: tuple[float, float] = (0.4, 0.85)
    frame_depth: tuple[float, float] = (0.07, 0.14)
    frame_width: tuple[float, float] = (0.04, 0.09)
    mullion_width: tuple[float, float] = (0.04, 0.08)
    stile_width: tuple[float, float] = (0.035, 0.07)
    bar_rows: tuple[int, int] = (2, 4)
    bar_cols: tuple[int, int] = (1, 2)
    transom_fraction: tuple[float, float] = (0.18, 0.3)
    sill_depth: tuple[float, float] = (0.03, 0.1)
    sill_thickness: tuple[float, float] = (0.025, 0.05)
    shutter_thickness: tuple[float, float] = (0.025, 0.04)
    shutter_leaf_width: tuple[float, float] = (0.55, 0.8)
    shutter_angle: tuple[float, float] = (1.25, 1.5)
    curtain_offset: tuple[float, float] = (0.06, 0.2)
    curtain_rise: tuple[float, float] = (0.05, 0.2)
    curtain_overhang: tuple[float, float] = (0.05, 0.25)
    curtain_drop: tuple[float, float] = (0.6, 0.98)
    curtain_open: tuple[float, float] = (0.45, 0.75)



RANGES = Ranges()



# -- the window's layout: frame proportions, locks, vents (``categories/window.py`` reads these) --------
LOCK = dict(base=(0.064, 0.012), lever=(0.05, 0.012, 0.006), hub=0.009, gap=0.001)
"""Cam sash lock (m): base length along the rail and height, lever (length, width, thickness), hub radius, gap
between base and lever. Double-hung sashes carry one cam lock, two on units wider than about 36 in (0.9 m)
(Andersen 400 / Marvin / Pella double-hung hardware: 60-75 mm bases, the lever turning a quarter to a half turn
in the rail's plane)."""
LOCKS_FROM = 0.9
LEVER_TURN = np.pi / 2  # an espagnolette lever's quarter turn (Hoppe, Roto: 90 degrees to open)
VENT = dict(length=0.3, height=0.02, depth=0.012, wall=0.002, slide=0.08, stroke=0.035,
            grip=(0.016, 0.02, 0.01))  # the slide's thumb grip (chosen, no datasheet): width, how far it stands
# out of the housing's face (far enough for fingertips to pinch it clear of the housing), height
CLR_VENT = 0.0015  # the vent's slide in its housing


TRANSOM_FROM = 1.1  # frames taller than this may have a transom light
SILL_EAR = 0.03  # the sill reaches this far past the frame on each side
BOTTOM_RAIL = 1.25  # the bottom rail is this much wider than the jambs


SIZES = {"tilt_turn": dict(width=(0.6, 1.6), height=(0.6, 2.4)), "awning": dict(width=(0.6, 2.5), height=(0.4, 1.0)),
         "double_hung": dict(width=(0.6, 1.2), height=(0.9, 2.0))}
"""Frame sizes of the designs that come in a narrower range (manufacturers' size tables: Roto, Velfac,
Andersen 400 series): a wider or taller draw is brought into it."""


MIN_SASH = 0.25
"""m: the narrowest sash a frame is divided into. The automatic count (opening / sash_width >= 0.4 m,
rounded) never goes below 0.26 m; the narrowest stock casements are ~0.4 m overall (Andersen 400 series
size tables). Fuzz draw 51 (sash_count 4 in a 0.6 m tilt-and-turn frame) made 6 cm sashes narrower than their
two stiles, whose turns jammed at 0.8 rad."""
JAMB_MAX = 0.12  # the jambs' and head's face width: at most this share of the frame's width and height
MULLION_MAX = 0.1  # a mullion: at most this share of the opening
MOST_SASHES = 4  # the automatic sash count: at most four
SOFTWOOD = 500.0
"""kg/m^3 of a painted frame, sash or shutter: painted joinery is softwood (pine, spruce, fir) or
engineered laminated pine, 400-550 kg/m^3 at 12 % moisture (USDA Wood Handbook FPL-GTR-282, 2021,
ch. 5 tables of specific gravity), not the MDF (~750) the ``painted`` family weighs as."""
SILL_DRIP = 0.012  # an exterior sill's drip edge: 12 mm square under its outer edge
# an espagnolette lever's free spindle: 1.5 mm off the rose's face (the spindle was sunk 2 mm into it), 5.5 mm
SPINDLE = (0.0035, 0.0055)
KNOB = (0.016, 0.035)  # m: a sash knob's cap radius and projection (32 mm knob, 35 mm proud)


def _knob(at: Frame) -> list[g.Piece]:
    """A sash knob (:func:`~.hardware.knob_handle`) standing on the sash face at ``at`` (z out of it)."""
    return list(hardware.knob_handle(*KNOB, "handle").placed(at).pieces)


def sash(y0, y1, z0, z1, x0, x1, sw, p) -> list[g.Piece]:
    """A glazed sash: a frame of stiles and rails, a pane, optional glazing bars."""
    sw = min(sw, 0.22 * (y1 - y0), 0.22 * (z1 - z0))
    hole = (y0 + sw, z0 + sw, y1 - sw, z1 - sw)
    xc = (x0 + x1) / 2
    pieces = [
        g.panel([x0, y0, z0], [x1, y1, z1], "frame", "x", holes=[hole]),
        g.box_between([xc - GLASS / 2, hole[0] - 0.004, hole[1] - 0.004],
                      [xc + GLASS / 2, hole[2] + 0.004, hole[3] + 0.004], "glass"),
    ]
    if p["glazing"] == "bars":
        bar, bd = min(0.022, 0.6 * sw), 0.35 * (x1 - x0)
        rows, cols = p["bar_rows"], p["bar_cols"] if (y1 - y0) > 0.45 else 1
        for r in range(1, rows):
            z = hole[1] + r * (hole[3] - hole[1]) / rows
            pieces.append(g.box_between([xc - bd, hole[0], z - bar / 2], [xc + bd, hole[2], z + bar / 2], "frame"))
        for c in range(1, cols):
            y = hole[0] + c * (hole[2] - hole[0]) / cols
            pieces.append(g.box_between([xc - bd, y - bar / 2, hole[1]], [xc + bd, y + bar / 2, hole[3]], "frame"))
    return pieces


def lever(x, y, z) -> list[g.Piece]:
    """A window lever on a rose: the lever points down."""
    return [
        g.box_between([x, y - 0.016, z - 0.04], [x + 0.008, y + 0.016, z + 0.03], "handle", bevel=0.003,
                      name="handle"),
        g.cylinder([x + 0.006, y, z], [x + 0.03, y, z], 0.0055, "handle", 16, name="handle"),
        g.box_between([x + 0.022, y - 0.0075, z - 0.12], [x + 0.036, y + 0.0075, z + 0.012], "handle",
                      bevel=0.004, name="handle"),
    ]


def casement(frame, light, p, dims, transom, middle):
    """Frame members and inward-opening casement sashes; returns (sashes, room-side x).

    ``middle()`` draws the hinge side ("left" or "right") of a middle sash. Sashes are
    ``(name, pieces, joint spec)``; the frame's pieces go to ``frame``, a transom light's glass
    to ``light``."""
    fd, yi0, yi1, zi0, zs1, mw = dims
    n = p["sash_count"] or int(np.clip(round((yi1 - yi0) / p["sash_width"]), 1, 4))
    st = min(float(np.clip(0.5 * fd, 0.035, 0.06)), fd - CLR - 0.015)
    xs0, xs1 = fd / 2 - st, fd / 2  # sash back and front faces (flush with the frame)
    # hinge sides: left half on the left, right half on the right, the middle one either way
    sides = []
    for i in range(n):
        c = i - (n - 1) / 2
        sides.append("left" if c < 0 else "right" if c > 0 else middle())
    # every sash sweeps at most sqrt(s^2 + st^2) from its hinge: its free back corner creeps out
    s_low = 0.8 * ((yi1 - yi0) - (n - 1) * mw) / n
    creep = math.hypot(s_low, st) - s_low
    # members between sashes: a mullion, or nothing for a French pair (free edges facing)
    between = []
    for i in range(n - 1):
        french = sides[i] == "left" and sides[i + 1] == "right" and p["meeting"] == "french"
        between.append("french" if french else "mullion")
    gaps = []  # (gap at the left edge, gap at the right edge) of each sash
    for i, side in enumerate(sides):
        free = CLR + creep + 0.001
        left = CLR if side == "left" else free
        right = CLR if side == "right" else free
        if i > 0 and between[i - 1] == "french":
            left = creep + CLR / 2 + 0.001
        if i < n - 1 and between[i] == "french":
            right = creep + CLR / 2 + 0.001
        gaps.append((left, right))
    members = sum(mw for b in between if b == "mullion")
    s = ((yi1 - yi0) - members - sum(a + b for a, b in gaps)) / n

    cells, y, cell_start = [], yi0, yi0
    spans = []
    for i in range(n):
        a = y + gaps[i][0]
        spans.append((a, a + s))
        y = a + s + gaps[i][1]
        if i == n - 1 or between[i] == "mullion":
            cells.append((cell_start, zi0, y, zs1))
            y += mw if i < n - 1 else 0.0
            cell_start = y
    holes = cells + ([transom] if transom else [])
    frame.append(ring(xs0 - CLR, fd / 2, holes, p))
    stops = [(a + LIP, b + LIP, c - LIP, d - LIP) for a, b, c, d in holes]
    frame.append(ring(-fd / 2, xs0 - CLR, stops, p))
    if transom:
        a, b, c, d = transom
        light.append(g.box_between([xs0 - CLR - GLASS, a + LIP / 2, b + LIP / 2], [xs0 - CLR, c - LIP / 2, d - LIP / 2],
                                   "glass"))

    sashes = []
    zb, zt = zi0 + CLR, zs1 - CLR
    for i, ((a, b), side) in enumerate(zip(spans, sides)):
        pieces = sash(a, b, zb, zt, xs0, xs1, p["stile_width"], p)
        sw = min(p["stile_width"], 0.22 * (b - a), 0.22 * (zt - zb))
        y_free = b - sw / 2 if side == "left" else a + sw / 2
        zh = zb + min(0.5 * (zt - zb), 1.0)
        if p["handle_style"] == "lever":
            pieces += lever(xs1, y_free, zh)
        else:
            pieces += _knob(Frame.at((xs1, y_free, zh), z=(1, 0, 0)))
        y_hinge = a if side == "left" else b
        for zk in (zb + 0.12 * (zt - zb), zt - 0.12 * (zt - zb)):  # hinge knuckles (no collision)
            knuckle = g.cylinder([xs1 + 0.0045, y_hinge, zk - 0.03], [xs1 + 0.0045, y_hinge, zk + 0.03], 0.0045,
                                 "handle", 12, name="hinge").replace(convex=[])
            pieces.append(knuckle)
        axis = (0, 0, -1) if side == "left" else (0, 0, 1)
        spec = J.revolute("frame", f"sash_{i}", (xs1, y_hinge, zb), axis, 0.0, math.pi / 2, role="hinge")
        sashes.append((f"sash_{i}", pieces, spec))
    # curtains hang far enough in front for the sashes to open some way before the core stops them
    x_room = xs1 + (0.04 if p["handle_style"] == "lever" else 0.036) + 0.5 * s
    return sashes, x_room


def ring(x0, x1, holes, p) -> g.Piece:
    """A frame slab from x0 to x1 over the whole frame face with the given openings."""
    W, H = p["width"], p["height"]
    z0 = p["sill_thickness"] if p["has_sill"] else 0.0
    return g.panel([x0, -W / 2, z0], [x1, W / 2, z0 + H], "frame", "x", holes=holes)


def sliding(frame, light, p, dims, transom, middle):
    """Frame with two tracks and sliding sashes; returns (sashes, room-side x)."""
    fd, yi0, yi1, zi0, zs1 = dims
    n = p["sash_count"] or int(np.clip(round((yi1 - yi0) / p["sash_width"]), 1, 4))
    st = float(np.clip(0.3 * fd, 0.022, 0.045))
    st = min(st, (fd - TRACK_GAP - 0.004) / 2)
    xb = (-TRACK_GAP / 2 - st, -TRACK_GAP / 2)  # back track (outside)
    xf = (TRACK_GAP / 2, TRACK_GAP / 2 + st)  # front track (room side)
    sw = min(p["stile_width"], 0.2 * (zs1 - zi0))
    A, B = yi0 + CLR, yi1 - CLR
    ov = 0.7 * sw  # meeting stiles overlap
    zb, zt = zi0 + CLR, zs1 - CLR

    # frame: the full-depth ring, track divider and lips at the sill and the head
    holes = [(yi0, zi0, yi1, zs1)] + ([transom] if transom else [])
    frame.append(ring(-fd / 2, fd / 2, holes, p))
    lip_h = min(0.016, zb - zi0 + 0.012)
    for z_a, z_b in ((zi0, zi0 + lip_h), (zs1 - lip_h, zs1)):
        frame.append(g.box_between([-DIVIDER / 2, yi0, z_a], [DIVIDER / 2, yi1, z_b], "frame"))
        if xf[1] + CLR + 0.004 < fd / 2:
            frame.append(g.box_between([xf[1] + CLR, yi0, z_a], [fd / 2, yi1, z_b], "frame"))
            frame.append(g.box_between([-fd / 2, yi0, z_a], [xb[0] - CLR, yi1, z_b], "frame"))
    if transom:
        a, b, c, d = transom
        light.append(g.box_between([-GLASS / 2, a, b], [GLASS / 2, c, d], "glass"))

    if n == 1:  # a fixed pane in the back track, the sash in the front track
        s = ((B - A) + ov) / 2
        fixed_left = middle() == "right"  # the sash starts on the right
        ya = A if fixed_left else B - s
        frame += sash(ya, ya + s, zb, zt, *xb, sw, p)
        y0 = B - s if fixed_left else A
        layout = [(y0, "front", -1 if fixed_left else 1, (B - A) - s)]
    else:
        s = ((B - A) + (n - 1) * ov) / n
        starts = [A + i * (s - ov) for i in range(n)]
        tracks = ["back" if i % 2 == 0 else "front" for i in range(n)]
        dirs, spaces = [], []
        for i in range(n):
            same = [k for k in range(n) if tracks[k] == tracks[i]]
            k = same.index(i)
            lo = starts[same[k - 1]] + s if k > 0 else A
            hi = starts[same[k + 1]] if k < len(same) - 1 else B + 0.0
            left, right = starts[i] - lo, hi - (starts[i] + s)
            if abs(left - right) < 1e-9:
                d = -1 if middle() == "left" else 1
            else:
                d = 1 if right > left else -1
            dirs.append(d)
            spaces.append((left, right, k, same))
        layout = []
        for i in range(n):
            left, right, k, same = spaces[i]
            d = dirs[i]
            space = right if d > 0 else left
            nb = (same[k + 1] if k < len(same) - 1 else None) if d > 0 else (same[k - 1] if k > 0 else None)
            if nb is None:
                travel = space
            elif dirs[nb] == -d:
                travel = (space - CLR) / 2
            else:
                travel = space - CLR
            layout.append((starts[i], tracks[i], d, travel))

    sashes = []
    for i, (y0, track, d, travel) in enumerate(layout):
        x0, x1 = xb if track == "back" else xf
        pieces = sash(y0, y0 + s, zb, zt, x0, x1, sw, p)
        sw_i = min(sw, 0.22 * s, 0.22 * (zt - zb))
        y_pull = y0 + sw_i / 2 if d > 0 else y0 + s - sw_i / 2  # on the trailing stile
        depth = PULL if track == "back" else 0.02
        length = min(0.14, 0.25 * (zt - zb))
        pull = hardware.edge_pull(length, "handle", depth=depth, lip=min(0.012, 0.6 * sw_i))
        pieces += pull.placed(Frame.at((x1, y_pull, zb + 0.5 * (zt - zb)), z=(1, 0, 0), x=(0, 0, 1))).pieces
        spec = J.prismatic("frame", f"sash_{i}", (0.5 * (x0 + x1), y0 + s / 2, 0.5 * (zb + zt)), (0, d, 0),
                           0.0, max(travel, 0.01), role="slide")
        sashes.append((f"sash_{i}", pieces, spec))
    return sashes, xf[1] + 0.02


def shutters(p, W, H, fd, z0) -> list:
    """Shutters outside the frame, hinged on its outer edges, closed at rest.

    Each side is one leaf, or two (a bifold) when it is wider than ``shutter_leaf_width``:
    the inner leaf hangs on the outer leaf's free edge (hinge line on the outside face)
    and folds back over it by up to 0.8 pi. It is never wider than the outer leaf, so
    folded on an open outer leaf it stays beside the window. Returns ``(name, pieces, joint spec)``
    per leaf, outer leaves first on each side.
    """
    t = p["shutter_thickness"]
    ha, hb = z0 + CLR, z0 + H - CLR
    x1 = -fd / 2 - CLR  # inner face (toward the frame)
    x0 = x1 - t  # outer face, where the hinge lines run
    fold = W / 2 > p["shutter_leaf_width"]
    leaf = W / 4 if fold else W / 2
    creep = math.hypot(leaf, t) - leaf  # a free back corner creeps this far out as it turns
    side = W / 2 - (creep + CLR / 2 + 0.001)  # each side's leaves end this far from the centre
    out = []
    for k, sign in enumerate((-1, 1)):
        y_out = sign * W / 2
        axis = (0, 0, 1) if sign < 0 else (0, 0, -1)  # the free edge swings out toward -X
        outer = side / 2 - 0.003 if fold else side
        ya, yb = sorted((y_out, y_out - sign * outer))
        name = f"shutter_{k}"
        out.append((name, shutter_leaf(ya, yb, ha, hb, x0, x1, p),
                    J.revolute("frame", name, (x0, y_out, ha), axis, 0.0, p["shutter_angle"], role="hinge")))
        if fold:
            y_hinge = y_out - sign * side / 2
            ya, yb = sorted((y_hinge - sign * 0.003, y_out - sign * side))
            inner = f"shutter_{k + 2}"
            out.append((inner, shutter_leaf(ya, yb, ha, hb, x0, x1, p),
                        J.revolute(name, inner, (x0, y_hinge, ha), axis, 0.0, 0.8 * math.pi, role="hinge")))
    return out


def shutter_leaf(ya, yb, za, zb, x0, x1, p) -> list[g.Piece]:
    style, w, h = p["shutter_style"], yb - ya, zb - za
    sw = min(0.06, 0.2 * w)
    rail = za + 0.45 * h if h > 1.2 else None
    holes = [(ya + sw, za + sw, yb - sw, (rail - sw / 2) if rail else zb - sw)]
    if rail:
        holes.append((ya + sw, rail + sw / 2, yb - sw, zb - sw))
    if style == "boarded":
        n = max(2, round(w / 0.12))
        bw = w / n
        pieces = [g.box_between([x0 + 0.3 * (x1 - x0), ya + k * bw + 0.001, za], [x1, ya + (k + 1) * bw - 0.001, zb],
                                "shutter", bevel=0.002) for k in range(n)]
        for zc in (za + 0.15 * h, zb - 0.15 * h):  # ledges on the outside face
            pieces.append(g.box_between([x0, ya + 0.02, zc - 0.05],
                                        [x0 + 0.3 * (x1 - x0) + 0.001, yb - 0.02, zc + 0.05], "shutter"))
        return pieces
    pieces = [g.panel([x0, ya, za], [x1, yb, zb], "shutter", "x", holes=holes)]
    xc, t = (x0 + x1) / 2, x1 - x0
    if style == "panelled":
        for a, b, c, d in holes:
            pieces.append(g.box_between([xc - 0.3 * t, a, b], [xc + 0.3 * t, c, d], "shutter"))
            pieces.append(g.box_between([x0 + 0.1 * t, a + 0.025, b + 0.025], [x1 - 0.1 * t, c - 0.025, d - 0.025],
                                        "shutter", bevel=0.006))
        return pieces
    # louvred: slats tilted down toward the outside, overlapping like a roof
    meshes, convex = [], []
    ang = math.radians(55)
    ln = 0.9 * t / math.cos(ang)
    thick = 0.005
    pitch = max(0.8 * ln * math.sin(ang), 0.03)
    for a, b, c, d in holes:
        count = max(1, int((d - b) / pitch))
        step = (d - b) / count
        for k in range(count):
            zc = b + (k + 0.5) * step
            u = np.array([math.cos(ang), math.sin(ang)])  # in (x, z): up toward the frame
            nrm = np.array([-u[1], u[0]])
            pts = []
            for sa in (-1, 1):
                for sb in (-1, 1):
                    px, pz = np.array([xc, zc]) + sa * u * ln / 2 + sb * nrm * thick / 2
                    pz = min(max(pz, b + 0.0005), d - 0.0005)
                    pts += [(px, a, pz), (px, c, pz)]
            pts = np.array(pts)
            meshes.append(g.convex_hull(pts))
            convex.append(pts)
    mesh = trimesh.util.concatenate(meshes)
    pieces.append(g.Piece(mesh.vertices, mesh.faces, "shutter", convex))
    return pieces




def curtains(p, W, H, fd, z0, fw, x_room, single: int = 0):
    """A rod on two brackets above the frame and two pleated halves sliding apart, or (``single`` = +1 or -1)
    one panel across the whole rod that draws to that side (a single-panel curtain, common on narrow windows).

    Returns the rod's pieces (fixed to the frame) and ``(name, pieces, joint spec)`` per panel."""
    amp, tc = 0.025, 0.004  # pleat half-depth, fabric thickness
    xc = x_room + p["curtain_offset"] + amp + tc  # curtain and rod plane
    rr = 0.012
    zr = z0 + H + p["curtain_rise"]
    span = W / 2 + p["curtain_overhang"]  # closed curtains reach +-span
    half = span - 0.004
    panels = [(sign * 0.002, sign * span, sign) for sign in (-1, 1)]  # (inner edge, outer edge, direction)
    if single:
        half = 2 * span - 0.004
        panels = [(-single * span, single * span, single)]
    travel = p["curtain_open"] * half
    ends = {s: span + (travel if not single or s == single else 0.0) + 0.03 for s in (-1, 1)}
    rod = [g.cylinder([xc, -ends[-1], zr], [xc, ends[1], zr], rr, "rod", 20)]
    for s in (-1, 1):
        rod.append(g.sphere([xc, s * (ends[s] + 0.02), zr], 0.022, "rod"))
        yb = s * (W / 2 - fw / 2)
        rod += [
            g.box_between([fd / 2 - 0.012, yb - 0.01, z0 + H - fw], [fd / 2, yb + 0.01, zr + 0.006], "rod"),
            g.box_between([fd / 2 - 0.012, yb - 0.006, zr - 0.006], [xc, yb + 0.006, zr + 0.006], "rod"),
        ]
    halves = []

    zt = zr - rr - 0.022
    zb = zt - p["curtain_drop"] * (zt - 0.015)
    lam = 0.14  # pleat wavelength
    for k, (y_in, y_out, sign) in enumerate(panels):
        n = max(2, int(round(abs(y_out - y_in) / (lam / 2))))
        ys = np.linspace(y_in, y_out, n + 1)
        xs = xc + amp * np.where(np.arange(n + 1) % 2 == 0, 1.0, -1.0)
        meshes, convex = [], []
        for i in range(n):
            a, b = np.array([xs[i], ys[i]]), np.array([xs[i + 1], ys[i + 1]])
            d = (b - a) / np.linalg.norm(b - a)
            nrm = np.array([-d[1], d[0]]) * tc / 2
            pts = np.array([(*q, z) for q in (a - nrm, a + nrm, b - nrm, b + nrm) for z in (zb, zt)])
            pts = pts[:, [0, 1, 2]]
            meshes.append(g.convex_hull(pts))
            convex.append(pts)
        mesh = trimesh.util.concatenate(meshes)
        pieces = [g.Piece(mesh.vertices, mesh.faces, "curtain", convex)]
        for y in ys[::2]:  # rings around the rod (decoration: no collision)
            ring = trimesh.creation.annulus(r_min=rr + 0.004, r_max=rr + 0.009, height=0.008)
            ring.apply_transform(trimesh.transformations.rotation_matrix(math.pi / 2, [1, 0, 0]))
            ring.apply_translation([xc, y, zr])
            pieces.append(g.Piece(ring.vertices, ring.faces, "rod", []))
            hook = g.cylinder([xc, y, zt - 0.005], [xc, y, zr - rr - 0.008], 0.0015, "rod", 8).replace(convex=[])
            pieces.append(hook)
        name = f"curtain_{k}"
        halves.append((name, pieces, J.prismatic("frame", name, (xc, (y_in + y_out) / 2, (zb + zt) / 2), (0, sign, 0),
                                                  0.0, travel, role="slide")))
    return rod, halves


# -- tilt-and-turn, top-hung awning, double-hung -----------------------------------------------------------
# Tilt-and-turn sashes tilt inward about their bottom rail by 10-15 degrees (a 100-150 mm gap at the top)
# before turning on their side hinges (Roto NT, Winkhaus activPilot hardware); top-hung awnings open
# outward 30-45 degrees on their top edge; double-hung sashes: the lower one slides up in the room-side
# track, the upper one tilts in for cleaning (tilt-in sashes, Andersen 400 / Marvin, 0.6-1.2 m wide).

TILT = math.radians(12)  # tilt-and-turn: the tilt
AWNING_OPENS = math.radians(36)  # top-hung: the mechanical maximum of its friction stays
AWNING_PIVOT = 0.6  # top-hung: the pivot sits this share of the sash depth from its outer face (in front
#                     of the sash's centre of mass: gravity presses it closed)
UPPER_TILT = math.pi / 3  # double-hung: the upper sash's declared tilt; the core stops it at the lower sash
TILT_CLEAR = 0.004  # m: a tilting sash's top back edge passes under the head with this much to spare


def tilt_turn(frame, light, p, dims, transom, middle):
    """Casement frame and sashes that turn on their side hinge and tilt about their bottom rail's front
    edge (flip_revolute: turn, then tilt about y through that edge)."""
    made, x_room = casement(frame, light, p, dims, transom, middle)
    out = []
    for name, pieces, spec in made:
        d = spec.dofs[0]
        v = np.vstack([pc.vertices for pc in pieces if pc.material != "handle"])
        pivot = (float(v[:, 0].max()), float(v[:, 1].mean()), float(v[:, 2].min()))
        # tilting about its front bottom edge, the sash's back top edge first rises by hypot(depth, height) -
        # height (at atan(depth / height), as it leaves the head): a short deep sash would scrape the head
        # across the CLR gap, so such a sash is made that much lower
        h, depth = float(np.ptp(v[:, 2])), float(np.ptp(v[:, 0]))
        short = math.hypot(depth, h) - h + TILT_CLEAR - CLR
        if short > 0:
            lower = np.eye(4)
            lower[2, 2] = (h - short) / h
            lower[2, 3] = pivot[2] * (1 - lower[2, 2])
            pieces = [pc.transformed(lower) for pc in pieces]
        # turn first, then tilt about the sash's own bottom rail. A real tilt-and-turn handle selects one
        # mode (the gear locks the other hinge): the turn and the tilt exclude each other (exclusive)
        out.append((name, pieces, J.flip_revolute("frame", name, d.origin, d.axis, (d.lower, d.upper), pivot,
                                                  (0, 1, 0), (0.0, TILT), role="hinge", exclusive=True)))
    return out, x_room


def _cells(yi0, yi1, n, mw):
    """``n`` equal cells across the opening, separated by mullions ``mw`` wide."""
    w = ((yi1 - yi0) - (n - 1) * mw) / n
    return [(yi0 + i * (w + mw), yi0 + i * (w + mw) + w) for i in range(n)]


def awning(frame, light, p, dims, transom, middle):
    """Top-hung sashes flush with the outer face, side by side between mullions, opening outward about a
    horizontal pivot near their top; glazing stops on the room side. Returns (sashes, room-side x)."""
    fd, yi0, yi1, zi0, zs1, mw = dims
    n = p["sash_count"] or int(np.clip(round((yi1 - yi0) / p["sash_width"]), 1, 4))
    st = min(float(np.clip(0.5 * fd, 0.035, 0.06)), fd - CLR - 0.015)
    xs0, xs1 = -fd / 2, -fd / 2 + st
    cells = [(a, zi0, b, zs1) for a, b in _cells(yi0, yi1, n, mw)]
    frame.append(ring(-fd / 2, xs1 + CLR, cells, p))
    frame.append(ring(xs1 + CLR, fd / 2, [(a + LIP, b + LIP, c - LIP, d - LIP) for a, b, c, d in cells], p))
    x_piv = xs0 + AWNING_PIVOT * st
    top_gap = CLR + (x_piv - xs0) * math.sin(AWNING_OPENS) + 0.001  # the outer top edge rises into it
    sashes = []
    for i, (a, _, b, _) in enumerate(cells):
        ya, yb, zb, zt = a + CLR, b - CLR, zi0 + CLR, zs1 - top_gap
        pieces = sash(ya, yb, zb, zt, xs0, xs1, p["stile_width"], p)
        sw = min(p["stile_width"], 0.22 * (yb - ya), 0.22 * (zt - zb))
        zk = zb + max(sw / 2, LIP + 0.022)  # the handle clears the stop lip below it
        pieces += _knob(Frame.at((xs1, (ya + yb) / 2, zk), z=(1, 0, 0)))
        spec = J.revolute("frame", f"sash_{i}", (x_piv, (ya + yb) / 2, zt), (0, 1, 0), 0.0, AWNING_OPENS,
                          role="hinge")
        sashes.append((f"sash_{i}", pieces, spec))
    return sashes, fd / 2 + 0.06


def double_hung(frame, light, p, dims, transom, middle):
    """Two sashes in two tracks: the lower one (room side) slides up, the upper one (outside) tilts in about
    its bottom rail's front edge. Returns (sashes, room-side x)."""
    fd, yi0, yi1, zi0, zs1 = dims
    st = min(float(np.clip(0.3 * fd, 0.022, 0.045)), (fd - TRACK_GAP - 0.004) / 2)
    xb = (-TRACK_GAP / 2 - st, -TRACK_GAP / 2)  # upper sash (outside)
    xf = (TRACK_GAP / 2, TRACK_GAP / 2 + st)  # lower sash (room side)
    sw = min(p["stile_width"], 0.2 * (zs1 - zi0), 0.2 * (yi1 - yi0))
    ov = 0.7 * sw  # the meeting rails overlap
    zb, zt = zi0 + CLR, zs1 - CLR
    zm = (zb + zt) / 2
    frame.append(ring(-fd / 2, fd / 2, [(yi0, zi0, yi1, zs1)], p))
    # blind stops behind the upper sash (jambs, head, sill), stop beads before the lower one below the
    # meeting rail and on the sill
    for y0, y1 in ((yi0, yi0 + LIP), (yi1 - LIP, yi1)):
        frame.append(g.box_between([-fd / 2, y0, zi0], [xb[0] - CLR, y1, zs1], "frame"))
        frame.append(g.box_between([xf[1] + CLR, y0, zi0], [fd / 2, y1, zm - ov / 2 - 0.01], "frame"))
    frame.append(g.box_between([-fd / 2, yi0, zs1 - LIP], [xb[0] - CLR, yi1, zs1], "frame"))
    frame.append(g.box_between([-fd / 2, yi0, zi0], [xb[0] - CLR, yi1, zi0 + LIP], "frame"))
    frame.append(g.box_between([xf[1] + CLR, yi0, zi0], [fd / 2, yi1, zi0 + LIP], "frame"))
    ya, yb = yi0 + CLR, yi1 - CLR
    lower = sash(ya, yb, zb, zm + ov / 2, *xf, sw, p)
    sw_l = min(sw, 0.22 * (yb - ya), 0.22 * (zm + ov / 2 - zb))
    pull = hardware.edge_pull(min(0.12, 0.3 * (yb - ya)), "handle", depth=0.02, lip=min(0.012, 0.6 * sw_l))
    lower += pull.placed(Frame.at((xf[1], (ya + yb) / 2, zb + sw_l / 2), z=(1, 0, 0), x=(0, 1, 0))).pieces
    upper = sash(ya, yb, zm - ov / 2, zt, *xb, sw, p)
    sw_u = min(sw, 0.22 * (yb - ya), 0.22 * (zt - zm + ov / 2))
    for y in (ya + sw_u / 2, yb - sw_u / 2):  # the tilt latches at the ends of its top rail
        upper.append(g.box_between([xb[1], y - 0.012, zt - sw_u / 2 - 0.008], [xb[1] + 0.005, y + 0.012,
                                                                                zt - sw_u / 2 + 0.008],
                                   "handle", bevel=0.0015, name="handle"))
    travel = zt - (zm + ov / 2) - 0.02  # the lower sash stops short of the head
    return [("sash_0", lower, J.prismatic("frame", "sash_0", (xf[1], (ya + yb) / 2, zb), (0, 0, 1), 0.0, travel,
                                          role="slide")),
            ("sash_1", upper, J.revolute("frame", "sash_1", (xb[1], (ya + yb) / 2, zm - ov / 2), (0, 1, 0), 0.0,
                                         UPPER_TILT, role="hinge"))], xf[1] + 0.05


# -- window fittings -------------------------------------------------------------------------------
def sill(width: float, frame_depth: float, sill_depth: float, z0: float) -> list[g.Piece]:
    """An exterior sill slab under a frame (its top at ``z0``), ``sill_depth`` out from the frame's outer face and
    ``SILL_EAR`` past it each side, with a drip edge under its outer edge."""
    W, fd, sd = width, frame_depth, sill_depth
    x0, y0, y1 = -fd / 2 - sd, -W / 2 - SILL_EAR, W / 2 + SILL_EAR
    return [g.box_between([x0, y0, 0.0], [fd / 2, y1, z0], "frame", bevel=0.003),
            g.box_between([x0, y0, -SILL_DRIP], [-fd / 2 - sd + SILL_DRIP, y1, 0.0], "frame")]  # drip edge


def sash_lock(xs, y: float, z: float) -> tuple[list[g.Piece], list[g.Piece], tuple]:
    """A cam sash lock (``LOCK``) on a meeting rail over ``xs`` whose top is at ``z``, centred at ``y``: its base
    screwed to the rail's top and its lever (hub and arm) lying along +y. Returns the base, the lever and the
    lever's pivot."""
    bl, bh = LOCK["base"]
    ll, lw, lt = LOCK["lever"]
    xc = (xs[0] + xs[1]) / 2
    base = [g.box_between([xs[0] + 0.002, y - bl / 2, z], [xs[1], y + bl / 2, z + bh], "handle", bevel=0.002)]
    z0 = z + bh + LOCK["gap"]
    lever_ = [g.cylinder([xc, y, z0], [xc, y, z0 + lt + 0.002], LOCK["hub"], "handle", 24),
              g.box_between([xc - lw / 2, y, z0], [xc + lw / 2, y + ll, z0 + lt], "handle", bevel=0.002)]
    return base, lever_, (xc, y, z0)


def free_spindle(spindle: g.Piece) -> tuple[g.Piece, tuple]:
    """An espagnolette lever's spindle (``spindle``, as sunk into its rose) shortened to turn free of the rose;
    returns it and its axis's start."""
    b = spindle.bounds
    y, z = (b[0][1:] + b[1][1:]) / 2
    x0 = float(b[0][0]) + SPINDLE[0]
    return g.cylinder([x0, y, z], [float(b[1][0]), y, z], SPINDLE[1], "handle", 16, name="handle"), (x0, y, z)


def trickle_vent(span, x: float, z: float, h: float) -> tuple[list[g.Piece], list[g.Piece], tuple, float]:
    """A trickle vent (``VENT``) on a head's room face ``x``, over the sash spanning ``span`` in y, centred at
    height ``z`` in a head ``h`` high: a housing with a slot and a shutter slide that covers or opens it.
    Returns the housing, the slide's pieces (with its thumb grip), the slide's start and its travel."""
    ln = min(VENT["length"], 0.8 * (span[1] - span[0]))
    yc = (span[0] + span[1]) / 2
    hh = min(VENT["height"], 0.8 * h)
    d, t = VENT["depth"], VENT["wall"]
    y0, y1 = yc - ln / 2, yc + ln / 2
    housing = [
        g.box_between([x, y0, z - hh / 2], [x + d, y1, z - hh / 2 + t], "handle"),  # floor of the track
        g.box_between([x, y0, z + hh / 2 - t], [x + d, y1, z + hh / 2], "handle"),  # roof
        g.box_between([x, y0 - t, z - hh / 2], [x + d, y0, z + hh / 2], "handle"),  # end caps
        g.box_between([x, y1, z - hh / 2], [x + d, y1 + t, z + hh / 2], "handle")]
    sw = min(VENT["slide"], 0.45 * ln)
    travel = min(VENT["stroke"], ln - sw - 2 * CLR_VENT)
    ys = y0 + CLR_VENT
    slide = g.box_between([x + 0.002, ys, z - hh / 2 + t + CLR_VENT],
                          [x + d - 0.001, ys + sw, z + hh / 2 - t - CLR_VENT], "handle", bevel=0.0008)
    # the slide is pushed by its thumb grip, standing out of the housing's face (the slide itself lies inside
    # the housing: nothing else of it can be taken), pinched across from the front
    gw, gp, gh = VENT["grip"]
    yg, xf = ys + sw / 2, x + d + gp
    grasp = Grasp.make((xf, yg, z), (-1, 0, 0), (0, 1, 0), gw, gp / 2, "line_fixed_handle",
                       ((x + d - 0.001 + (gp + 0.001) / 2, yg, z), (gp + 0.001, gw, gh), np.eye(3)))
    grip = g.box_between([x + d - 0.002, yg - gw / 2, z - gh / 2], [xf, yg + gw / 2, z + gh / 2], "handle",
                         bevel=0.001).with_grasps(grasp)
    return housing, [slide, grip], (x + d / 2, ys, z), travel
