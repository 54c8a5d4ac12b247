"""Dining table: a rectangular or oval top on an apron, on 4 legs or a pedestal.

X is the long axis (``length``), Y the short axis (``width``), Z is up. The top
overhangs an apron of four boards; the apron stands on 4 legs at its corners
(tapered, turned or square) or on one pedestal (two, trestle style, on a table
longer than 1.9 m) under cross beams just below the apron. Optional mechanisms:

* ``extension``: the top is two halves split at x = 0 that slide apart along the
  long axis (prismatic, +X and -X: horizontal, so neutral under gravity), each
  by up to ``extension_fraction`` of the apron's half length. They rest 3 mm above
  the apron rim. The leaf they reveal is stored fixed inside the apron, just below
  the halves (a ``leaf`` part on a fixed joint).
* ``drawers``: 1-2 drawers in each long apron board (one or both sides), pulled
  out along the short axis (+Y or -Y) by 3/4 of their depth, each with a knob or
  a bar handle. They sit below the stored leaf and clear of the legs.
* ``adjustable_legs``: each leg is a square sleeve under the apron corner and an
  inner leg sliding in it; the inner leg rests at its bottom (on the floor) and
  slides up (prismatic +Z, lower limit 0: gravity holds it at rest).

A table that would grow no moving part at all gets the extension. Everything
slides away from everything else: drawers below the top halves, halves above the
apron, inner legs inside their sleeves, so all joints at 100 % still collide with nothing.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Int, Schema

GROWTH = Growth(
    dining_table=Rule(required=("top", "apron", "support"),
                      optional={"extension": 0.6, "drawers": 0.4, "adjustable_legs": 0.25}),
    support=Rule(one_of={"legs": 0.7, "pedestal": 0.3}),
    drawer=Rule(required=("front", "box", "handle")),
)
"""``support.one_of`` is object-wide, so it is the ``support`` parameter (same weights);
``adjustable_legs`` only grows on legs."""

_SUPPORTS = GROWTH.rules["support"].one_of

SCHEMA = Schema((
    Float("length", "top length (X, the long axis) with the extension closed", "m", 1.4, 2.8),
    Float("width", "top width (Y)", "m", 0.9, 1.2),
    Float("height", "overall height", "m", 0.7, 0.8),
    Choice("top_shape", "shape of the top", choices=("rectangular", "oval"), weights=(0.7, 0.3)),
    Float("top_thickness", "thickness of the top", "m", 0.025, 0.045),
    Float("end_overhang", "overhang of a rectangular top beyond the apron at each end (X)", "m", 0.06, 0.25),
    Float("side_overhang", "overhang of a rectangular top beyond the apron at each side (Y)", "m", 0.05, 0.12),
    Float("apron_height", "apron height (raised to fit a leaf and drawers)", "m", 0.08, 0.14),
    Choice("support", "what carries the apron", choices=tuple(_SUPPORTS), weights=tuple(_SUPPORTS.values())),
    Choice("leg_style", "leg shape", choices=("tapered", "turned", "square"), weights=(0.4, 0.35, 0.25)),
    Float("leg_width", "leg side (square and tapered) or diameter (turned) at the top", "m", 0.05, 0.09),
    Float("extension_fraction", "how far each half slides out, as a fraction of the apron's half length",
          "", 0.25, 0.4),
    Int("drawer_count", "drawers per drawer side", "", 1, 2),
    Choice("drawer_sides", "drawers in one long side (+Y) or both", choices=("one", "both")),
    Choice("handle_style", "drawer handle", choices=("knob", "bar"), weights=(0.55, 0.45)),
    Float("leg_travel", "how far an adjustable inner leg slides up", "m", 0.03, 0.1),
    Float("pedestal_radius", "pedestal column radius", "m", 0.05, 0.09),
    Choice("top_finish", "material of the top and the leaf", choices=("wood", "painted"), weights=(0.75, 0.25)),
    Choice("frame_finish", "legs, apron, pedestal", choices=("wood", "painted", "brushed_metal"),
           weights=(0.6, 0.25, 0.15)),
    Choice("handle_finish", "drawer handle material", choices=("brushed_metal", "chrome", "wood")),
    *GROWTH.flags(),
))

MATERIALS = {"top": "top_finish", "frame": "frame_finish", "handle": "handle_finish",
             "metal": "brushed_metal", "foot": "rubber"}
"""Material slot -> family, or the name of the parameter that picks the family."""

SEAT = 0.003  # top halves above the apron rim
SPLIT = 0.004  # gap between the two halves at rest
BOARD = 0.02  # apron board thickness
CLEAR = 0.003  # drawer fronts in their openings, inner legs in their sleeves
LEAF_T = 0.02  # stored leaf thickness
SLEEVE_WALL = 0.004
DRAWER_WALL = 0.01


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    bp = Blueprint("dining_table", materials={
        slot: p[v] if v in SCHEMA.names else v for slot, v in MATERIALS.items()})
    L, W, H, tt = p["length"], p["width"], p["height"], p["top_thickness"]
    oval = p["top_shape"] == "oval"
    legs = p["support"] == "legs"
    drawers = p["has_drawers"]
    adjustable = legs and p["has_adjustable_legs"]
    extension = p["has_extension"] or not (drawers or adjustable)

    # apron footprint inside the top
    if oval:  # the apron corners stay well inside the ellipse
        La, Wa = 0.64 * L, 0.64 * W
    else:
        La, Wa = L - 2 * p["end_overhang"], W - 2 * p["side_overhang"]
    lw = p["leg_width"] if legs else 0.0
    zt0 = H - tt
    za1 = zt0 - (SEAT if extension else 0.0)
    need = 0.012 + 0.06 + 0.012 + (LEAF_T + 0.01 if extension else 0.0) if drawers else 0.06
    ah = max(p["apron_height"], need)
    za0 = za1 - ah
    leaf_top = za1 - 0.004
    leaf_bot = leaf_top - LEAF_T

    # --- body: apron (with drawer openings), support -------------------------
    n_d = p["drawer_count"] if drawers else 0
    sides = (1, -1) if p["drawer_sides"] == "both" else (1,)
    x_in = La / 2 - max(lw, BOARD)  # free length between the legs (half)
    dw = min(0.5, 2 * x_in / max(n_d, 1) - 0.1)
    xs = [0.0] if n_d == 1 else [-x_in / 2, x_in / 2]
    hz0 = za0 + 0.012
    hz1 = (leaf_bot - 0.006) if extension else za1 - 0.012
    holes = [(x - dw / 2, hz0, x + dw / 2, hz1) for x in xs] if drawers else []

    xb = La / 2 - lw  # boards run between the legs
    body = []
    for s in (1, -1):
        hs = holes if (drawers and s in sides) else []
        body.append(g.panel([-xb, s * Wa / 2 - (BOARD if s > 0 else 0), za0],
                            [xb, s * Wa / 2 + (0 if s > 0 else BOARD), za1], "frame", "y", holes=hs))
        body.append(g.box_between([s * La / 2 - (BOARD if s > 0 else 0), -Wa / 2 + max(lw, BOARD), za0],
                                  [s * La / 2 + (0 if s > 0 else BOARD), Wa / 2 - max(lw, BOARD), za1], "frame"))
    if not extension:
        body += _top(L, W, zt0, H, oval, 0.0)
    corners = [(sx * (La / 2 - lw / 2), sy * (Wa / 2 - lw / 2)) for sx in (1, -1) for sy in (1, -1)]
    inner_legs = []
    if legs and not adjustable:
        for c in corners:
            body += _leg(p["leg_style"], c, lw, 0.0, za1)
    elif adjustable:
        zs0 = 0.45 * H  # sleeve bottom
        zi1 = zs0 + 0.12  # inner leg top at rest
        travel = min(p["leg_travel"], za1 - 0.03 - zi1)
        wi = lw - 2 * (SLEEVE_WALL + CLEAR)
        for k, (cx, cy) in enumerate(corners):
            body += _sleeve(cx, cy, lw, zs0, za1)
            inner_legs.append((f"leg_{k}", [
                g.box_between([cx - wi / 2, cy - wi / 2, 0.012], [cx + wi / 2, cy + wi / 2, zi1], "metal",
                              bevel=0.002),
                g.box_between([cx - wi / 2 - 0.002, cy - wi / 2 - 0.002, 0.0],
                              [cx + wi / 2 + 0.002, cy + wi / 2 + 0.002, 0.012], "foot"),
            ], (cx, cy, zi1), travel))
    else:
        body += _pedestals(p, L, La, Wa, za0)
    bp.add("body", "body", body)

    # --- extension: two halves and the stored leaf ---------------------------------
    if extension:
        ext = p["extension_fraction"] * La / 2
        xl = min(ext, x_in - 0.01)
        bp.add("leaf", "leaf", [g.box_between([-xl, -Wa / 2 + BOARD, leaf_bot], [xl, Wa / 2 - BOARD, leaf_top],
                                              "top")])
        bp.join(J.fixed("body", "leaf"))
        for name, s in (("top_front", 1), ("top_back", -1)):
            bp.add(name, "top", _half(L, W, zt0, H, oval, s))
            bp.join(J.prismatic("body", name, (s * SPLIT / 2, 0.0, zt0), (s, 0, 0), 0.0, ext, role="slide"))

    # --- drawers ------------------------------------------------------------------------
    depth = min(0.45, (Wa - 2 * BOARD) * (0.45 if len(sides) == 2 else 0.8))
    k = 0
    for s in sides:
        for x0, z0, x1, z1 in holes:
            name = f"drawer_{k}"
            k += 1
            bp.add(name, "drawer", _drawer(p, (x0 + CLEAR, x1 - CLEAR), (z0 + CLEAR, z1 - CLEAR), s, Wa / 2,
                                           depth))
            bp.join(J.prismatic("body", name, ((x0 + x1) / 2, s * Wa / 2, (z0 + z1) / 2), (0, s, 0), 0.0,
                                0.75 * depth, role="slide"))

    for name, pieces, origin, travel in inner_legs:
        bp.add(name, "leg", pieces)
        bp.join(J.prismatic("body", name, origin, (0, 0, 1), 0.0, travel, role="telescope"))
    return bp


# ---------------------------------------------------------------------------
# pieces


def _outline(L, W, oval, n=96):
    """Points of the top's outline (x, y), counter-clockwise."""
    if oval:
        th = np.linspace(0, 2 * math.pi, n, endpoint=False)
        return np.c_[L / 2 * np.cos(th), W / 2 * np.sin(th)]
    return np.array([[L / 2, W / 2], [-L / 2, W / 2], [-L / 2, -W / 2], [L / 2, -W / 2]])


def _slab(xy, z0, z1, bevel):
    """A convex slab over a convex outline, its top and bottom edges bevelled toward the centre."""
    c = xy.mean(0)
    pts = []
    for z, shrink in ((z0, bevel), (z0 + bevel, 0.0), (z1 - bevel, 0.0), (z1, bevel)):
        d = xy - c
        scale = 1.0 - shrink / np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-9)
        pts.append(np.c_[c + d * scale, np.full(len(xy), z)])
    return g.from_trimesh(g.convex_hull(np.vstack(pts)), "top")


def _top(L, W, z0, z1, oval, _):
    return [_slab(_outline(L, W, oval), z0, z1, 0.2 * (z1 - z0))]


def _half(L, W, z0, z1, oval, s):
    """One half of a split top, from x = s * SPLIT / 2 outward."""
    xy = _outline(L, W, oval, 192)
    xs = SPLIT / 2
    keep = xy[s * xy[:, 0] > xs + 1e-4]
    if oval:
        yc = W / 2 * math.sqrt(max(0.0, 1 - (2 * xs / L) ** 2))
    else:
        yc = W / 2
    pts = np.vstack([keep, [[s * xs, yc], [s * xs, -yc]]])
    return [_slab(pts, z0, z1, 0.15 * (z1 - z0))]


def _leg(style, c, w, z0, z1):
    cx, cy = c
    r = w / 2
    if style == "square":
        return [g.box_between([cx - r, cy - r, z0], [cx + r, cy + r, z1], "frame", bevel=0.003)]
    if style == "tapered":
        rb = 0.55 * r
        pts = np.array([[cx + sx * rr, cy + sy * rr, z] for rr, z in ((rb, z0), (r, z1))
                        for sx in (-1, 1) for sy in (-1, 1)])
        return [g.from_trimesh(g.convex_hull(pts), "frame")]
    # turned: a smooth swelling profile below a square block that meets the apron
    Lh = z1 - z0
    block = 0.2 * Lh
    zz = np.linspace(0.0, Lh - block, 20)
    t = zz / (Lh - block)
    rad = r * (0.5 + 0.2 * t + 0.28 * np.sin(math.pi * np.clip(1.6 * t - 0.2, 0, 1)) ** 2)
    rad = np.minimum(rad, 0.95 * r)
    prof = [(0.0, 0.0), *zip(rad, zz), (0.0, Lh - block)]
    return [g.revolve(prof, "frame", center=(cx, cy, z0), sections=48),
            g.box_between([cx - r, cy - r, z0 + Lh - block - 0.001], [cx + r, cy + r, z1], "frame")]


def _sleeve(cx, cy, w, z0, z1):
    """A square tube of four walls (hollow for the inner leg) with a cap at the top."""
    r, t = w / 2, SLEEVE_WALL
    return [
        g.box_between([cx - r, cy - r, z0], [cx + r, cy - r + t, z1], "frame"),
        g.box_between([cx - r, cy + r - t, z0], [cx + r, cy + r, z1], "frame"),
        g.box_between([cx - r, cy - r + t, z0], [cx - r + t, cy + r - t, z1], "frame"),
        g.box_between([cx + r - t, cy - r + t, z0], [cx + r, cy + r - t, z1], "frame"),
        g.box_between([cx - r, cy - r, z1 - 0.01], [cx + r, cy + r, z1], "frame"),
    ]


def _pedestals(p, L, La, Wa, za0):
    """One column (two on a long table) on a foot, under cross beams below the apron."""
    rc = p["pedestal_radius"]
    zb = za0 - 0.002  # beam tops, just under the apron
    zb0 = zb - 0.04
    xs = [0.0] if L <= 1.9 else [-0.27 * La, 0.27 * La]
    pieces = [g.box_between([-La / 2, -0.035, zb0], [La / 2, 0.035, zb], "frame")]
    for x in xs:
        pieces.append(g.box_between([x - 0.035, -Wa / 2, zb0], [x + 0.035, Wa / 2, zb], "frame"))
        zz = np.linspace(0.06, zb0, 16)
        t = (zz - zz[0]) / (zz[-1] - zz[0])
        rad = rc * (1.0 - 0.25 * np.sin(math.pi * t) + 0.35 * (1 - t) ** 4)
        prof = [(0.0, 0.06), *zip(rad, zz), (0.0, zb0)]
        pieces.append(g.revolve(prof, "frame", center=(x, 0, 0), sections=48))
        if len(xs) == 1:  # a round domed foot
            Rf = 0.32 * p["width"]
            pieces.append(g.revolve([(0.0, 0.0), (Rf, 0.0), (Rf, 0.02), (0.7 * Rf, 0.045), (1.3 * rc, 0.065),
                                     (0.0, 0.065)], "frame", center=(x, 0, 0), sections=64))
        else:  # a trestle foot along Y
            pieces.append(g.box_between([x - 0.05, -0.36 * p["width"], 0.0], [x + 0.05, 0.36 * p["width"], 0.065],
                                        "frame", bevel=0.01))
    if len(xs) == 2:  # a low stretcher between the two columns
        pieces.append(g.box_between([xs[0], -0.025, 0.18], [xs[1], 0.025, 0.23], "frame"))
    return pieces


def _drawer(p, xr, zr, s, y_face, depth):
    """Drawer front flush with the apron face at ``s * y_face``, a box behind it, a handle."""
    x0, x1 = xr
    z0, z1 = zr
    yo = s * y_face  # outer face
    yi = yo - s * BOARD
    yb = yo - s * depth
    lo_y, hi_y = sorted((yi, yb))
    t = DRAWER_WALL
    pieces = [
        g.box_between([x0, min(yo, yi), z0], [x1, max(yo, yi), z1], "frame"),
        g.box_between([x0, lo_y, z0], [x0 + t, hi_y, z1 - 0.01], "frame"),
        g.box_between([x1 - t, lo_y, z0], [x1, hi_y, z1 - 0.01], "frame"),
        g.box_between([x0 + t, min(yb, yb + s * t), z0], [x1 - t, max(yb, yb + s * t), z1 - 0.01], "frame"),
        g.box_between([x0 + t, lo_y, z0], [x1 - t, hi_y, z0 + 0.008], "frame"),
    ]
    anchor = ((x0 + x1) / 2, yo, (z0 + z1) / 2)
    if p["handle_style"] == "knob":
        pieces += g.knob_handle(anchor, (0, s, 0), "handle", radius=min(0.016, 0.3 * (z1 - z0)))
    else:
        pieces += g.bar_handle(anchor, (0, s, 0), (1, 0, 0), min(0.16, 0.5 * (x1 - x0)), "handle",
                               standoff=0.025, radius=0.005)
    return pieces
