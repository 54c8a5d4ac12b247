"""Window: a frame with 1-4 casement or sliding sashes, optional shutters and curtains.

X is depth (the room side faces +X), Y is width, Z is up. The frame (jambs, head,
bottom rail, mullions, an optional transom light and the glazing stops) is the
root; its bottom stands at z = 0, or on an exterior sill slab when there is one.

* ``casement``: each sash (a glazed frame in the ``glass`` slot, optionally
  divided by glazing bars) sits flush with the frame's room-side face and opens
  inward (+X) about a vertical hinge through the front face at its hinge edge, so
  it always moves away from the stop behind it. Sashes in the left half hinge
  on their left edge (axis -Z), those in the right half on their right edge
  (+Z); a middle sash hinges on either side. So neighbours are always separated
  by the plane of a hinge edge and never sweep into each other; the one pair whose
  free edges meet is either split by a mullion or is a French pair (gap wide
  enough for the free corners' outward creep). Handles (lever or knob) are on the
  free stile.
* ``sliding``: the sashes run in two parallel tracks (separated in X by more than
  the back sashes' finger pulls), alternating tracks so neighbours overlap at their
  meeting stiles. Each sash slides along Y toward the larger free space of its
  track, stopping before the frame and before a same-track neighbour that may
  come toward it; a single sliding sash slides over a fixed pane. Sill and head
  carry a track divider and outer lips.

Optional shutters hang outside (-X) on the frame's outer edges: closed at rest,
they turn about Z away from the window up to ``shutter_angle`` (< pi/2); on a wide
window each side is a bifold whose inner leaf folds back over the outer one. Optional
curtain halves hang from a rod on the room side and slide outward along Y from
the centre (horizontal slides: neutral under gravity). In front of casements the
rod stands off by half a sash width more; the core stops the casements
before they reach the curtains (``limit_to_clearance``). A transom light (fixed glass above a bar)
grows only on frames taller than 1.1 m. Every hinge axis is vertical and every
slide horizontal, so nothing moves under gravity.
"""

from __future__ import annotations

import math

import numpy as np
import trimesh

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Int, Schema

GROWTH = Growth(
    window=Rule(required=("frame", "sash"),
                optional={"shutters": 0.2, "curtains": 0.3, "sill": 0.6, "transom": 0.25}),
    sash=Rule(required=("glass", "handle"), one_of={"casement": 0.55, "sliding": 0.45}),
    shutter=Rule(one_of={"louvred": 0.45, "panelled": 0.3, "boarded": 0.25}),
    middle=Rule(one_of={"left": 0.5, "right": 0.5}),
)
"""``sash.one_of`` and ``shutter.one_of`` are object-wide, so they are the ``style`` and
``shutter_style`` parameters (same weights); ``middle.one_of`` is drawn from the structure
stream for the one sash that has no side: the middle casement of an odd count (its
hinge side), the middle sliding sash of three (its direction), the moving sash of a
single slider (the side it starts on)."""

_STYLES = GROWTH.rules["sash"].one_of
_SHUTTERS = GROWTH.rules["shutter"].one_of

SCHEMA = Schema((
    Float("width", "overall frame width (Y)", "m", 0.6, 2.5),
    Float("height", "overall frame height, excl. the sill (Z)", "m", 0.6, 2.5),
    Choice("style", "how the sashes open", choices=tuple(_STYLES), weights=tuple(_STYLES.values())),
    Int("sash_count", "sashes; auto = round(opening width / sash_width), 1..4", "", 1, 4, auto=True),
    Float("sash_width", "target sash width for the automatic sash count", "m", 0.4, 0.85),
    Float("frame_depth", "frame depth (X)", "m", 0.07, 0.14),
    Float("frame_width", "face width of jambs and head (the bottom rail is 1.25x)", "m", 0.04, 0.09),
    Float("mullion_width", "face width of mullions and the transom bar", "m", 0.04, 0.08),
    Float("stile_width", "face width of a sash frame", "m", 0.035, 0.07),
    Choice("frame_finish", "frame and sash material", choices=("painted", "wood", "plastic"),
           weights=(0.4, 0.3, 0.3)),
    Choice("glazing", "plain panes or panes divided by glazing bars", choices=("plain", "bars"),
           weights=(0.65, 0.35)),
    Int("bar_rows", "pane rows of a sash with glazing bars", "", 2, 4),
    Int("bar_cols", "pane columns of a sash with glazing bars", "", 1, 2),
    Choice("meeting", "where two casements' free edges meet: a mullion or a French pair",
           choices=("mullion", "french")),
    Choice("handle_style", "casement handle", choices=("lever", "knob"), weights=(0.7, 0.3)),
    Choice("handle_finish", "handle material", choices=("chrome", "brushed_metal", "plastic")),
    Float("transom_fraction", "height of the transom light as a fraction of the opening", "",
          0.18, 0.3),
    Float("sill_depth", "exterior sill projection beyond the frame (X)", "m", 0.03, 0.1),
    Float("sill_thickness", "exterior sill thickness", "m", 0.025, 0.05),
    Choice("shutter_style", "shutter leaves", choices=tuple(_SHUTTERS), weights=tuple(_SHUTTERS.values())),
    Choice("shutter_finish", "shutter material", choices=("painted", "wood"), weights=(0.7, 0.3)),
    Float("shutter_thickness", "shutter leaf thickness", "m", 0.025, 0.04),
    Float("shutter_leaf_width", "widest single shutter leaf; a wider side folds in two leaves", "m",
          0.55, 0.8),
    Float("shutter_angle", "how far a shutter opens (it stops short of the wall plane)", "rad",
          1.25, 1.5),
    Float("curtain_offset", "clearance from the sash handles to the curtains (casements: + half a sash width)",
          "m", 0.06, 0.2),
    Float("curtain_rise", "height of the curtain rod above the frame", "m", 0.05, 0.2),
    Float("curtain_overhang", "rod and closed curtains reach past each side of the frame", "m",
          0.05, 0.25),
    Float("curtain_drop", "curtain length as a fraction of the rod height", "", 0.6, 0.98),
    Float("curtain_open", "how far a curtain half slides, as a fraction of its width", "", 0.45, 0.75),
    Choice("rod_finish", "curtain rod material", choices=("brushed_metal", "wood", "chrome")),
    *GROWTH.flags(),
))

_FRAME = {"painted": "painted:white|off_white|light_grey|grey|charcoal|black|sage|navy",
          "plastic": "plastic:white|light_grey|dark_grey|black", "wood": "wood"}
_SHUTTER = {"painted": "painted:sage|navy|charcoal|white|off_white|pastel_blue|pastel_green|grey|black",
            "wood": "wood"}

CLR = 0.004  # m: clearance around every moving part
GLASS = 0.006  # glass pane thickness
LIP = 0.012  # glazing stop / track lip overlap into the opening
TRACK_GAP = 0.016  # sliding: back sash front face to front sash back face
DIVIDER = 0.006  # sliding: track divider width (X)
PULL = 0.007  # sliding: finger pull depth on a back-track sash (fits in TRACK_GAP)


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    bp = Blueprint("window", materials={
        "frame": _FRAME[p["frame_finish"]], "glass": "glass:clear|clear_blue",
        "handle": p["handle_finish"] if p["handle_finish"] != "plastic" else "plastic:white|black",
        "shutter": _SHUTTER[p["shutter_finish"]], "curtain": "fabric", "rod": p["rod_finish"],
    })
    W, H, fd, fw = p["width"], p["height"], p["frame_depth"], p["frame_width"]
    z0 = p["sill_thickness"] if p["has_sill"] else 0.0
    fw = min(fw, 0.12 * W, 0.12 * H)
    yi0, yi1 = -W / 2 + fw, W / 2 - fw  # opening
    zi0, zi1 = z0 + 1.25 * fw, z0 + H - fw
    mw = min(p["mullion_width"], 0.1 * (yi1 - yi0))

    frame: list[g.Piece] = []
    if p["has_sill"]:
        sd = p["sill_depth"]
        frame += [
            g.box_between([-fd / 2 - sd, -W / 2 - 0.03, 0.0], [fd / 2, W / 2 + 0.03, z0], "frame", bevel=0.003),
            g.box_between([-fd / 2 - sd, -W / 2 - 0.03, -0.012], [-fd / 2 - sd + 0.012, W / 2 + 0.03, 0.0],
                          "frame"),  # drip edge
        ]
    zs1 = zi1  # top of the sash area
    transom = None
    if p["has_transom"] and H > 1.1:
        zt = zi1 - p["transom_fraction"] * (zi1 - zi0)
        zs1 = zt - mw / 2
        transom = (yi0, zt + mw / 2, yi1, zi1)

    if p["style"] == "casement":
        sashes, x_room = _casement(frame, p, (fd, yi0, yi1, zi0, zs1, mw), transom, structure)
    else:
        sashes, x_room = _sliding(frame, p, (fd, yi0, yi1, zi0, zs1), transom, structure)
    bp.add("frame", "frame", frame)
    for name, pieces, spec in sashes:
        bp.add(name, "sash", pieces)
        bp.join(spec)

    if p["has_shutters"]:
        _shutters(bp, p, W, H, fd, z0)
    if p["has_curtains"]:
        _curtains(bp, p, W, H, fd, z0, fw, x_room)
    return bp


# ---------------------------------------------------------------------------- sashes


def _sash(y0, y1, z0, z1, x0, x1, sw, p) -> list[g.Piece]:
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


def _lever(x, y, z) -> list[g.Piece]:
    """A window lever on a rose: the lever points down."""
    return [
        g.box_between([x, y - 0.016, z - 0.04], [x + 0.008, y + 0.016, z + 0.03], "handle", bevel=0.003,
                      name="handle"),
        g.cylinder([x + 0.006, y, z], [x + 0.03, y, z], 0.0055, "handle", 16, name="handle"),
        g.box_between([x + 0.022, y - 0.0075, z - 0.12], [x + 0.036, y + 0.0075, z + 0.012], "handle",
                      bevel=0.004, name="handle"),
    ]


def _casement(frame, p, dims, transom, structure):
    """Frame members and inward-opening casement sashes; returns (sashes, room-side x)."""
    fd, yi0, yi1, zi0, zs1, mw = dims
    n = p["sash_count"] or int(np.clip(round((yi1 - yi0) / p["sash_width"]), 1, 4))
    st = min(float(np.clip(0.5 * fd, 0.035, 0.06)), fd - CLR - 0.015)
    xs0, xs1 = fd / 2 - st, fd / 2  # sash back and front faces (flush with the frame)
    # hinge sides: left half on the left, right half on the right, the middle one either way
    sides = []
    for i in range(n):
        c = i - (n - 1) / 2
        sides.append("left" if c < 0 else "right" if c > 0 else GROWTH.choose("middle", structure))
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
    frame.append(_ring(xs0 - CLR, fd / 2, holes, p))
    stops = [(a + LIP, b + LIP, c - LIP, d - LIP) for a, b, c, d in holes]
    frame.append(_ring(-fd / 2, xs0 - CLR, stops, p))
    if transom:
        a, b, c, d = transom
        frame.append(g.box_between([xs0 - CLR - GLASS, a + LIP / 2, b + LIP / 2], [xs0 - CLR, c - LIP / 2, d - LIP / 2],
                                   "glass"))

    sashes = []
    zb, zt = zi0 + CLR, zs1 - CLR
    for i, ((a, b), side) in enumerate(zip(spans, sides)):
        pieces = _sash(a, b, zb, zt, xs0, xs1, p["stile_width"], p)
        sw = min(p["stile_width"], 0.22 * (b - a), 0.22 * (zt - zb))
        y_free = b - sw / 2 if side == "left" else a + sw / 2
        zh = zb + min(0.5 * (zt - zb), 1.0)
        if p["handle_style"] == "lever":
            pieces += _lever(xs1, y_free, zh)
        else:
            pieces += g.knob_handle((xs1, y_free, zh), (1, 0, 0), "handle", radius=0.016, depth=0.035)
        y_hinge = a if side == "left" else b
        for zk in (zb + 0.12 * (zt - zb), zt - 0.12 * (zt - zb)):  # hinge knuckles (no collision)
            knuckle = g.cylinder([xs1 + 0.0045, y_hinge, zk - 0.03], [xs1 + 0.0045, y_hinge, zk + 0.03], 0.0045,
                                 "handle", 12, name="hinge")
            knuckle.convex = []
            pieces.append(knuckle)
        axis = (0, 0, -1) if side == "left" else (0, 0, 1)
        spec = J.revolute("frame", f"sash_{i}", (xs1, y_hinge, zb), axis, 0.0, math.pi / 2, role="hinge")
        sashes.append((f"sash_{i}", pieces, spec))
    # curtains hang far enough in front for the sashes to open some way before the core stops them
    x_room = xs1 + (0.04 if p["handle_style"] == "lever" else 0.036) + 0.5 * s
    return sashes, x_room


def _ring(x0, x1, holes, p) -> g.Piece:
    """A frame slab from x0 to x1 over the whole frame face with the given openings."""
    W, H = p["width"], p["height"]
    z0 = p["sill_thickness"] if p["has_sill"] else 0.0
    return g.panel([x0, -W / 2, z0], [x1, W / 2, z0 + H], "frame", "x", holes=holes)


def _sliding(frame, p, dims, transom, structure):
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
    frame.append(_ring(-fd / 2, fd / 2, holes, p))
    lip_h = min(0.016, zb - zi0 + 0.012)
    for z_a, z_b in ((zi0, zi0 + lip_h), (zs1 - lip_h, zs1)):
        frame.append(g.box_between([-DIVIDER / 2, yi0, z_a], [DIVIDER / 2, yi1, z_b], "frame"))
        if xf[1] + CLR + 0.004 < fd / 2:
            frame.append(g.box_between([xf[1] + CLR, yi0, z_a], [fd / 2, yi1, z_b], "frame"))
            frame.append(g.box_between([-fd / 2, yi0, z_a], [xb[0] - CLR, yi1, z_b], "frame"))
    if transom:
        a, b, c, d = transom
        frame.append(g.box_between([-GLASS / 2, a, b], [GLASS / 2, c, d], "glass"))

    if n == 1:  # a fixed pane in the back track, the sash in the front track
        s = ((B - A) + ov) / 2
        fixed_left = GROWTH.choose("middle", structure) == "right"  # the sash starts on the right
        ya = A if fixed_left else B - s
        frame += _sash(ya, ya + s, zb, zt, *xb, sw, p)
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
                d = -1 if GROWTH.choose("middle", structure) == "left" else 1
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
        pieces = _sash(y0, y0 + s, zb, zt, x0, x1, sw, p)
        sw_i = min(sw, 0.22 * s, 0.22 * (zt - zb))
        y_pull = y0 + sw_i / 2 if d > 0 else y0 + s - sw_i / 2  # on the trailing stile
        depth = PULL if track == "back" else 0.02
        length = min(0.14, 0.25 * (zt - zb))
        pieces += g.pull_handle((x1, y_pull, zb + 0.5 * (zt - zb)), (1, 0, 0), (0, 0, 1), length, "handle",
                                depth=depth, lip=min(0.012, 0.6 * sw_i))
        spec = J.prismatic("frame", f"sash_{i}", (0.5 * (x0 + x1), y0 + s / 2, 0.5 * (zb + zt)), (0, d, 0),
                           0.0, max(travel, 0.01), role="slide")
        sashes.append((f"sash_{i}", pieces, spec))
    return sashes, xf[1] + 0.02


# ---------------------------------------------------------------------------- shutters


def _shutters(bp, p, W, H, fd, z0):
    """Shutters outside the frame, hinged on its outer edges, closed at rest.

    Each side is one leaf, or two (a bifold) when it is wider than ``shutter_leaf_width``:
    the inner leaf hangs on the outer leaf's free edge (hinge line on the outside face)
    and folds back over it by up to 0.8 pi. It is never wider than the outer leaf, so
    folded on an open outer leaf it stays beside the window.
    """
    t = p["shutter_thickness"]
    ha, hb = z0 + CLR, z0 + H - CLR
    x1 = -fd / 2 - CLR  # inner face (toward the frame)
    x0 = x1 - t  # outer face, where the hinge lines run
    fold = W / 2 > p["shutter_leaf_width"]
    leaf = W / 4 if fold else W / 2
    creep = math.hypot(leaf, t) - leaf  # a free back corner creeps this far out as it turns
    side = W / 2 - (creep + CLR / 2 + 0.001)  # each side's leaves end this far from the centre
    for k, sign in enumerate((-1, 1)):
        y_out = sign * W / 2
        axis = (0, 0, 1) if sign < 0 else (0, 0, -1)  # the free edge swings out toward -X
        outer = side / 2 - 0.003 if fold else side
        ya, yb = sorted((y_out, y_out - sign * outer))
        name = f"shutter_{k}"
        bp.add(name, "shutter", _leaf(ya, yb, ha, hb, x0, x1, p))
        bp.join(J.revolute("frame", name, (x0, y_out, ha), axis, 0.0, p["shutter_angle"], role="hinge"))
        if fold:
            y_hinge = y_out - sign * side / 2
            ya, yb = sorted((y_hinge - sign * 0.003, y_out - sign * side))
            inner = f"shutter_{k + 2}"
            bp.add(inner, "shutter", _leaf(ya, yb, ha, hb, x0, x1, p))
            bp.join(J.revolute(name, inner, (x0, y_hinge, ha), axis, 0.0, 0.8 * math.pi, role="hinge"))


def _leaf(ya, yb, za, zb, x0, x1, p) -> list[g.Piece]:
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


# ---------------------------------------------------------------------------- curtains


def _curtains(bp, p, W, H, fd, z0, fw, x_room):
    """A rod on two brackets above the frame and two pleated halves sliding apart."""
    amp, tc = 0.025, 0.004  # pleat half-depth, fabric thickness
    xc = x_room + p["curtain_offset"] + amp + tc  # curtain and rod plane
    rr = 0.012
    zr = z0 + H + p["curtain_rise"]
    span = W / 2 + p["curtain_overhang"]  # closed curtains reach +-span
    half = span - 0.004
    travel = p["curtain_open"] * half
    rod_end = span + travel + 0.03
    rod = [g.cylinder([xc, -rod_end, zr], [xc, rod_end, zr], rr, "rod", 20)]
    for s in (-1, 1):
        rod.append(g.sphere([xc, s * (rod_end + 0.02), zr], 0.022, "rod"))
        yb = s * (W / 2 - fw / 2)
        rod += [
            g.box_between([fd / 2 - 0.012, yb - 0.01, z0 + H - fw], [fd / 2, yb + 0.01, zr + 0.006], "rod"),
            g.box_between([fd / 2 - 0.012, yb - 0.006, zr - 0.006], [xc, yb + 0.006, zr + 0.006], "rod"),
        ]
    bp.extend("frame", rod)

    zt = zr - rr - 0.022
    zb = zt - p["curtain_drop"] * (zt - 0.015)
    lam = 0.14  # pleat wavelength
    for k, sign in enumerate((-1, 1)):
        y_in, y_out = sign * 0.002, sign * span
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
            hook = g.cylinder([xc, y, zt - 0.005], [xc, y, zr - rr - 0.008], 0.0015, "rod", 8)
            hook.convex = []
            pieces.append(hook)
        name = f"curtain_{k}"
        bp.add(name, "curtain", pieces)
        bp.join(J.prismatic("frame", name, (xc, sign * span / 2, (zb + zt) / 2), (0, sign, 0), 0.0, travel,
                            role="slide"))
