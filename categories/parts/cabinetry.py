"""Kitchen cabinetry: carcasses, styled fronts, concealed hinges, legs, worktops, sinks, baskets, carousels.

Everything here speaks world coordinates of a cabinet whose fronts face +X (X depth, Y width,
Z up) and returns lists of :class:`~infmob_usd.geometry.Piece`; the kitchen cabinet layout
adds them to its parts. Sizes are real products' (sources beside each constant).
"""

from __future__ import annotations

import math

from infmob_usd import geometry as g
from infmob_usd.frames import Frame

from . import hardware, panels

# -- kitchen cabinet dimensions (the layout in ``categories/kitchen_cabinet.py`` reads these) ----
GAP = 0.003  # between neighbouring fronts and between moving parts and the carcass
COLUMN = 0.45  # a column per 45 cm of width
COLUMN_MIN = 0.2  # the narrowest column (IKEA METOD's narrowest base cabinet is 20 cm): a hinged leaf's free
#                   edge swings out sideways by thickness^2 / (2 width) and must stay inside the 3 mm reveal
DOUBLE = 0.6  # columns wider than this have double doors
COLUMN_MAX = 1.0  # the widest column (US base cabinets go to 42-48 in; a 1.2 m drawer front and box weigh ~40 kg)
KITCHEN_COLUMN_MAX = 0.9  # a kitchen wall's columns: at most 90 cm (IKEA METOD's widest base cabinet is 80 cm)
SPLASH = 0.012  # splashback panel (12 mm compact laminate / glass)
WALL_MIN = 0.4  # the lowest wall cabinet (IKEA METOD 40 cm high)
DRAWER_WALL = 0.009  # drawer box boards (Blum LEGRABOX: 16 mm bottom on 1 mm steel sides; plywood boxes 9 mm)
TILT = math.radians(25)  # tilt-out sink fronts tip 20-30 degrees (Rev-A-Shelf 6572 tip-out trays)
FLAP = math.radians(100)  # lift-up flap stays open 90-107 degrees (Blum AVENTOS HK)
TOP_OVER = 0.02  # worktop overhang at the front
TOP_END = 0.005  # worktop overhang at a free end of the run
TOP_DRAWER = 0.2  # a top drawer is this fraction of a column's height
SINK_DEPTH = 0.19  # bowl depth
SINK_FRONT = 0.16  # false-front height of a sink base
SINK_MARGIN = (0.1, 0.12, 0.1)  # worktop left around the sink cut-out: front, back, sides
GATE = math.pi / 2  # a door with pull-outs or a carousel behind it
INNER_CLEAR = 0.025  # an inner drawer's box keeps this far from the carcass sides (the hinges)
SPLITS = {2: (0.5, 0.5), 3: (0.4, 0.4, 0.2), 4: (0.3, 0.3, 0.2, 0.2)}  # drawer heights, bottom up
RAIL_BELOW = 0.02  # a wall run's suspension rail: its top this far below the cabinets' top
TALL_SPLIT = 0.45  # a tall cabinet's fixed shelf (upper over lower door) at this fraction of its height
TALL_SHELVES = 3  # the upper door's compartment: this many equal shelf spaces
TALL_HANDLE = 0.1  # handles of a tall cabinet's doors this far from the split
WALL_HANDLE = 0.08  # a wall door's handle: this fraction of its height above its bottom edge
CORNER_BLIND = 0.05  # a corner unit's blind panel reaches this far past the unit's middle
CORNER_LEG = 0.06  # legs under the corner box, this far in from its edges
LIFT_HANDLE = 0.04  # handles of tilt-out fronts and flaps this far from the free edge

# The kitchen cabinet's parameter ranges (min, max), metres unless marked:
RANGES = {
    "width": (1.2, 4.8),  # a kitchen wall's run: 2-10 cabinets of 40-60 cm
    # EN 1116 / IKEA METOD: base cabinets 60 cm deep incl. front, worktop at 85-92 cm
    "base_depth": (0.55, 0.62), "base_height": (0.85, 0.92),
    "tall_height": (1.95, 2.25),  # IKEA METOD high cabinets 200 / 220 cm + 8-10 cm legs
    "wall_depth": (0.3, 0.35), "wall_height": (0.6, 0.9),  # wall cabinets 30-35 cm deep (IKEA METOD 37 cm with door)
    "column_width": (0.4, 0.6),  # IKEA METOD 40 / 60 cm high-cabinet widths
    "corner_size": (0.84, 0.92),  # corner base 88 x 88 cm (IKEA METOD), lazy-susan bases 33-36 in
    "sink_width": (0.8, 1.0),  # sink bases 80 / 90 / 100 cm (IKEA METOD), 30-36 in
    "kitchen_width": (2.4, 4.8),  # a kitchen wall of 4-8 base cabinets (IKEA METOD 40/60/80 cm units)
    "wall_gap": (0.45, 0.6),  # worktop to wall-cabinet bottom: IKEA kitchen planner 50-60 cm; NKBA minimum 15 in
    "board": (0.016, 0.019), "front_thickness": (0.016, 0.022),
    "worktop_thickness": (0.02, 0.04),  # laminate 28-40 mm, stone 20-30 mm
    "plinth_height": (0.08, 0.14),  # IKEA METOD legs 8 cm; US toe kicks 3.5-4.5 in
    "drawer_travel": (0.6, 0.9),  # ratio: full-extension runners 0.9
    "door_angle": (math.pi / 2, 0.65 * math.pi),  # rad: Blum CLIP top hinges 95, 107, 110, 155 degrees
}


def centred(size: float) -> tuple[float, float]:
    """The span ``size`` wide centred on 0 (a run's ys, a carcass's xs)."""
    return (-size / 2, size / 2)


def inset(span, by: float) -> tuple[float, float]:
    """``span`` shrunk by ``by`` at both ends (inside the boards, or a front's reveal)."""
    return (span[0] + by, span[1] - by)


def split(span, first: float) -> tuple[tuple[float, float], tuple[float, float]]:
    """``span`` cut ``first`` from its start: the first part and the rest (a corner or sink box and the run
    beside it)."""
    cut = span[0] + first
    return (span[0], cut), (cut, span[1])


def front_part(xs, depth: float) -> tuple[float, float]:
    """The front ``depth`` of ``xs`` (a box flush with the fronts, less deep than the span)."""
    return (xs[1] - depth, xs[1])


def mid_shelf(xs, ys, zs, t: float) -> g.Piece:
    """A shelf board half way up a compartment."""
    return panels.shelf(xs, ys, (zs[0] + zs[1]) / 2, t, "body")


def open_shelves(xs, ys, zs, t: float, rng) -> list[g.Piece]:
    """An open column's 1-2 shelves (drawn), evenly spaced."""
    k = 1 + int(rng.integers(1, 3))
    return [panels.shelf(xs, ys, zs[0] + (zs[1] - zs[0]) * i / k, t, "body") for i in range(1, k)]


def splashback(x: float, ys, zs) -> g.Piece:
    """A panel on the wall between the worktop and the wall cabinets (it carries them)."""
    return g.box_between([x, ys[0], zs[0]], [x + SPLASH, ys[1], zs[1]], "body")


def sink_fronts(ys, zs, t: float, beside: bool) -> tuple[tuple, tuple, tuple]:
    """A sink box's front span (narrowed to half a divider where a run is ``beside`` it), its tilt-out
    false front's z span at the top and its doors' z span below."""
    fy = (ys[0] + GAP, ys[1] - t / 2 - GAP / 2 if beside else ys[1] - GAP)
    fz1 = zs[1] - GAP
    return fy, (fz1 - SINK_FRONT, fz1), (zs[0] + GAP, fz1 - SINK_FRONT - GAP)


def corner_front(xs, ys, zs, t: float, ft: float, style: str) -> tuple[list[g.Piece], tuple, tuple, dict]:
    """A corner box's front: the blind panel's pieces (fixed in the carcass, reaching :data:`CORNER_BLIND`
    past the middle), the door's leaf (hinged on the run's side), the fronts' z span and where the
    carousel behind it turns (``centre``, ``radius``, ``zs``)."""
    D = xs[1] - xs[0]
    mid = (ys[0] + ys[1]) / 2 - CORNER_BLIND
    fz = (zs[0] + GAP, zs[1] - GAP)
    x = xs[1]
    blind = front(x + GAP, x + GAP + ft, (ys[0] + GAP, mid - GAP / 2), fz, style, "front")[0]
    leaf = (mid + GAP / 2, ys[1] - t / 2 - GAP / 2, "right")
    carousel = dict(centre=(x - D / 2, (ys[0] + ys[1]) / 2), radius=min(D, ys[1] - ys[0]) / 2 - t - CAROUSEL_CLEAR,
                    zs=(zs[0] + t, zs[1] - t))
    return blind, leaf, fz, carousel


def tall_split(xs, ys, zs, fzs, t: float) -> tuple[list[g.Piece], tuple, tuple, tuple]:
    """A tall cabinet's fixed shelf at :data:`TALL_SPLIT` with :data:`TALL_SHELVES` spaces over it: the
    boards, the upper door's and the lower door's z spans and the compartment under the split."""
    split = zs[0] + TALL_SPLIT * (zs[1] - zs[0])
    boards = [g.box_between([xs[0] + t / 2, ys[0], split - t], [xs[1], ys[1], split], "body")] + \
        [panels.shelf(xs, ys, split + (zs[1] - split) * i / TALL_SHELVES, t, "body") for i in range(1, TALL_SHELVES)]
    fsplit = split - t / 2
    return boards, (fsplit + GAP / 2, fzs[1]), (fzs[0], fsplit - GAP / 2), (zs[0], split - t)


def drawer_over_doors(xs, ys, zs, fzs, t: float) -> tuple[g.Piece, tuple, tuple, tuple, tuple]:
    """A top drawer (:data:`TOP_DRAWER` of the column) over doors: the board between them, the drawer's
    inner and front z spans, the doors' compartment and front z spans."""
    fh, ih = fzs[1] - fzs[0], zs[1] - zs[0]
    s = 1 - TOP_DRAWER
    top_f = (fzs[0] + s * fh, fzs[1])
    top_i = (zs[0] + s * ih, zs[1])
    board = g.box_between([xs[0] + t / 2, ys[0], top_i[0] - t], [xs[1], ys[1], top_i[0]], "body")
    return board, top_i, top_f, (zs[0], top_i[0] - t), (fzs[0], top_f[0] - GAP / 2)


def pull_frame(x: float, ys, z: float) -> Frame:
    """A drawer's slide: out of the carcass along +X from its front ``x``, mid-width, at height ``z``."""
    return Frame.at((x, sum(ys) / 2, z), z=(1, 0, 0))


def leaf_pair(fys) -> list[tuple[float, float, str]]:
    """Two leaves splitting the front span ``fys`` with a reveal between them, hinged at the outer edges."""
    mid = sum(fys) / 2
    return [(fys[0], mid - GAP / 2, "left"), (mid + GAP / 2, fys[1], "right")]


def front_span(c: int, n: int, ys, run, t: float) -> tuple[float, float]:
    """The front of column ``c`` of ``n`` over ``ys`` in a run over ``run`` (dividers ``t`` thick): half a
    reveal off a divider's middle, a reveal in from the run's ends."""
    (ya, yb), (W0, W1) = ys, run
    return (ya - t / 2 + GAP / 2 if c > 0 else W0 + GAP, yb + t / 2 - GAP / 2 if c < n - 1 else W1 - GAP)


def divider(xs, y: float, zs, t: float) -> g.Piece:
    """A divider board between two columns, to the right of ``y``, set back half a board from the back."""
    return g.box_between([xs[0] + t * 0.5, y, zs[0] + t], [xs[1], y + t, zs[1] - t], "body")


# Handles (hardware.handle): 128-320 mm bar pulls, 30 mm knobs 25 mm proud, edge pulls as long as asked.
BAR_HANDLE = hardware.BAR_SPAN
HANDLE_REACH = 0.03  # a door's handle keeps this far (beyond half its length) from the door's ends
HANDLE_IN = 0.05  # on a slab front a handle is 50 mm from the edge (framed: on the stile or rail)
DOOR_HANDLE = (0.8, 0.9, 0.45)  # handle height / door height: on doors under 0.9 m, on taller doors

# Drawers: 12 mm runner space either side, the box 10 mm off the back, 2 mm behind the front; a
# deep drawer (over 25 cm) has its handle near the top edge (on a slab front HANDLE_IN down); the box
# stays 12 mm over the drawer below and 30 mm under the next one.
RUNNER = 0.012
BOX_BACK = 0.01
BOX_FRONT = 0.002
DEEP_DRAWER = 0.25
BOX_BELOW, BOX_ABOVE = 0.012, 0.03
# Inner (behind-door) drawers: at most 30 cm pitch, 2 cm over the carcass bottom, boxes at most
# 16 cm tall and 4 cm under the next; set back 30 mm behind the door, 16 mm fronts, 30 mm low sides.
INNER_PITCH, INNER_FLOOR, INNER_H, INNER_ROOM = 0.3, 0.02, 0.16, 0.04
INNER_SETBACK, INNER_FRONT, INNER_LOW = 0.03, 0.016, 0.03

# Pull-out larder (Kesseböhmer Dispensa): 90 % extension, a frame of 20 mm steel tube (1.2 mm wall)
# 15 mm in from the carcass sides: rear posts and top rails; the baskets from 5 cm up, 20 cm of the
# height kept free at the top, 1 cm in from the frame.
PULLOUT_EXTENSION = 0.9
PULLOUT_CLEAR = 0.015
TUBE, TUBE_WALL = 0.02, 0.0012
PULLOUT_FLOOR = (0.01, 0.03)  # the front's foot box, over the carcass bottom
BASKETS_FROM, BASKETS_ROOM, BASKET_IN = 0.05, 0.2, 0.01

# Lazy-susan bearing plates (80 mm, 4 mm) top and bottom; trays from 4 cm over the lower plate,
# 10 cm kept free at the top; trays 2 cm inside the carcass.
BEARING_R, BEARING_T = 0.04, 0.004
TRAYS_FROM, TRAYS_ROOM, CAROUSEL_CLEAR = 0.04, 0.1, 0.02

# Tilt-out sink front (Rev-A-Shelf 6572): a sponge tray 6 cm deep and 4.2 cm high, 5 cm in from the
# front's sides, its floor 15 mm over the hinge.
# (x: its back 6 cm behind the front, its back wall 3 mm; z: floor 15-18 mm, lip up to 6 cm over the hinge)
SPONGE_TRAY = {"back": 0.06, "wall": 0.057, "inset": 0.05, "floor": (0.015, 0.018), "lip": 0.06}

# Legs: behind a kick board (IKEA METOD plinth: set back 50 mm, legs 6-8 cm in), or visible legs with
# levellers 5 cm in from the edges, a pair per 60 cm of run.
PLINTH_LEGS = (0.06, 0.08, 0.06)  # legs in from the back, the front and the sides
KICK_BOARD = (0.06, 0.045, 0.005, 0.002)  # back of board from the front, front of board, end inset, floor gap
LEG_IN, LEG_PITCH, LEG_RUN_END = 0.05, 0.6, 0.12

# Front styles. Shaker / raised-panel frames: 60-70 mm stiles and rails on a 600 mm door
# (Shaker cabinet doors, e.g. IKEA AXSTAD / BODBYN: 62 mm frame, 5-6 mm recessed centre panel).
FRAME = 0.065
RECESS = 0.006  # a shaker centre panel sits this far behind the frame's face
RAISE_BEVEL = 0.012  # the bevelled margin of a raised (fielded) panel
GLASS = 0.004  # 4 mm float glass in a glazed door (IKEA BODBYN glass door)
FRONT_STYLES = ("slab", "shaker", "raised", "glazed")

# Concealed cup hinge: 35 mm cup, 11-13 mm deep, cup centre 22.5 mm from the door edge, fitted
# 80-100 mm from the door's top and bottom (Blum CLIP top 110 degree hinge, data sheet).
CUP_R = 0.0175
CUP_EDGE = 0.0225
CUP_PROUD = 0.0015  # the cup's rim stands this far off the door's inner face

# Adjustable cabinet legs with levellers: 8-15 cm, 40-50 mm foot (IKEA METOD / Häfele Axilo 78).
LEG_R = 0.022
FOOT_R = 0.028
FOOT_H = 0.008

# Wire baskets of pull-out larders: 6 mm rod rims, 80-100 mm deep (Kesseböhmer Dispensa).
BASKET_H = 0.09
ROD = 0.003
MESH = 0.0004

# Lazy susan: 25 mm pole, trays with a 40-50 mm rim (Rev-A-Shelf 6000 series, 28-32 in trays).
POLE_R = 0.0125
TRAY_RIM = 0.045
TRAY_T = 0.005


def carcass(xs, ys, zs, t: float, slot: str, top: bool = True) -> list[g.Piece]:
    """An open-fronted carcass: two sides, a bottom, a top (or two top rails when ``top`` is
    False, as a sink base has: the bowl drops between them) and a half-board back."""
    (x0, x1), (y0, y1), (z0, z1) = xs, ys, zs
    out = [g.box_between([x0, y0, z0], [x1, y0 + t, z1], slot),
           g.box_between([x0, y1 - t, z0], [x1, y1, z1], slot),
           g.box_between([x0 + t / 2, y0 + t, z0], [x1, y1 - t, z0 + t], slot),
           g.box_between([x0, y0 + t, z0], [x0 + t / 2, y1 - t, z1], slot)]
    if top:
        out.append(g.box_between([x0 + t / 2, y0 + t, z1 - t], [x1, y1 - t, z1], slot))
    else:  # front and back rails, 80 mm deep
        out += [g.box_between([x1 - 0.08, y0 + t, z1 - t], [x1, y1 - t, z1], slot),
                g.box_between([x0 + t / 2, y0 + t, z1 - t], [x0 + 0.08, y1 - t, z1], slot)]
    return out


def frame_width(w: float, h: float, style: str) -> float:
    """The stile and rail width of a framed front of ``w`` x ``h`` (0 for a slab, or a front too small
    for a frame)."""
    return 0.0 if style == "slab" or min(w, h) < 0.09 else min(FRAME, 0.2 * min(w, h))


def front(x0: float, x1: float, ys, zs, style: str, slot: str, glass: str = "glass",
          glazed: bool = False) -> tuple[list[g.Piece], float]:
    """A door or drawer front from ``x0`` (inner face) to ``x1`` (outer face) over ``ys`` x ``zs``.

    ``style``: ``slab`` (one bevelled board), ``shaker`` (a frame of stiles and rails around a
    recessed centre panel), ``raised`` (the frame around a fielded panel with bevelled margins),
    ``glazed`` (the frame around a pane of glass; only where ``glazed`` is True, else shaker).
    Returns the pieces and the x of the face at the centre (where a centred handle mounts).
    """
    (y0, y1), (z0, z1) = ys, zs
    w, h, ft = y1 - y0, z1 - z0, x1 - x0
    f = frame_width(w, h, style)
    if not f:
        return [g.box_between([x0, y0, z0], [x1, y1, z1], slot, bevel=0.002)], x1
    frame = [g.box_between([x0, y0, z0], [x1, y0 + f, z1], slot, bevel=0.0015),
             g.box_between([x0, y1 - f, z0], [x1, y1, z1], slot, bevel=0.0015),
             g.box_between([x0, y0 + f, z0], [x1, y1 - f, z0 + f], slot, bevel=0.0015),
             g.box_between([x0, y0 + f, z1 - f], [x1, y1 - f, z1], slot, bevel=0.0015)]
    inner = ([y0 + f, z0 + f], [y1 - f, z1 - f])
    if style == "glazed" and glazed:
        xm = x0 + ft / 2
        pane = g.box_between([xm - GLASS / 2, *inner[0]], [xm + GLASS / 2, *inner[1]], glass)
        # glazing beads hold the pane on its inner side
        b = 0.008
        beads = [g.box_between([x0, inner[0][0], inner[0][1]], [xm - GLASS / 2, inner[0][0] + b, inner[1][1]], slot),
                 g.box_between([x0, inner[1][0] - b, inner[0][1]], [xm - GLASS / 2, inner[1][0], inner[1][1]], slot)]
        return frame + [pane] + beads, x1
    if style == "raised":
        field = g.box_between([x0, *inner[0]], [x1, *inner[1]], slot, bevel=min(RAISE_BEVEL, 0.45 * (ft - 0.004)))
        return frame + [field], x1
    return frame + [g.box_between([x0, *inner[0]], [x1 - RECESS, *inner[1]], slot)], x1 - RECESS


def hinge_cups(x_inner: float, y_edge: float, inward: int, zs, slot: str) -> list[g.Piece]:
    """The two cups of concealed hinges on a door's inner face (``x_inner``), ``inward`` (+1 / -1)
    the direction from the hinge edge ``y_edge`` into the door; a third on doors over 1.2 m."""
    z0, z1 = zs
    h = z1 - z0
    at = [z0 + min(0.1, 0.2 * h), z1 - min(0.1, 0.2 * h)] + ([(z0 + z1) / 2] if h > 1.2 else [])
    y = y_edge + inward * CUP_EDGE
    return [g.cylinder([x_inner - CUP_PROUD, y, z], [x_inner, y, z], CUP_R, slot, 16, name="hinge") for z in at]


def legs(xs, ys, h: float, slot: str, foot: str) -> list[g.Piece]:
    """Adjustable legs under a carcass bottom at height ``h``: a tube and a leveller foot at every
    (x, y) of ``xs`` x ``ys``."""
    out = []
    for x in xs:
        for y in ys:
            out += [g.cylinder([x, y, FOOT_H], [x, y, h], LEG_R, slot, 16, name="leg"),
                    g.cylinder([x, y, 0.0], [x, y, FOOT_H], FOOT_R, foot, 16, name="foot")]
    return out


def worktop(xs, ys, z0: float, z1: float, slot: str, hole=None) -> list[g.Piece]:
    """A worktop slab; with ``hole`` ((x0, x1), (y0, y1)) it is four boards around the sink cut-out."""
    (x0, x1), (y0, y1) = xs, ys
    if hole is None:
        return [g.box_between([x0, y0, z0], [x1, y1, z1], slot, bevel=0.003)]
    (hx0, hx1), (hy0, hy1) = hole
    return [g.box_between([x0, y0, z0], [x1, hy0, z1], slot, bevel=0.002),
            g.box_between([x0, hy1, z0], [x1, y1, z1], slot, bevel=0.002),
            g.box_between([x0, hy0, z0], [hx0, hy1, z1], slot),
            g.box_between([hx1, hy0, z0], [x1, hy1, z1], slot)]


def sink(hole, z_top: float, depth: float, slot: str, tap: str) -> list[g.Piece]:
    """An inset stainless bowl in ``hole`` of a worktop whose top is ``z_top``: a 1 mm-proud rim,
    four walls, a bottom with a drain, and a mixer tap behind it (bowl 0.18-0.20 m deep: Franke,
    Blanco single-bowl inset sinks)."""
    (x0, x1), (y0, y1) = hole
    w, r = 0.0012, 0.025  # sheet, rim width over the worktop
    zb = z_top - depth
    out = [g.box_between([x0 - r, y0 - r, z_top], [x0 + 0.002, y1 + r, z_top + 0.002], slot),
           g.box_between([x1 - 0.002, y0 - r, z_top], [x1 + r, y1 + r, z_top + 0.002], slot),
           g.box_between([x0 + 0.002, y0 - r, z_top], [x1 - 0.002, y0 + 0.002, z_top + 0.002], slot),
           g.box_between([x0 + 0.002, y1 - 0.002, z_top], [x1 - 0.002, y1 + r, z_top + 0.002], slot),
           g.box_between([x0, y0, zb], [x0 + w, y1, z_top], slot),
           g.box_between([x1 - w, y0, zb], [x1, y1, z_top], slot),
           g.box_between([x0 + w, y0, zb], [x1 - w, y0 + w, z_top], slot),
           g.box_between([x0 + w, y1 - w, zb], [x1 - w, y1, z_top], slot),
           g.box_between([x0 + w, y0 + w, zb], [x1 - w, y1 - w, zb + w], slot),
           g.cylinder([(x0 + x1) / 2, (y0 + y1) / 2, zb + w], [(x0 + x1) / 2, (y0 + y1) / 2, zb + w + 0.002],
                      0.045, slot, 24, name="drain")]
    # a mixer tap on the rim behind the bowl: body, spout rising and reaching over the bowl
    xt, yt = x0 - r / 2 - 0.012, (y0 + y1) / 2
    spout = 0.6 * (x1 - x0)
    out += [g.cylinder([xt, yt, z_top + 0.002], [xt, yt, z_top + 0.16], 0.022, tap, 20, name="tap"),
            g.cylinder([xt, yt, z_top + 0.16], [xt, yt, z_top + 0.28], 0.011, tap, 16, name="tap"),
            g.cylinder([xt - 0.004, yt, z_top + 0.27], [xt + spout, yt, z_top + 0.27], 0.011, tap, 16, name="tap"),
            g.cylinder([xt + spout - 0.011, yt, z_top + 0.26], [xt + spout - 0.011, yt, z_top + 0.20], 0.011, tap,
                       16, name="tap")]
    return out


def basket(xs, ys, z: float, slot: str, h: float = BASKET_H) -> list[g.Piece]:
    """A wire basket: a mesh floor (a thin plate) and a rod rim on four low walls."""
    (x0, x1), (y0, y1) = xs, ys
    r = ROD
    out = [g.box_between([x0, y0, z], [x1, y1, z + 2 * r], slot),
           g.box_between([x0, y0, z + 2 * r], [x0 + 2 * r, y1, z + h], slot),
           g.box_between([x1 - 2 * r, y0, z + 2 * r], [x1, y1, z + h], slot),
           g.box_between([x0 + 2 * r, y0, z + 2 * r], [x1 - 2 * r, y0 + 2 * r, z + h], slot),
           g.box_between([x0 + 2 * r, y1 - 2 * r, z + 2 * r], [x1 - 2 * r, y1, z + h], slot)]
    # wire mesh weighs what a 0.4 mm sheet would: a 50 x 45 cm basket ~1.5 kg
    return [pc.replace(sheet=MESH) for pc in out]


def carousel_tray(cx: float, cy: float, z: float, radius: float, slot: str) -> g.Piece:
    """One lazy-susan tray: a round floor with an upstanding rim, around the pole at (cx, cy)."""
    prof = [(0.0, 0.0), (radius, 0.0), (radius, TRAY_RIM), (radius - 0.006, TRAY_RIM),
            (radius - 0.006, TRAY_T), (0.0, TRAY_T)]
    return g.revolve(prof, slot, center=(cx, cy, z), sections=48, name="tray")


def pole(cx: float, cy: float, z0: float, z1: float, slot: str) -> g.Piece:
    return g.cylinder([cx, cy, z0], [cx, cy, z1], POLE_R, slot, 16, name="pole")


def wall_rail(xs, ys, z: float, slot: str) -> list[g.Piece]:
    """The steel suspension rail a wall cabinet hangs on, behind its back at the top (IKEA METOD
    suspension rail: 13 x 60 mm profile) and the two hanger housings inside the carcass."""
    (x0, _), (y0, y1) = xs, ys
    return [g.box_between([x0 - 0.013, y0 + 0.02, z - 0.06], [x0, y1 - 0.02, z], slot, name="rail")]


def angle(deg: float) -> float:
    return math.radians(deg)


# -- kitchen cabinet assemblies -----------------------------------------------------------------
def handle_on(style: str, length: float, at, across=(0, 1, 0)) -> list[g.Piece]:
    """The pieces of a :func:`~.hardware.handle` of ``style`` on a front face at point ``at``."""
    return hardware.on_face(hardware.handle(style, length), at, across)


def drawer(xs, ys, fys, fz, bz, t: float, ft: float, style: str, handle_style) -> tuple[list[g.Piece], tuple]:
    """A drawer in a carcass over ``xs`` x ``ys`` (board ``t``): a front (``style``, thickness ``ft``)
    over ``fys`` x ``fz`` a reveal in front of the carcass, its box (``bz`` its z range) on runners,
    and a handle of ``handle_style`` (None: none). Returns the pieces and the box (x0, x1, y0, y1,
    z0, z1)."""
    xf = xs[1]
    box = (xs[0] + t + BOX_BACK, xf - BOX_FRONT, ys[0] + RUNNER, ys[1] - RUNNER, bz[0], bz[1])
    pieces = panels.box_drawer((xf + GAP, xf + GAP + ft, *fys, *fz), box, DRAWER_WALL, "front", "body")[1:]
    face, xface = front(xf + GAP, xf + GAP + ft, fys, fz, style, "front")
    pieces += face
    if handle_style:
        f = frame_width(fys[1] - fys[0], fz[1] - fz[0], style)
        if fz[1] - fz[0] > DEEP_DRAWER:  # deep drawers: the handle near the top edge, on the top rail
            hz, hx = fz[1] - (f / 2 if f else HANDLE_IN), xf + GAP + ft
        else:
            hz, hx = sum(fz) / 2, xface
        pieces += handle_on(handle_style, min(0.5 * (fys[1] - fys[0]), BAR_HANDLE[1]), (hx, sum(fys) / 2, hz))
    return pieces, box


def drawer_stack(splits, zs, fzs):
    """Rows of a drawer stack: per share of ``splits`` (bottom up) the front's z range in ``fzs`` and
    the box's in the carcass interior ``zs`` (the box stays above the front of the drawer below, or
    pulling it drags that one along)."""
    fh, ih = fzs[1] - fzs[0], zs[1] - zs[0]
    f0, i0 = fzs[0], zs[0]
    rows = []
    for s in splits:
        fz = (f0 + GAP / 2, f0 + s * fh - GAP / 2)
        rows.append((fz, (max(i0 + BOX_BELOW, fz[0]), i0 + s * ih - BOX_ABOVE)))
        f0 += s * fh
        i0 += s * ih
    return rows


def door(x1: float, leaf, fzs, ft: float, style: str, handle_style, glazed: bool = False, handle_at=None):
    """A hinged door a reveal in front of a carcass face ``x1``: ``leaf`` (y0, y1, hinge side), over
    ``fzs``; its front, hinge cups and a handle of ``handle_style`` (None: none) on the free stile, at
    ``handle_at`` (else 80 % up a short door, 45 % up a tall one). Returns the pieces and the hinge
    frame (on the front face at the hinge edge; its axis makes the door swing out, +X)."""
    ya, yb, side = leaf
    xf = x1 + GAP
    pieces, _ = front(xf, xf + ft, (ya, yb), fzs, style, "front", glazed=glazed)
    pieces += hinge_cups(xf, ya if side == "left" else yb, 1 if side == "left" else -1, fzs, "hinge")
    h = fzs[1] - fzs[0]
    if handle_style:
        length = min(0.3 * h, BAR_HANDLE[1])
        low, tall, high = DOOR_HANDLE
        hz = handle_at if handle_at is not None else fzs[0] + (low if h < tall else high) * h
        reach = (max(length, BAR_HANDLE[0]) if handle_style == "bar" else length) / 2 + HANDLE_REACH
        hz = min(max(hz, fzs[0] + reach), fzs[1] - reach)  # the whole handle on the door
        f = frame_width(yb - ya, h, style)
        off = f / 2 if f else min(HANDLE_IN, 0.3 * (yb - ya))  # on the stile of a framed door
        pieces += handle_on(handle_style, length, (xf + ft, yb - off if side == "left" else ya + off, hz),
                            across=(0, 0, 1))
    hinge = Frame.at((xf + ft, ya if side == "left" else yb, fzs[0]), z=(0, 0, -1 if side == "left" else 1))
    return pieces, hinge


def inner_drawer_rows(k: int, zs) -> list[tuple[float, float]]:
    """z ranges of ``k`` inner drawers in a compartment ``zs``: at most 30 cm apart."""
    pitch = min((zs[1] - zs[0]) / k, INNER_PITCH)
    out = []
    for r in range(k):
        z = zs[0] + INNER_FLOOR + r * pitch
        out.append((z, z + min(INNER_H, pitch - INNER_ROOM)))
    return out


def inner_drawer(xs, ys, zs, t: float) -> tuple[list[g.Piece], float, float]:
    """An internal pull-out: a low-fronted box set back behind the door, narrowed to pass the hinges
    (Blum / IKEA METOD inner drawers: ~25 mm each side). Returns the pieces and the box's x range."""
    clear = INNER_CLEAR
    x0, x1 = xs[0] + t + BOX_BACK, xs[1] - INNER_SETBACK
    pieces = panels.box_drawer((x1 - INNER_FRONT, x1, ys[0] + clear, ys[1] - clear, zs[0], zs[1]),
                               (x0, x1 - INNER_FRONT, ys[0] + clear, ys[1] - clear, zs[0], zs[1] - INNER_LOW),
                               DRAWER_WALL, "body", "body")
    return pieces, x0, x1


def pullout(xs, ys, fys, fzs, zs, t: float, ft: float, style: str, handle_style, baskets: int):
    """A full-height pull-out larder: the front on full-extension runners carries a frame of wire
    baskets hung on two rear posts and two top rails. Returns the pieces, the travel, and per basket
    its (xs, ys, z)."""
    pieces, _ = drawer(xs, ys, fys, fzs, (zs[0] + PULLOUT_FLOOR[0], zs[0] + PULLOUT_FLOOR[1]), t, ft, style,
                       handle_style)
    clear = PULLOUT_CLEAR
    x0, x1 = xs[0] + t + BOX_BACK, xs[1] - BOX_FRONT
    y0, y1 = ys[0] + clear, ys[1] - clear
    # keep the front; the baskets hang on two rear posts and two top rails of 20 mm steel tube
    frame = [g.box_between([x0, y, zs[0] + PULLOUT_FLOOR[0]], [x0 + TUBE, y + TUBE, zs[1] - TUBE], "wire").replace(
        sheet=TUBE_WALL) for y in (y0, y1 - TUBE)]
    frame += [g.box_between([x0 + TUBE, y, zs[1] - 2 * TUBE], [x1, y + TUBE, zs[1] - TUBE], "wire").replace(
        sheet=TUBE_WALL) for y in (y0, y1 - TUBE)]
    rows = [((x0 + TUBE, x1), (y0 + BASKET_IN, y1 - BASKET_IN),
             zs[0] + BASKETS_FROM + k * (zs[1] - zs[0] - BASKETS_ROOM) / baskets) for k in range(baskets)]
    return [pc for pc in pieces if pc.material != "body"] + frame, PULLOUT_EXTENSION * (x1 - x0), rows


def carousel(cx: float, cy: float, zs, trays: int, slot: str):
    """A lazy susan's bearing plates (fixed, in the carcass) and its pole, from the lower to the upper
    plate. Returns the plates, the pole, the pole's foot z and the trays' z."""
    plates = [g.cylinder([cx, cy, zs[0]], [cx, cy, zs[0] + BEARING_T], BEARING_R, slot, 24),
              g.cylinder([cx, cy, zs[1] - BEARING_T], [cx, cy, zs[1]], BEARING_R, slot, 24)]
    z0, z1 = zs[0] + 2 * BEARING_T, zs[1] - 2 * BEARING_T
    return plates, pole(cx, cy, z0, z1, slot), z0, [z0 + TRAYS_FROM + k * (z1 - z0 - TRAYS_ROOM) / trays
                                                   for k in range(trays)]


def tilt_front(xs, fys, fzs, ft: float, style: str, handle_style):
    """A sink base's false front (slab, or shaker for any framed style) that tips out about its bottom
    edge, a sponge tray behind it. Returns the pieces and the hinge frame (about the outer bottom
    edge, +Y: the top tips out towards +X)."""
    xf = xs[1] + GAP
    pieces, _ = front(xf, xf + ft, fys, fzs, "slab" if style == "slab" else "shaker", "front")
    s = SPONGE_TRAY
    y0, y1 = fys[0] + s["inset"], fys[1] - s["inset"]
    f0, f1 = s["floor"]
    pieces += [g.box_between([xf - s["back"], y0, fzs[0] + f0], [xf - BOX_FRONT, y1, fzs[0] + f1], "tray"),
               g.box_between([xf - s["back"], y0, fzs[0] + f1], [xf - s["wall"], y1, fzs[0] + s["lip"]], "tray")]
    if handle_style:
        pieces += handle_on(handle_style, min(0.4 * (fys[1] - fys[0]), BAR_HANDLE[1]),
                            (xf + ft, sum(fys) / 2, fzs[1] - LIFT_HANDLE))
    return pieces, Frame.at((xf + ft, sum(fys) / 2, fzs[0]), z=(0, 1, 0))


def flap(xs, fys, fzs, ft: float, style: str, handle_style):
    """A lift-up flap hinged at its inner top edge (Blum AVENTOS HK): the bottom swings out and up;
    hanging closed, its weight keeps it on its rest stop. Returns the pieces and the hinge frame."""
    xf = xs[1] + GAP
    pieces, xface = front(xf, xf + ft, fys, fzs, style, "front", glazed=True)
    if handle_style:
        pieces += handle_on(handle_style, min(0.5 * (fys[1] - fys[0]), BAR_HANDLE[1]),
                            (xface, sum(fys) / 2, fzs[0] + LIFT_HANDLE))
    return pieces, Frame.at((xf, sum(fys) / 2, fzs[1]), z=(0, -1, 0))


def plinth(xs, ys, z0: float) -> list[g.Piece]:
    """Legs behind a kick board clipped on, set back 50 mm (IKEA METOD plinth)."""
    (y0, y1), (x0, x1) = ys, xs
    back, fwd, side = PLINTH_LEGS
    kb0, kb1, end, floor = KICK_BOARD
    return (legs([x0 + back, x1 - fwd], [y0 + side, y1 - side], z0, "leg", "foot")
            + [g.box_between([x1 - kb0, y0 + end, 0.0], [x1 - kb1, y1 - end, z0 - floor], "plinth")])


def leg_run(xs, ys, z0: float) -> list[g.Piece]:
    """Visible legs with levellers, one pair per ~60 cm of run."""
    (y0, y1), (x0, x1) = ys, xs
    n = max(2, 1 + math.ceil((y1 - y0 - LEG_RUN_END) / LEG_PITCH))
    at = [y0 + LEG_IN + i * (y1 - y0 - 2 * LEG_IN) / (n - 1) for i in range(n)]
    return legs([x0 + LEG_IN, x1 - LEG_IN], at, z0, "leg", "foot")


def corner_legs(x: float, ys, z0: float) -> list[g.Piece]:
    """Two legs under a corner box's front ``x`` (its back edge), in from its ends ``ys``."""
    return legs([x + CORNER_LEG], [ys[0] + CORNER_LEG, ys[1] - CORNER_LEG], z0, "leg", "foot")


def sink_hole(xs, ys):
    """The worktop's cut-out for a sink over a base box ``xs`` x ``ys``."""
    front_, back, side = SINK_MARGIN
    return ((xs[0] + front_, xs[1] - back), (ys[0] + side, ys[1] - side))


def kitchen_worktop(xs, ys, z0: float, z1: float, hole=None, corner=None) -> list[g.Piece]:
    """The worktop over a run ``xs`` x ``ys``: overhanging at the front and the ends, cut out for a
    sink (``hole``), with a corner box's deeper part (``corner``: (y, x) of its inner corner)."""
    pieces = worktop((xs[0], xs[1] + TOP_OVER), (ys[0] - TOP_END, ys[1] + TOP_END), z0, z1, "top", hole)
    if corner is not None:  # the corner box's deeper part
        yc, xc = corner
        pieces.append(g.box_between([xc, ys[0] - TOP_END, z0], [xs[0], yc, z1], "top", bevel=0.002))
    return pieces
