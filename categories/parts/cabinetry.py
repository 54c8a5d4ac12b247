"""Kitchen cabinetry: carcasses, styled fronts, concealed hinges, legs, worktops, sinks, baskets, carousels.

Everything here speaks world coordinates of a cabinet whose fronts face +X (X depth, Y width,
Z up) and returns lists of :class:`~infmob_usd.geometry.Piece`; the kitchen cabinet layout
adds them to its parts. Sizes are real products' (sources beside each constant).
"""

from __future__ import annotations

import math

from infmob_usd import geometry as g

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
